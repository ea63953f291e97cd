#!/usr/bin/env bash
# run.sh - runs every test binary (cmocka, TAP output) and every cli_*.sh
# script. One line per test as it ends ("PASS name 12.3 s", "FAIL name ...
# (exit N)" with its output's tail, "SKIP name: reason"), then the ten
# slowest, and last "N passed, M failed, K skipped" (a cmocka binary counts
# each of its cases). Exit status 1 iff something failed.
# A cli_*.sh script is one test: exit 0 passes, 77 skips (it prints its own
# SKIP line), anything else fails.
pass=0 fail=0 skip=0
times=$(mktemp); trap 'rm -f "$times"' EXIT
now() { date +%s.%N; }
for t in "$@"; do
  name=$(basename "$t")
  out=$(mktemp)
  t0=$(now)
  if [[ $t == *.sh ]]; then
    bash "$t" >"$out" 2>&1; rc=$?
    secs=$(awk -v a="$t0" -v b="$(now)" 'BEGIN { printf "%.1f", b - a }')
    case $rc in
      0) pass=$((pass+1)); echo "PASS $name $secs s" ;;
      77) skip=$((skip+1)); grep '^SKIP ' "$out" || echo "SKIP $name: exit 77 with no reason" ;;
      *) fail=$((fail+1)); echo "FAIL $name $secs s (exit $rc)"; sed 's/^/    /' "$out" | tail -30 ;;
    esac
  else
    CMOCKA_MESSAGE_OUTPUT=TAP "$t" >"$out" 2>&1; rc=$?
    secs=$(awk -v a="$t0" -v b="$(now)" 'BEGIN { printf "%.1f", b - a }')
    grep '^SKIP ' "$out"
    p=$(grep -c '^ok ' "$out"); s=$(grep -c '^not ok .*# SKIP' "$out")
    f=$(grep '^not ok ' "$out" | grep -vc '# SKIP')
    pass=$((pass+p)); skip=$((skip+s)); fail=$((fail+f))
    if [ "$f" -gt 0 ] || { [ $rc -ne 0 ] && [ "$f" -eq 0 ]; }; then
      [ "$f" -eq 0 ] && fail=$((fail+1))   # crashed or exited non-zero with no failing case
      echo "FAIL $name $secs s (exit $rc)"; grep -v '^ok \|^SKIP ' "$out" | sed 's/^/    /' | tail -40
    else
      echo "PASS $name $secs s ($p cases)"
    fi
  fi
  echo "$secs $name" >>"$times"
  rm -f "$out"
done
echo "slowest:"
sort -rn "$times" | head -10 | awk '{ printf "    %7.1f s  %s\n", $1, $2 }'
echo "$pass passed, $fail failed, $skip skipped"
[ "$fail" -eq 0 ]

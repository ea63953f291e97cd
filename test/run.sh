#!/usr/bin/env bash
# run.sh - runs every test binary (cmocka, TAP output) and every cli_*.sh
# script, prints failures and "SKIP name: reason" lines, and ends with
# "N passed, M failed, K skipped". Exit status 1 iff something failed.
# A cli_*.sh script is one test: exit 0 passes, 77 skips (it prints its own
# SKIP line), anything else fails.
pass=0 fail=0 skip=0
for t in "$@"; do
  name=$(basename "$t")
  out=$(mktemp)
  if [[ $t == *.sh ]]; then
    bash "$t" >"$out" 2>&1; rc=$?
    grep '^SKIP ' "$out"
    case $rc in
      0) pass=$((pass+1)) ;;
      77) skip=$((skip+1)) ;;
      *) fail=$((fail+1)); echo "FAIL $name (exit $rc)"; sed 's/^/    /' "$out" | tail -30 ;;
    esac
  else
    CMOCKA_MESSAGE_OUTPUT=TAP "$t" >"$out" 2>&1; rc=$?
    grep '^SKIP ' "$out"
    p=$(grep -c '^ok ' "$out"); s=$(grep -c '^not ok .*# SKIP' "$out")
    f=$(grep '^not ok ' "$out" | grep -vc '# SKIP')
    pass=$((pass+p)); skip=$((skip+s)); fail=$((fail+f))
    if [ "$f" -gt 0 ] || { [ $rc -ne 0 ] && [ "$f" -eq 0 ]; }; then
      [ "$f" -eq 0 ] && fail=$((fail+1))   # crashed or exited non-zero with no failing case
      echo "FAIL $name (exit $rc)"; grep -v '^ok \|^SKIP ' "$out" | sed 's/^/    /' | tail -40
    fi
  fi
  rm -f "$out"
done
echo "$pass passed, $fail failed, $skip skipped"
[ "$fail" -eq 0 ]

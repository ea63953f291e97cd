#!/usr/bin/env bash
# run.sh - runs every test binary (cmocka, TAP output) and every cli_*.sh
# script, TEST_JOBS at a time (default: the machine's cores). One line per
# test as it ends ("PASS name 12.3 s", "FAIL name ... (exit N)" with its
# output's tail, "SKIP name: reason"), then the ten slowest, and last
# "N passed, M failed, K skipped" (a cmocka binary counts each of its
# cases). Exit status 1 iff something failed.
# A cli_*.sh script is one test: exit 0 passes, 77 skips (it prints its own
# SKIP line), anything else fails. A script with the line "# run.sh: alone"
# (real-time runs, a GUI driven by timed input, timeouts) runs after the
# others, by itself, so that a loaded machine cannot make it miss a deadline.
jobs=${TEST_JOBS:-$(nproc 2>/dev/null || echo 1)}
[ "$jobs" -ge 1 ] 2>/dev/null || jobs=1
dir=$(mktemp -d); trap 'rm -rf "$dir"' EXIT
now() { date +%s.%N; }

# run_one TEST N: runs it; its lines for the log in $dir/N.txt, "pass fail skip secs name" in $dir/N.res
run_one() {
  local t=$1 n=$2 name out rc secs t0 p f s
  name=$(basename "$t"); out="$dir/$n.out"; t0=$(now)
  if [[ $t == *.sh ]]; then
    bash "$t" >"$out" 2>&1; rc=$?
    secs=$(awk -v a="$t0" -v b="$(now)" 'BEGIN { printf "%.1f", b - a }')
    case $rc in
      0) echo "1 0 0 $secs $name" >"$dir/$n.res"; echo "PASS $name $secs s" >"$dir/$n.txt" ;;
      77) echo "0 0 1 $secs $name" >"$dir/$n.res"; { grep '^SKIP ' "$out" || echo "SKIP $name: exit 77 with no reason"; } >"$dir/$n.txt" ;;
      *) echo "0 1 0 $secs $name" >"$dir/$n.res"; { echo "FAIL $name $secs s (exit $rc)"; sed 's/^/    /' "$out" | tail -30; } >"$dir/$n.txt" ;;
    esac
  else
    CMOCKA_MESSAGE_OUTPUT=TAP "$t" >"$out" 2>&1; rc=$?
    secs=$(awk -v a="$t0" -v b="$(now)" 'BEGIN { printf "%.1f", b - a }')
    p=$(grep -c '^ok ' "$out"); s=$(grep -c '^not ok .*# SKIP' "$out")
    f=$(grep '^not ok ' "$out" | grep -vc '# SKIP')
    [ "$f" -eq 0 ] && [ $rc -ne 0 ] && f=1   # crashed or exited non-zero with no failing case
    echo "$p $f $s $secs $name" >"$dir/$n.res"
    { grep '^SKIP ' "$out"
      if [ "$f" -gt 0 ]; then echo "FAIL $name $secs s (exit $rc)"; grep -v '^ok \|^SKIP ' "$out" | sed 's/^/    /' | tail -40
      else echo "PASS $name $secs s ($p cases)"; fi; } >"$dir/$n.txt"
  fi
  rm -f "$out"
  # one test's lines at a time
  { flock 9; cat "$dir/$n.txt"; } 9>"$dir/print.lock"
}

shared=() alone=()
for t in "$@"; do
  if [[ $t == *.sh ]] && grep -q '^# run.sh: alone' "$t"; then alone+=("$t"); else shared+=("$t"); fi
done
n=0
for t in "${shared[@]}"; do
  while [ "$(jobs -rp | wc -l)" -ge "$jobs" ]; do wait -n; done
  n=$((n+1)); run_one "$t" $n &
done
wait
for t in "${alone[@]}"; do n=$((n+1)); run_one "$t" $n; done

cat "$dir"/*.res 2>/dev/null | awk -v out="$dir/sum" '
  { p += $1; f += $2; s += $3 } END { printf "%d %d %d\n", p, f, s > out }'
read -r pass fail skip <"$dir/sum"
echo "slowest:"
cat "$dir"/*.res | sort -k4 -rn | head -10 | awk '{ printf "    %7.1f s  %s\n", $4, $5 }'
echo "$pass passed, $fail failed, $skip skipped"
[ "$fail" -eq 0 ]

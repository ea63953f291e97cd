#!/usr/bin/env bash
# cli_report.sh - mmsim --report: PNG + SVG + JSON beside it for a short
# run, several colours, true and learned walls drawn, lap table in the JSON
# (the same as the run's own JSON), errors up front, nothing half written.
set -u
S=${MMSIM:-build/mmsim}
P="python3 test/pngcheck.py"
T=$(mktemp -d); trap 'rm -rf "$T"' EXIT
. "$(dirname "$0")/lib.sh"

# scripted driver (fast): no map of its own, so true walls only
"$S" --maze mazes/gen-5x5-s1.txt --driver scripted --runs 1 --json --report "$T/run.png" >"$T/out" 2>"$T/err"
rc=$?; [ $rc -eq 0 ] && ok "scripted run with report" || { bad "scripted run: exit $rc"; cat "$T/err"; }
[ -s "$T/run.png" ] && [ -s "$T/run.svg" ] && [ -s "$T/run.json" ] && ok "png, svg, json written" || bad "files: $(ls "$T")"
[ -z "$(ls "$T" | grep '\.tmp\.')" ] && ok "no temporaries left" || bad "temporaries: $(ls "$T")"
read -r w h cols walls <<<"$($P "$T/run.png" size colours near:b4b4b4:0 | tr '\n' ' ')"
[ "${w:-0}" -ge 400 ] && [ "${h:-0}" -ge 400 ] && ok "png size ${w}x$h" || bad "png size: $w x $h"
[ "${cols:-0}" -ge 8 ] && ok "png has $cols colours" || bad "png colours: $cols"
[ "${walls:-0}" -gt 1000 ] && ok "true walls drawn" || bad "true wall pixels: $walls"
same=$(python3 -c "
import json
r = json.load(open('$T/run.json')); d = json.loads(open('$T/out').read().splitlines()[-1])
print(len(r['laps']) == len(d['laps']) == 1 and all(abs(a['run_s'] - b['run_s']) < 0.0015 for a, b in zip(r['laps'], d['laps'])) and r['trajectory_samples'] > 100)")
[ "$same" = True ] && ok "lap table in the report JSON" || bad "report JSON: $(cat "$T/run.json")"
grep -q '^<svg ' "$T/run.svg" && grep -q '</svg>' "$T/run.svg" && grep -q 'Run time' "$T/run.svg" && ok "svg with lap table" || bad "svg"

# firmware: the learned walls appear in the learned colour
"$S" --maze mazes/gen-5x5-s1.txt --driver firmware --report "$T/fw" >"$T/out" 2>"$T/err"
rc=$?; [ $rc -eq 0 ] && ok "firmware run with report" || { bad "firmware run: exit $rc"; cat "$T/err"; }
[ -s "$T/fw" ] && [ -s "$T/fw.svg" ] && [ -s "$T/fw.json" ] && ok "name without .png: siblings appended" || bad "files: $(ls "$T")"
learned=$($P "$T/fw" near:202020:0)
[ "${learned:-0}" -gt 1000 ] && ok "learned walls drawn" || bad "learned wall pixels: $learned"
# the final path is drawn for runs that have one: the firmware (best path on
# its map), the scripted driver (it drives the true best path); an MCU run
# has none (test/cli_pil.sh)
got=$(python3 -c "import json,sys; print(*(json.load(open(f))['final_path_cells'] for f in sys.argv[1:]))" "$T/run.json" "$T/fw.json" 2>&1)
[ "$got" = "5 5" ] && [ "$($P "$T/fw" near:d9b8f0:0)" -gt 500 ] && [ "$($P "$T/run.png" near:d9b8f0:0)" -gt 500 ] \
  && ok "final path drawn for the firmware and the scripted driver" || bad "final path: $got"

# recording changes nothing in the run
"$S" --maze mazes/gen-5x5-s1.txt --driver firmware --json >"$T/a" 2>/dev/null
"$S" --maze mazes/gen-5x5-s1.txt --driver firmware --json --report "$T/again.png" >"$T/b" 2>/dev/null
[ "$(strip "$T/a")" = "$(strip "$T/b")" ] && ok "same run with and without --report" || bad "report changed the run"

# errors: one line, exit 2, before running; nothing written
"$S" --maze mazes/gen-5x5-s1.txt --report "$T/no/such/dir/x.png" >"$T/out" 2>"$T/err"; rc=$?
[ $rc -eq 2 ] && [ "$(wc -l <"$T/err")" -eq 1 ] && grep -q "^mmsim: --report: $T/no/such/dir/x.png: cannot write" "$T/err" \
  && ok "unwritable report path" || bad "unwritable report path: exit $rc $(cat "$T/err")"
mkdir "$T/dir" "$T/sib.svg"
for r in "" "$T/dir" "$T/dir/" "$T/sib.png"; do
  "$S" --maze mazes/gen-5x5-s1.txt --driver scripted --runs 1 --report "$r" >"$T/out" 2>"$T/err"; rc=$?
  [ $rc -eq 2 ] && [ "$(wc -l <"$T/err")" -eq 1 ] && [ ! -s "$T/out" ] && grep -q "^mmsim: --report: " "$T/err" \
    && ok "--report '$r': exit 2 before the run" || bad "--report '$r': exit $rc $(cat "$T/err")"
done
[ ! -e "$T/sib.png" ] && [ ! -e "$T/sib.json" ] && [ -z "$(ls "$T" "$T/dir" | grep '\.tmp\.')" ] && ok "nothing written for a refused --report" || bad "files left: $(ls "$T" "$T/dir")"
# all three files or none: the SVG (55 KB) fails under a 20 KB file size limit after the PNG
# (8 KB) was written; the old report stays whole
for e in png svg json; do echo "old $e" >"$T/old.$e"; done
( ulimit -f 20; trap '' XFSZ; exec "$S" --maze mazes/gen-5x5-s1.txt --driver scripted --runs 1 --report "$T/old.png" ) >"$T/out" 2>"$T/err"; rc=$?
[ $rc -eq 3 ] && [ "$(cat "$T/err")" = "$T/old.svg: cannot write: File too large" ] && ok "report write fails: exit 3, one line" || bad "report write fails: exit $rc $(cat "$T/err")"
[ "$(cat "$T/old.png" "$T/old.svg" "$T/old.json")" = "$(printf 'old png\nold svg\nold json')" ] && [ -z "$(ls "$T" | grep '\.tmp\.')" ] \
  && ok "report write fails: none of the three replaced, no temporaries" || bad "report write fails: $(ls -l "$T"/old.*)"
"$S" --batch mazes --report "$T/b.png" >"$T/out" 2>"$T/err"; rc=$?
[ $rc -eq 2 ] && [ ! -e "$T/b.png" ] && ok "--report with --batch refused" || bad "--report with --batch: exit $rc"

[ $fails -eq 0 ] || { echo "$fails failed"; exit 1; }

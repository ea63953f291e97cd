#!/usr/bin/env bash
# cli_report.sh - mmsim --report: PNG + SVG + JSON + the plots page
# (FILE-plots.png) beside it for a short run, several colours, true and
# learned walls drawn, lap table in the JSON (the same as the run's own
# JSON), the plots' curves where the values put them, a board run's watch
# panels, the same bytes from the same run, errors up front, nothing half
# written.
set -u
S=${MMSIM:-build/mmsim}
P="python3 test/tools/pngcheck.py"
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

# the plots page: its size from its panel count; every panel holds its
# first curve's pixels; the speed curve starts on the zero line and its top
# is the top tick's row, labelled with the JSON's top speed
# plots_check FILE.json [--speed] TITLE...: one line per failed check, nothing when all hold
# (--speed: the speed panel's checks, for a run that moves)
plots_check() { python3 - "$@" <<'PY'
import json, sys
sys.path.insert(0, 'test/tools')
from pngcheck import read_png
j = json.load(open(sys.argv[1])); want = [a for a in sys.argv[2:] if a != '--speed']
p = j['plots']; panels = p['panels']
w, h, bpp, rows = read_png(p['png'])
px = lambda x, y: bytes(rows[y][x * bpp:x * bpp + 3]).hex()
titles = [q['title'] for q in panels]
if (w, h) != (1200, 60 + 156 * len(panels) + 44): print(f'size {w}x{h} for {len(panels)} panels')
for t in want:
    if t not in titles: print(f'no panel {t}: {titles}')
blue = '1f77b4'  # each panel's first series; the others' colours after it
palette = {blue, 'ff7f0e', '2ca02c', '9467bd', '8c564b', 'e377c2', '17becf', 'bcbd22'}
for q in panels:
    x0, y0, x1, y1 = q['box_px']
    n = 0
    for y in range(y0, y1 + 1):
        n += sum(px(x, y) in palette for x in range(x0, x1 + 1))
        if n >= x1 - x0: break
    if n < x1 - x0: print(f"panel {q['title']}: {n} curve pixels")
# laps shaded: the middle of each lap, just under each box's top, is the lap's shade or a curve's;
# contacts marked: red at each panel's foot
col = lambda q, t: q['box_px'][0] + round(t / p['t_end_s'] * (q['box_px'][2] - q['box_px'][0]))
for q in panels:
    for i, lap in enumerate(j['laps']):
        c = px(col(q, (lap['start_s'] + lap['end_s']) / 2), q['box_px'][1] + 1)
        if c not in palette | {'e4eefa', 'd2e2f6'}: print(f"panel {q['title']}: lap {i + 1} not shaded ({c})")
    red = sum(px(x, q['box_px'][3] - 2) == 'e02020' for x in range(q['box_px'][0], q['box_px'][2] + 1))
    if (red > 0) != (p['contacts'] > 0): print(f"panel {q['title']}: {red} contact pixels for {p['contacts']} contacts")
if '--speed' not in sys.argv: sys.exit(0)
sp = panels[0]
x0, y0, x1, y1 = sp['box_px']
if sp['title'] != 'speed' or sp['zero_row_px'] is None: print(f'first panel: {sp}')
elif px(x0, sp['zero_row_px']) != blue: print(f"speed at 0 s: pixel ({x0}, {sp['zero_row_px']}) is {px(x0, sp['zero_row_px'])}")
top = next((y for y in range(y0 - 2, y1 + 1) if any(px(x, y) == blue for x in range(x0, x1 + 1))), None)
if top != y0: print(f'speed curve top row {top}, top tick {y0}')
if abs(sp['y_hi'] - j['top_speed_m_s']) > 1e-9 or sp['label_hi'] != f"{j['top_speed_m_s']:.2f}":
    print(f"top tick {sp['y_hi']} '{sp['label_hi']}', top speed {j['top_speed_m_s']}")
PY
}
[ "$(wc -c <"$T/run-plots.png")" -gt 10000 ] && ok "plots page written beside the report" || bad "plots page: $(ls -l "$T")"
got=$(plots_check "$T/run.json" --speed speed "yaw rate" "motor volts" "motor current" "wheel speed" battery tof 2>&1)
[ -z "$got" ] && ok "plots page: size, every panel's curve, speed 0 at the start and its top at the top tick" || bad "plots page: $got"
"$S" --maze mazes/gen-5x5-s1.txt --driver scripted --runs 1 --report "$T/run2.png" >/dev/null 2>&1
cmp -s "$T/run-plots.png" "$T/run2-plots.png" && cmp -s "$T/run.png" "$T/run2.png" && ok "the same run: the same bytes" || bad "two runs' pictures differ"

# firmware: the learned walls appear in the learned colour
"$S" --maze mazes/gen-5x5-s1.txt --driver firmware --report "$T/fw" >"$T/out" 2>"$T/err"
rc=$?; [ $rc -eq 0 ] && ok "firmware run with report" || { bad "firmware run: exit $rc"; cat "$T/err"; }
[ -s "$T/fw" ] && [ -s "$T/fw.svg" ] && [ -s "$T/fw.json" ] && [ -s "$T/fw-plots.png" ] && ok "name without .png: siblings appended" || bad "files: $(ls "$T")"
learned=$($P "$T/fw" near:202020:0)
[ "${learned:-0}" -gt 1000 ] && ok "learned walls drawn" || bad "learned wall pixels: $learned"
# the final path is drawn for runs that have one: the firmware (best path on
# its map), the scripted driver (it drives the true best path); an MCU run
# has none (test/cli/cli_pil.sh)
got=$(python3 -c "import json,sys; print(*(json.load(open(f))['final_path_cells'] for f in sys.argv[1:]))" "$T/run.json" "$T/fw.json" 2>&1)
[ "$got" = "5 5" ] && [ "$($P "$T/fw" near:d9b8f0:0)" -gt 500 ] && [ "$($P "$T/run.png" near:d9b8f0:0)" -gt 500 ] \
  && ok "final path drawn for the firmware and the scripted driver" || bad "final path: $got"

# a robot with a gyro: its panel, its peaks those of the true yaw rate (noise and bias off)
(cat robots/paper.ini; printf '\n[gyro.z]\nx_mm = 0\ny_mm = 0\nz_mm = 20\nyaw_deg = 0\nnoise_density_dps_rthz = 0\nbias_dps = 0\nbias_rw_dps_rts = 0\n') >"$T/gyro.ini"
"$S" --maze mazes/gen-5x5-s1.txt --robot "$T/gyro.ini" --driver scripted --runs 1 --report "$T/gyro.png" >/dev/null 2>"$T/err"
got=$(plots_check "$T/gyro.json" tof gyro 2>&1; python3 -c "
import json, sys
q = {p['title']: p for p in json.load(open(sys.argv[1]))['plots']['panels']}
g, y = q['gyro'], q['yaw rate']
if not (abs(g['y_hi'] - y['y_hi']) < 0.05 * y['y_hi'] and abs(g['y_lo'] - y['y_lo']) < 0.05 * -y['y_lo']): print(g, y)" "$T/gyro.json" 2>&1)
[ -z "$got" ] && ok "gyro panel: its range within 5 % of the yaw rate's" || bad "gyro panel: $got"

# a run with wall contacts (the ToF firmware on the IR robot): each marked
"$S" --maze mazes/gen-5x5-s1.txt --robot robots/ukmarsbot.ini --driver firmware --time-limit 10 --json --report "$T/hit.png" \
  >"$T/out" 2>"$T/err"
n=$(python3 -c "import json,sys; print(json.loads(open(sys.argv[1]).read().splitlines()[-1])['collisions'], json.load(open(sys.argv[2]))['plots']['contacts'])" "$T/out" "$T/hit.json" 2>&1)
got=$(plots_check "$T/hit.json" ir 2>&1)
[ -z "$got" ] && [ "${n% *}" -gt 0 ] && [ "${n% *}" = "${n#* }" ] && ok "wall contacts marked: $n" || bad "contacts: $n $got"

# a board run with watched variables: a panel each, the counter's curve rising
IMG=build/clients/board/WatchProbe.elf
want_rc 0 "WatchProbe builds for the Nano" env -u MAKEFLAGS -u MFLAGS -u MAKELEVEL make --no-print-directory "$IMG"
"$S" --maze mazes/gen-5x5-s1.txt --board ukmarsbot --robot robots/ukmarsbot.ini --time-limit 2 --avr "$IMG" \
  --watch ticks,down --report "$T/board.png" >"$T/out" 2>"$T/err"
rc=$?; [ $rc -eq 1 ] && ok "board run with --watch and a report" || { bad "board run: exit $rc"; cat "$T/err"; }
got=$(plots_check "$T/board.json" ir ticks down 2>&1)
[ -z "$got" ] && ok "board plots page: IR and a panel per watched variable" || bad "board plots page: $got"
got=$(python3 -c "
import json, sys
q = {p['title']: p for p in json.load(open(sys.argv[1]))['plots']['panels']}
t, d = q['ticks'], q['down']
print(t['y_lo'] == 0 and t['y_hi'] > 150 and d['y_hi'] == 0 and d['y_lo'] < -150)" "$T/board.json" 2>&1)
[ "$got" = True ] && ok "watch panels' axes: ticks counts up, down counts down" || bad "watch panels: $got"

# recording changes nothing in the run
"$S" --maze mazes/gen-5x5-s1.txt --driver firmware --json >"$T/a" 2>/dev/null
"$S" --maze mazes/gen-5x5-s1.txt --driver firmware --json --report "$T/again.png" >"$T/b" 2>/dev/null
[ "$(strip "$T/a")" = "$(strip "$T/b")" ] && ok "same run with and without --report" || bad "report changed the run"

# errors: one line, exit 2, before running; nothing written
"$S" --maze mazes/gen-5x5-s1.txt --report "$T/no/such/dir/x.png" >"$T/out" 2>"$T/err"; rc=$?
[ $rc -eq 2 ] && [ "$(wc -l <"$T/err")" -eq 1 ] && grep -q "^mmsim: --report: $T/no/such/dir/x.png: cannot write" "$T/err" \
  && ok "unwritable report path" || bad "unwritable report path: exit $rc $(cat "$T/err")"
mkdir "$T/dir" "$T/sib.svg" "$T/pl-plots.png"
for r in "" "$T/dir" "$T/dir/" "$T/sib.png" "$T/pl.png"; do
  "$S" --maze mazes/gen-5x5-s1.txt --driver scripted --runs 1 --report "$r" >"$T/out" 2>"$T/err"; rc=$?
  [ $rc -eq 2 ] && [ "$(wc -l <"$T/err")" -eq 1 ] && [ ! -s "$T/out" ] && grep -q "^mmsim: --report: " "$T/err" \
    && ok "--report '$r': exit 2 before the run" || bad "--report '$r': exit $rc $(cat "$T/err")"
done
[ ! -e "$T/sib.png" ] && [ ! -e "$T/sib.json" ] && [ ! -e "$T/pl.png" ] && [ -z "$(ls "$T" "$T/dir" | grep '\.tmp\.')" ] \
  && ok "nothing written for a refused --report" || bad "files left: $(ls "$T" "$T/dir")"
# all four files or none: the SVG (55 KB) fails under a 20 KB file size limit after the PNG
# (8 KB) was written; the old report stays whole
for e in png svg json; do echo "old $e" >"$T/old.$e"; done
echo "old plots" >"$T/old-plots.png"
( ulimit -f 20; trap '' XFSZ; exec "$S" --maze mazes/gen-5x5-s1.txt --driver scripted --runs 1 --report "$T/old.png" ) >"$T/out" 2>"$T/err"; rc=$?
[ $rc -eq 3 ] && [ "$(cat "$T/err")" = "$T/old.svg: cannot write: File too large" ] && ok "report write fails: exit 3, one line" || bad "report write fails: exit $rc $(cat "$T/err")"
[ "$(cat "$T/old.png" "$T/old.svg" "$T/old.json" "$T/old-plots.png")" = "$(printf 'old png\nold svg\nold json\nold plots')" ] && [ -z "$(ls "$T" | grep '\.tmp\.')" ] \
  && ok "report write fails: none of the four replaced, no temporaries" || bad "report write fails: $(ls -l "$T"/old*)"
"$S" --batch mazes --report "$T/b.png" >"$T/out" 2>"$T/err"; rc=$?
[ $rc -eq 2 ] && [ ! -e "$T/b.png" ] && ok "--report with --batch refused" || bad "--report with --batch: exit $rc"

[ $fails -eq 0 ] || { echo "$fails failed"; exit 1; }

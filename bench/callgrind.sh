#!/usr/bin/env bash
# callgrind.sh - the physics' cost in host instructions per simulated ms
# (valgrind's callgrind: the same count whatever the machine's load), beside
# the real-time factor (the best of 3 plain runs: it does depend on the load),
# for seven runs: the firmware contest on japan2018 (seed 1, the paper
# robot), the scripted driver on a 16x16 maze, UKMARSBOT (robots/ukmarsbot.ini)
# scripted on the same maze, the scripted driver on a 32x32 maze
# (mazes/gen-32x32-s1.txt), the 16x16 scripted run at a 2 ms step, and the
# firmware and UKMARSBOT runs with [sim] wheels = hinge (the form other
# than the default spin bodies). Each
# runs --time-limit CG_LIMIT_S (default 5 s of contest time; the lap under way
# runs on, so the simulated time is the JSON's sim_time_s, and the figure is
# callgrind's total over it). docs/BENCHMARKS.md has where the step's
# instructions go.
# Usage: bench/callgrind.sh [MMSIM]   (environment: SHARED, CG_LIMIT_S)
set -u
S=${1:-build/mmsim}
SHARED=${SHARED:-../shared}
LIMIT=${CG_LIMIT_S:-5}
if ! command -v valgrind >/dev/null; then
  echo "SKIP callgrind instructions per simulated ms: no valgrind (make deps)"
  exit 0
fi
J2018=$SHARED/mazes/classic/japan2018.txt
[ -f "$J2018" ] || J2018=mazes/gen-16x16-s1.txt # without the maze database: a generated 16x16
T=$(mktemp -d); trap 'rm -rf "$T"' EXIT
# case NAME ARGS...: one callgrind run and three plain runs of mmsim ARGS
case_ir() {
  local name=$1; shift
  valgrind --tool=callgrind --callgrind-out-file="$T/cg.out" "$S" "$@" --json --time-limit "$LIMIT" \
    >"$T/cg.json" 2>"$T/cg.err" || [ $? = 1 ] || { echo "$name: mmsim failed under callgrind"; return; }
  for i in 1 2 3; do "$S" "$@" --json --time-limit "$LIMIT" 2>/dev/null | tail -1; done >"$T/plain.json"
  ir=$(sed -n 's/.*Collected : //p' "$T/cg.err")
  step=$(callgrind_annotate --inclusive=yes "$T/cg.out" 2>/dev/null | awk '/:dWorldStep /{gsub(",", "", $1); print $1; exit}')
  python3 - "$name" "$ir" "${step:-0}" "$T/cg.json" "$T/plain.json" <<'PY'
import json, sys
name, ir, step = sys.argv[1], int(sys.argv[2]), int(sys.argv[3])
d = json.loads(open(sys.argv[4]).read().splitlines()[-1])
rtf = [json.loads(l)["real_time_factor"] for l in open(sys.argv[5]) if l.strip()]
ms = d["sim_time_s"] * 1000
print("callgrind %-40s: %.3f G instructions / %.3f s simulated = %.1f k / ms (dWorldStep %.1f k / ms); real-time factor best of 3 %.0fx" % (
    name, ir / 1e9, d["sim_time_s"], ir / ms / 1e3, step / ms / 1e3, max(rtf) if rtf else 0))
PY
}
case_ir "firmware $(basename "$J2018" .txt) seed 1" --maze "$J2018" --driver firmware --seed 1
case_ir "scripted gen-16x16-s1" --maze mazes/gen-16x16-s1.txt --driver scripted
case_ir "UKMARSBOT scripted gen-16x16-s1" --maze mazes/gen-16x16-s1.txt --driver scripted --robot robots/ukmarsbot.ini
case_ir "scripted gen-32x32-s1" --maze mazes/gen-32x32-s1.txt --driver scripted
printf '[sim]\nstep_s = 0.002\n' >"$T/s2.ini" # scripted runs may take a 2 ms step (docs/REFERENCE.md, "Config")
case_ir "scripted gen-16x16-s1, 2 ms step" --maze mazes/gen-16x16-s1.txt --driver scripted --config "$T/s2.ini"
printf '[sim]\nwheels = hinge\n' >"$T/hinge.ini" # each wheel a body on a hinge (sim/world/README.md)
case_ir "firmware $(basename "$J2018" .txt) seed 1, wheels = hinge" --maze "$J2018" --driver firmware --seed 1 --config "$T/hinge.ini"
case_ir "UKMARSBOT scripted gen-16x16-s1, wheels = hinge" --maze mazes/gen-16x16-s1.txt --driver scripted --robot robots/ukmarsbot.ini --config "$T/hinge.ini"
# ODE's exact step alone for the robot's 19 rows and for the 9 of the wheels'
# spin as bodies of their own (bench/ode_rows.c): instructions per step, the
# difference of 3,000 and 1,000 steps
O=$(dirname "$S")/ode_rows
if [ -x "$O" ]; then
  for form in hinge spin; do
    a=$(valgrind --tool=callgrind --callgrind-out-file=/dev/null "$O" $form 1000 2>&1 | sed -n 's/.*Collected : //p')
    b=$(valgrind --tool=callgrind --callgrind-out-file=/dev/null "$O" $form 3000 2>&1 | sed -n 's/.*Collected : //p')
    awk -v f=$form -v a="$a" -v b="$b" 'BEGIN { printf "callgrind ode_rows %-5s (%s rows): %.1f k instructions per 1 ms step\n", f, f == "hinge" ? 19 : 9, (b - a) / 2000 / 1e3 }'
  done
else
  echo "SKIP ode_rows: no $O (make $O)"
fi

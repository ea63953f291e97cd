#!/usr/bin/env bash
# armboard.sh - an unmodified ARM image on the emulated STM32 board: Bulebots'
# bulebule (make client-bulebule) on boards/bulebule.ini, maze
# classic/001-anomaly-test, started as sim/arm/README.md says (a press, two
# long presses, a hand before the front sensors; it leaves the start cell
# at 20.7 s of simulated time).
#  - host instructions per simulated ms (valgrind's callgrind: the same count
#    whatever the load): the difference of the runs ending at ARM_CG_A and
#    ARM_CG_B s (default 0.5 and 1.5: after the start-up's translations,
#    bulebule at work: SysTick 1 kHz, TIM1 10 kHz, busy loops, no WFI);
#    under callgrind a simulated second takes about two minutes, so the
#    window is in the boot, not the search
#  - the real-time factor of the run through its search: ended by --input's
#    end at ARM_SEARCH_END s (default 30.7: the boot, the calibration, and
#    10 s of search after it leaves the start cell at 20.7 s)
# Usage: bench/armboard.sh [MMSIM]   (environment: SHARED, B)
set -u
S=${1:-build/mmsim}
B=${B:-build}
SHARED=${SHARED:-../shared}
A=${ARM_CG_A:-0.5} Z=${ARM_CG_B:-1.5} SEARCH=${ARM_SEARCH_END:-30.7}
ELF=$B/clients/bulebule/src/main.elf
MAZE=$SHARED/mazes/classic/001-anomaly-test.txt
[ -s "$ELF" ] || { echo "SKIP bulebule: no $ELF (make client-bulebule)"; exit 0; }
[ -f "$MAZE" ] || { echo "SKIP bulebule: no $MAZE"; exit 0; }
IN="1 button; 3 button=1; 7 button=1; 18 occlude=fl; 18.5 occlude=fr; 19 occlude=fl; 20 occlude=fl"
run() { "$S" --board bulebule --firmware "$ELF" --maze "$MAZE" --json "$@"; }
if command -v valgrind >/dev/null; then
  cg() { valgrind --tool=callgrind --callgrind-out-file=/dev/null "$S" --board bulebule --firmware "$ELF" --maze "$MAZE" --json \
           --input "$IN; $1 end" 2>&1 >/dev/null | sed -n 's/.*Collected : //p'; }
  a=$(cg "$A"); z=$(cg "$Z")
  awk -v a="$a" -v z="$z" -v s0="$A" -v s1="$Z" 'BEGIN { printf "bulebule on the STM32 board: %.1f M host instructions per simulated ms (callgrind, %s-%s s: %.2f G - %.2f G)\n", (z - a) / ((s1 - s0) * 1000) / 1e6, s0, s1, z / 1e9, a / 1e9 }'
else
  echo "SKIP bulebule instructions: no valgrind"
fi
run --input "$IN; $SEARCH end" --time-limit 120 2>/dev/null | tail -1 | python3 -c '
import json, sys
d = json.loads(sys.stdin.read())
p = d["final_pose"]
print("bulebule boot and search on the STM32 board (ended at %s s): sim %.1f s, wall %.1f s, real-time factor %.2fx, cycles %d, final pose (%.3f, %.3f) m, exit %s" % (
    sys.argv[1], d["sim_time_s"], d["wall_time_s"], d["real_time_factor"], d["board"]["cycles"], p["x_m"], p["y_m"], d["exit_reason"]))' "$SEARCH"

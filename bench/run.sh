#!/usr/bin/env bash
# run.sh - `make bench`: flood timing, exploration over the database,
# firmware size. Record the output in docs/BENCHMARKS.md with date and machine.
set -u
B=build
SHARED=${SHARED:-../shared}
DB=$SHARED/mazes
echo "machine: $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //'), $(date -u +%Y-%m-%d)"
if [ -d "$DB" ]; then
  $B/bench_flood "$DB/classic/japan2018.txt" "$DB/halfsize/japan2019hef.txt"
  for m in japan2018 japan2019; do
    printf '%s: ' "$m"; $B/mmmaze explore --json "$DB/classic/$m.txt"
  done
  start=$(date +%s%N)
  $B/mmmaze explore --all "$DB/classic" 2>/dev/null
  end=$(date +%s%N)
  awk -v ns=$((end - start)) 'BEGIN { printf "wall time of mmmaze explore --all classic: %.2f s\n", ns / 1e9 }'
  for m in japan2018 japan2019; do
    for i in 1 2 3; do $B/mmsim --maze "$DB/classic/$m.txt" --json; done | python3 -c '
import json, sys
runs = [json.loads(l) for l in sys.stdin]
d = runs[0]
print("mmsim %s (scripted driver, 3 runs to the goal): sim %.1f s, real-time factor best %.0fx median %.0fx, laps %s, collisions %d" % (
    d["maze"].split("/")[-1], d["sim_time_s"], max(r["real_time_factor"] for r in runs),
    sorted(r["real_time_factor"] for r in runs)[1], [l["run_s"] for l in d["laps"]], d["collisions"]))'
  done
else
  echo "SKIP database benchmarks: $DB not found"
  $B/bench_flood mazes/*.txt
fi
base=$($B/simavr_cycles $B/avr/flood0.elf 2>/dev/null | tail -1); ten=$($B/simavr_cycles $B/avr/flood10.elf 2>/dev/null | tail -1)
awk -v a="$base" -v b="$ten" 'BEGIN { c = (b - a) / 10; printf "AVR (ATmega328P 16 MHz, simavr): full heading-aware flood of a blank 16x16 map: %d cycles = %.1f ms\n", c, c / 16000 }'
base=$($B/simavr_cycles $B/avr/tick0.elf 2>/dev/null | tail -1); hundred=$($B/simavr_cycles $B/avr/tick100.elf 2>/dev/null | tail -1)
awk -v a="$base" -v b="$hundred" 'BEGIN { c = (b - a) / 100; printf "AVR (ATmega328P 16 MHz, simavr): one control tick (motion_tick, float): %d cycles = %.3f ms\n", c, c / 16000 }'
make -s firmware-size

#!/usr/bin/env bash
# run.sh - `make bench`: flood timing, exploration over the database,
# firmware size, processor-in-the-loop contests. Record the output in docs/BENCHMARKS.md with date and machine.
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
print("mmsim %s (our firmware, search and 3 speed runs): sim %.1f s, real-time factor best %.0fx median %.0fx, laps %s, collisions %d" % (
    d["maze"].split("/")[-1], d["sim_time_s"], max(r["real_time_factor"] for r in runs),
    sorted(r["real_time_factor"] for r in runs)[1], [l["run_s"] for l in d["laps"]], d["collisions"]))'
  done
  # the physical lower bounds of a speed run with this robot and motor: on
  # each maze's best orthogonal path, and over every path of the speed run's
  # diagonal and slalom moves (docs/BENCHMARKS.md, "Speed runs against physics",
  # "Best runs against the diagonal lower bound")
  python3 bench/lower_bound.py --mmsim $B/mmsim --mmmaze $B/mmmaze "$DB/classic/japan2018.txt" "$DB/classic/japan2019.txt"
else
  echo "SKIP database benchmarks: $DB not found"
  $B/bench_flood mazes/*.txt
fi
# The physics in host instructions per simulated ms (bench/callgrind.sh:
# firmware japan2018, scripted 16x16, UKMARSBOT scripted, scripted 32x32)
SHARED=$SHARED bash bench/callgrind.sh $B/mmsim
# AVR floods (bench/avr_flood.c: marks 1-6, the true map is $BENCH_MAZE)
$B/simavr_cycles $B/avr/flood.elf 2>/dev/null | awk -v maze="$(basename "${BENCH_MAZE:-true map}" .txt)" '
  BEGIN { what[1] = "full heading-aware flood, blank 16x16 map"; what[2] = "blank map, from the start, stopping there"
          what[3] = "full heading-aware flood, true map " maze; what[4] = "true map " maze ", from the start, stopping there"
          what[5] = "every flood of a grid-mode search of " maze; what[6] = "every search decision (explore_next) of " maze }
  /^mark/ { n = $2 + 0; printf "AVR (ATmega328P 16 MHz, simavr): %s: %s calls, mean %d cycles = %.1f ms, max %d = %.1f ms\n",
            what[n], $3, $6, $6 / 16000, $8, $8 / 16000 }'
base=$($B/simavr_cycles $B/avr/tick0.elf 2>/dev/null | tail -1); hundred=$($B/simavr_cycles $B/avr/tick100.elf 2>/dev/null | tail -1)
awk -v a="$base" -v b="$hundred" 'BEGIN { c = (b - a) / 100; printf "AVR (ATmega328P 16 MHz, simavr): one control tick (motion_tick, float): %d cycles = %.3f ms\n", c, c / 16000 }'
# LCM telemetry overhead: the firmware contest on mazes/gen-16x16-s1.txt, best
# of 7 runs' CPU time (user + sys; steadier than wall time on a shared
# machine), headless vs publishing at the default and the highest rate
python3 - "$B/mmsim" <<'PYEOF'
import json, os, resource, subprocess, sys, tempfile
sim, maze = sys.argv[1], "mazes/gen-16x16-s1.txt"
d = tempfile.mkdtemp(); log = os.path.join(d, "run.lcmlog")
modes = [("headless", []), ("--lcm-log", ["--lcm-log", log]), ("--lcm=memq://", ["--lcm=memq://"]),
         ("--lcm-log --lcm=memq://", ["--lcm-log", log, "--lcm=memq://"]),
         ("--lcm-log --lcm-rate 1000", ["--lcm-log", log, "--lcm-rate", "1000"])]
best = {}
for rep in range(7):  # modes interleaved, so drifting load hits them alike
    for name, args in modes:
        r0 = resource.getrusage(resource.RUSAGE_CHILDREN)
        out = subprocess.run([sim, "--maze", maze, "--driver", "firmware", "--json"] + args, capture_output=True, text=True).stdout
        r1 = resource.getrusage(resource.RUSAGE_CHILDREN)
        cpu = (r1.ru_utime - r0.ru_utime) + (r1.ru_stime - r0.ru_stime)
        best[name] = min(best.get(name, cpu), cpu)
        simt = json.loads(out.splitlines()[-1])["sim_time_s"]
        size = os.path.getsize(log) if os.path.exists(log) else None
        if size is not None: os.remove(log)
        if rep == 0: best[name + " size"] = size
for name, args in modes:
    size = best[name + " size"]
    print("mmsim telemetry %-26s: %.3f s CPU for %.1f s of contest (%+.1f %% vs headless)%s" % (
        name, best[name], simt, (best[name] / best["headless"] - 1) * 100, "" if size is None else ", log %.1f MB" % (size / 1e6)))
os.rmdir(d)
PYEOF
# The same comparison counted in instructions (valgrind's callgrind: the same
# count every run, whatever the load), on the firmware contest on gen-8x8-s1
if command -v valgrind >/dev/null; then
  TL=$(mktemp -d)
  for mode in headless --lcm-log --lcm=memq:// "--lcm-log --lcm-rate 1000"; do
    case $mode in
      headless) args=() ;;
      --lcm-log) args=(--lcm-log "$TL/run.lcmlog") ;;
      --lcm=memq://) args=(--lcm=memq://) ;;
      *) args=(--lcm-log "$TL/run.lcmlog" --lcm-rate 1000) ;;
    esac
    n=$(valgrind --tool=callgrind --callgrind-out-file=/dev/null $B/mmsim --maze mazes/gen-8x8-s1.txt --driver firmware \
      --json "${args[@]}" 2>&1 >/dev/null | sed -n 's/.*Collected : //p')
    [ "$mode" = headless ] && base=$n
    awk -v m="$mode" -v n="$n" -v b="$base" 'BEGIN { printf "mmsim telemetry %-26s: %.3f G instructions, gen-8x8-s1 firmware contest (%+.1f %% vs headless)\n", m, n / 1e9, (n / b - 1) * 100 }'
  done
  rm -rf "$TL"
else
  echo "SKIP telemetry instruction counts: no valgrind"
fi
# The board emulation in host instructions per simulated ms (callgrind: the
# same count every run): mazerunner-core's search (the issue-23 command, 5 s)
# and the sketch pair that polls the encoders with INT0/INT1 in low-level
# mode (their reset default) and in edge mode (3 s each)
if command -v valgrind >/dev/null; then
  board_ir() { # SECONDS IMAGE [ARGS...]: callgrind's count / simulated ms
    local s=$1 img=$2; shift 2
    valgrind --tool=callgrind --callgrind-out-file=/dev/null $B/mmsim --board ukmarsbot --avr "$img" --robot robots/ukmarsbot.ini \
      --maze mazes/gen-16x16-s1.txt --time-limit "$s" --json "$@" 2>&1 >/dev/null | sed -n 's/.*Collected : //p' |
      awk -v s="$s" '{ printf "%.3f", $1 / (s * 1000) / 1e6 }'
  }
  if [ -f $B/clients/mazerunner-core-uk.elf ]; then
    mrc=$(board_ir 5 $B/clients/mazerunner-core-uk.elf --input "0.2 send=X; 0.5 switches=2; 1.0 button; 2.0 occlude=left")
    echo "board: mazerunner-core-uk search, 5 s: $mrc M host instructions per simulated ms"
  else
    echo "SKIP board mazerunner-core search: no $B/clients/mazerunner-core-uk.elf (make mrc-images)"
  fi
  lvl=$(board_ir 3 $B/clients/board/EncPoll.elf); edg=$(board_ir 3 $B/clients/board/EncPollEdge.elf)
  awk -v l="$lvl" -v e="$edg" 'BEGIN { printf "board: encoders polled, INT0/INT1 low-level mode %s M, edge mode %s M host instructions per simulated ms (%.2fx)\n", l, e, l / e }'
else
  echo "SKIP board instruction counts: no valgrind"
fi
make -s firmware-size
# Processor in the loop: the whole mouse (make arduino) in simavr, a full
# 16x16 contest each on the Uno and the Mega 2560 image: real-time factor
# (goal >= 2x), laps, contacts, the stack's high-water mark (SRAM painted)
# and the runner's worst control tick (Timer1: link poll + fw_tick + sends)
for img in uno/Mouse.elf mega2560/Mouse.elf; do
  mcu=atmega328p; [ "${img%%/*}" = mega2560 ] && mcu=atmega2560
  static=$(avr-size -A "$B/arduino/$img" | awk '$1 == ".data" || $1 == ".bss" { s += $2 } END { print s }')
  $B/mmsim --maze mazes/gen-16x16-s1.txt --avr "$B/arduino/$img" --mcu $mcu --time-limit 300 --json --verbose \
    2>"$B/pil-bench.err" | tail -1 | python3 -c '
import json, re, sys
d = json.loads(sys.stdin.read()); a = d["avr"]; err = open(sys.argv[3]).read()
m = re.search(r"runner: (\d+) Hz tick, (\d+) overruns, worst (\d+) us", err)
tick = "%s Hz, %s overruns, worst tick %s us = %d cycles" % (m[1], m[2], m[3], int(m[3]) * 16) if m else "no runner report"
print("PIL %s gen-16x16-s1: %s, sim %.1f s, wall %.1f s, real-time factor %.1fx, laps %s, contact steps %d; static RAM %s B, stack %d B, gap %d B; %s" % (
    sys.argv[1], d["exit_reason"], d["sim_time_s"], d["wall_time_s"], d["real_time_factor"], [l["run_s"] for l in d["laps"]],
    d["collisions"], sys.argv[2], a["stack_max_bytes"], a["sram_free_min_bytes"], tick))' "$img" "$static" "$B/pil-bench.err"
done
# The Uno's whole japan2019 contest (search, proof, back, 3 speed runs; ~50 s
# of wall time): its staircases and long straights broke the AVR's speed runs
# before each run flooded once and ran at 900 mm/s (docs/BENCHMARKS.md)
$B/mmsim --maze "$DB/classic/japan2019.txt" --avr "$B/arduino/uno/Mouse.elf" --json 2>/dev/null | tail -1 | python3 -c '
import json, sys
d = json.loads(sys.stdin.read())
print("PIL uno/Mouse.elf classic/japan2019: %s, sim %.1f s, wall %.1f s, real-time factor %.1fx, laps %s, contact steps %d" % (
    d["exit_reason"], d["sim_time_s"], d["wall_time_s"], d["real_time_factor"], [l["run_s"] for l in d["laps"]], d["collisions"]))' \
  || echo "SKIP PIL japan2019: no $DB/classic/japan2019.txt"
rm -f "$B/pil-bench.err"
# The Cortex-M core on libunicorn (sim/arm): host ns per simulated instruction, exception round trip
$B/armcore_speed || echo "SKIP ARM core: build/armcore_speed failed"
# An unmodified ARM image on the STM32 board: bulebule's host instructions per simulated ms and its search's real-time factor
B=$B SHARED=$SHARED bash bench/armboard.sh $B/mmsim

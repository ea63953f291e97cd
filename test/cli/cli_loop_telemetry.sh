#!/usr/bin/env bash
# run.sh: alone (timed: real-time runs, timed input or timeouts)
# cli_loop_telemetry.sh - every driver's run publishes its telemetry at the
# same rate: the contest loop (sim/contest/run.c), not the driver, publishes
# after each physics step. An LCM log (--lcm-log) of a 3 s run on the same
# maze holds MM_POSE, MM_MOTORS, MM_SENSORS and MM_PARTS at 100 per
# simulated second (one per 10 physics steps, plus the final state) and
# MM_RACE at 10 per second, for: the in-process firmware (the reference),
# the scripted driver, an mms algorithm, an image on the emulated board
# (--board, our MotorPwm sketch: its motors' commands are in MM_MOTORS), a
# processor in the loop (--avr, the Uno Mouse) and a serial link nobody
# answers (--pty, 1 s in real time); the last two also log MM_LINK.
# The board and PIL images come from `make board-sketches` and `make
# arduino` (make test builds both); without them: SKIP.
set -u
S=${MMSIM:-build/mmsim}
L=${MMLOG:-build/mmlog}
B=${BUILD:-build}
T=$(mktemp -d); trap 'rm -rf "$T"' EXIT
. "$(dirname "$0")/lib.sh"
M=mazes/gen-5x5-s1.txt
BOARD_IMG=
for f in "$B/clients/board/MotorPwm.elf" "$B/arduino/nano/board/MotorPwm.elf"; do [ -f "$f" ] && { BOARD_IMG=$f; break; }; done
PIL_IMG=$B/arduino/uno/Mouse-5x5.elf
[ -n "$BOARD_IMG" ] || { echo "SKIP cli_loop_telemetry: no MotorPwm.elf board image (make board-sketches)"; exit 77; }
[ -f "$PIL_IMG" ] || { echo "SKIP cli_loop_telemetry: $PIL_IMG absent (make arduino)"; exit 77; }

# logged NAME [mmsim flags...]: the run's JSON in $T/NAME.json, its log's summary in $T/NAME.sum
logged() { local name=$1; shift
  "$S" --maze $M --json --lcm-log "$T/$name.lcmlog" "$@" >"$T/$name.json" 2>"$T/$name.err"
  local rc=$?
  case $rc in 0|1) ;; *) bad "$name: mmsim exit $rc: $(head -3 "$T/$name.err")"; return 1 ;; esac
  "$L" --json "$T/$name.lcmlog" >"$T/$name.sum" 2>"$T/$name.sumerr" || { bad "$name: mmlog: $(cat "$T/$name.sumerr")"; return 1; }
  "$L" --dump MM_MOTORS "$T/$name.lcmlog" >"$T/$name.motors" 2>/dev/null
  return 0; }
# rates NAME [CHANNEL...]: each channel's count is what its rate gives over the run's simulated time,
# and its count per simulated second matches the firmware run's
rates() { local name=$1; shift
  python3 - "$T" "$name" "$@" <<'PY' && ok "$name: every channel at the firmware run's rate" || bad "$name: telemetry counts"
import json, sys
T, name, extra = sys.argv[1], sys.argv[2], sys.argv[3:]
def load(n):
    run = json.loads(open("%s/%s.json" % (T, n)).read().splitlines()[-1])
    return run, json.load(open("%s/%s.sum" % (T, n)))
run, summ = load(name)
ref_run, ref = load("firmware")
steps = round(run["sim_time_s"] * 1000)  # 1 ms physics steps
def expect(period):  # the multiples of the period, plus the final state
    return steps // period + (1 if steps % period else 0)
fails = []
for ch, period in [("MM_POSE", 10), ("MM_MOTORS", 10), ("MM_SENSORS", 10), ("MM_PARTS", 10), ("MM_RACE", 100)] + \
                  [(c, 100) for c in extra]:
    n = summ.get(ch, {}).get("count", 0)
    rate = n / run["sim_time_s"]
    ref_rate = ref[ch]["count"] / ref_run["sim_time_s"] if ch in ref else None
    print("%s %-10s %5d in %.3f s: %6.2f per s (firmware %s)" % (name, ch, n, run["sim_time_s"], rate,
          "%.2f" % ref_rate if ref_rate is not None else "-"))
    if n != expect(period): fails.append("%s: %d, want %d" % (ch, n, expect(period)))
    if ref_rate is not None and abs(rate - ref_rate) > 0.02 * ref_rate: fails.append("%s: %.2f per s, firmware %.2f" % (ch, rate, ref_rate))
    if summ.get(ch, {}).get("bad", 0): fails.append("%s: undecodable messages" % ch)
if fails: print("\n".join(fails)); sys.exit(1)
PY
}

logged firmware --time-limit 3 && rates firmware
logged scripted --driver scripted --time-limit 3 && rates scripted
logged mms --mms "python3 test/mms/floodfill.py 2" --time-limit 3 && rates mms
logged board --board ukmarsbot --avr "$BOARD_IMG" --robot robots/ukmarsbot.ini --time-limit 3 && rates board
python3 -c "import json,sys; m=[json.loads(l) for l in open(sys.argv[1])]; sys.exit(0 if any(x['command'] != [0, 0] for x in m) else 1)" "$T/board.motors" \
  && ok "board: MM_MOTORS carries the board's motor commands" || bad "board: MM_MOTORS commands all zero"
logged pil --avr "$PIL_IMG" --time-limit 3 && rates pil MM_LINK
logged serial --pty --silence-ms 0 --time-limit 1 && rates serial MM_LINK

[ $fails -eq 0 ] || { echo "$fails failed"; exit 1; }

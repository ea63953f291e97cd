#!/usr/bin/env bash
# run.sh: alone (timed: real-time runs, timed input or timeouts)
# cli_hil.sh - hardware in the loop: the wire codec's shared vectors on an
# AVR in simavr; mmsim --pty with hil_mcu.py playing the MCU (compat and
# framed; it speaks protocol version 1 and gets no version-2 message); a
# device unplugged and plugged back; the simulator stopped and started
# again while the MCU stays up; flag and device errors.
set -u
S=${MMSIM:-build/mmsim}
B=${BUILD:-build}
T=$(mktemp -d); trap 'rm -rf "$T"; [ -n "${SIMPID:-}" ] && kill "$SIMPID" 2>/dev/null' EXIT
ONE_ERROR_LINE=1; . "$(dirname "$0")/lib.sh"

# the codec on a 16-bit-int AVR: same vectors as the host test
if command -v simavr >/dev/null && [ -f "$B/avr/wire_selftest.elf" ]; then
  timeout 60 simavr -m atmega328p -f 16000000 "$B/avr/wire_selftest.elf" >"$T/avr" 2>&1
  grep -q 'wire vectors: 0 failed' "$T/avr" && ok "AVR wire vectors" || bad "AVR wire vectors: $(cat -v "$T/avr")"
else
  echo "SKIP cli_hil AVR vectors: simavr or $B/avr/wire_selftest.elf missing"
fi

# platformio.ini parses (PlatformIO cannot download its platforms here: no build)
PIO=${PIO:-${BUILD:-build}/pio/bin/pio}; [ -x "$PIO" ] || PIO=$(command -v pio)
if [ -n "$PIO" ]; then
  PLATFORMIO_SETTING_ENABLE_TELEMETRY=No "$PIO" project config >"$T/pio" 2>&1 && grep -q "env:uno" "$T/pio" && grep -q "env:megaatmega2560" "$T/pio" \
    && grep -q "env:native" "$T/pio" && grep -q "symlink://hal/arduino" "$T/pio" \
    && ok "platformio.ini parses" || bad "platformio.ini: $(tail -3 "$T/pio")"
else
  echo "SKIP cli_hil platformio.ini check: pio not installed"
fi

# flag and device errors: 2 for bad flags, 3 for a device that fails
M=mazes/gen-5x5-s1.txt
want_rc 2 "bad baud" "$S" --maze $M --pty --baud 9
want_rc 2 "baud too high" "$S" --maze $M --pty --baud 12000001
want_rc 2 "fractional baud" "$S" --maze $M --pty --baud 115200.5
want_rc 2 "bad protocol" "$S" --maze $M --pty --protocol morse
grep -q "^mmsim: --protocol: expected framed or compat, got 'morse'" "$T/err" && ok "protocol error line" || bad "protocol error line: $(cat "$T/err")"
want_rc 2 "serial and pty" "$S" --maze $M --pty --serial /dev/null
want_rc 2 "protocol without a link" "$S" --maze $M --protocol compat
want_rc 2 "bad silence" "$S" --maze $M --pty --silence-ms -1
want_rc 2 "silence too long" "$S" --maze $M --pty --silence-ms 60001
# --silence-ms 0 (no watchdog) is accepted: a pty nobody opens, 1 s
"$S" --maze $M --pty --silence-ms 0 --time-limit 1 --json >"$T/s0.json" 2>"$T/s0.err"; rc=$?
[ $rc -eq 1 ] && [ "$(python3 -c "import json,sys; print(json.load(open(sys.argv[1]))['link']['silence_ms'])" "$T/s0.json" 2>&1)" = 0 ] \
  && ok "--silence-ms 0 accepted: no watchdog in the JSON" || bad "--silence-ms 0: exit $rc $(cat "$T/s0.err" "$T/s0.json")"
want_rc 2 "serial with batch" "$S" --batch mazes --serial /dev/null
want_rc 3 "missing device" "$S" --maze $M --serial "$T/no-such-tty"
grep -q "no-such-tty: cannot open: No such file or directory" "$T/err" && ok "device error line" || bad "device error line: $(cat "$T/err")"
want_rc 3 "not a terminal" "$S" --maze $M --serial /dev/null
grep -q "^mmsim: /dev/null: not a serial device" "$T/err" && ok "not-a-tty error line" || bad "not-a-tty line: $(cat "$T/err")"
want_rc 2 "bad maze with a link" "$S" --maze "$T/none.txt" --pty

# mmsim --pty with hil_mcu.py as the MCU: sensors out, motors in, silence,
# unplug and replug; in real time, 4 s each (compat has no silence watchdog
# by default: asked for here with --silence-ms 100, framed's default)
hil() { local proto=$1
  "$S" --maze $M --pty --protocol "$proto" $([ "$proto" = compat ] && echo --silence-ms 100) --time-limit 4 --json --lcm-log "$T/$proto.lcmlog" >"$T/$proto.json" 2>"$T/$proto.err" &
  SIMPID=$!
  local p="" i
  for i in $(seq 100); do p=$(sed -n 's/^mmsim: pty //p' "$T/$proto.err" 2>/dev/null); [ -n "$p" ] && break; sleep 0.05; done
  if [ -z "$p" ]; then
    wait $SIMPID; SIMPID=
    if grep -q "cannot create a pseudo-terminal" "$T/$proto.err"; then echo "SKIP cli_hil $proto: no pseudo-terminals here"; return; fi
    bad "$proto: no pty path: $(cat "$T/$proto.err")"; return
  fi
  python3 test/tools/hil_mcu.py "$proto" "$p" 2.5 >"$T/$proto.mcu" 2>&1 && ok "$proto: MCU got sensors: $(cat "$T/$proto.mcu")" \
    || bad "$proto: MCU side: $(cat "$T/$proto.mcu")"
  wait $SIMPID; local rc=$?; SIMPID=
  [ $rc -eq 1 ] && ok "$proto: exit 1 (goal not reached)" || bad "$proto: mmsim exit $rc: $(cat "$T/$proto.err")"
  local got
  got=$(python3 -c "
import json,sys; d=json.load(open(sys.argv[1])); l=d['link']; e=l['decoder']
print(d['driver'], l['protocol'], l['baud'], l['connects'] >= 2, l['disconnects'] >= 1, l['silences'] >= 1,
      sum(e[k] for k in ('crc','cobs','overflow','unknown','length','value')), l['mcu_log_lines'] >= 1,
      d['final_pose']['y_m'] > 0.09 + 0.03, l['tx_dropped'], l['handshake'])" "$T/$proto.json" 2>&1)
  # no --baud: the protocol's default, 115200 compat, 1,000,000 framed
  local baud=115200; [ "$proto" = framed ] && baud=1000000
  [ "$got" = "serial $proto $baud True True True 1 True True 0 True" ] && ok "$proto: link report (default baud $baud, one garbage chunk counted)" || bad "$proto: link report: $got $(cat "$T/$proto.json")"
  # MM_LINK telemetry (10 Hz): the same counters as the JSON; connected goes
  # 1 (MCU open), 0 (unplugged), 1 (back), 0 (the test MCU ended)
  "${MMLOG:-build/mmlog}" --dump MM_LINK "$T/$proto.lcmlog" >"$T/$proto.link" 2>&1
  got=$(python3 -c "
import json,sys; d=json.load(open(sys.argv[1]))['link']; m=[json.loads(x) for x in open(sys.argv[2])]
print(len(m), m[-1]['bytes_to_mcu'] == d['tx_bytes'], m[-1]['bytes_from_mcu'] == d['rx_bytes'], m[-1]['frame_errors'],
      m[-1]['baud'] == d['baud'], ''.join('1' if x['connected'] else '0' for x in m).strip('0').count('01'), m[-1]['handshake'] == d['handshake'])" \
      "$T/$proto.json" "$T/$proto.link" 2>&1)
  [ "$got" = "40 True True 1 True 1 True" ] && ok "$proto: MM_LINK log (counters, unplug and replug, one error)" || bad "$proto: MM_LINK: $got"
  grep -q "MCU silent: motors off" "$T/$proto.err" && grep -q "disconnected, motors off" "$T/$proto.err" \
    && grep -q "^mcu: hello from the test MCU" "$T/$proto.err" && ok "$proto: states reported" || bad "$proto: states: $(cat "$T/$proto.err")"
}
if command -v python3 >/dev/null; then hil compat; hil framed; else echo "SKIP cli_hil pty: python3 missing"; fi
grep -q "hello from the MCU: protocol 1, ToF range 1200 mm" "$T/framed.err" && ok "framed handshake reported" || bad "framed handshake: $(cat "$T/framed.err")"
# hil_mcu.py speaks protocol version 1: accepted, and sent none of version 2's messages (ROBOT, GYRO, BATTERY, IR)
got=$(python3 -c "
import json,sys; l=json.load(open(sys.argv[1]))['link']; print(l['mcu_version'], sum(l['v2'].values()))" "$T/framed.json" 2>&1)
[ "$got" = "1 0" ] && ok "a version-1 MCU: accepted, no version-2 messages" || bad "version-1 MCU: $got"

# compat as the paper's library: one motor command, then only
# sensor reads. By default the command holds (no watchdog) and the robot
# drives on until the wall north of cell (0,1) (its face at y 0.354 m: the
# robot's centre stops at 0.294); with --silence-ms 100 it stops soon after
# the start. At rest the front sensor is 0.209 m from that wall: the MCU,
# decoding with the paper's 1.0 m, must read about that (with our 1.2 m
# scale it read 1/1.2 of it, 174 mm).
once() { local name=$1; shift
  "$S" --maze $M --pty --protocol compat "$@" --time-limit 3 --json >"$T/$name.json" 2>"$T/$name.err" &
  SIMPID=$!
  local p="" i
  for i in $(seq 100); do p=$(sed -n 's/^mmsim: pty //p' "$T/$name.err" 2>/dev/null); [ -n "$p" ] && break; sleep 0.05; done
  if [ -z "$p" ]; then wait $SIMPID; SIMPID=; echo "SKIP cli_hil $name: no pty: $(head -1 "$T/$name.err")"; return 1; fi
  python3 test/tools/hil_mcu.py once "$p" 2.8 >"$T/$name.mcu" 2>&1 || bad "$name: MCU side: $(cat "$T/$name.mcu")"
  wait $SIMPID; SIMPID=
  python3 -c "
import json,sys; d=json.load(open(sys.argv[1])); l=d['link']
print(round(d['final_pose']['y_m'], 2), l['silences'], l['silence_ms'], l['compat_range_m'])" "$T/$name.json" 2>&1
  return 0 # (1 only when skipped: a failed check above shows in the output)
}
if command -v python3 >/dev/null; then
  if got=$(once once); then
    [ "$got" = "0.29 0 0 1.0" ] && ok "compat, one command: held until the wall, no watchdog ($got)" \
      || bad "compat, one command: $got $(cat "$T/once.err")"
    rest=$(sed -n 's/.*front_at_rest \([0-9]*\).*/\1/p' "$T/once.mcu")
    [ -n "$rest" ] && [ "$rest" -ge 190 ] && [ "$rest" -le 228 ] && ok "compat distance at the paper's 1.0 m scale: front $rest mm at 209" \
      || bad "compat distance scale: $(cat "$T/once.mcu")"
  fi
  if got=$(once once100 --silence-ms 100); then
    read -r y sil ms rng <<<"$got"
    python3 -c "import sys; sys.exit(0 if float(sys.argv[1]) < 0.2 else 1)" "$y" && [ "$sil" -ge 1 ] && [ "$ms" = 100 ] \
      && grep -q "MCU silent: motors off" "$T/once100.err" && ok "compat with --silence-ms 100: the watchdog stops it ($got)" \
      || bad "compat --silence-ms 100: $got $(cat "$T/once100.err")"
  fi
fi

# a real serial device path (a pty slave behind a symlink), custom baud via
# termios2, unplugged and plugged back: mmsim reports it and reopens it
if command -v python3 >/dev/null; then
  python3 test/tools/hil_replug.py "$T/tty" 1.2 >"$T/replug.out" 2>&1 &
  RP=$!
  for i in $(seq 100); do [ -e "$T/tty" ] && break; sleep 0.05; done
  "$S" --maze $M --serial "$T/tty" --baud 250000 --protocol compat --time-limit 4 --json >"$T/rp.json" 2>"$T/rp.err"; rc=$?
  wait $RP && ok "replug: device side: $(cat "$T/replug.out")" || bad "replug device side: $(cat "$T/replug.out") $(cat "$T/rp.err")"
  [ $rc -eq 1 ] && ok "replug: mmsim exit 1" || bad "replug: mmsim exit $rc: $(cat "$T/rp.err")"
  got=$(python3 -c "
import json,sys; l=json.load(open(sys.argv[1]))['link']
print(l['baud'], l['connects'] >= 2, l['disconnects'] >= 1, l['decoder']['unknown'])" "$T/rp.json" 2>&1)
  [ "$got" = "250000 True True 0" ] && ok "replug: reconnected" || bad "replug: $got $(cat "$T/rp.err")"
  grep -q "disconnected, motors off" "$T/rp.err" && [ "$(grep -c ': connected at' "$T/rp.err")" -ge 2 ] \
    && ok "replug: states reported" || bad "replug states: $(cat "$T/rp.err")"
fi

# the simulator stops and starts again while the MCU stays up (a board that
# does not reset when the port opens): hil_mcu.py owns the device and keeps
# running through two mmsim runs. Each run handshakes again (the MCU answers
# the new HELLO) and the MCU drives the robot off the start; run 1 at
# 115200 baud (frames cross step boundaries there, so its exit likely cuts
# one: the MCU's decoder must count exactly that one bad chunk), run 2 at
# the framed default, 1,000,000 baud.
if command -v python3 >/dev/null; then
  python3 test/tools/hil_mcu.py framed "$T/dev" 30 --own 2 >"$T/own.mcu" 2>&1 &
  OWN=$!
  for i in $(seq 100); do [ -e "$T/dev" ] && break; sleep 0.05; done
  for run in 1 2; do
    "$S" --maze $M --serial "$T/dev" $([ $run = 1 ] && echo --baud 115200) --time-limit 1.5 --json >"$T/own$run.json" 2>"$T/own$run.err"; rc=$?
    [ $rc -eq 1 ] && ok "sim restart $run: mmsim exit 1" || bad "sim restart $run: mmsim exit $rc: $(cat "$T/own$run.err")"
    got=$(python3 -c "
import json,sys; d=json.load(open(sys.argv[1])); l=d['link']
print(l['baud'], l['handshake'], l['connects'], l['disconnects'], sum(v for k,v in l['decoder'].items() if k not in ('bytes','frames_ok')),
      l['decoder']['frames_ok'] > 200, d['final_pose']['y_m'] > 0.09 + 0.03)" "$T/own$run.json" 2>&1)
    want="$([ $run = 1 ] && echo 115200 || echo 1000000) True 1 0 0 True True"
    [ "$got" = "$want" ] && ok "sim restart $run: handshake, the MCU drives, no errors (baud $(echo $want | cut -d' ' -f1))" \
      || bad "sim restart $run: $got (want $want) $(cat "$T/own$run.err")"
  done
  wait $OWN && ok "sim restart: MCU side: $(cat "$T/own.mcu")" || bad "sim restart: MCU side: $(cat "$T/own.mcu")"
fi

[ $fails -eq 0 ] || exit 1

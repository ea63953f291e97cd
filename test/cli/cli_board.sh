#!/usr/bin/env bash
# cli_board.sh - an AVR image on the emulated UKMARSBOT board
# (mmsim --board ukmarsbot --avr IMAGE, sim/board, boards/ukmarsbot-v1.3.ini).
# Our sketches (test/firmware/arduino/board, built for the Nano with the Debian
# Arduino core) check each part against the physics: motor PWM and
# direction (two Timer1 modes), both encoders at full speed (every edge an
# interrupt, the decoded count = the physics' count), INT0/INT1 in
# low-level mode (flags, a re-firing ISR, a sleeping core: what simavr's own
# per-cycle check gives, run with it on and compared), the ADC (single,
# free-running and interrupt-driven conversions, emitters off and on, the
# switch ladder, the battery), an auto-trigger simavr lacks; bad board files
# and images. Then mazerunner-core (if ../shared has it): banner and RDY,
# `B` within 2 % of the simulated battery after D1, `S` changes with a wall, the same
# JSON twice; and its idle speed (simulated s per wall s) is printed.
set -u
B=${BUILD:-build}
SHARED=${SHARED:-../shared}
MRC_DIR=${MRC_DIR:-$SHARED/clients/mazerunner-core}
MMSIM=${MMSIM:-$B/mmsim}
T=$(mktemp -d); trap 'rm -rf "$T"' EXIT
. "$(dirname "$0")/lib.sh"
mk() { env -u MAKEFLAGS -u MFLAGS -u MAKELEVEL make --no-print-directory B="$B" SHARED="$SHARED" "$@"; }
# UKMARSBOT standing in its start cell's centre: the checks below measure from there
# (the robot file starts it with its back to the wall; mazerunner's search: cli_mazerunner_search.sh)
ROBOT=$T/ukmarsbot-centre.ini
sed 's/^start = back_to_wall$/start = centre/' robots/ukmarsbot.ini >"$ROBOT"
SK=$B/clients/board

want_rc 0 "the board sketches build for the Nano" mk board-sketches
# open 16x16 mazes (posts only): as is, and with a wall east of the start cell
open_mazes "$T"
run() { local img=$1 maze=$2; shift 2; "$MMSIM" --maze "$maze" --board ukmarsbot --avr "$img" --robot $ROBOT --json "$@"; }
js() { python3 -c "import json,sys; j=json.loads(open(sys.argv[1]).read().splitlines()[-1]); $2" "$1"; }

# ---- bad input: one line, exit 2 ----
ONE_ERROR_LINE=1
# the board file and its mainboard's parts file (boards/parts/), each copied: a fault in either is
# named by its own file and line
cp boards/ukmarsbot-v1.3.ini "$T/good.ini"
mkdir -p "$T/parts"
MB=parts/ukmarsbot-mainboard-v1.3.ini
# part NAME SED: the board file NAME.ini naming parts/NAME.ini, the mainboard's parts edited by SED
part() { sed "s|^mainboard = .*|mainboard = parts/$1.ini|" "$T/good.ini" >"$T/$1.ini"; sed "$2" boards/$MB >"$T/parts/$1.ini"; }
part pwm 's/^pwm_pin = D9$/pwm_pin = D6/'
part pin 's/^int_pin = D2$/int_pin = D22/'
part missing '/^r_ground_ohm/d'
cp boards/$MB "$T/$MB"
sed 's/^pin = D13$/pin = D3/' "$T/good.ini" >"$T/twice.ini"
sed 's/^vcc_v = 5.0$/vcc_v = 12/' "$T/good.ini" >"$T/vcc.ini"
printf '[board]\nnmae = x\n' >"$T/unknown.ini"
# a key given twice (an emitter's pin = D11 then pin = A0: the last won) and an indented line
sed 's/^pin = D11$/pin = D11\npin = A0/' "$T/good.ini" >"$T/dupkey.ini"
sed 's/^vcc_v = 5.0$/vcc_v = 5.0\n  3.3/' "$T/good.ini" >"$T/cont.ini"
# a mainboard figure given in the board file too (the diode's drop), and a parts file that is not there
sed 's/^\[analog\]$/[battery]\ndiode_drop_v = 0\n\n[analog]/' "$T/good.ini" >"$T/again.ini"
sed 's|^mainboard = .*|mainboard = parts/nosuch.ini|' "$T/good.ini" >"$T/nomb.ini"
for f in pwm pin missing twice vcc unknown dupkey cont again; do
  want_rc 2 "bad board file ($f): exit 2" run $SK/MotorPwm.elf "$T/open.txt" --board "$T/$f.ini" --time-limit 1
  cp "$T/err" "$T/err.$f"
  case $f in pwm|pin|missing|again) file=$T/parts/$f.ini ;; *) file=$T/$f.ini ;; esac
  [ $f = again ] && file=$T/$MB
  grep -qE "^$file:[0-9]+: [a-z]+(\.[a-z]+)?\.[a-z_]+: " "$T/err" && ok "bad board file ($f): FILE:LINE: section.key: reason" \
    || bad "bad board file ($f): $(cat "$T/err")"
done
grep -q "battery.diode_drop_v: given in $T/again.ini too: a figure of the mainboard has one place" "$T/err.again" \
  && ok "a mainboard figure in the board file too: refused" || bad "again: $(cat "$T/err.again")"
want_rc 2 "a mainboard file that is not there" run $SK/MotorPwm.elf "$T/open.txt" --board "$T/nomb.ini" --time-limit 1
grep -qx "$T/nomb.ini: board.mainboard: $T/parts/nosuch.ini: no such file" "$T/err" \
  && ok "no mainboard file: its line" || bad "no mainboard file: $(cat "$T/err")"
n=$(grep -n '^pin = D11$' "$T/good.ini" | cut -d: -f1)
grep -qx "$T/dupkey.ini:$((n + 1)): emitter.front.pin: given twice (first on line $n)" "$T/err.dupkey" \
  && ok "board file: a named part's key twice: its line" || bad "board key twice: $(cat "$T/err.dupkey")"
n=$(grep -n '^vcc_v' "$T/good.ini" | cut -d: -f1)
grep -q "^$T/cont.ini:$((n + 1)): board.vcc_v: an indented line continues its value" "$T/err.cont" \
  && ok "board file: continuation line: its line" || bad "board continuation: $(cat "$T/err.cont")"
want_rc 2 "unknown board name" run $SK/MotorPwm.elf "$T/open.txt" --board nosuchboard --time-limit 1
want_rc 2 "--board without --avr" "$MMSIM" --maze "$T/open.txt" --board ukmarsbot --time-limit 1
want_rc 2 "--input send= without --board" "$MMSIM" --maze "$T/open.txt" --input "1 send=B" --time-limit 1
printf 'int main(void) { for (;;) {} }\n' >"$T/m.c"
if avr-gcc -mmcu=atmega2560 -Os "$T/m.c" -o "$T/mega.elf" 2>/dev/null; then
  want_rc 2 "an image for the ATmega2560" run "$T/mega.elf" "$T/open.txt" --time-limit 1
  grep -q 'built for another MCU' "$T/err" && ok "  ... says so" || bad "  another MCU: $(cat "$T/err")"
fi
printf 'not an image\n' >"$T/x.elf"
want_rc 2 "not an image" run "$T/x.elf" "$T/open.txt" --time-limit 1
# image checks before simavr reads the image (sim/board/image.h; the whole corpus: test_image)
if avr-gcc -mmcu=attiny85 -Os "$T/m.c" -o "$T/tiny.elf" 2>/dev/null; then
  want_rc 2 "an image for the ATtiny85" run "$T/tiny.elf" "$T/open.txt" --time-limit 1
  grep -q 'built for another MCU (AVR architecture avr25' "$T/err" && ok "  ... says so" || bad "  attiny85: $(cat "$T/err")"
fi
python3 - "$SK/MotorPwm.elf" "$T" <<'PY'
import struct, sys
b = bytearray(open(sys.argv[1], "rb").read()); T = sys.argv[2]
shoff, = struct.unpack_from("<I", b, 32); shnum, shstr = struct.unpack_from("<HH", b, 48)
tab, = struct.unpack_from("<I", b, shoff + shstr * 40 + 16)
def sec(want):
    for i in range(shnum):
        h = shoff + i * 40; name, = struct.unpack_from("<I", b, h)
        if b[tab + name:b.index(b"\0", tab + name)] == want: return h, name
text, = [struct.unpack_from("<II", b, sec(n)[0] + 16) for n in (b".text",)]
data = struct.unpack_from("<II", b, sec(b".data")[0] + 16)
flash = bytes(b[text[0]:text[0] + text[1]] + b[data[0]:data[0] + data[1]])
def rec(t, a, d): r = bytes([len(d), a >> 8, a & 255, t]) + d; return ":" + (r + bytes([-sum(r) & 255])).hex().upper()
lines = [rec(0, a, flash[a:a + 16]) for a in range(0, len(flash), 16)]
open(T + "/good.hex", "w").write("\n".join(lines + [rec(1, 0, b"")]) + "\n")
bad = list(lines); bad[2] = bad[2][:-2] + ("00" if bad[2][-2:] != "00" else "01")
open(T + "/sum.hex", "w").write("\n".join(bad + [rec(1, 0, b"")]) + "\n")
open(T + "/cut.hex", "w").write("\n".join(lines[:5]) + "\n")
# .debug_info renamed .mmcu: a VCD trace of PORTB to a file in T, its period, command and console registers
h, name = sec(b".debug_info"); off, size = struct.unpack_from("<II", b, h + 16)
vcd = (T + "/trace.vcd").encode() + b"\0"
tags = bytes([12, len(vcd)]) + vcd + bytes([13, 4]) + struct.pack("<I", 1000) + bytes([14, 6, 255, 0x25, 0]) + b"PB\0"
tags += bytes([10, 2, 0x31, 0, 11, 2, 0x32, 0])
b[tab + name:tab + name + 6] = b".mmcu\0"; b[off:off + len(tags)] = tags; struct.pack_into("<I", b, h + 20, len(tags))
open(T + "/vcd.elf", "wb").write(b)
PY
want_rc 1 "the sketch as Intel HEX runs" run "$T/good.hex" "$T/open.txt" --time-limit 1
want_rc 2 "HEX with a bad checksum on line 3" run "$T/sum.hex" "$T/open.txt" --time-limit 1
grep -q "^mmsim: $T/sum.hex:3: bad checksum" "$T/err" && ok "  ... FILE:LINE: bad checksum" || bad "  checksum: $(cat "$T/err")"
want_rc 2 "HEX without its end record" run "$T/cut.hex" "$T/open.txt" --time-limit 1
grep -q "cut.hex: no end record" "$T/err" && ok "  ... says so" || bad "  cut HEX: $(cat "$T/err")"
want_rc 1 "an image whose .mmcu names a VCD trace runs" run "$T/vcd.elf" "$T/open.txt" --time-limit 1
[ ! -e "$T/trace.vcd" ] && [ ! -e gtkwave_trace.vcd ] && ok "  ... and writes no trace file" || bad "  a VCD trace was written"
want_rc 2 "ADC auto-trigger from Timer0: exit 2" run $SK/AdcTimerTrigger.elf "$T/open.txt" --time-limit 1
grep -q 'ADC auto-trigger source 4 (timer0 overflow.*simavr 1.6 does not emulate' "$T/err" && ok "  ... one clear line" \
  || bad "  auto-trigger: $(cat "$T/err")"
ONE_ERROR_LINE=0

# ---- motors: both wheels forward at duty 40/255 for 0.8 s, in two Timer1 modes ----
# D1 (the board file's battery.diode_drop_v) feeds the H-bridge's VM and the A7 divider
DROP=$(sed -n 's/^diode_drop_v *= *\([0-9.]*\).*/\1/p' boards/parts/ukmarsbot-mainboard-v1.3.ini); DROP=${DROP:-0}
want_rc 1 "MotorPwm runs (no goal: exit 1)" run $SK/MotorPwm.elf "$T/open.txt" --time-limit 2
cp "$T/out" "$T/motor.json"
js "$T/motor.json" "
b = j['board']; d = b['pwm_duty']; p = j['final_pose']
import math
assert j['console'] == 'DONE\r\n', j['console']
for s in 'left', 'right':
    assert d[s][0] == 0 and abs(d[s][1] - 40 / 255) < 2e-3, d
# forward: ORION's 475 mm/s/V less 0.34 V bias, time constant 0.19 s (robots/ukmarsbot.ini [measured.orion]):
# 0.8 s driven then braked: v_ss (0.8 - tau (1 - e^(-0.8/tau))) + v_ss tau
# the H-bridge's supply: the battery less D1's drop (the board file's battery.diode_drop_v: D1 feeds VM)
drop = $DROP
v = 0.475 * (40 / 255 * (b['battery_v'] - drop) - 0.34); tau = 0.19
want = v * (0.8 - tau * (1 - math.exp(-0.8 / tau))) + v * tau * (1 - math.exp(-0.8 / tau))
moved = p['y_m'] - 0.09
assert abs(moved - want) < 0.15 * want, (moved, want)
assert abs(p['x_m'] - 0.09) < 0.01 and abs(p['heading_rad'] - math.pi / 2) < 0.05, p
print('moved %.3f m north, expected %.3f m' % (moved, want))
" >"$T/m.txt" 2>&1 && ok "motors: duty 40/255 in both modes, both wheels forward at the expected speed ($(cat "$T/m.txt"))" \
  || bad "motors: $(tail -3 "$T/m.txt")"

# ---- encoders: full speed, then back ----
want_rc 1 "EncoderCount runs" run $SK/EncoderCount.elf "$T/open.txt" --time-limit 2.5
cp "$T/out" "$T/enc.json"
js "$T/enc.json" "
b = j['board']; c = j['console'].split()
assert c[0] == 'COUNTS' and c[3] == 'EDGES', c
l, r, el, er = int(c[1]), int(c[2]), int(c[4]), int(c[5])
# every edge an interrupt, none lost
assert el == b['interrupts']['INT0'] == b['encoder_edges']['left'], (el, b)
assert er == b['interrupts']['INT1'] == b['encoder_edges']['right'], (er, b)
# the decoded count is the physics' (36 counts a motor turn x 11.4), but for the edge the settling
# robot may make before the sketch attaches its interrupts
s = b['sim_encoder_counts']
assert abs(l - s['left']) <= 1 and abs(r - s['right']) <= 1, (l, r, s)
assert l > 2000 and r > 2000 and el > l + 1000, (l, r, el)
assert b['pwm_duty']['left'] == [-60 / 255, 1.0] or abs(b['pwm_duty']['left'][0] + 60 / 255) < 1e-6, b['pwm_duty']
print('L %d R %d (physics %d %d), %d + %d edges' % (l, r, s['left'], s['right'], el, er))
" >"$T/e.txt" 2>&1 && ok "encoders: every edge counted at full speed ($(cat "$T/e.txt"))" || bad "encoders: $(tail -3 "$T/e.txt")"

# ---- INT0/INT1 in low-level mode: the behaviour of simavr's own per-cycle check ----
# (sim/board/extint_level.h). Each sketch runs twice: with our check and with
# simavr's own (MMSIM_SIMAVR_LEVEL=1, sim/board/avrhost.c), and the two must
# give the same console and interrupt counts, cycle for cycle. The figures
# below are that run's, recorded (the images as tools/arduino-build builds
# them, -flto; --time-limit 1.5 on the contest clock: the robot leaves the
# start cell at 0.25 s, the run ends at 1.753 s); they are cycle-exact and
# move with any change of the robot's motion (the encoder pins' edges):
# EIFR's flags with interrupts on and off, and INT0's ISR running again and
# again while D2 is low, its timing folded into the last number of each INT0 line.
# level SKETCH: runs it both ways into $T/ours and $T/simavr; 0 iff they agree
level() {
  want_rc 1 "$1 runs" "$MMSIM" --board ukmarsbot --avr $SK/$1.elf --robot robots/ukmarsbot.ini \
    --maze mazes/gen-16x16-s1.txt --time-limit 1.5 --json
  cp "$T/out" "$T/ours"
  want_rc 1 "$1 runs with simavr's own level check" env MMSIM_SIMAVR_LEVEL=1 "$MMSIM" --board ukmarsbot --avr $SK/$1.elf \
    --robot robots/ukmarsbot.ini --maze mazes/gen-16x16-s1.txt --time-limit 1.5 --json
  cp "$T/out" "$T/simavr"
  python3 -c "
import json, sys
a, b = (json.loads(open(f).read().splitlines()[-1]) for f in sys.argv[1:3])
assert a['console'] == b['console'] and a['board']['interrupts'] == b['board']['interrupts'], (a['console'], b['console'], a['board']['interrupts'], b['board']['interrupts'])
" "$T/ours" "$T/simavr" >"$T/l.txt" 2>&1 && ok "$1: the console and interrupt counts of simavr's own level check" \
    || bad "$1 against simavr's own check: $(tail -3 "$T/l.txt")"
}
level LevelInt
js "$T/ours" "
want = 'FLAGS low 1001 on 1587 off 0 after 1591\r\nINT0 3 0 9302\r\nINT0 2511 12 45977\r\nINT0 5000 25 64059\r\nINT0 7515 37 25684\r\nINT0 10000 50 33715\r\nINT0 12491 62 5003\r\n'
assert j['console'] == want, (j['console'], want)
assert j['board']['interrupts'].get('INT0') == 14441, j['board']['interrupts']
print(want.split(chr(13))[0])
" >"$T/l.txt" 2>&1 && ok "level-mode INT0/INT1 as recorded ($(cat "$T/l.txt"))" || bad "level mode: $(tail -3 "$T/l.txt")"

# a sleeping firmware with INT0 low in level mode wakes at the cycles simavr's own check gives
level SleepLevel
js "$T/ours" "
want = 'WAKES 716 479 2707\r\nWAKES 1589 1130 9443\r\nWAKES 2091 1397 43120\r\nWAKES 2580 1652 64360\r\nWAKES 3068 1906 64693\r\nWAKES 3557 2160 48068\r\nWAKES 4044 2414 20118\r\n'
assert j['console'] == want, (j['console'], want)
assert j['board']['interrupts'] == {'INT1': 2419, 'TIMER0_OVF': 1713, 'USART_UDRE': 151}, j['board']['interrupts']
print(want.split(chr(13))[-2].strip())
" >"$T/l.txt" 2>&1 && ok "sleeping with level-mode INT0 as recorded ($(cat "$T/l.txt"))" || bad "sleep, level mode: $(tail -3 "$T/l.txt")"

# ---- ADC ----
# A7 reads the battery after the board's series diode D1 (DROP: the board file's battery.diode_drop_v)
for m in open east; do
  want_rc 1 "AdcProbe on the $m maze" run $SK/AdcProbe.elf "$T/$m.txt" --time-limit 1
  cp "$T/out" "$T/adc-$m.json"
done
js "$T/adc-open.json" "
b = j['board']; L = j['console'].split('\r\n')
o = L[0].split(); f = L[1].split()
off = [int(x) for x in o[1:5]]; on = [int(x) for x in o[6:10]]; sw = int(o[11]); bat = int(o[13])
e = json.loads(open(sys.argv[1].replace('open', 'east')).read().splitlines()[-1])['console'].split()
assert all(5 <= x <= 15 for x in off), off                      # dark: the ambient counts
assert on[1] > off[1] + 50 and on[2] > off[2] + 50, (off, on)   # the diagonals see the posts lit
assert int(e[7]) > on[1] + 40, (e[7], on[1])                    # A1 (right diagonal) sees the east wall
thr = [660, 647, 630, 614, 590, 570, 545, 522, 461, 429, 385, 343, 271, 212, 128, 44, 0]
assert sw > (thr[0] + thr[1]) / 2 and sw <= 800, sw             # switches 0
v = bat * 5.0 / 1023 * 2; after_d1 = b['battery_v'] - $DROP
assert abs(v - after_d1) < 0.02 * after_d1, (v, after_d1)
assert f[0] == 'FREE' and 90 <= int(f[1]) <= 100 and abs(int(f[2]) - bat) <= 2, f   # 16 MHz / 128 / 13 for 10 ms
assert b['adc_conversions']['A7'] >= 91, b['adc_conversions']
print('dark %s lit %s, east wall A1 %s, switches %d, battery %.2f V of %.2f less D1 %.2f' % (off, on, e[7], sw, v, b['battery_v'], $DROP))
" >"$T/a.txt" 2>&1 && ok "ADC: single, free-running and interrupt-driven; emitters off/on; wall; switches; battery ($(cat "$T/a.txt"))" \
  || bad "ADC: $(tail -3 "$T/a.txt")"

# ---- mazerunner-core ----
MRC=$B/clients/mazerunner-core-uk.elf
if [ ! -f "$MRC_DIR/mazerunner-core/mazerunner-core.ino" ] && [ ! -f "$MRC_DIR/mazerunner-core.ino" ]; then
  echo "SKIP cli_board: mazerunner-core: $MRC_DIR not found"
  [ $fails -eq 0 ] && exit 0 || exit 1
fi
[ -s "$MRC" ] || mk client-mazerunner >/dev/null 2>&1
for m in open east; do
  want_rc 1 "mazerunner-core-uk on the board ($m maze): B and S" run "$MRC" "$T/$m.txt" --time-limit 2 --input "0.5 send=B; 1.0 send=S"
  cp "$T/out" "$T/mrc-$m.json"
done
js "$T/mrc-open.json" "
c = j['console'].replace('\r', '').split('\n')
assert 'MAZERUNNER-CORE' in c and 'RDY' in c, c[:6]
bl = [x for x in c if x.startswith('Battery: ')][0]
v = float(bl.split()[1]); sim = j['board']['battery_v'] - $DROP
assert abs(v - sim) <= 0.02 * sim, (v, sim)
print('battery %.2f V, simulated %.3f V less D1' % (v, sim))
" >"$T/b.txt" 2>&1 && ok "mazerunner-core: MAZERUNNER-CORE, RDY; B within 2 % ($(cat "$T/b.txt"))" || bad "mazerunner-core B: $(tail -3 "$T/b.txt")"
want_rc 1 "the .hex image runs too" run "${MRC%.elf}.hex" "$T/open.txt" --time-limit 1 --input "0.5 send=?"
js "$T/out" "c = j['console'].replace('\\r', ''); assert 'MAZERUNNER-CORE' in c and '?   : this text' in c, c[:300]" 2>"$T/h.txt" \
  && ok "  ... its banner and its help for '?'" || bad "  .hex: $(tail -1 "$T/h.txt")"
sline() { js "$1" "print([x for x in j['console'].replace('\r', '').split('\n') if x.startswith('|')][0])"; }
so=$(sline "$T/mrc-open.json" 2>&1); se=$(sline "$T/mrc-east.json" 2>&1)
python3 -c "
import sys
a = [int(x) for x in sys.argv[1].replace('|', ' ').split()[:4]]; b = [int(x) for x in sys.argv[2].replace('|', ' ').split()[:4]]
assert b[2] > a[2] + 30 and abs(b[1] - a[1]) < 10, (a, b)   # lfs lss rss rfs: rss sees the east wall
" "$so" "$se" 2>"$T/s.txt" && ok "mazerunner-core S: rss rises with a wall on the right ('$so' -> '$se')" || bad "S: $so / $se: $(tail -1 "$T/s.txt")"
run "$MRC" "$T/east.txt" --time-limit 2 --input "0.5 send=B; 1.0 send=S" >"$T/again.json" 2>/dev/null
[ "$(strip "$T/mrc-east.json")" = "$(strip "$T/again.json")" ] && ok "the same console and JSON on a second run" || bad "a second run differs"
# speed: mazerunner-core idle (its systick, ADC sequence and prompt), 20 simulated s
run "$MRC" "$T/open.txt" --time-limit 20 >"$T/idle.json" 2>/dev/null
echo "speed: mazerunner-core idle on the board: $(js "$T/idle.json" "print(j['real_time_factor'])")x real time ($(js "$T/idle.json" "print(j['sim_time_s'], 's in', j['wall_time_s'], 's')"))"
[ $fails -eq 0 ]

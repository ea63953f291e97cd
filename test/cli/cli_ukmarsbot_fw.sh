#!/usr/bin/env bash
# run.sh: alone (timed: real-time runs, timed input or timeouts)
# cli_ukmarsbot_fw.sh - our mouse firmware on the UKMARSBOT board's own
# HAL (hal/ukmarsbot), the image a user flashes, run on the emulated board
# (mmsim --board ukmarsbot --avr build/ukmarsbot/mouse.elf):
#  - `make firmware-ukmarsbot` builds it and prints flash (<= 30720 B) and
#    static RAM and the stack headroom measured on the emulated board
#    (>= 400 B, for the basic build too); platformio.ini's [env:ukmarsbot] lists the same source
#    files and flags, its robot profile's -I and pre-build script (and `pio project config` reads it, where pio is
#    installed);
#  - it boots: the banner on the console, the battery as the simulated one
#    after the board's diode; the console commands work: `i` (IR lit minus
#    dark) reads a wall east of the start cell on the right diagonal sensor
#    and not without it; `m` (the motor test) drives the robot forward and
#    both encoders count forward; `k` reports the stack left and no tick
#    overrun;
#  - IR walls (firmware/walls_ir.c): calibrated against the start cell's
#    walls (c, f), kept in EEPROM (--eeprom), reloaded at the next power-on
#    and read right (w) in other start cells;
#  - the BASIC sensor board's build boots on its board file;
#  - a second run gives the same console and JSON.
set -u
B=${BUILD:-build}
MMSIM=${MMSIM:-$B/mmsim}
T=$(mktemp -d); trap 'rm -rf "$T"' EXIT
. "$(dirname "$0")/lib.sh"
command -v avr-gcc >/dev/null || { echo "SKIP cli_ukmarsbot_fw: avr-gcc not installed"; exit 77; }
mk() { env -u MAKEFLAGS -u MFLAGS -u MAKELEVEL make --no-print-directory B="$B" "$@"; }

want_rc 0 "make firmware-ukmarsbot" mk firmware-ukmarsbot
grep -E "^ukmarsbot: flash [0-9]+ B of 30720, static RAM [0-9]+ B of 2048" "$T/out" >"$T/size" \
  && ok "$(cat "$T/size")" || bad "no size line: $(tail -3 "$T/out")"
stack_ok() { awk '/^ukmarsbot: stack headroom [0-9]+ B: RAM never written during a contest/ { if ($4 >= 400) { print; ok = 1 } } END { exit !ok }' "$T/out"; }
stack_ok >"$T/stack" && ok "$(cat "$T/stack")" || bad "no stack headroom line of >= 400 B: $(tail -3 "$T/out")"
[ -f $B/ukmarsbot/mouse.elf ] && [ -f $B/ukmarsbot/mouse.hex ] && ok "mouse.elf and mouse.hex" || bad "images missing"

# PlatformIO builds the same files with the same flags
mk -s ukmarsbot-src >"$T/make.src"
python3 - "$T/make.src" <<'PY' >"$T/pio.chk" && ok "platformio.ini [env:ukmarsbot]: $(cat "$T/pio.chk")" || bad "platformio.ini: $(cat "$T/pio.chk")"
import configparser, glob, os, sys
cp = configparser.ConfigParser(); cp.read("platformio.ini")
env = cp["env:ukmarsbot"]
dirs = [d.strip()[len("symlink://"):] for d in env["lib_deps"].split("\n") if d.strip()]
pio = sorted(f for d in dirs for f in glob.glob(os.path.join(d, "*.c")))
make = sorted(open(sys.argv[1]).read().split())
if pio != make:
    sys.exit(print("files differ: make only %s, pio only %s" % (set(make) - set(pio), set(pio) - set(make))) or 1)
flags = env["build_flags"].split()
for f in ("-DMAZE_MAX_SIZE=16", "-Ihal", "-Ifirmware", "-Ihal/ukmarsbot", "-std=c99", "-DHAL_IR_LIT_MINUS_DARK", "-Ibuild/gen/ukmarsbot"):
    if f not in flags: sys.exit(print("build_flags lack", f) or 1)
# the robot profile: written by the pre-build script from the robot file the flags name
if env.get("custom_robot") != "ukmarsbot" or env.get("extra_scripts", "").split() != ["pre:tools/pio_profile.py"]:
    sys.exit(print("custom_robot/extra_scripts:", env.get("custom_robot"), env.get("extra_scripts")) or 1)
if env["board"] != "nanoatmega328" or env.get("framework"): sys.exit(print("board/framework:", env["board"], env.get("framework")) or 1)
print("the same %d source files as make" % len(pio))
PY
PIO=${PIO:-$B/pio/bin/pio}; [ -x "$PIO" ] || PIO=$(command -v pio)
if [ -n "$PIO" ]; then
  PLATFORMIO_SETTING_ENABLE_TELEMETRY=No "$PIO" project config >"$T/pioc" 2>&1 && grep -q "env:ukmarsbot" "$T/pioc" \
    && grep -q "symlink://hal/ukmarsbot" "$T/pioc" && ok "pio project config reads env:ukmarsbot" || bad "pio project config: $(tail -3 "$T/pioc")"
else
  echo "(pio not installed: platformio.ini checked by the file comparison above only)"
fi

# open 16x16 mazes (posts only): as is, and with a wall east of the start cell
open_mazes "$T"
ROBOT=$T/ukmarsbot-centre.ini
sed 's/^start = back_to_wall$/start = centre/' robots/ukmarsbot.ini >"$ROBOT"
HANDS="0.3 send=i; 0.4 send=b; 0.5 send=m; 1.3 send=e; 1.4 send=k; 1.5 end"
run() { "$MMSIM" --maze "$1" --board ukmarsbot --avr $B/ukmarsbot/mouse.elf --robot "$ROBOT" --input "$HANDS" --json; }
js() { python3 -c "import json,sys; j=json.loads(open(sys.argv[1]).read().splitlines()[-1]); c=j['console'].replace('\r',''); $2" "$1"; }

want_rc 1 "open maze: boots, commands (no goal: exit 1)" run "$T/open.txt"; cp "$T/out" "$T/open.json"
want_rc 1 "east wall: boots, commands" run "$T/east.txt"; cp "$T/out" "$T/east.json"
js "$T/open.json" "
assert c.startswith('UKMARSBOT mouse (hal/ukmarsbot, advanced sensors)\ntick 250 Hz, '), c[:200]
b = j['board']; mv = [int(l.split()[1]) for l in c.splitlines() if l.startswith('battery ') and l.endswith(' mV')]
assert mv and abs(mv[-1] / 1000 - (b['battery_v'] - 1.0)) < 0.05, (mv, b['battery_v'])
print(c.splitlines()[1])
" >"$T/msg" && ok "banner; battery $(grep -o '[0-9]* mV' "$T/msg" | head -1) = the simulated battery less D1 (1.0 V) within 50 mV" || bad "banner/battery: $(cat "$T/msg")"
ir() { js "$1" "print(' '.join([l for l in c.splitlines() if l.startswith('IR ') and ' dark ' in l][0].split()[1:5]))"; }
O=$(ir "$T/open.json"); E=$(ir "$T/east.json")
python3 - "$O" "$E" <<'PY' && ok "IR (lfs lds rds rfs, lit - dark): open $O, east wall $E: the right diagonal sees it" || bad "IR: open $O, east $E"
import sys
o, e = [list(map(int, a.split())) for a in sys.argv[1:]]
assert e[2] > o[2] + 40, (o, e)                         # rds: the new wall (open: the post beyond)
assert abs(e[1] - o[1]) <= 3, (o, e)                    # lds: the west wall in both
PY
js "$T/open.json" "
enc = [l for l in c.splitlines() if l.startswith('encoders ')]
l, r = map(int, enc[-1].split()[1:3])
d = j['board']['pwm_duty']; p = j['final_pose']
assert 'motors 256/1023 for 500 ms' in c, c
assert l > 300 and r > 300 and abs(l - r) < 0.05 * l, enc
assert d['left'][1] > 0.1 and d['right'][1] > 0.1, d
assert p['y_m'] > 0.09 + 0.1 and abs(p['x_m'] - 0.09) < 0.02, p
stk = [l for l in c.splitlines() if l.startswith('stack unused')][0]
assert ' overruns 0,' in stk, stk
print(enc[-1], 'y', p['y_m'], '|', stk)
" >"$T/msg" && ok "motor test: $(cat "$T/msg")" || bad "motor test: $(cat "$T/msg")"

# the same run again: the same console and JSON
want_rc 1 "open maze again" run "$T/open.txt"
[ "$(strip "$T/open.json")" = "$(strip "$T/out")" ] && ok "deterministic: the same console and JSON twice" || bad "two runs differ"

# IR walls (firmware/walls_ir.c) from a calibration kept in EEPROM: calibrated in a
# start cell closed on three sides, backed against its rear wall (c: the sides, f: the
# front), saved; the next power-on loads it and reads the walls of other start cells
python3 - "$T" <<'PY'
import sys
n = 16; rows = ["o" + "---o" * n]
for r in range(n):
    row = "|" + "    " * (n - 1) + "   |"
    if r == n - 1: row = row[:4] + "|" + row[5:]
    rows += [row, "o" + ("---o" * n if r == n - 1 else "   o" * n)]
rows[-3] = "o---" + rows[-3][4:]
open(sys.argv[1] + "/closed.txt", "w").write("\n".join(rows) + "\n")
PY
wrun() { "$MMSIM" --maze "$1" --board ukmarsbot --avr $B/ukmarsbot/mouse.elf --robot robots/ukmarsbot.ini --eeprom "$T/ee.bin" --input "$2" --json; }
want_rc 1 "calibration run" wrun "$T/closed.txt" "0.3 send=c; 0.5 send=f; 0.7 send=w; 1 end"; cp "$T/out" "$T/cal.json"
want_rc 1 "open start cell, calibration reloaded" wrun "$T/open.txt" "0.3 send=w; 1 end"; cp "$T/out" "$T/w1.json"
want_rc 1 "start cell with its east wall" wrun "$T/east.txt" "0.3 send=w; 1 end"; cp "$T/out" "$T/w2.json"
wl() { js "$1" "print([l for l in c.splitlines() if l.startswith('$2')][${3:-0}])"; }
js "$T/cal.json" "
assert 'IR calibration: ORION' in c, c
cals = [l for l in c.splitlines() if l.startswith('calibrated and saved: ')]
assert len(cals) == 2, c
assert [l for l in c.splitlines() if l.startswith('walls ')][0].startswith('walls LFR '), c
" && ok "calibrated in the closed start cell: $(wl "$T/cal.json" "calibrated" 1); $(wl "$T/cal.json" "walls")" || bad "calibration: $(js "$T/cal.json" "print(c)")"
for f in w1:L-- w2:L-R; do
  js "$T/${f%%:*}.json" "
assert 'IR calibration from EEPROM' in c, c
assert [l for l in c.splitlines() if l.startswith('walls ')][0].startswith('walls ${f#*:} '), c
" && ok "reloaded from EEPROM: $(wl "$T/${f%%:*}.json" "walls") as the maze has it" || bad "walls ${f#*:}: $(js "$T/${f%%:*}.json" "print(c)")"
done

# the BASIC sensor board's build on its board file
want_rc 0 "make firmware-ukmarsbot UKB_SENSOR_BOARD=basic" mk firmware-ukmarsbot UKB_SENSOR_BOARD=basic
stack_ok >"$T/stack" && ok "basic: $(cat "$T/stack")" || bad "basic: no stack headroom line of >= 400 B: $(tail -3 "$T/out")"
want_rc 1 "basic build boots" "$MMSIM" --maze "$T/east.txt" --board ukmarsbot-basic --avr $B/ukmarsbot-basic/mouse.elf \
  --robot robots/ukmarsbot-basic-12.ini --input "0.3 send=i; 0.5 end" --json
cp "$T/out" "$T/basic.json"
js "$T/basic.json" "
assert c.startswith('UKMARSBOT mouse (hal/ukmarsbot, basic sensors)'), c[:200]
v = list(map(int, [l for l in c.splitlines() if l.startswith('IR ') and ' dark ' in l][0].split()[1:4]))
assert v[1] > 20 and v[2] > 20, v   # right and left: both side walls of the start cell
print(v)
" >"$T/msg" && ok "basic board: banner, IR (front right left) $(cat "$T/msg")" || bad "basic: $(cat "$T/msg")"

[ $fails -eq 0 ] && echo "cli_ukmarsbot_fw: all ok" || { echo "cli_ukmarsbot_fw: $fails failed"; exit 1; }

#!/usr/bin/env bash
# cli_board_periph.sh - a sketch of ours per peripheral of the
# UKMARSBOT board (test/firmware/arduino/board, `make periph-sketches`), each built
# for the Nano and run on the emulated board against the physics:
#   mmsim --board ukmarsbot --avr SKETCH.elf --robot robots/ukmarsbot.ini ...
# MotorPwm (Timer1 in three modes, direction pins), Encoders (counts vs the
# distance driven), AdcIr (A0..A3 dark and lit, which sensor sees what),
# Switches (A6 decoded with mazerunner-core's adc_thesholds), Battery (A7 vs
# the simulated battery), UartEcho (115200 and 9600 baud), Persist (EEPROM,
# .noinit across a reset). The images are checked first, and the two that
# need no board (UartEcho, Persist) also run in plain simavr (mrc_boot);
# without the board emulation (no --board in mmsim, or no
# boards/ukmarsbot-v1.3.ini) the rest is one SKIP line.
set -u
B=${BUILD:-build}
MMSIM=${MMSIM:-$B/mmsim}
MMLOG=${MMLOG:-$B/mmlog}
BOOT=${MRC_BOOT:-$B/test/mrc_boot}
SHARED=${SHARED:-../shared}
MRC_DIR=${MRC_DIR:-$SHARED/clients/mazerunner-core}
SK=$B/arduino/nano/board
ROBOT=robots/ukmarsbot.ini
SKETCHES="MotorPwm Encoders AdcIr Switches Battery UartEcho UartEcho9600 Persist"
T=$(mktemp -d); trap 'rm -rf "$T"' EXIT
. "$(dirname "$0")/lib.sh"
mk() { env -u MAKEFLAGS -u MFLAGS -u MAKELEVEL make --no-print-directory B="$B" "$@"; }

# ---- the images: ATmega328P ELFs that fit the Nano
for s in $SKETCHES; do [ -s "$SK/$s.elf" ] || { mk periph-sketches >"$T/make.out" 2>&1 || { bad "make periph-sketches: $(tail -3 "$T/make.out")"; }; break; }; done
for s in $SKETCHES; do
  elf=$SK/$s.elf
  [ -s "$elf" ] || { bad "$s: $elf not built"; continue; }
  avr-objdump -s -j .note.gnu.avr.deviceinfo "$elf" 2>/dev/null | grep -q atmega328p \
    && ok "$s: an ATmega328P image" || bad "$s: no atmega328p device note"
done
avr-size -A "$SK/Persist.elf" 2>/dev/null | grep -q '^\.noinit ' && ok "Persist: a .noinit section" || bad "Persist: no .noinit section"

# ---- plain simavr (no board): the UART and the power-on state
if [ -x "$BOOT" ] || mk "$BOOT" >/dev/null 2>&1; then
  for s in UartEcho UartEcho9600; do
    baud=115200; [ $s = UartEcho9600 ] && baud=9600
    timeout 60 "$BOOT" "$SK/$s.elf" 0.6 0.2=hello "0.4=two words" 2>"$T/err" | tr -d '\r' >"$T/$s.sim"
    [ "$(cat "$T/$s.sim")" = "$(printf 'UARTECHO %s\nECHO hello\nECHO two words' $baud)" ] \
      && ok "$s in simavr: banner and both lines echoed" || bad "$s in simavr: $(head -c 200 "$T/$s.sim" | cat -v)"
  done
  timeout 60 "$BOOT" "$SK/Persist.elf" 0.2 2>"$T/err" | tr -d '\r' >"$T/persist.sim"
  [ "$(grep -v '^MCUSR' "$T/persist.sim")" = "$(printf 'PERSIST\nBOOT 0\nEE 1')" ] \
    && ok "Persist in simavr: power-on BOOT 0 (SRAM zero), EE 1 (EEPROM erased)" || bad "Persist in simavr: $(cat "$T/persist.sim")"
else
  bad "$BOOT not built"
fi

# ---- the board emulation
"$MMSIM" --board ukmarsbot --help >"$T/out" 2>"$T/err"
if grep -q -- "--board" "$T/err" || [ ! -f boards/ukmarsbot-v1.3.ini ]; then
  echo "SKIP cli_board_periph: no board emulation yet ($( [ -f boards/ukmarsbot-v1.3.ini ] || echo 'no boards/ukmarsbot-v1.3.ini; ')mmsim --board ukmarsbot --help: $(head -1 "$T/err"))"
  [ $fails -eq 0 ] && exit 77 || exit 1
fi

# An open 16x16 maze: the outer walls, and the start cell's west and east
# walls (side walls for the IR sensors); 2.7 m of floor ahead of the start.
python3 - >"$T/open16.txt" <<'EOF'
n = 16
rows = ["o" + "---o" * n]
for y in range(n - 1, -1, -1):
    line = "|"
    for x in range(n):
        line += " S " if (x, y) == (0, 0) else "   "
        line += "|" if x == n - 1 or (x, y) == (0, 0) else " "
    rows.append(line)
    rows.append("o" + ("---o" if y == 0 else "   o") * n)
print("\n".join(rows))
EOF
MAZE=$T/open16.txt

# brun NAME SKETCH TIME_LIMIT INPUT [mmsim args]: the run's JSON in
# $T/NAME.json (its last line), its console in $T/NAME.con (no CRs)
brun() { local name=$1 img=$2 tl=$3 input=$4; shift 4
  local in=(); [ -n "$input" ] && in=(--input "$input")
  timeout 300 "$MMSIM" --board ukmarsbot --avr "$SK/$img.elf" --robot "$ROBOT" --maze "$MAZE" --time-limit "$tl" "${in[@]}" --json "$@" \
    >"$T/$name.out" 2>"$T/$name.err"; local rc=$?
  tail -1 "$T/$name.out" >"$T/$name.json"
  # exit 1: the goal not reached (these runs do not go there)
  if [ $rc -gt 1 ] || ! python3 -c 'import json,sys; json.load(open(sys.argv[1]))' "$T/$name.json" 2>/dev/null; then
    bad "$name: mmsim exit $rc, no JSON: $(head -3 "$T/$name.err")"; : >"$T/$name.con"; echo '{}' >"$T/$name.json"; return 1
  fi
  python3 -c 'import json,sys; sys.stdout.write(json.load(open(sys.argv[1])).get("console", "").replace("\r", ""))' "$T/$name.json" >"$T/$name.con"
  grep -q . "$T/$name.con" && ok "$name: ran, its console in the JSON" || bad "$name: empty console (no \"console\" in the JSON?)"
  return 0; }
# jv FILE EXPR: a Python expression over d, the JSON object
jv() { python3 -c 'import json,sys; d=json.load(open(sys.argv[1])); print(eval(sys.argv[2]))' "$1" "$2" 2>/dev/null; }
# The numbers under "board" whose key path matches a regex, "path value" lines
bnums() { python3 - "$1" "$2" <<'EOF'
import json, re, sys
d = json.load(open(sys.argv[1])).get("board", {})
def walk(v, path):
    if isinstance(v, dict):
        for k, x in v.items(): yield from walk(x, path + [str(k)])
    elif isinstance(v, list):
        for i, x in enumerate(v): yield from walk(x, path + [str(i)])
    elif isinstance(v, (int, float)) and not isinstance(v, bool):
        yield ".".join(path), v
for p, v in walk(d, []):
    if re.search(sys.argv[2], p, re.I): print(p, v)
EOF
}

# ---- MotorPwm: forward (analogWrite), back (fast PWM 8-bit), forward (TOP = ICR1), at 25 %
brun motor MotorPwm 5 "4.5 end"
if grep -q '^DONE$' "$T/motor.con"; then
  python3 - "$T/motor.con" >"$T/motor.chk" <<'EOF'
import sys
p = {}
for l in open(sys.argv[1]):
    f = l.split()
    if f and f[0] == "PHASE": p[f[1]] = (int(f[3]), int(f[4]))
for side in (0, 1):
    name = ("left", "right")[side]
    fw, fs, rv, rs, ic = (p[k][side] for k in ("fwd", "fwd_stop", "rev", "rev_stop", "icr"))
    print(("ok" if fw > 2000 else "bad"), f"{name}: forward 1 s at 25 % (analogWrite): {fw} counts (> 2000)")
    print(("ok" if fs >= fw else "bad"), f"{name}: stopped, no counts back ({fw} -> {fs})")
    print(("ok" if rv < fs - 1000 else "bad"), f"{name}: reverse 0.6 s (fast PWM 8-bit): {fs} -> {rv} (< -1000)")
    print(("ok" if ic > rs + 700 else "bad"), f"{name}: forward 0.5 s (fast PWM, TOP = ICR1): {rs} -> {ic} (> +700)")
l, r = p["fwd"]
print(("ok" if abs(l - r) < 0.05 * max(l, r) else "bad"), f"both wheels alike forward: {l} and {r} (5 %)")
EOF
  while read -r k msg; do [ "$k" = ok ] && ok "MotorPwm $msg" || bad "MotorPwm $msg"; done <"$T/motor.chk"
  [ -s "$T/motor.chk" ] || bad "MotorPwm: PHASE lines: $(head -c 300 "$T/motor.con")"
else
  bad "MotorPwm: no DONE: $(head -c 300 "$T/motor.con")"
fi
# duty range per motor in the JSON: both directions at ~25 %
for side in left right; do
  read -r lo hi < <(jv "$T/motor.json" '" ".join(map(str, d["board"]["pwm_duty"]["'$side'"]))')
  if [ -n "${hi:-}" ]; then
    awk -v a="$lo" -v b="$hi" 'BEGIN {exit !(a <= -0.24 && a >= -0.27 && b >= 0.24 && b <= 0.27)}' \
      && ok "MotorPwm: $side duty range $lo .. $hi (about -0.25 .. 0.25)" || bad "MotorPwm: $side duty range $lo .. $hi, want about -0.25 .. 0.25"
  else
    bad "MotorPwm: no board.pwm_duty.$side [min, max] in the JSON: $(jv "$T/motor.json" 'json.dumps(d.get("board"))' | head -c 300)"
  fi
done
[ "$(jv "$T/motor.json" 'd["contacts"]["front"] + d["contacts"]["side"]')" = 0 ] && ok "MotorPwm: no front or side contact" \
  || bad "MotorPwm: contacts $(jv "$T/motor.json" 'd.get("contacts")')"
# the physics' pose: forward after 1 s, back after the reverse, forward again at the end
brun motor0 MotorPwm 1 "0.001 end" >/dev/null
brun motor1 MotorPwm 2 "1.0 end" >/dev/null
brun motor2 MotorPwm 3 "2.2 end" >/dev/null
y0=$(jv "$T/motor0.json" 'd["final_pose"]["y_m"]'); y1=$(jv "$T/motor1.json" 'd["final_pose"]["y_m"]')
y2=$(jv "$T/motor2.json" 'd["final_pose"]["y_m"]'); y3=$(jv "$T/motor.json" 'd["final_pose"]["y_m"]')
h3=$(jv "$T/motor.json" 'd["final_pose"]["heading_rad"]')
if [ -n "$y0" ] && [ -n "$y1" ] && [ -n "$y2" ] && [ -n "$y3" ]; then
  awk -v a="$y0" -v b="$y1" 'BEGIN {exit !(b > a + 0.5)}' && ok "MotorPwm: north $y0 -> $y1 m in the first second" || bad "MotorPwm: y $y0 -> $y1 m in the first second, want > +0.5"
  awk -v a="$y1" -v b="$y2" 'BEGIN {exit !(b < a - 0.25)}' && ok "MotorPwm: back to $y2 m after the reverse" || bad "MotorPwm: y $y1 -> $y2 m after the reverse, want < -0.25"
  awk -v a="$y2" -v b="$y3" 'BEGIN {exit !(b > a + 0.2)}' && ok "MotorPwm: forward again to $y3 m (ICR1 mode)" || bad "MotorPwm: y $y2 -> $y3 m in ICR1 mode, want > +0.2"
  awk -v h="$h3" 'BEGIN {exit !(h > 1.2708 && h < 1.8708)}' && ok "MotorPwm: still facing north ($h3 rad)" || bad "MotorPwm: heading $h3 rad at the end, want pi/2 +- 0.3"
else
  bad "MotorPwm: no final_pose: $y0 $y1 $y2 $y3"
fi

# ---- Encoders: counts vs the distance driven (36 counts a motor turn x 11.4)
brun enc0 Encoders 1 "0.001 end" >/dev/null
brun enc Encoders 3 "2.1 end"
python3 - "$T/enc.con" "$T/enc0.json" "$T/enc.json" "$ROBOT" >"$T/enc.chk" <<'EOF'
import configparser, json, math, sys
last = None
for l in open(sys.argv[1]):
    f = l.split()
    if f[:1] == ["ENC"] and f[1] == "left" and f[3] == "right": last = f
if not last:
    print("bad no ENC line"); sys.exit()
L, R, nl, nr = int(last[2]), int(last[4]), int(last[6]), int(last[7])
c = configparser.ConfigParser(inline_comment_prefixes=(";",)); c.read(sys.argv[4])
dl, dr = float(c["chassis.body"]["wheel_left_d_mm"]) / 1000, float(c["chassis.body"]["wheel_right_d_mm"]) / 1000
per_turn = float(c["encoder.left"]["encoder_ppr"]) * float(c["motor.left"]["gear_ratio"])
p0, p1 = json.load(open(sys.argv[2]))["final_pose"], json.load(open(sys.argv[3]))["final_pose"]
dist = math.hypot(p1["x_m"] - p0["x_m"], p1["y_m"] - p0["y_m"])
from_counts = (L * math.pi * dl + R * math.pi * dr) / 2 / per_turn
print("ok" if L > 500 and R > 500 else "bad", f"forward 1 s: left {L}, right {R} counts (> 500, forward positive)")
print("ok" if abs(from_counts - dist) <= 0.02 * dist else "bad",
      f"counts x pi D / {per_turn:.1f} = {from_counts * 1000:.1f} mm, the pose moved {dist * 1000:.1f} mm (2 %)")
for side, n, d in (("left", L, dl), ("right", R, dr)):
    want = dist / (math.pi * d) * per_turn
    print("ok" if abs(n - want) <= 0.04 * want else "bad", f"{side}: {n} counts, {want:.0f} from the distance (4 %: the robot's slight curve)")
print("ok" if L <= nl <= L + 20 and R <= nr <= R + 20 else "bad", f"one interrupt per count: {nl} {nr} interrupts for {L} {R} counts (a few back as it stops)")
EOF
while read -r k msg; do [ "$k" = ok ] && ok "Encoders: $msg" || bad "Encoders: $msg"; done <"$T/enc.chk"
for v in INT0 INT1; do
  n=$(bnums "$T/enc.json" "$v" | awk '{print $2; exit}')
  [ -n "$n" ] && [ "$n" -gt 500 ] && ok "Encoders: $v serviced $n times (the JSON's board)" || bad "Encoders: $v interrupts in the JSON: '${n}'"
done
brun enc_again Encoders 3 "2.1 end" >/dev/null
a=$(strip "$T/enc.json" 2>/dev/null); [ -n "$a" ] && [ "$a" = "$(strip "$T/enc_again.json" 2>/dev/null)" ] && ok "Encoders: a second run prints the same JSON" || bad "Encoders: two runs differ"

# ---- AdcIr: dark ~ ambient, the diagonals see the start cell's side walls,
# a hand before one front sensor lights that one only
brun ir AdcIr 3 "0.5 occlude=left; 1.2 occlude=right; 1.85 end"
python3 - "$T/ir.con" >"$T/ir.chk" <<'EOF'
import sys
rows = []
for l in open(sys.argv[1]):
    f = l.split()
    if f[:1] == ["IR"] and len(f) == 5: rows.append(tuple(int(x) for x in f[1:]))
if len(rows) < 60:
    print(f"bad only {len(rows)} IR lines"); sys.exit()
name = {0: "A0 right front", 1: "A1 right diagonal", 2: "A2 left diagonal", 3: "A3 left front"}
occl = lambda ms: "left" if 520 <= ms <= 780 else "right" if 1220 <= ms <= 1480 else None if not (480 <= ms <= 820 or 1180 <= ms <= 1520) else "edge"
darks = [d for ch, d, l, ms in rows]
print("ok" if all(4 <= d <= 16 for d in darks) else "bad", f"dark readings {min(darks)}..{max(darks)} (ambient 10 +- 6)")
for ch in range(4):
    free = [l - d for c, d, l, ms in rows if c == ch and occl(ms) is None]
    if ch in (1, 2):
        print("ok" if min(free) > 20 else "bad", f"{name[ch]}: lit - dark {min(free)}..{max(free)} facing the side wall (> 20)")
    else:
        print("ok" if max(free) < 20 else "bad", f"{name[ch]}: lit - dark {min(free)}..{max(free)} with 2.7 m of open floor ahead (< 20)")
for side, ch, other in (("left", 3, 0), ("right", 0, 3)):
    mine = [l - d for c, d, l, ms in rows if c == ch and occl(ms) == side]
    theirs = [l - d for c, d, l, ms in rows if c == other and occl(ms) == side]
    ok = mine and theirs and min(mine) > 100 and max(theirs) < 100
    print("ok" if ok else "bad", f"occlude={side}: {name[ch]} {mine} (> 100), {name[other]} {theirs} (< 100)")
EOF
while read -r k msg; do [ "$k" = ok ] && ok "AdcIr: $msg" || bad "AdcIr: $msg"; done <"$T/ir.chk"
bnums "$T/ir.json" 'adc' >"$T/adc"
for ch in 0 1 2 3; do
  n=$(awk -v c=$ch '$1 ~ "(^|[^0-9])"c"$" || tolower($1) ~ "a"c"$" {print $2; exit}' "$T/adc")
  [ -n "$n" ] && [ "$n" -ge 36 ] && ok "AdcIr: $n conversions of channel $ch in the JSON's board" || bad "AdcIr: conversions of channel $ch: '$n' ($(head -c 200 "$T/adc" | tr '\n' ' '))"
done

# ---- Switches: A6 decoded as mazerunner-core does (switches.h read() with
# config-ukmarsbot.h's adc_thesholds, checked against the source when present)
THR="660, 647, 630, 614, 590, 570, 545, 522, 461, 429, 385, 343, 271, 212, 128, 44, 0"
if [ -f "$MRC_DIR/mazerunner-core/config-ukmarsbot.h" ]; then
  grep -q "adc_thesholds\[\] PROGMEM = {$THR};" "$MRC_DIR/mazerunner-core/config-ukmarsbot.h" \
    && ok "Switches: the thresholds are mazerunner-core's" || bad "Switches: config-ukmarsbot.h's adc_thesholds changed: $(grep adc_thesholds "$MRC_DIR/mazerunner-core/config-ukmarsbot.h")"
fi
# decode: "ms raw N" lines from SW lines (N: mazerunner-core's read(), 16 = button)
decode() { python3 - "$1" "$THR" <<'EOF'
import sys
t = [int(x) for x in sys.argv[2].split(",")]
def read(raw):
    if raw > 800: return 16
    for i in range(16):
        if raw > (t[i] + t[i + 1]) // 2: return i
    return -1
for l in open(sys.argv[1]):
    f = l.split()
    if f[:1] == ["SW"] and len(f) == 3: print(f[2], f[1], read(int(f[1])))
EOF
}
brun sw Switches 2 "0.2 switches=0; 0.4 switches=5; 0.6 switches=15; 0.8 button=down; 1.0 button=up; 1.2 end"
decode "$T/sw.con" >"$T/sw.dec"
for want in "300 0" "350 0" "500 5" "550 5" "700 15" "750 15" "900 16" "950 16" "1100 15" "1150 15"; do
  set -- $want
  got=$(awk -v ms=$1 '$1 >= ms && $1 < ms + 10 {print $3 " (raw " $2 ")"; exit}' "$T/sw.dec")
  [ "${got%% *}" = "$2" ] && ok "Switches: at $1 ms: $got$( [ $2 = 16 ] && echo ', the button')" || bad "Switches: at $1 ms: '$got', want $2"
done
in=""; for n in $(seq 0 15); do in="$in$(awk -v n=$n 'BEGIN {printf "%.1f switches=%d; ", 0.1 * (n + 1), n}')"; done
brun sw16 Switches 2 "${in}1.7 button=down; 1.8 end"
decode "$T/sw16.con" >"$T/sw16.dec"
wrong=""
for n in $(seq 0 15); do
  ms=$((100 * (n + 1) + 50))
  got=$(awk -v ms=$ms '$1 >= ms && $1 < ms + 10 {print $3; exit}' "$T/sw16.dec")
  [ "$got" = "$n" ] || wrong="$wrong $n->'$got'"
done
[ -z "$wrong" ] && ok "Switches: every N 0..15 decodes to N" || bad "Switches: decoded wrong:$wrong"
got=$(awk '$1 >= 1750 && $1 < 1760 {print $3; exit}' "$T/sw16.dec")
[ "$got" = 16 ] && ok "Switches: the button over switches 15 reads as the button" || bad "Switches: the button over 15: '$got'"

# ---- Battery: A7 through D1 and the 1:2 divider vs the simulated battery (MM_PARTS) less D1's drop
brun bat Battery 2 "1.05 end" --lcm-log "$T/bat.lcmlog"
DROP=$(sed -n 's/^diode_drop_v *= *\([0-9.]*\).*/\1/p' boards/parts/ukmarsbot-mainboard-v1.3.ini); DROP=${DROP:-0}
if [ -s "$T/bat.lcmlog" ] && "$MMLOG" --dump MM_PARTS "$T/bat.lcmlog" >"$T/parts.jsonl" 2>"$T/err"; then
  python3 - "$T/bat.con" "$T/parts.jsonl" "$DROP" >"$T/bat.chk" <<'EOF'
import bisect, json, sys
parts = [json.loads(l) for l in open(sys.argv[2]) if l.strip()]
ts = [p["utime"] / 1e6 for p in parts]
n = 0
for l in open(sys.argv[1]):
    f = l.split()
    if f[:1] != ["BAT"]: continue
    mv, ms = int(f[1]), int(f[3])
    i = min(max(bisect.bisect_left(ts, ms / 1000) , 0), len(ts) - 1)
    v = parts[i]["battery_v"] - float(sys.argv[3])  # after D1
    n += 1
    if abs(mv / 1000 - v) > 0.02 * v:
        print(f"bad at {ms} ms: BAT {mv} mV, the simulated battery {v:.3f} V (2 %)"); sys.exit()
    last = (mv, v)
print("ok" if n >= 9 else "bad", f"{n} readings within 2 % of the simulated battery less D1's {sys.argv[3]} V (last {last[0]} mV vs {last[1]:.3f} V)" if n else "no BAT line")
EOF
  while read -r k msg; do [ "$k" = ok ] && ok "Battery: $msg" || bad "Battery: $msg"; done <"$T/bat.chk"
else
  bad "Battery: no MM_PARTS from --lcm-log: $(head -2 "$T/err" "$T/bat.err")"
fi

# ---- UartEcho: send= typed with a newline, echoed, at 115200 and 9600 baud
for s in UartEcho UartEcho9600; do
  brun $s $s 1 "0.3 send=hello; 0.5 send=two words; 0.8 end" >/dev/null
  [ "$(grep '^ECHO' "$T/$s.con")" = "$(printf 'ECHO hello\nECHO two words')" ] \
    && ok "$s: both lines echoed" || bad "$s: console $(head -c 200 "$T/$s.con" | cat -v)"
done

# ---- Persist: power-on SRAM zero, a reset keeps it; EEPROM kept across the reset
brun persist Persist 1 "0.5 reset; 1.0 end"
[ "$(grep '^BOOT\|^EE' "$T/persist.con")" = "$(printf 'BOOT 0\nEE 1\nBOOT 1\nEE 2')" ] \
  && ok "Persist: BOOT 0 at power-on, 1 after the reset (.noinit kept); EE 1 then 2" \
  || bad "Persist: console $(tr '\n' '|' <"$T/persist.con")"
n=$(bnums "$T/persist.json" 'reset' | awk '{print $2; exit}')
[ "$n" = 1 ] && ok "Persist: one reset in the JSON's board" || bad "Persist: resets in the JSON: '$n'"
brun persist2 Persist 1 "0.5 end" >/dev/null
[ "$(grep '^BOOT\|^EE' "$T/persist2.con")" = "$(printf 'BOOT 0\nEE 1')" ] \
  && ok "Persist: a new run powers on afresh (BOOT 0, EE 1)" || bad "Persist: second run: $(tr '\n' '|' <"$T/persist2.con")"

[ $fails -eq 0 ]

#!/usr/bin/env bash
# cli_board_push.sh - a person's hands on the robot's body (--input push,
# lift, place) with an encoder-calibration sketch (test/firmware/arduino/board/
# HandCount.ino: prints its counts every 100 ms, never drives the motors) on
# boards/ukmarsbot-v1.3.ini, checked against the robot file's physics:
# counts = distance / (pi x wheel diameter) x encoder_ppr x gear_ratio, each
# wheel within 2 %; a robot left standing counts no edge in 2 s; a turn by
# hand gives opposite counts of track/2 x angle each; lifted, a push moves
# nothing and counts nothing, and placed it rolls again; bad push values and
# an occlusion of a sensor the robot lacks are one line and exit 2.
set -u
B=${BUILD:-build}
MMSIM=${MMSIM:-$B/mmsim}
SK=$B/clients/board
ROBOT=robots/ukmarsbot.ini
T=$(mktemp -d); trap 'rm -rf "$T"' EXIT
. "$(dirname "$0")/lib.sh"
mk() { env -u MAKEFLAGS -u MFLAGS -u MAKELEVEL make --no-print-directory B="$B" "$@"; }
[ -s "$SK/HandCount.elf" ] || { mk "$SK/HandCount.elf" >"$T/make.out" 2>&1 || bad "make HandCount.elf: $(tail -3 "$T/make.out")"; }
# An open 16x16 maze (the outer walls only)
python3 - >"$T/open16.txt" <<'PY'
n = 16
rows = ["o" + "---o" * n]
for y in range(n - 1, -1, -1):
    rows.append("|" + "".join((" S " if (x, y) == (0, 0) else "   ") + ("|" if x == n - 1 else " ") for x in range(n)))
    rows.append("o" + ("---o" if y == 0 else "   o") * n)
print("\n".join(rows))
PY
MAZE=$T/open16.txt
run() { local name=$1 tl=$2 input=$3
  want_rc 1 "$name: runs" "$MMSIM" --board ukmarsbot --avr "$SK/HandCount.elf" --robot "$ROBOT" --maze "$MAZE" --time-limit "$tl" \
    --input "$input" --json
  tail -1 "$T/out" >"$T/$name.json"; }
# check NAME EXPR: a Python check over d (the run's JSON), hc(ms) (the sketch's
# last "HC" line at or before ms: (ms, L, R, EL, ER)), want(mm) (the counts
# per wheel for mm of rolling: the robot file's physics) and the robot's
# numbers; prints "ok TEXT" or "bad TEXT".
check() { python3 - "$T/$1.json" "$ROBOT" "$2" <<'PY'
import configparser, json, math, sys
d = json.load(open(sys.argv[1]))
ini = configparser.ConfigParser(inline_comment_prefixes=(";",))
ini.read(sys.argv[2])
diam = [float(ini["chassis.body"]["wheel_%s_d_mm" % s]) for s in ("left", "right")]
cpr = [float(ini["encoder.%s" % s]["encoder_ppr"]) * float(ini["motor.%s" % s]["gear_ratio"]) for s in ("left", "right")]
track = float(ini["chassis.body"]["wheel_track_mm"])
arc90 = track / 2 * math.pi / 2  # mm each wheel rolls in a 90 deg turn about the axle's middle
def want(mm): return [mm / (math.pi * diam[i]) * cpr[i] for i in range(2)]
lines = [tuple(int(v) for v in l.split()[1:6]) for l in d.get("console", "").replace("\r", "").splitlines() if l.startswith("HC ")]
def hc(ms): return [l for l in lines if l[0] <= ms][-1]
def near(got, exp, tol=0.02): return abs(got - exp) <= tol * abs(exp)
ok, text = eval(sys.argv[3])
print(("ok " if ok else "bad ") + text)
PY
}
verdict() { local line; line=$(check "$1" "$2" 2>&1 | tail -1)
  case "$line" in "ok "*) ok "$1: ${line#ok }" ;; *) bad "$1: ${line#bad }" ;; esac; }

# ---- standing 2 s, then rolled 180 mm forward over 1 s
run push 3.6 "2 push=180; 3.5 end"
verdict push "(hc(1950)[1:] == (0, 0, 0, 0), f'standing 2 s: counts and edges {hc(1950)[1:]} (want none)')"
verdict push "(all(near(hc(3450)[1 + i], want(180)[i]) for i in range(2)), f'180 mm: counts {hc(3450)[1:3]}, physics {[round(w, 1) for w in want(180)]}')"
verdict push "(abs(d['final_pose']['y_m'] - 0.0565 - 0.180) < 0.002 and d['collisions'] == 0, f\"moved to y {d['final_pose']['y_m']} m (from 0.0565 + 0.180)\")"

# ---- a turn by hand: 90 deg counter-clockwise about the axle's middle
run turn 4.1 "1 push=180; 2.5 push=0,90; 4 end"
verdict turn "(near(hc(3950)[1] - hc(2450)[1], -want(arc90)[0]) and near(hc(3950)[2] - hc(2450)[2], want(arc90)[1]), f'90 deg: counts {hc(2450)[1:3]} -> {hc(3950)[1:3]}, physics -+{[round(w, 1) for w in want(arc90)]}')"
verdict turn "(abs(d['final_pose']['heading_rad'] - math.pi) < 0.01, f\"heading {d['final_pose']['heading_rad']} rad (want pi)\")"

# ---- lifted: a push moves and counts nothing; placed, it rolls again
run lift 5.1 "0.5 lift; 1 push=100; 2.5 place; 3 push=90; 5 end"
verdict lift "(hc(2950)[1:] == (0, 0, 0, 0), f'carried and pushed: counts and edges {hc(2950)[1:]} (want none)')"
verdict lift "(all(near(hc(4950)[1 + i], want(90)[i]) for i in range(2)), f'placed, 90 mm: counts {hc(4950)[1:3]}, physics {[round(w, 1) for w in want(90)]}')"
verdict lift "(abs(d['final_pose']['y_m'] - 0.0565 - 0.090) < 0.002, f\"moved to y {d['final_pose']['y_m']} m (from 0.0565 + 0.090 only)\")"

# ---- what cannot be: one line, exit 2, before the run
for bad_in in "1 push=1000,0,1" "1 push=10,x" "1 occlude=front"; do
  ONE_ERROR_LINE=1 want_rc 2 "--input '$bad_in': exit 2" "$MMSIM" --board ukmarsbot --avr "$SK/HandCount.elf" --robot "$ROBOT" --maze "$MAZE" \
    --time-limit 1 --input "$bad_in" --json
  grep -q -- "--input:1:3: " "$T/err" && ok "'$bad_in': $(cat "$T/err")" || bad "'$bad_in': $(cat "$T/err")"
done
grep -q "its sensors: lfs, lds, rds, rfs" "$T/err" && ok "occlude: the robot's sensor names given" || bad "occlude: $(cat "$T/err")"

[ $fails -eq 0 ] && echo "PASS cli_board_push" || { echo "FAIL cli_board_push ($fails)"; exit 1; }

#!/usr/bin/env bash
# cli_robot.sh - mmsim --robot and --print-robot (robot files, docs/ROBOTS.md):
# a bad robot file is one line FILE:LINE... and exit 2; --print-robot's
# text loads back; --robot robots/paper.ini runs as the built-in robot.
set -u
S=${MMSIM:-build/mmsim}
T=$(mktemp -d); trap 'rm -rf "$T"' EXIT
. "$(dirname "$0")/lib.sh"
M=mazes/gen-5x5-s1.txt

ONE_ERROR_LINE=1
sed 's/^body_w_mm = 96/body_w_mm = 5/' robots/paper.ini >"$T/bad.ini"
n=$(grep -n '^body_w_mm' "$T/bad.ini" | cut -d: -f1)
want_rc 2 "bad robot file" "$S" --maze $M --robot "$T/bad.ini"
[ "$(cat "$T/err")" = "$T/bad.ini:$n: chassis.body.body_w_mm: 5 mm is out of range [10, 300]" ] && ok "bad robot file: FILE:LINE: KIND.NAME.key: reason" || bad "bad robot file: $(cat "$T/err")"
{ cat robots/paper.ini; printf '\n[laser.x]\n'; } >"$T/kind.ini"
want_rc 2 "unknown kind" "$S" --print-robot --robot "$T/kind.ini"
grep -q "^$T/kind.ini:$(( $(wc -l <robots/paper.ini) + 2 )): laser.x: unknown kind" "$T/err" && ok "unknown kind: its line" || bad "unknown kind: $(cat "$T/err")"
want_rc 2 "missing robot file" "$S" --maze $M --robot "$T/none.ini"
grep -q "^$T/none.ini: " "$T/err" && ok "missing robot file: FILE: reason" || bad "missing robot file: $(cat "$T/err")"
want_rc 2 "robot file as config" "$S" --maze $M --config robots/paper.ini
grep -q "^robots/paper.ini:[0-9]*: chassis.body.body_w_mm: a robot's number: it belongs in the robot file" "$T/err" \
  && ok "a robot file given as --config: to --robot" || bad "robot file as config: $(cat "$T/err")"
# an indented line (libinih: more of the key above, body_mass_g = 1999) and a key given twice
sed 's/^body_mass_g = 127$/body_mass_g = 127\n  1999/' robots/paper.ini >"$T/cont.ini"
n=$(( $(grep -n '^body_mass_g' robots/paper.ini | cut -d: -f1) + 1 ))
want_rc 2 "robot file: an indented continuation line" "$S" --maze $M --robot "$T/cont.ini"
[ "$(cat "$T/err")" = "$T/cont.ini:$n: chassis.body.body_mass_g: an indented line continues its value (INI continuation lines are refused: start the line in its first column)" ] \
  && ok "robot file: continuation line: FILE:LINE" || bad "robot continuation: $(cat "$T/err")"
sed 's/^body_mass_g = 127$/body_mass_g = 127\nbody_mass_g = 200/' robots/paper.ini >"$T/twice.ini"
want_rc 2 "robot file: a key given twice" "$S" --maze $M --robot "$T/twice.ini"
[ "$(cat "$T/err")" = "$T/twice.ini:$n: chassis.body.body_mass_g: given twice (first on line $((n - 1)))" ] \
  && ok "robot file: key twice: FILE:LINE" || bad "robot key twice: $(cat "$T/err")"
ONE_ERROR_LINE=0

# --print-robot loads back, prints the same (apart from its first line, the path)
want_rc 0 "--print-robot" "$S" --print-robot
cp "$T/out" "$T/printed.ini"
grep -q '^\[chassis.body\]$' "$T/printed.ini" && grep -q '^\[tof.front\]$' "$T/printed.ini" && ok "printed robot has its sections" || bad "printed robot: $(head -5 "$T/printed.ini")"
want_rc 0 "printed robot loads" "$S" --print-robot --robot "$T/printed.ini"
[ "$(tail -n +2 "$T/out")" = "$(tail -n +2 "$T/printed.ini")" ] && ok "printed robot loads back to the same text" || bad "round trip: $(diff "$T/out" "$T/printed.ini" | head -5)"
want_rc 0 "paper.ini prints as the built-in" "$S" --print-robot --robot robots/paper.ini
[ "$(cat "$T/out")" = "$(cat "$T/printed.ini")" ] && ok "robots/paper.ini prints as the built-in robot" || bad "paper.ini print: $(diff "$T/out" "$T/printed.ini" | head -5)"

# a run with --robot robots/paper.ini: the same JSON as without (apart from the wall clock, "robot" and "contacts")
want_rc 0 "run, built-in robot" "$S" --maze $M --runs 1 --json --seed 3
cp "$T/out" "$T/a"
want_rc 0 "run, --robot robots/paper.ini" "$S" --maze $M --runs 1 --json --seed 3 --robot robots/paper.ini
cp "$T/out" "$T/b"
[ "$(python3 -c "import json,sys; print(json.loads(open(sys.argv[1]).read().splitlines()[-1]).get('robot'))" "$T/b")" = robots/paper.ini ] \
  && ok "JSON names the robot file" || bad "no robot field: $(cat "$T/b")"
python3 -c "
import json,sys
a, b = (json.loads(open(f).read().splitlines()[-1]) for f in sys.argv[1:3])
for d in (a, b):
    for k in ('wall_time_s', 'real_time_factor', 'robot', 'contacts'): d.pop(k, None)
sys.exit(a != b)" "$T/a" "$T/b" && ok "--robot robots/paper.ini: the same run as the built-in robot" || bad "paper.ini run differs: $(cat "$T/a" "$T/b")"
# another robot: another config hash
sed 's/^body_mass_g = 127/body_mass_g = 150/' robots/paper.ini >"$T/heavy.ini"
want_rc 0 "run, a heavier robot" "$S" --maze $M --runs 1 --json --seed 3 --robot "$T/heavy.ini"
[ "$(python3 -c "import json,sys; print(json.loads(open(sys.argv[1]).read().splitlines()[-1])['config_hash'] != json.loads(open(sys.argv[2]).read().splitlines()[-1])['config_hash'])" "$T/out" "$T/a")" = True ] \
  && ok "another robot: another config hash" || bad "config hash unchanged by the robot"
# the robot against the world: known once both files are (a narrow world, a wide robot)
sed 's/^wheel_track_mm = 96/wheel_track_mm = 170/' robots/paper.ini >"$T/wide.ini"
sed 's/^body_w_mm = 96/body_w_mm = 180/' "$T/wide.ini" >"$T/wide2.ini"
want_rc 2 "a robot wider than a corridor" "$S" --maze $M --robot "$T/wide2.ini"
grep -q "wide2.ini: world.cell_m: the robot is wider than a corridor (178 mm over its tyres, the corridor 168 mm)" "$T/err" \
  && ok "wide robot: one line naming the corridor" || bad "wide robot: $(cat "$T/err")"
printf '[world]\ncell_m = 0.09\nwall_thick_m = 0.006\npost_m = 0.006\n' >"$T/half.ini"
want_rc 2 "the paper robot in half-size corridors" "$S" --maze $M --config "$T/half.ini"
grep -q "half.ini: world.cell_m: the robot is wider than a corridor" "$T/err" && ok "half size: refused, one line" || bad "half size: $(cat "$T/err")"
# the contest side of a board: hands, goal, start pose, contacts by kind
want_rc 2 "--input's board actions without a board" "$S" --maze $M --input "1 switches=2"
grep -q "^--input: switches, button, reset and send act on a board" "$T/err" && ok "--input without --board: one line" || bad "input without board: $(cat "$T/err")"
want_rc 2 "--input: an unknown action" "$S" --maze $M --input "0.5 wave"
grep -q -- "--input:1:5: unknown action" "$T/err" && ok "--input: unknown action at its column" || bad "unknown action: $(cat "$T/err")"
want_rc 2 "--goal outside the maze" "$S" --maze $M --goal 5,0
want_rc 1 "--input end" "$S" --maze $M --robot robots/ukmarsbot.ini --driver scripted --input "0 end" --json
python3 -c "
import json,sys
d = json.loads(open(sys.argv[1]).read().splitlines()[-1])
p = d['final_pose']
# back_to_wall: the body's rear 0.5 mm from the start cell's south wall face (6 mm): centre at 6.5 + 50 mm
assert d['exit_reason'] == 'input_end', d
assert abs(p['y_m'] - 0.0565) < 0.001 and abs(p['x_m'] - 0.09) < 0.001, p
assert set(d['contacts']) == {'front', 'side', 'rear_soft', 'rear'}, d
" "$T/out" && ok "UKMARSBOT starts with its back to the wall; contacts by kind in the JSON" || bad "start pose: $(tail -1 "$T/out")"
want_rc 0 "--goal 1,0 (scripted)" "$S" --maze mazes/gen-16x16-s1.txt --driver scripted --goal 1,0 --runs 1 --json
python3 -c "
import json,sys
d = json.loads(open(sys.argv[1]).read().splitlines()[-1])
assert d['reached_goal'] and d['laps'][0]['run_s'] < 3, d
" "$T/out" && ok "--goal: laps to that cell" || bad "goal: $(tail -1 "$T/out")"
[ $fails -eq 0 ]

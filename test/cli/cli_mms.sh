#!/usr/bin/env bash
# run.sh: alone (timed: real-time runs, timed input or timeouts)
# cli_mms.sh - mmsim --mms: mms algorithms (test/mms/*.py, written for these
# tests) drive the physically simulated robot through the mms text API;
# protocol conformance; the algorithm's faults end the run cleanly.
set -u
S=${MMSIM:-build/mmsim}
T=$(mktemp -d); trap 'rm -rf "$T"' EXIT
. "$(dirname "$0")/lib.sh"
py() { python3 -c "import json,sys; d=json.loads(open('$T/out').read().splitlines()[-1]); print($1)"; }
command -v python3 >/dev/null || { echo "SKIP cli_mms: python3 missing"; exit 77; }
A="python3 test/mms"

# algorithms reach the goal on the robot's own sensing
for m in gen-5x5-s1 gen-6x6-s1 gen-8x8-s1; do
  want_rc 0 "floodfill $m" "$S" --maze mazes/$m.txt --mms "$A/floodfill.py 2" --json
  [ "$(py "(d['driver'], d['reached_goal'], d['exit_reason'], len(d['laps']), d['collisions'], d['mms']['crashes'], d['mms']['stats']['best_run_distance'] > 0, d['mms']['stats']['score'] < 2000)")" = "('mms', True, 'mms_exited', 2, 0, 0, True, True)" ] \
    && ok "floodfill $m: two runs to the goal, no crash, no contact" || bad "floodfill $m: $(cat "$T/out")"
done
[ "$(py "sorted(d.keys()) + sorted(d['mms'].keys()) + sorted(d['mms']['stats'].keys())")" = "['best_run_s', 'collisions', 'config_hash', 'driver', 'exit_reason', 'final_pose', 'first_run_s', 'laps', 'maze', 'mms', 'reached_goal', 'real_time_factor', 'seed', 'sim_time_s', 'wall_time_s', 'colors', 'command', 'commands', 'crashes', 'exit_signal', 'exit_status', 'ideal_walls', 'invalid_commands', 'moves', 'resets', 'stats', 'texts', 'timeout_ms', 'wall_contacts', 'best_run_distance', 'best_run_effective_distance', 'best_run_turns', 'current_run_distance', 'current_run_effective_distance', 'current_run_turns', 'score', 'total_distance', 'total_effective_distance', 'total_turns']" ] \
  && ok "json keys" || bad "json keys: $(cat "$T/out")"
for m in gen-5x5-s1 gen-8x8-s1; do
  want_rc 0 "wall follower $m" "$S" --maze mazes/$m.txt --mms "$A/wallfollow.py" --json
  [ "$(py "(d['reached_goal'], d['exit_reason'], d['mms']['exit_status'])")" = "(True, 'mms_exited', 0)" ] && ok "wall follower $m reached the goal" || bad "wall follower $m: $(cat "$T/out")"
done
# a wall follower loops forever on 6x6-s1: goal not reached, its own exit 1 is a failure (3)
want_rc 3 "wall follower fails on a looped maze" "$S" --maze mazes/gen-6x6-s1.txt --mms "$A/wallfollow.py" --json
[ "$(py "(d['reached_goal'], d['exit_reason'], d['mms']['stats']['score'])")" = "(False, 'mms_failed', 2000.0)" ] && ok "score 2000 without the goal" || bad "looped maze: $(cat "$T/out")"

# half steps: every move starts with moveForwardHalf 1 onto the boundary, then 2K-1 half steps
for m in gen-8x8-s1 gen-16x16-s2; do
  want_rc 0 "floodfill in half steps $m" "$S" --maze mazes/$m.txt --mms "$A/floodfill.py 2 half" --json
  [ "$(py "(d['reached_goal'], d['exit_reason'], len(d['laps']), d['collisions'], d['mms']['crashes'], d['mms']['stats']['score'] < 2000)")" = "(True, 'mms_exited', 2, 0, 0, True)" ] \
    && ok "floodfill in half steps $m: two runs, no crash, no contact" || bad "floodfill in half steps $m: $(cat "$T/out")"
done
[ "$(py "(d['mms']['stats']['total_distance'], d['mms']['stats']['best_run_distance'], d['mms']['stats']['best_run_effective_distance'])")" = "(51, 16.5, 15.75)" ] \
  && ok "half steps: distances in half cells (best run 16.5 cells, effective 15.75)" || bad "half-step stats: $(cat "$T/out")"

# --verbose: the dialogue on stderr with the simulation time
want_rc 0 "verbose trace" "$S" --maze mazes/gen-5x5-s1.txt --mms "$A/wallfollow.py" --verbose
grep -q '^mms *0\.[0-9]* > moveForward$' "$T/err" && grep -q '^mms *[0-9.]* < ack$' "$T/err" && grep -q '^mms *[0-9.]* > setColor 0 1 g$' "$T/err" \
  && ok "verbose trace" || bad "verbose trace: $(head -5 "$T/err")"

# determinism, and sensed walls = the maze file's on a noise-free robot
"$S" --maze mazes/gen-8x8-s1.txt --mms "$A/floodfill.py 2" --json >"$T/a"; "$S" --maze mazes/gen-8x8-s1.txt --mms "$A/floodfill.py 2" --json >"$T/b"
[ "$(strip "$T/a")" = "$(strip "$T/b")" ] && ok "mms run deterministic" || bad "mms run deterministic"
"$S" --print-robot | sed 's/^cv *=.*/cv = 0/' >"$T/quiet.ini"
[ "$(grep -c '^cv = 0$' "$T/quiet.ini")" = 3 ] || bad "noise-free robot: not three ToF cv lines"

for run in "gen-8x8-s1 2" "gen-16x16-s2 2" "gen-8x8-s1 2 half"; do
  set -- $run; m=$1; shift
  "$S" --maze mazes/$m.txt --robot "$T/quiet.ini" --mms "$A/floodfill.py $*" --json >"$T/sensed"
  "$S" --maze mazes/$m.txt --robot "$T/quiet.ini" --mms "$A/floodfill.py $*" --mms-ideal-walls --json >"$T/ideal"
  same=$(python3 -c "
import json
a, b = (json.loads(open('$T/' + f).read().splitlines()[-1]) for f in ('sensed', 'ideal'))
keys = ('laps', 'sim_time_s', 'reached_goal', 'collisions', 'final_pose')
print(a['reached_goal'] and all(a[k] == b[k] for k in keys) and a['mms']['stats'] == b['mms']['stats'] and a['mms']['moves'] == b['mms']['moves'] and b['mms']['ideal_walls'])")
  [ "$same" = True ] && ok "$m ($*): ideal walls and sensed walls give the same run" || bad "$m ($*) ideal vs sensed: $(cat "$T/sensed") $(cat "$T/ideal")"
done

# algorithms that wait for Reset: after the goal resetwait.py polls
# wasReset until it is true, then ackReset and a second run. Simulation time
# stands still while an algorithm thinks, so polling alone would never reach
# a reset time (the run would end after 10^6 commands, mms_flood): an
# algorithm that asks 10 times without a move idles: --mms-reset-at S lets the contest clock run
# to S (the robot at rest), --mms-reset-at idle presses Reset at once; with
# neither the run ends (mms_idle, exit 1)
want_rc 0 "waits for Reset, --mms-reset-at 30" "$S" --maze mazes/gen-5x5-s1.txt --mms "$A/resetwait.py 2" --mms-reset-at 30 --json
[ "$(py "(d['exit_reason'], len(d['laps']), d['laps'][0]['end_s'] < 5, 30 <= d['laps'][1]['start_s'] < 31, d['mms']['resets'], d['collisions'])")" = "('mms_exited', 2, True, True, 1, 0)" ] \
  && ok "the clock ran to the reset time at 30 s, then a second run" || bad "reset at 30: $(cat "$T/out" "$T/err")"
cp "$T/out" "$T/r30"
want_rc 0 "waits for Reset, --mms-reset-at idle" "$S" --maze mazes/gen-5x5-s1.txt --mms "$A/resetwait.py 3" --mms-reset-at idle --json
[ "$(py "(d['exit_reason'], len(d['laps']), d['laps'][2]['start_s'] < 15, d['mms']['resets'], d['collisions'])")" = "('mms_exited', 3, True, 2, 0)" ] \
  && ok "Reset pressed each time the algorithm idles: three runs" || bad "reset on idle: $(cat "$T/out" "$T/err")"
cp "$T/out" "$T/ridle"
"$S" --maze mazes/gen-5x5-s1.txt --mms "$A/resetwait.py 3" --mms-reset-at idle --json >"$T/ridle2" 2>/dev/null
[ "$(strip "$T/ridle")" = "$(strip "$T/ridle2")" ] && ok "reset on idle deterministic" || bad "reset on idle not deterministic"
want_rc 1 "waits for a Reset that never comes" "$S" --maze mazes/gen-5x5-s1.txt --mms "$A/resetwait.py 1 forever" --json
[ "$(py "(d['exit_reason'], d['reached_goal'], d['mms']['commands'] < 100)")" = "('mms_idle', True, True)" ] \
  && grep -q "^mmsim: mms: the algorithm '$A/resetwait.py 1 forever' waits for Reset (wasReset 10 times without a move) and none is coming" "$T/err" \
  && ok "no Reset coming: mms_idle, exit 1, one line" || bad "idle for ever: $(cat "$T/out" "$T/err")"
want_rc 0 "reset time after the contest's end" "$S" --maze mazes/gen-5x5-s1.txt --mms "$A/resetwait.py 1 forever" --mms-reset-at 15 --time-limit 10 --json
[ "$(py "(d['exit_reason'], len(d['laps']), d['sim_time_s'] < 11)")" = "('time_limit', 1, True)" ] \
  && ok "the clock runs to the contest's end: time_limit" || bad "reset after the end: $(cat "$T/out")"
want_rc 2 "--mms-reset-at soon" "$S" --maze mazes/gen-5x5-s1.txt --mms "$A/resetwait.py" --mms-reset-at soon
grep -q "^mmsim: --mms-reset-at: expected seconds of simulation time from 0 to 86400, or idle, got 'soon'" "$T/err" && [ "$(wc -l <"$T/err")" = 1 ] \
  && ok "--mms-reset-at error line" || bad "--mms-reset-at error: $(cat "$T/err")"
want_rc 2 "--mms-reset-at -1" "$S" --maze mazes/gen-5x5-s1.txt --mms "$A/resetwait.py" --mms-reset-at -1

# protocol conformance: every command, valid and invalid (test/mms/conform.py)
want_rc 0 "conformance client" "$S" --maze mazes/gen-5x5-s1.txt --mms "$A/conform.py" --mms-reset-at 0.1 --json
grep -q '^algo: conform: [0-9]* checks ok$' "$T/err" && ok "conformance: $(grep -o '[0-9]* checks' "$T/err")" || bad "conformance: $(cat "$T/err")"
[ "$(py "(d['exit_reason'], d['reached_goal'], d['collisions'], d['mms']['resets'], d['mms']['stats']['best_run_distance'], d['mms']['colors'], sorted(d['mms']['texts'].items()))")" = "('mms_exited', True, 0, 1, 9.5, {'3,3': 'G'}, [('0,1', 'ok'), ('1,1', 'hello worl'), ('2,2', 'a?b?'), ('3,4', 'two  space'), ('4,4', 'abc')])" ] \
  && ok "conformance: goal by half steps (9.5 cells), colours and texts (10 printable characters, others '?')" || bad "conformance JSON: $(cat "$T/out")"

# the run report draws the algorithm's colours (floodfill: cyan on its path) and texts
want_rc 0 "report of an mms run" "$S" --maze mazes/gen-8x8-s1.txt --mms "$A/floodfill.py 2" --report "$T/r.png"
cyan=$(python3 test/tools/pngcheck.py "$T/r.png" near:00ffff:8)
[ "${cyan:-0}" -gt 2000 ] && ok "report: cell colours drawn ($cyan cyan pixels)" || bad "report: cyan pixels: $cyan"
grep -q '>6</text>' "$T/r.svg" && ok "report: cell texts drawn" || bad "report: no cell text in the SVG"

# a wall first sensed during a move of several cells (the north wall of (0,1), unknown at the
# start): the robot stops at the centre of (0,1) and answers crash; one cell driven
for mv in "moveForward 2" "moveForwardHalf 3"; do
  want_rc 1 "wall sensed mid-move: $mv" "$S" --maze mazes/gen-5x5-s1.txt --json \
    --mms "$A/script.py 'wallFront=false' '$mv=crash' 'getStat total-distance=1' 'getStat total-effective-distance=1' 'wallFront=true' 'wallBack=false'"
  grep -q '^algo: script: 6 checks ok$' "$T/err" && [ "$(py "(d['mms']['crashes'], d['mms']['moves'], abs(d['final_pose']['y_m'] - 0.27) < 0.01, abs(d['final_pose']['x_m'] - 0.09) < 0.01)")" = "(1, 1, True, True)" ] \
    && ok "wall sensed mid-move: $mv: crash at the centre of the last free cell" || bad "wall sensed mid-move: $mv: $(cat "$T/err" "$T/out")"
done

# turned round on a boundary: back into the cell it came from (queries facing back, a refused
# move through the start's south wall, mms's run rules: back at the start ends the run)
want_rc 1 "turned round on a boundary" "$S" --maze mazes/gen-5x5-s1.txt --json \
  --mms "$A/script.py 'moveForwardHalf=ack' 'turnLeft=ack' 'turnLeft=ack' 'wallFront=false' 'wallFront 2=true' 'wallLeft=true' 'wallFrontLeft=true' 'wallFrontRight=true' 'moveForwardHalf 3=crash' 'moveForwardHalf=ack' 'wallFront=true' 'turnLeft=ack' 'turnLeft=ack' 'moveForwardHalf 3=crash' 'moveForwardHalf 2=ack' 'wallFront=true' 'wallLeft=true' 'wallRight=false' 'getStat total-distance=2' 'getStat total-effective-distance=2' 'getStat current-run-distance=1'"
grep -q '^algo: script: 21 checks ok$' "$T/err" && [ "$(py "(d['collisions'], abs(d['final_pose']['y_m'] - 0.27) < 0.01)")" = "(0, True)" ] \
  && ok "turned round on a boundary: answers, stats, at (0,1)" || bad "turned round on a boundary: $(cat "$T/err" "$T/out")"

# a robot longer than the firmware thinks (150 mm, not 120): its turns sweep 89 mm and touch the walls
sed 's/^body_l_mm *=.*/body_l_mm = 150/' robots/paper.ini >"$T/long.ini"
want_rc 0 "a robot too long for its turns" "$S" --maze mazes/gen-5x5-s1.txt --robot "$T/long.ini" --mms "$A/wallfollow.py" --json
[ "$(py "(d['reached_goal'], d['collisions'] > 0, d['mms']['wall_contacts'] == d['collisions'])")" = "(True, True, True)" ] \
  && ok "physical wall contacts in the JSON ($(py "d['collisions']"))" || bad "wall contacts: $(cat "$T/out")"

# a robot too weak to move (0.5 V battery): the firmware's stall stop answers crash and ends the run
sed 's/^ocv_v *=.*/ocv_v = 0.5/' robots/paper.ini >"$T/weak.ini"
want_rc 1 "stuck robot" "$S" --maze mazes/gen-5x5-s1.txt --robot "$T/weak.ini" --mms "$A/floodfill.py" --json
[ "$(py "(d['exit_reason'], d['mms']['crashes'], d['reached_goal'])")" = "('crash_stop', 1, False)" ] && grep -q "^mmsim: mms: the robot is stuck (motion stall) during a forward move: run ended$" "$T/err" \
  && ok "stuck robot: crash_stop, one message" || bad "stuck robot: $(cat "$T/out" "$T/err")"

# faults: the run ends with one message, the JSON summary, the child reaped
fault() { local rc=$1 reason=$2 desc=$3; shift 3
  want_rc "$rc" "fault: $desc" "$S" --maze mazes/gen-5x5-s1.txt --json --mms-timeout-ms 300 --mms "$@"
  [ "$(py "d['exit_reason']")" = "$reason" ] && ok "fault: $desc -> $reason" || bad "fault: $desc: $(cat "$T/out")"
  if [ "$rc" = 3 ]; then [ "$(wc -l <"$T/err")" -ge 1 ] && grep -q "^mmsim: mms: " "$T/err" && ok "fault: $desc: message" || bad "fault: $desc: no message"; fi
  [ "$(py "d['mms']['exit_status'] is not None or d['mms']['exit_signal'] is not None")" = True ] && ok "fault: $desc: child reaped" || bad "fault: $desc: not reaped"
}
fault 1 mms_exited "exits at once" "exit 0"
fault 3 mms_failed "exits with status 7" "exit 7"
fault 3 mms_failed "command not found" "$T/no-such-algorithm"
fault 3 mms_failed "killed by a signal" 'kill -9 $$'
fault 3 mms_timeout "hangs" "sleep 31.4159"
fault 3 mms_failed "closes its output and hangs" "exec >&-; sleep 31.4158"
fault 3 mms_flood "floods stdout with invalid lines" "yes"
fault 3 mms_timeout "floods queries without reading answers" "yes mazeWidth"
fault 3 mms_garbage "prints an endless line" "cat /dev/zero"
fault 3 mms_failed "crashes mid-run" "$A/wallfollow.py & sleep 0.2; kill -9 \$!; exit 9"
# the shell exits but leaves a process behind (its group is killed all the same)
left() { sleep 0.2; if pgrep -f "sleep $1" >/dev/null; then bad "$2: a process left running"; else ok "$2: nothing left running"; fi; }
fault 1 mms_exited "exits, a background process without its pipes" "sleep 31.4103 >/dev/null </dev/null & exit 0"
left 31.4103 "background process without pipes"
fault 3 mms_timeout "exits, a background process holds its output" "sleep 31.4101 & exit 0"
grep -q "^mmsim: mms: the algorithm 'sleep 31.4101 & exit 0' exited with status 0, but a process it started keeps its output open and sent no command for 300 ms$" "$T/err" \
  && ok "background process holds the output: message" || bad "background process holds the output: $(cat "$T/err")"
left 31.4101 "background process holding the output"
# mmsim itself killed (SIGTERM): the algorithm's process group goes too
"$S" --maze mazes/gen-5x5-s1.txt --mms "sleep 31.4157" --mms-timeout-ms 60000 >"$T/out" 2>"$T/err" & mp=$!
for _ in $(seq 50); do pgrep -f "sleep 31.4157" >/dev/null && break; sleep 0.1; done
kill -TERM $mp; wait $mp; rc=$?
[ $rc -eq 143 ] && ok "mmsim killed: dies of the signal" || bad "mmsim killed: exit $rc"
sleep 0.2
if pgrep -f "sleep 31.415[789]" >/dev/null; then bad "no processes left behind"; pgrep -fa "sleep 31.415"; else ok "no processes left behind"; fi

# what the algorithm starts in a new session (setsid) or leaves orphaned goes too, checked by
# pid: after the run's end, and after SIGKILL of mmsim (its guardian ends the tree)
alive() { [ -r "/proc/$1/stat" ] && ! grep -q '^[0-9]* (.*) Z ' "/proc/$1/stat"; }
pids_gone() { local desc=$1 f p left=""; shift
  for f in "$@"; do
    p=$(cat "$f" 2>/dev/null); [ -n "$p" ] || { bad "$desc: no pid in $f"; continue; }
    for _ in $(seq 40); do alive "$p" || break; sleep 0.05; done
    alive "$p" && { left="$left $p"; kill -KILL "$p" 2>/dev/null; }
  done
  [ -z "$left" ] && ok "$desc: gone" || bad "$desc: left running:$left"; }
want_rc 1 "algorithm starts a process in a new session, then exits" "$S" --maze mazes/gen-5x5-s1.txt --json --mms-timeout-ms 2000 \
  --mms "setsid sh -c 'echo \$\$ >$T/sid1; exec sleep 30.4201' </dev/null >/dev/null 2>&1 & (setsid sh -c 'echo \$\$ >$T/sid2; exec sleep 30.4202' </dev/null >/dev/null 2>&1 &); while [ ! -s $T/sid1 ] || [ ! -s $T/sid2 ]; do sleep 0.05; done; exit 0"
pids_gone "new session and orphan after the run" "$T/sid1" "$T/sid2"
rm -f "$T"/sid*
"$S" --maze mazes/gen-5x5-s1.txt --mms-timeout-ms 60000 \
  --mms "echo \$\$ >$T/sh; setsid sh -c 'echo \$\$ >$T/sid3; exec sleep 30.4203' </dev/null >/dev/null 2>&1 & sleep 30.4204 & echo \$! >$T/bg; wait" >"$T/out" 2>"$T/err" & mp=$!
for _ in $(seq 100); do [ -s "$T/sid3" ] && [ -s "$T/bg" ] && break; sleep 0.05; done
kill -KILL $mp; wait $mp 2>/dev/null
pids_gone "shell, its child and a new session after SIGKILL of mmsim" "$T/sh" "$T/bg" "$T/sid3"

# the algorithm's stderr: each line as "algo: LINE", control bytes escaped, so it cannot
# forge or hide a line of ours; the same in the --verbose trace
want_rc 1 "stderr of the algorithm" "$S" --maze mazes/gen-5x5-s1.txt \
  --mms "printf 'one\\033[2J\\rmmsim: forged\\nsnow \\342\\230\\203 \\342\\200\\256rtl\\ntab\\there\\\\\\nno newline' >&2; exit 0"
grep -q '^mmsim: forged' "$T/err" && bad "stderr: a forged line got through: $(cat -v "$T/err")" || ok "stderr: no forged line"
[ "$(grep '^algo: ' "$T/err")" = "$(printf 'algo: one\\x1B[2J\\x0Dmmsim: forged\nalgo: snow \342\230\203 \\xE2\\x80\\xAErtl\nalgo: tab\\x09here\\\\\nalgo: no newline')" ] \
  && ok "stderr: escaped lines, printable UTF-8 kept, a last line without a newline" || bad "stderr lines: $(cat -v "$T/err")"
want_rc 1 "trace of an odd command" "$S" --maze mazes/gen-5x5-s1.txt --verbose --mms "printf 'mazeWidth\\033]0;x\\007\\n'; exit 0"
grep -q '^mms  *[0-9.]* > (ignored) mazeWidth\\x1B\]0;x\\x07$' "$T/err" && ! grep -q "$(printf '\033')" "$T/err" \
  && ok "trace: the algorithm's line escaped" || bad "trace: $(cat -v "$T/err")"

# bad flags
ONE_ERROR_LINE=1
want_rc 2 "--mms-ideal-walls needs --mms" "$S" --maze mazes/gen-5x5-s1.txt --mms-ideal-walls
want_rc 2 "--mms with --driver scripted" "$S" --maze mazes/gen-5x5-s1.txt --mms true --driver scripted
want_rc 2 "--mms-timeout-ms 0" "$S" --maze mazes/gen-5x5-s1.txt --mms true --mms-timeout-ms 0
want_rc 2 "--mms ''" "$S" --maze mazes/gen-5x5-s1.txt --mms ''
want_rc 2 "--mms with --batch" "$S" --batch mazes --mms true
[ $fails -eq 0 ]

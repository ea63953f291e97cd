#!/usr/bin/env bash
# run.sh: alone (timed: real-time runs, timed input or timeouts)
# cli_mmsim.sh - the headless simulator: JSON keys, determinism, lap table,
# zero wall contacts on generated mazes, config errors, exit codes, batch.
set -u
S=${MMSIM:-build/mmsim}
T=$(mktemp -d); trap 'rm -rf "$T"' EXIT
. "$(dirname "$0")/lib.sh"
py() { python3 -c "import json,sys; d=json.loads(open('$T/out').read().splitlines()[-1]); print($1)"; }

want_rc 0 "run 8x8 json" "$S" --maze mazes/gen-8x8-s1.txt --driver scripted --runs 2 --json --seed 5
[ "$(py "sorted(d.keys())")" = "['best_run_s', 'collisions', 'config_hash', 'driver', 'exit_reason', 'final_pose', 'first_run_s', 'laps', 'maze', 'reached_goal', 'real_time_factor', 'seed', 'sim_time_s', 'wall_time_s']" ] && ok "json keys" || bad "json keys: $(cat "$T/out")"
[ "$(py "(d['reached_goal'], d['collisions'], len(d['laps']), d['exit_reason'], d['seed'])")" = "(True, 0, 2, 'done', 5)" ] && ok "two laps, no contact" || bad "laps: $(cat "$T/out")"
[ "$(py "all(abs(l['run_s'] - (l['end_s'] - l['start_s'])) < 0.0015 for l in d['laps']) and d['best_run_s'] == min(l['run_s'] for l in d['laps'])")" = True ] && ok "lap arithmetic" || bad "lap arithmetic"
cp "$T/out" "$T/a"; "$S" --maze mazes/gen-8x8-s1.txt --driver scripted --runs 2 --json --seed 5 >"$T/b"
[ "$(strip "$T/a")" = "$(strip "$T/b")" ] && ok "deterministic" || bad "deterministic"

want_rc 0 "text lap table" "$S" --maze mazes/gen-6x6-s1.txt --driver scripted --runs 1
grep -q '^Lap   Start time  End time    Run time' "$T/out" && grep -q '^1     0:00.000' "$T/out" && ok "lap table" || bad "lap table: $(cat "$T/out")"

# the default driver is the mouse's firmware; --runs N: N speed runs after the search
want_rc 0 "default driver, one speed run" "$S" --maze mazes/gen-8x8-s1.txt --runs 1 --json
[ "$(py "(d['driver'], len(d['laps']), d['final_path_optimal'], d['exit_reason'])")" = "('firmware', 2, True, 'done')" ] && ok "firmware by default, --runs 1: search + 1 speed run" || bad "default driver: $(cat "$T/out")"
want_rc 0 "firmware, five speed runs" "$S" --maze mazes/gen-5x5-s1.txt --runs 5 --json
[ "$(py "len(d['laps'])")" = 6 ] && ok "--runs 5: search + 5 speed runs" || bad "--runs 5: $(cat "$T/out")"

# config: print -> load gives the same hash; errors with FILE:LINE
"$S" --print-config >"$T/cfg.ini"
want_rc 0 "run with printed config" "$S" --maze mazes/gen-5x5-s1.txt --runs 1 --json --config "$T/cfg.ini"
h1=$(py "d['config_hash']"); "$S" --maze mazes/gen-5x5-s1.txt --runs 1 --json >"$T/out"; h2=$(py "d['config_hash']")
[ "$h1" = "$h2" ] && ok "config hash stable" || bad "config hash"
printf '[sim]\nstep_s = 0.001\nwarp = 9\n' >"$T/bad.ini"
want_rc 2 "unknown config key" "$S" --maze mazes/gen-5x5-s1.txt --config "$T/bad.ini"
grep -q "^$T/bad.ini:3: sim.warp: unknown key$" "$T/err" && ok "config error line" || bad "config error line: $(cat "$T/err")"
# a robot's number in a config file: where it belongs now
printf '[world]\ncell_m = 0.18\n[motor]\nbattery_v = 7.4\n' >"$T/old.ini"
want_rc 2 "a robot key in a config" "$S" --maze mazes/gen-5x5-s1.txt --config "$T/old.ini"
[ "$(cat "$T/err")" = "$T/old.ini:4: motor.battery_v: a robot's number: it belongs in the robot file (--robot FILE, docs/ROBOTS.md)" ] \
  && ok "a robot key in a config: one line to the robot file" || bad "robot key in a config: $(cat "$T/err")"
printf '[world]\nbody_wall_mu = 0.4\n' >"$T/v.ini"
"$S" --maze mazes/gen-5x5-s1.txt --runs 1 --json --config "$T/v.ini" >"$T/out"; h3=$(py "d['config_hash']")
[ "$h3" != "$h2" ] && ok "config hash changes" || bad "config hash changes"

# bad input and unreachable goals
want_rc 2 "missing maze" "$S" --maze "$T/none.txt"
want_rc 2 "bad flag" "$S" --maze mazes/gen-5x5-s1.txt --warp
want_rc 2 "bad seed" "$S" --maze mazes/gen-5x5-s1.txt --seed x
want_rc 2 "no maze" "$S"
want_rc 2 "bad driver" "$S" --maze mazes/gen-5x5-s1.txt --driver warp
grep -q "^mmsim: --driver: expected firmware or scripted, got 'warp'" "$T/err" && ok "driver error line" || bad "driver error line: $(cat "$T/err")"
want_rc 2 "bad profile" "$S" --maze mazes/gen-5x5-s1.txt --profile ice
want_rc 2 "bad centre post" "$S" --maze mazes/gen-5x5-s1.txt --centre-post maybe
want_rc 2 "bad time limit" "$S" --maze mazes/gen-5x5-s1.txt --time-limit 0
printf 'o---o---o---o\n| S |   |   |\no---o---o---o\n' >"$T/closed.txt"
want_rc 1 "unreachable goal" "$S" --maze "$T/closed.txt" --driver scripted --json
[ "$(py "(d['reached_goal'], d['exit_reason'])")" = "(False, 'unreachable')" ] && ok "unreachable reported" || bad "unreachable reported"
want_rc 1 "time limit" "$S" --maze mazes/gen-16x16-s1.txt --time-limit 5 --json
[ "$(py "d['exit_reason']")" = "time_limit" ] && ok "time_limit reason" || bad "time_limit reason: $(cat "$T/out")"

# batch: one line per maze, input order, worst exit code
mkdir "$T/batch"; cp mazes/gen-5x5-s1.txt "$T/batch/a.txt"; cp "$T/closed.txt" "$T/batch/b.txt"; cp mazes/gen-6x6-s1.txt "$T/batch/c.txt"
want_rc 1 "batch worst code" "$S" --batch "$T/batch" --jobs 2 --runs 1
[ "$(python3 -c "import json; print([json.loads(l)['maze'].split('/')[-1] for l in open('$T/out')])")" = "['a.txt', 'b.txt', 'c.txt']" ] && ok "batch order" || bad "batch order: $(cat "$T/out")"
# a bad maze in a batch still has its line (no_result, its exit code), in order
mkdir "$T/b9"; for i in 1 2 3 4 6 7 8 9; do cp mazes/gen-5x5-s1.txt "$T/b9/m$i.txt"; done
printf 'o---o\n| x |\n' >"$T/b9/m5.txt"
want_rc 2 "batch with a bad maze" "$S" --batch "$T/b9" --jobs 2 --runs 1
[ "$(python3 -c "import json; print([(json.loads(l)['maze'][-6:], json.loads(l)['exit_reason'], json.loads(l).get('exit_code')) for l in open('$T/out')])")" = "[('m1.txt', 'done', None), ('m2.txt', 'done', None), ('m3.txt', 'done', None), ('m4.txt', 'done', None), ('m5.txt', 'no_result', 2), ('m6.txt', 'done', None), ('m7.txt', 'done', None), ('m8.txt', 'done', None), ('m9.txt', 'done', None)]" ] && ok "batch: one line per maze in order, the bad one too" || bad "batch with a bad maze: $(cat "$T/out")"
grep -q "m5.txt:2:3: stray character 'x'" "$T/err" && ok "batch: the bad maze's error line" || bad "batch error line: $(cat "$T/err")"
# SIGTERM to a batch: its running jobs end too (checked by pid), then it dies of the signal
mkdir "$T/slow"; for i in 1 2 3; do cp mazes/gen-16x16-s1.txt "$T/slow/m$i.txt"; done
"$S" --batch "$T/slow" --jobs 2 --realtime --driver scripted >"$T/out" 2>"$T/err" & bp=$!
for _ in $(seq 100); do [ "$(pgrep -P $bp | wc -l)" -ge 2 ] && break; sleep 0.1; done
kids=$(pgrep -P $bp | tr '\n' ' ')
kill -TERM $bp
timeout 10 bash -c "while kill -0 $bp 2>/dev/null; do sleep 0.05; done"; wait $bp; rc=$?
sleep 0.2; left=""
for k in $kids; do [ -d /proc/$k ] && left="$left $k"; done
[ $rc -eq 143 ] && [ -n "$kids" ] && [ -z "$left" ] && ok "SIGTERM to a batch: its jobs ($kids) end, it dies of the signal" \
  || { bad "SIGTERM to a batch: exit $rc, jobs '$kids', left running:$left"; kill -KILL $left 2>/dev/null; }

# bad numbers and combinations: one error line, exit 2
ONE_ERROR_LINE=1
for a in "--runs 0" "--runs 65" "--runs 1.5" "--runs x" "--jobs 0" "--jobs 2.5" "--runs 0x10" "--runs ' 2'" "--runs +2" "--runs 1e1" "--time-limit inf" "--seed 0x10" "--lcm-rate ' 100'"; do
  eval "want_rc 2 \"bad number: $a\" \"\$S\" --maze mazes/gen-5x5-s1.txt $a"
done
grep -q "^mmsim: --lcm-rate: expected a number from 1 to 1000, got ' 100'$" "$T/err" && ok "number error line" || bad "number error line: $(cat "$T/err")"
for a in 4294967360x64 64x4294967360 0x10x64 " 64x64" "64x64 " 64x +64x64; do
  want_rc 2 "bad --size '$a'" "$S" --maze mazes/gen-5x5-s1.txt --screenshot "$T/s.png" --size "$a"
done
want_rc 2 "--maze with --batch" "$S" --batch "$T/batch" --maze mazes/gen-5x5-s1.txt
grep -q "^mmsim: --maze and --batch: one at a time" "$T/err" && ok "--maze with --batch: error line" || bad "--maze with --batch: $(cat "$T/err")"
ONE_ERROR_LINE=0

# the firmware in the loop: search, prove, speed runs on small mazes
for m in gen-5x5-s1 gen-8x8-s1 gen-16x16-s1 gen-16x16-s2; do
  want_rc 0 "firmware contest $m" "$S" --maze mazes/$m.txt --driver firmware --json
  [ "$(py "(d['driver'], d['reached_goal'], d['final_path_optimal'], d['exit_reason'], len(d['laps']) >= 2, d['best_run_s'] <= d['first_run_s'], d['collisions'])")" = "('firmware', True, True, 'done', True, True, 0)" ] && ok "firmware $m proven and raced, no wall touched" || bad "firmware $m: $(cat "$T/out")"
done
"$S" --maze mazes/gen-5x5-s1.txt --driver firmware --json >"$T/f1"; "$S" --maze mazes/gen-5x5-s1.txt --driver firmware --json >"$T/f2"
[ "$(strip "$T/f1")" = "$(strip "$T/f2")" ] && ok "firmware run deterministic" || bad "firmware run deterministic"
# a full-size contest: japan2019 seed 4 touched a wall (a staircase of smooth
# turns with no side walls in the first speed run; in-place U-turns) before
# the heading fix from the wall ahead at stops and the gentler turn entry
DB=${SHARED:-../shared}/mazes/classic
if [ -f "$DB/japan2019.txt" ]; then
  want_rc 0 "firmware contest japan2019 seed 4" "$S" --maze "$DB/japan2019.txt" --driver firmware --seed 4 --json
  [ "$(py "(d['reached_goal'], d['final_path_optimal'], d['exit_reason'], len(d['laps']) >= 2, d['collisions'])")" = "(True, True, 'done', True, 0)" ] && ok "firmware japan2019 seed 4 proven and raced, no wall touched" || bad "firmware japan2019 seed 4: $(cat "$T/out")"
else
  echo "SKIP cli_mmsim japan2019 firmware contest: $DB/japan2019.txt not found"
fi
want_rc 1 "firmware, goal unreachable" "$S" --maze "$T/closed.txt" --driver firmware --json
[ "$(py "d['exit_reason']")" = "unreachable" ] && ok "firmware reports unreachable" || bad "firmware unreachable: $(cat "$T/out")"
[ $fails -eq 0 ]

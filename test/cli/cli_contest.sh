#!/usr/bin/env bash
# cli_contest.sh - mmsim --contest NAME|FILE (contests/*.ini): for each
# scoring rule a scripted run whose JSON score is the rule applied to the
# same JSON's laps (run time, search time, touches, the runs and time limit
# that count); the maze geometry reaches the world (a half-size profile: 90 mm
# cells, on a ../shared/mazes/halfsize maze); the maze file's own goal marks
# win over the profile's goal; bad contest files are one FILE:LINE:COL line
# and exit 2; --print-contest's text loads back; no --contest, no "contest".
set -u
S=${MMSIM:-build/mmsim}
SHARED=${SHARED:-../shared}
T=$(mktemp -d); trap 'rm -rf "$T"' EXIT
. "$(dirname "$0")/lib.sh"
M16=mazes/gen-16x16-s1.txt
M5=mazes/gen-5x5-s1.txt

# check_score FILE: the "contest" object's score is its rule applied to the
# laps of the same JSON; prints "ok" or what differs.
check_score() { python3 - "$1" <<'PY'
import json, math, sys
d = json.loads(open(sys.argv[1]).read().splitlines()[-1])
c, laps = d["contest"], d["laps"]
runs = c["run_scores"]
assert len(runs) == len(laps), ("runs", len(runs), len(laps))
best = None
for lap, r in zip(laps, runs):
    assert r["lap"] == lap["lap"] and r["run_s"] == lap["run_s"] and r["search_s"] == lap["start_s"], (r, lap)
    s = r["run_s"] + r["touches"] * c["touch_penalty_s"]
    if c["scoring"] == "run_plus_search":
        s += r["search_s"] / c["search_divisor"]
    else:
        assert c["scoring"] == "best_run" and c["search_divisor"] == 0, c
    s = math.floor(s * 1000 + 0.5) / 1000  # to 1 ms, halves up, as C's round() on these positive figures
    assert abs(r["score_s"] - s) < 1e-9, (r, s)
    over = lap["end_s"] > c["time_limit_s"]
    counts = (c["runs"] == 0 or lap["lap"] <= c["runs"]) and not over
    assert r["counts"] == counts, (r, counts)
    if counts and (best is None or s < best[0]):
        best = (s, lap["lap"])
want = (None, None) if best is None else best
assert (c["score_s"], c["score_lap"]) == want, ((c["score_s"], c["score_lap"]), want)
print("ok")
PY
}
# jv FILE EXPR: a Python expression over the last JSON line d
jv() { python3 -c "import json,sys; d=json.loads(open(sys.argv[1]).read().splitlines()[-1]); v=($2); print(v)" "$1"; }

# best_run (classic-japan): 3 scripted runs, the score is the fastest
want_rc 0 "classic-japan: scripted, 3 runs" "$S" --maze $M16 --driver scripted --runs 3 --contest classic-japan --json
r=$(check_score "$T/out" 2>&1); [ "$r" = ok ] && ok "best_run: the score is the fastest counted run of the JSON's laps" || bad "best_run: $r"
[ "$(jv "$T/out" "d['contest']['name'], d['contest']['scoring'], len(d['laps']), d['contest']['score_s'] == min(l['run_s'] for l in d['laps'])")" = "('classic-japan', 'best_run', 3, True)" ] \
  && ok "best_run: name, rule, 3 laps, score = the best lap" || bad "best_run: $(jv "$T/out" "d['contest']")"

# the number of runs: a profile counting 2, a mouse making 3: the third does not count
sed 's/^runs = 5$/runs = 2/' contests/classic-japan.ini >"$T/two.ini"
want_rc 0 "runs = 2: scripted, 3 runs" "$S" --maze $M16 --driver scripted --runs 3 --contest "$T/two.ini" --json
r=$(check_score "$T/out" 2>&1); [ "$r" = ok ] && ok "runs = 2: the score's rule holds" || bad "runs = 2: $r"
[ "$(jv "$T/out" "[r['counts'] for r in d['contest']['run_scores']], d['contest']['name']")" = "([True, True, False], 'two')" ] \
  && ok "runs = 2: the third run does not count" || bad "runs = 2: $(jv "$T/out" "d['contest']")"

# without --runs the contest's number of runs: the scripted driver makes 2, the text says the score
want_rc 0 "runs = 2 without --runs: scripted, text" "$S" --maze $M5 --driver scripted --contest "$T/two.ini"
grep -c '^[0-9]  ' "$T/out" | grep -qx 2 && grep -qE '^contest two \(best_run\): score [0-9.]+ s \(lap [12]\)$' "$T/out" \
  && ok "runs = 2 without --runs: 2 laps; the summary's contest line" || bad "runs without --runs: $(cat "$T/out")"

# the time limit: --time-limit over the profile's; a run that ends after it does not count
# (the contest ends at its limit before the third run: exit 1, as without --contest)
want_rc 1 "time limit 30 s: scripted, 3 runs" "$S" --maze $M16 --driver scripted --runs 3 --contest classic-uk --time-limit 30 --json
r=$(check_score "$T/out" 2>&1); [ "$r" = ok ] && ok "time limit: the score's rule holds" || bad "time limit: $r"
[ "$(jv "$T/out" "[r['counts'] for r in d['contest']['run_scores']], d['contest']['runs'], d['contest']['score_lap']")" = "([True, False], 0, 1)" ] \
  && ok "time limit: the run after it does not count (runs = 0: any number)" || bad "time limit: $(jv "$T/out" "d['laps'], d['contest']")"

# run_plus_search (apec): run + search/30 + 2 s a touch; a lift between runs 1 and 2
want_rc 0 "apec: scripted, 3 runs, a lift at 20 s" "$S" --maze $M16 --driver scripted --runs 3 --contest apec --input "20 lift; 20.5 place" --json
r=$(check_score "$T/out" 2>&1); [ "$r" = ok ] && ok "run_plus_search: every run's score and the lowest from the JSON's laps" || bad "run_plus_search: $r"
[ "$(jv "$T/out" "[r['touches'] for r in d['contest']['run_scores']], d['contest']['search_divisor'], d['contest']['touch_penalty_s'], d['contest']['score_lap']")" = "([0, 1, 1], 30.0, 2.0, 1)" ] \
  && ok "run_plus_search: the touch counts from run 2 on; 1/30 and 2 s from contests/apec.ini" || bad "apec: $(jv "$T/out" "d['contest']")"
[ "$(jv "$T/out" "all(r['score_s'] - r['run_s'] > 2 + 0.5 for r in d['contest']['run_scores'][1:])")" = True ] \
  && ok "run_plus_search: runs 2 and 3 score above their run time by the touch and the search share" || bad "apec shares: $(jv "$T/out" "d['contest']")"
# the same inputs, the same JSON (apart from the wall time)
cp "$T/out" "$T/apec1"
want_rc 0 "apec again" "$S" --maze $M16 --driver scripted --runs 3 --contest apec --input "20 lift; 20.5 place" --json
[ "$(strip "$T/out")" = "$(strip "$T/apec1")" ] && ok "apec: the same JSON twice" || bad "apec: two runs differ"
# our firmware under apec (a search, then 3 speed runs): the rule holds on its laps too
want_rc 0 "apec: our firmware" "$S" --maze $M16 --contest apec --json
r=$(check_score "$T/out" 2>&1); [ "$r" = ok ] && ok "run_plus_search on our firmware's search and speed runs" || bad "apec firmware: $r"
# other shares from a file: search/1 and 20 s a touch, a touch before the first run
sed -e 's/^search_divisor = 30$/search_divisor = 1/' -e 's/^touch_penalty_s = 2$/touch_penalty_s = 20/' contests/apec.ini >"$T/heavy.ini"
want_rc 0 "heavy shares: scripted, 2 runs" "$S" --maze $M16 --driver scripted --runs 2 --contest "$T/heavy.ini" --input "0.01 lift; 0.2 place" --json
r=$(check_score "$T/out" 2>&1); [ "$r" = ok ] && ok "run_plus_search (search/1, 20 s a touch): the rule holds" || bad "heavy: $r"
[ "$(jv "$T/out" "[r['touches'] for r in d['contest']['run_scores']], round(d['contest']['score_s'] - d['laps'][0]['run_s'], 3)")" = "([1, 1], 20.0)" ] \
  && ok "a touch before the first run: 20 s on every run" || bad "heavy: $(jv "$T/out" "d['contest']")"

# the maze file's goal marks win over the profile's goal; without marks the profile's goal is the goal
sed 's/^goal = 7,7 8,8$/goal = 0,1 0,1/' contests/classic-japan.ini >"$T/corner.ini"
want_rc 0 "profile goal 0,1, the file marks G at 2,2" "$S" --maze $M5 --driver scripted --runs 1 --contest "$T/corner.ini" --json
marked=$(jv "$T/out" "d['laps'][0]['run_s']")
sed 's/G/ /' $M5 >"$T/nog.txt"
want_rc 0 "profile goal 0,1, the file marks none" "$S" --maze "$T/nog.txt" --driver scripted --runs 1 --contest "$T/corner.ini" --json
plain=$(jv "$T/out" "d['laps'][0]['run_s']")
want_rc 0 "no contest, the file marks G at 2,2" "$S" --maze $M5 --driver scripted --runs 1 --json
base=$(jv "$T/out" "d['laps'][0]['run_s']")
[ "$marked" = "$base" ] && python3 -c "import sys; sys.exit(not float('$plain') < float('$marked') / 2)" \
  && ok "goal: the file's G marks win ($marked s as without --contest); unmarked, the profile's goal 0,1 ($plain s)" \
  || bad "goal: marked $marked, unmarked $plain, no contest $base"

# no --contest: no "contest" key (the JSON as before)
[ "$(jv "$T/out" "'contest' in d")" = False ] && ok "no --contest: no contest object" || bad "no --contest: $(cat "$T/out")"

# the world's numbers: a half-size profile sets 90 mm cells, 6 mm walls 25 mm high
# the paper robot scaled to fit a 84 mm corridor (50 mm wide and long, sensors inside)
python3 - robots/paper.ini "$T/half.ini" <<'PY'
import sys
s = open(sys.argv[1]).read()
for a, b in {"body_w_mm = 96": "body_w_mm = 50", "body_l_mm = 120": "body_l_mm = 60", "wheel_track_mm = 96": "wheel_track_mm = 50",
             "caster_y_mm = -55": "caster_y_mm = -25", "x_mm = -40": "x_mm = -20", "x_mm = 40": "x_mm = 20", "y_mm = 50": "y_mm = 25",
             "y_mm = 55": "y_mm = 27"}.items():
    assert a in s, a
    s = s.replace(a, b)
open(sys.argv[2], "w").write(s)
PY
want_rc 0 "--print-config --contest halfsize-japan" "$S" --print-config --contest halfsize-japan --robot "$T/half.ini"
grep -qx 'cell_m = 0.09 ; m; classic rules: 180 mm cells (half-size: 90 mm)' "$T/out" && grep -q '^wall_height_m = 0.025 ' "$T/out" && grep -q '^wall_thick_m = 0.006 ' "$T/out" \
  && ok "halfsize-japan: the world's cell_m 0.09, walls 6 mm x 25 mm" || bad "halfsize config: $(grep -E '^(cell|wall)' "$T/out")"
want_rc 2 "halfsize-japan with the paper robot: wider than a 84 mm corridor" "$S" --maze $M16 --contest halfsize-japan --driver scripted
grep -q "the robot is wider than a corridor (104 mm over its tyres, the corridor 84 mm)" "$T/err" && ok "halfsize-japan: the corridor is 90 - 6 mm" || bad "halfsize fit: $(cat "$T/err")"

# --print-contest: the resolved profile; it loads back and prints the same
want_rc 0 "--print-contest apec" "$S" --print-contest --contest apec
tail -n +2 "$T/out" >"$T/p1"; cp "$T/out" "$T/printed.ini"
want_rc 0 "printed contest loads" "$S" --print-contest --contest "$T/printed.ini"
tail -n +2 "$T/out" | cmp -s - "$T/p1" && grep -qx 'search_divisor = 30' "$T/p1" && grep -qx 'scoring = run_plus_search' "$T/p1" \
  && ok "--print-contest: loads back the same" || bad "--print-contest: $(diff <(tail -n +2 "$T/out") "$T/p1")"
for c in classic-japan classic-uk halfsize-japan apec; do
  want_rc 0 "shipped contest $c loads" "$S" --print-contest --contest $c
  # every key has a '; source:' line right above it
  python3 - contests/$c.ini <<'PY' && ok "$c: each key with its source line" || bad "$c: a key without a source line"
import sys
lines = open(sys.argv[1]).read().splitlines()
for i, l in enumerate(lines):
    if l and not l.startswith((";", "[")) and "=" in l:
        assert lines[i - 1].startswith("; source: "), l
PY
done
# the contests/ folder beside an installed mmsim (PREFIX/share/mmsim/contests), from another directory
mkdir -p "$T/prefix/bin" "$T/prefix/share/mmsim/contests" "$T/elsewhere"
cp "$S" "$T/prefix/bin/mmsim"; cp contests/apec.ini "$T/prefix/share/mmsim/contests/only-here.ini"
(cd "$T/elsewhere" && "$T/prefix/bin/mmsim" --print-contest --contest only-here >"$T/out" 2>"$T/err") \
  && grep -qx 'scoring = run_plus_search' "$T/out" && ok "--contest NAME: found in PREFIX/share/mmsim/contests" || bad "installed contest: $(cat "$T/err")"

# bad input: one FILE:LINE:COL line, exit 2
ONE_ERROR_LINE=1
sed 's/^cell_mm = 180$/cell_mm = 180\ncolour = red/' contests/classic-japan.ini >"$T/key.ini"
n=$(grep -n '^colour' "$T/key.ini" | cut -d: -f1)
want_rc 2 "unknown key" "$S" --maze $M16 --contest "$T/key.ini"
[ "$(cat "$T/err")" = "$T/key.ini:$n:1: maze.colour: unknown key" ] && ok "unknown key: FILE:LINE:COL" || bad "unknown key: $(cat "$T/err")"
sed 's/^cell_mm = 180$/cell_mm = 9000/' contests/classic-japan.ini >"$T/value.ini"
n=$(grep -n '^cell_mm' "$T/value.ini" | cut -d: -f1)
want_rc 2 "bad value" "$S" --maze $M16 --contest "$T/value.ini"
grep -q "^$T/value.ini:$n:11: maze.cell_mm: 9000 mm is out of range \[50, 500\]" "$T/err" && ok "bad value: FILE:LINE:COL at the value" || bad "bad value: $(cat "$T/err")"
sed 's/^heading = north$/heading = up/' contests/classic-japan.ini >"$T/word.ini"
n=$(grep -n '^heading' "$T/word.ini" | cut -d: -f1)
want_rc 2 "bad word" "$S" --print-contest --contest "$T/word.ini"
grep -q "^$T/word.ini:$n:11: maze.heading: 'up' is not one of north east south west" "$T/err" && ok "bad word: its choices" || bad "bad word: $(cat "$T/err")"
sed 's/^goal = 7,7 8,8$/goal = 7,7 16,8/' contests/classic-japan.ini >"$T/goal.ini"
n=$(grep -n '^goal' "$T/goal.ini" | cut -d: -f1)
want_rc 2 "goal outside the maze" "$S" --maze $M16 --contest "$T/goal.ini"
[ "$(cat "$T/err")" = "$T/goal.ini:$n:8: maze.goal: cells 7,7 16,8 reach outside the 16x16 maze" ] && ok "goal outside: FILE:LINE:COL" || bad "goal outside: $(cat "$T/err")"
sed 's/^goal = 7,7 8,8$/goal = 7,7/' contests/classic-japan.ini >"$T/rect.ini"
want_rc 2 "goal not a rectangle" "$S" --maze $M16 --contest "$T/rect.ini"
grep -q "^$T/rect.ini:$n:8: maze.goal: expected two corner cells X0,Y0 X1,Y1" "$T/err" && ok "goal: two corners wanted" || bad "goal rect: $(cat "$T/err")"
grep -v '^search_divisor' contests/apec.ini >"$T/share.ini"
n=$(grep -n '^scoring' "$T/share.ini" | cut -d: -f1)
want_rc 2 "run_plus_search without search_divisor" "$S" --maze $M16 --contest "$T/share.ini"
grep -q "^$T/share.ini:$n:11: rules.scoring: run_plus_search needs search_divisor" "$T/err" && ok "run_plus_search: needs its share" || bad "share: $(cat "$T/err")"
grep -v '^time_limit_s' contests/apec.ini >"$T/missing.ini"
want_rc 2 "a missing key" "$S" --maze $M16 --contest "$T/missing.ini"
grep -q "^$T/missing.ini: rules.time_limit_s: missing" "$T/err" && ok "a missing key: FILE: section.key" || bad "missing: $(cat "$T/err")"
printf '[maze]\nmax_width = 16\n  17\n' >"$T/cont.ini"
want_rc 2 "a continuation line" "$S" --maze $M16 --contest "$T/cont.ini"
grep -q "^$T/cont.ini:3:3: maze.max_width: an indented line" "$T/err" && ok "a continuation line: FILE:LINE:COL" || bad "continuation: $(cat "$T/err")"
printf '[scoring]\n' >"$T/sec.ini"
want_rc 2 "unknown section" "$S" --maze $M16 --contest "$T/sec.ini"
grep -q "^$T/sec.ini:1:1: \[scoring\]: unknown section" "$T/err" && ok "unknown section: FILE:LINE:COL" || bad "section: $(cat "$T/err")"
want_rc 2 "unknown contest name" "$S" --maze $M16 --contest olympic
grep -q "^mmsim: --contest olympic: no contests/NAME.ini of that name" "$T/err" && ok "unknown contest name: one line" || bad "name: $(cat "$T/err")"
want_rc 2 "a missing contest file" "$S" --maze $M16 --contest "$T/none.ini"
grep -q "^$T/none.ini: cannot open" "$T/err" && ok "missing file: FILE: reason" || bad "missing file: $(cat "$T/err")"
sed 's/^max_width = 16$/max_width = 4/;s/^goal = 7,7 8,8$/goal = 1,1 2,2/' contests/classic-japan.ini >"$T/small.ini"
want_rc 2 "a maze larger than the contest's" "$S" --maze $M5 --contest "$T/small.ini"
grep -q "^$M5: a 5x5 maze, larger than contest small's 4x16" "$T/err" && ok "maze larger than the contest's: one line" || bad "larger: $(cat "$T/err")"
want_rc 2 "--print-contest alone" "$S" --print-contest
grep -q "print-contest needs --contest" "$T/err" && ok "--print-contest needs --contest" || bad "print alone: $(cat "$T/err")"
ONE_ERROR_LINE=0

# a half-size maze of the database with the half-size profile: 90 mm cells in the world
H=$SHARED/mazes/halfsize/japan2019hef.txt
if [ ! -f "$H" ]; then
  echo "SKIP cli_contest: $H absent (the half-size maze database, ../shared/mazes); the other checks ran: $fails failed"
  [ $fails -eq 0 ] && exit 77 || exit 1
fi
want_rc 0 "halfsize-japan on $H: scripted, 1 run" "$S" --maze "$H" --robot "$T/half.ini" --driver scripted --runs 1 --contest halfsize-japan --json
r=$(check_score "$T/out" 2>&1); [ "$r" = ok ] && ok "halfsize: the score's rule holds" || bad "halfsize: $r"
# back home in the start cell of a 90 mm pitch: x within (0, 0.09) m
[ "$(jv "$T/out" "d['reached_goal'], 0 < d['final_pose']['x_m'] < 0.09, 0 < d['final_pose']['y_m'] < 0.09, d['contest']['name']")" = "(True, True, True, 'halfsize-japan')" ] \
  && ok "halfsize: the goal reached and back in the 90 mm start cell" || bad "halfsize run: $(jv "$T/out" "d['laps'], d['final_pose'], d['exit_reason']")"
echo "$fails failed"
[ $fails -eq 0 ]

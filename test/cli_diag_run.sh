#!/usr/bin/env bash
# cli_diag_run.sh - the example firmware's speed runs on plan_run's moves
# (firmware/plan.c: straights, diagonals and slaloms; firmware/mouse.c
# drives them). uk2011follower (seed 1): the mouse reaches the goal without
# touching a wall, its best run follows a plan with diagonal moves (the
# firmware's log line "run N: M moves, D diagonal, V mm/s turns") and beats
# the best of the orthogonal runs, 23.436 s (smooth 90s only, main e1bfe63,
# the same inputs). japan2019 (staircases, seed 1): every speed run is a
# planned one and none touches a wall.
set -u
S=${MMSIM:-build/mmsim}
T=$(mktemp -d); trap 'rm -rf "$T"' EXIT
. "$(dirname "$0")/lib.sh"
command -v python3 >/dev/null || { echo "SKIP cli_diag_run: python3 missing"; exit 77; }
DB=${SHARED:-../shared}/mazes/classic
[ -f "$DB/uk2011follower.txt" ] && [ -f "$DB/japan2019.txt" ] || { echo "SKIP cli_diag_run: $DB not found"; exit 77; }

# check JSON LOG DIAG BOUND: goal, no contact, every speed run planned; the
# best one with diagonal moves (DIAG 1) and under BOUND s (0: no bound)
check() {
python3 - "$1" "$2" "$3" "$4" <<'PY'
import json, re, sys
j = json.loads(open(sys.argv[1]).read().splitlines()[-1])
log = open(sys.argv[2]).read()
want_diag, bound = sys.argv[3] == "1", float(sys.argv[4])
assert j["reached_goal"] and j["collisions"] == 0, ("collisions", j["collisions"])
laps = j["laps"][1:]  # the first lap is the search
assert laps, "no speed run"
plans = {int(m.group(1)): m.group(0) for m in re.finditer(r"^run (\d+): \d+ moves, (\d+) diagonal, \d+ mm/s turns$", log, re.M)}
assert all(l["lap"] - 1 in plans for l in laps), "a speed run without a plan: %s" % sorted(plans)
best = min(laps, key=lambda l: l["run_s"])
run = best["lap"] - 1
if want_diag:
    assert int(re.search(r"(\d+) diagonal", plans[run]).group(1)) > 0, "best run %d has no diagonal move: %s" % (run, plans[run])
if bound > 0:
    assert best["run_s"] < bound, "best run %.3f s, not below the orthogonal %.3f s" % (best["run_s"], bound)
print("best run %d: %.3f s, %s" % (run, best["run_s"], plans[run]))
PY
}

want_rc 0 "uk2011follower: goal reached" "$S" --maze "$DB/uk2011follower.txt" --seed 1 --json --verbose
check "$T/out" "$T/err" 1 23.436 >"$T/msg" 2>&1 && ok "uk2011follower: $(cat "$T/msg")" || bad "uk2011follower: $(cat "$T/msg")"

want_rc 0 "japan2019: goal reached" "$S" --maze "$DB/japan2019.txt" --seed 1 --json --verbose
check "$T/out" "$T/err" 0 0 >"$T/msg" 2>&1 && ok "japan2019: $(cat "$T/msg")" || bad "japan2019: $(cat "$T/msg")"

[ $fails -eq 0 ] && echo "cli_diag_run: all ok" || { echo "cli_diag_run: $fails failed"; exit 1; }

#!/usr/bin/env bash
# cli_planned_runs.sh - the example firmware's speed runs on plan_run's
# moves (firmware/plan.c picks straights, diagonals and slaloms by time;
# firmware/slalom.c sizes the slaloms; firmware/mouse.c drives them). On
# japan2019 (staircases) and uk2011follower, seed 1: the mouse reaches the
# goal without touching a wall, every speed run follows a plan (the
# firmware's log line "run N: M moves, D diagonal, V mm/s turns"), with no
# diagonal move (robot_config.h RC_DIAG_*: the paper robot's wheels pass the
# posts 3.1 mm off on a diagonal, so at its 400 mm/s on diagonals the
# planner finds none worth driving), the runs climb (the first at the safe
# S90 speed RC_SLALOM_SAFE_MM_S 350, the later ones, each after a clean
# run, at RC_SLALOM_FAST_MM_S 390; the other turn kinds at their own
# speeds), and the best run is within 1 % of the measured one (24.463 s and
# 21.088 s; with every turn at the S90's speed 24.663 s and 21.421 s; the
# orthogonal runs, on hinged wheels, smooth 90s only at 650 mm/s: 27.028 s
# and 23.454 s).
set -u
S=${MMSIM:-build/mmsim}
T=$(mktemp -d); trap 'rm -rf "$T"' EXIT
. "$(dirname "$0")/lib.sh"
command -v python3 >/dev/null || { echo "SKIP cli_planned_runs: python3 missing"; exit 77; }
DB=${SHARED:-../shared}/mazes/classic
[ -f "$DB/uk2011follower.txt" ] && [ -f "$DB/japan2019.txt" ] || { echo "SKIP cli_planned_runs: $DB not found"; exit 77; }

# check JSON LOG BEST_S: goal, no contact, every speed run planned without
# diagonals, the first at 350 mm/s turns and the others at 390, the best
# one under 1.01 x BEST_S
check() {
python3 - "$1" "$2" "$3" <<'PY'
import json, re, sys
j = json.loads(open(sys.argv[1]).read().splitlines()[-1])
log = open(sys.argv[2]).read()
want = float(sys.argv[3])
assert j["reached_goal"] and j["collisions"] == 0, ("collisions", j["collisions"])
laps = j["laps"][1:]  # the first lap is the search
assert laps, "no speed run"
plans = {int(m.group(1)): (int(m.group(2)), m.group(0), int(m.group(3))) for m in re.finditer(r"^run (\d+): \d+ moves, (\d+) diagonal, (\d+) mm/s turns$", log, re.M)}
assert all(l["lap"] - 1 in plans for l in laps), "a speed run without a plan: %s" % sorted(plans)
assert all(d == 0 for d, _, _ in plans.values()), "a plan with diagonal moves: %s" % [p for _, p, _ in plans.values()]
climb = [plans[n][2] for n in sorted(plans)]
assert len(climb) >= 2 and climb[0] == 350 and all(v == 390 for v in climb[1:]), "turn speeds by run: %s" % climb
best = min(laps, key=lambda l: l["run_s"])
assert best["run_s"] < 1.01 * want, "best run %.3f s, not within 1 %% of %.3f s" % (best["run_s"], want)
print("best run %d: %.3f s (measured %.3f s), turns by run %s mm/s, %s" % (best["lap"] - 1, best["run_s"], want, climb, plans[best["lap"] - 1][1]))
PY
}

for m in "japan2019 24.463" "uk2011follower 21.088"; do
  set -- $m
  want_rc 0 "$1: goal reached" "$S" --maze "$DB/$1.txt" --seed 1 --json --verbose
  check "$T/out" "$T/err" "$2" >"$T/msg" 2>&1 && ok "$1: $(cat "$T/msg")" || bad "$1: $(cat "$T/msg")"
done

[ $fails -eq 0 ] && echo "cli_planned_runs: all ok" || { echo "cli_planned_runs: $fails failed"; exit 1; }

#!/usr/bin/env bash
# cli_ukbhost.sh - the firmware's host build for UKMARSBOT (build/ukb/mmsim:
# robots/ukmarsbot.ini's [firmware] with its host-only speed-run figures, the
# planner of plan.c, robots/ukmarsbot.ini's IR wall sensors read lit minus
# dark): on mazes/gen-8x8-s26.txt a contest of the search and two speed
# runs reaches the goal with no contact; the first speed run (the safe
# figures) plans no diagonal, the second (the fast ones, after a clean
# run) drives F45, a diagonal straight, two V90s and D45 (5 diagonal
# moves); first run 39.332 s, best 7.855 s, the path proven at step 43.
set -u
B=${BUILD:-build}
UKB=${UKB_MMSIM:-$B/ukb/mmsim}
T=$(mktemp -d); trap 'rm -rf "$T"' EXIT
. "$(dirname "$0")/lib.sh"
mk() { env -u MAKEFLAGS -u MFLAGS -u MAKELEVEL make --no-print-directory B="$B" "$@"; }
[ -n "${UKB_MMSIM:-}" ] || want_rc 0 "make $UKB" mk "$UKB"

want_rc 0 "gen-8x8-s26: the contest, two speed runs (goal reached: exit 0)" \
  "$UKB" --maze mazes/gen-8x8-s26.txt --robot robots/ukmarsbot.ini --runs 2 --json --verbose
python3 - "$T/out" "$T/err" <<'PY' >"$T/msg" && ok "gen-8x8-s26: $(cat "$T/msg")" || bad "gen-8x8-s26: $(cat "$T/msg")"
import json, re, sys
j = json.loads(open(sys.argv[1]).read().splitlines()[-1])
log = open(sys.argv[1]).read() + open(sys.argv[2]).read()
runs = {int(m.group(1)): int(m.group(2)) for m in re.finditer(r"^run (\d+): \d+ moves, (\d+) diagonal", log, re.M)}
assert j["reached_goal"], "goal not reached"
assert sum(j["contacts"].values()) == 0 and j["collisions"] == 0, j["contacts"]
assert runs == {1: 0, 2: 5}, "diagonal moves per speed run: %s" % runs
got = (j["first_run_s"], j["best_run_s"], j["proven_at_step"], len(j["laps"]))
assert got == (39.332, 7.855, 43, 3), got
print("goal, no contact, diagonal moves per run %s, first run %s s, best %s s, proven at step %s" %
      (runs, j["first_run_s"], j["best_run_s"], j["proven_at_step"]))
PY

[ $fails -eq 0 ] && echo "cli_ukbhost: all ok" || { echo "cli_ukbhost: $fails failed"; exit 1; }

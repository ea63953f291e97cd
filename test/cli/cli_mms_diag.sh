#!/usr/bin/env bash
# cli_mms_diag.sh - mms 1.2's diagonal commands on the physically simulated
# robot: test/mms/diagonal.py (written for these tests) searches in whole
# cells, then drives the shortest known path with every corner cut by
# 45-degree turns and staircases as diagonals (turnLeft45, turnRight45,
# moveForward and moveForwardHalf on a diagonal), checks wallFront/wallLeft/
# wallRight N on the diagonals against its own map on mms's half-cell grid,
# sends a diagonal from a cell centre and one into a wall (both `crash`,
# nothing moving) and checks getStat against its own count of the run.
set -u
S=${MMSIM:-build/mmsim}
T=$(mktemp -d); trap 'rm -rf "$T"' EXIT
. "$(dirname "$0")/lib.sh"
command -v python3 >/dev/null || { echo "SKIP cli_mms_diag: python3 missing"; exit 77; }
A="python3 test/mms/diagonal.py"
py() { python3 -c "import json,sys; d=json.loads(open('$T/out').read().splitlines()[-1]); print($1)"; }

for m in gen-5x5-s1 gen-6x6-s1 gen-8x8-s1 gen-16x16-s1 gen-16x16-s2; do
  want_rc 0 "diagonals $m" "$S" --maze mazes/$m.txt --mms "$A" --json --verbose
  [ "$(py "(d['reached_goal'], d['exit_reason'], d['collisions'], d['mms']['exit_status'])")" = "(True, 'mms_exited', 0, 0)" ] \
    && ok "diagonals $m: the goal reached, no contact" || bad "diagonals $m: $(tail -1 "$T/out") $(grep 'diagonal.py' "$T/err")"
  # the algorithm's own count of the diagonal run: turns, cells, effective cells, crashes
  exp=$(sed -n 's/^algo: expect //p' "$T/err")
  got=$(py "'%d %g %g %d' % (d['mms']['stats']['best_run_turns'], d['mms']['stats']['best_run_distance'], d['mms']['stats']['best_run_effective_distance'], d['mms']['crashes'])")
  [ -n "$exp" ] && [ "$exp" = "$got" ] && ok "diagonals $m: stats as mms counts them ($got)" || bad "diagonals $m: stats $got, the algorithm counted '$exp'"
  for c in turnLeft45 turnRight45; do
    grep -q "^mms *[0-9.]* > $c\$" "$T/err" && grep -A1 "^mms *[0-9.]* > $c\$" "$T/err" | grep -q '< ack$' \
      && ok "diagonals $m: $c answered ack" || bad "diagonals $m: no $c answered ack"
  done
done
# gen-16x16-s1: every diagonal command in one run; the best run counts
# each 45-degree turn as a turn and a diagonal half step as half a cell
# (mms counts steps, not lengths)
want_rc 0 "gen-16x16-s1 again" "$S" --maze mazes/gen-16x16-s1.txt --mms "$A" --json --verbose
used=$(sed -n 's/^algo: used //p' "$T/err")
[ "$used" = "moveForward, moveForwardHalf, turnLeft45, turnRight45, wallFront N, wallLeft N, wallRight N" ] \
  && ok "gen-16x16-s1: every diagonal command sent ($used)" || bad "gen-16x16-s1: diagonal commands sent: '$used'"
grep -q '> wallLeft 3$' "$T/err" && grep -q '> wallRight 2$' "$T/err" && ok "gen-16x16-s1: wall queries of 2 and 3 half steps" \
  || bad "gen-16x16-s1: no wall queries with half steps"
[ "$(py "(d['mms']['stats']['best_run_turns'], d['mms']['stats']['best_run_distance'], d['mms']['crashes'])")" = "(14, 16, 2)" ] \
  && ok "gen-16x16-s1: best run 14 turns, 16 cells, two crashes refused" || bad "gen-16x16-s1 stats: $(tail -1 "$T/out")"
cp "$T/out" "$T/a"
"$S" --maze mazes/gen-16x16-s1.txt --mms "$A" --json >"$T/b" 2>/dev/null
[ "$(strip "$T/a")" = "$(strip "$T/b")" ] && ok "diagonal run deterministic" || bad "diagonal run deterministic"
# the maze file's walls answer the same as the robot's own sensing
want_rc 0 "gen-16x16-s1 ideal walls" "$S" --maze mazes/gen-16x16-s1.txt --mms "$A" --mms-ideal-walls --json
[ "$(py "(d['reached_goal'], d['collisions'], d['mms']['stats']['best_run_turns'], d['mms']['stats']['best_run_distance'], d['mms']['crashes'])")" = "(True, 0, 14, 16, 2)" ] \
  && ok "gen-16x16-s1 ideal walls: the same run" || bad "gen-16x16-s1 ideal walls: $(tail -1 "$T/out")"

[ $fails -eq 0 ] && echo "cli_mms_diag: all passed" || { echo "cli_mms_diag: $fails failed"; exit 1; }

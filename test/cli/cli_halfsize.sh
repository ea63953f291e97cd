#!/usr/bin/env bash
# cli_halfsize.sh - the firmware's 32x32 build for a half-size mouse
# (build/half/mmsim: robots/kerise-v5.ini, its [firmware] too) in
# 90 mm cells (mazes/halfsize-world.ini): on three half-size mazes of
# ../shared/mazes/halfsize, each with its own goal rectangle (the maze
# file's G marks, announced through hal_maze), it reaches the goal with no
# contact; its firmware's cell and wall are the maze config's. And the default build's 16x16 contest (its
# speed runs on plan_run's moves): on mazes/gen-16x16-s1.txt the centre
# goal in 13.509 s, best run 6.710 s (the first speed run 7.346 s, the later
# ones at the fast figures of robot_config.h RC_RUN_FAST_*, each turn kind
# at its own speed, RC_SLALOM_*_MM_S).
set -u
B=${BUILD:-build}
MMSIM=${MMSIM:-$B/mmsim}
HALF=${HALF_MMSIM:-$B/half/mmsim}
T=$(mktemp -d); trap 'rm -rf "$T"' EXIT
. "$(dirname "$0")/lib.sh"
SHARED=${SHARED:-../shared}
D=$SHARED/mazes/halfsize
[ -d "$D" ] || { echo "SKIP cli_halfsize: $D absent (the maze database: make mazes)"; exit 77; }
mk() { env -u MAKEFLAGS -u MFLAGS -u MAKELEVEL make --no-print-directory B="$B" "$@"; }
[ -n "${HALF_MMSIM:-}" ] || want_rc 0 "make $HALF" mk "$HALF"

# the firmware's maze (robots/kerise-v5.ini [firmware] cell_mm, wall_mm) is the maze config's
MKPROFILE=${MKPROFILE:-$B/mkprofile}
if [ -x "$MKPROFILE" ] && "$MKPROFILE" robots/kerise-v5.ini "$T/profile.h" 2>"$T/err"; then
  "$MMSIM" --print-config --config mazes/halfsize-world.ini --robot robots/kerise-v5.ini >"$T/cfg"
  python3 - "$T/profile.h" "$T/cfg" <<'PY' >"$T/msg" && ok "$(cat "$T/msg")" || bad "cell/wall: $(cat "$T/msg")"
import re, sys
h = dict(re.findall(r"#define (RC_\w+) ([-0-9.]+)f", open(sys.argv[1]).read()))
c = dict(re.findall(r"^(\w+) = ([-0-9.e]+)", open(sys.argv[2]).read(), re.M))
cell, wall = float(c["cell_m"]) * 1000, float(c["wall_thick_m"]) * 1000
assert abs(float(h["RC_CELL_MM"]) - cell) < 0.01 and abs(float(h["RC_WALL_MM"]) - wall) < 0.01, (h["RC_CELL_MM"], cell, h["RC_WALL_MM"], wall)
print("[firmware] cell %s mm, wall %s mm: mazes/halfsize-world.ini's" % (h["RC_CELL_MM"], h["RC_WALL_MM"]))
PY
else
  bad "mkprofile robots/kerise-v5.ini: $(cat "$T/err")"
fi

# goals: japan2017hes (4,4)-(5,5), taiwan2014hef 21x21 (5,7)-(6,8), uk2021-haz-half (6,1)-(7,2)
for m in japan2017hes taiwan2014hef uk2021-haz-half; do
  want_rc 0 "$m: the half-size contest (goal reached: exit 0)" \
    "$HALF" --maze "$D/$m.txt" --robot robots/kerise-v5.ini --config mazes/halfsize-world.ini --runs 1 --json
  python3 - "$T/out" <<'PY' >"$T/msg" && ok "$m: $(cat "$T/msg")" || bad "$m: $(cat "$T/msg")"
import json, sys
j = json.loads(open(sys.argv[1]).read().splitlines()[-1])
k = j["contacts"]
assert j["reached_goal"], "goal not reached"
assert sum(k.values()) == 0 and j["collisions"] == 0, k
print("goal, no contact, first run %s s, best %s s" % (j["first_run_s"], j["best_run_s"]))
PY
done

want_rc 0 "the default build on gen-16x16-s1" "$MMSIM" --maze mazes/gen-16x16-s1.txt --json
python3 - "$T/out" <<'PY' >"$T/msg" && ok "16x16 default: $(cat "$T/msg")" || bad "16x16 default: $(cat "$T/msg")"
import json, sys
j = json.loads(open(sys.argv[1]).read().splitlines()[-1])
assert j["reached_goal"] and j["collisions"] == 0, j["contacts"]
assert (j["first_run_s"], j["best_run_s"], j["proven_at_step"]) == (13.509, 6.71, 106), (j["first_run_s"], j["best_run_s"], j["proven_at_step"])
print("first run %s s, best %s s, proven at step %s" % (j["first_run_s"], j["best_run_s"], j["proven_at_step"]))
PY

[ $fails -eq 0 ] && echo "cli_halfsize: all ok" || { echo "cli_halfsize: $fails failed"; exit 1; }

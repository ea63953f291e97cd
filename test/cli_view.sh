#!/usr/bin/env bash
# run.sh: alone (timed: real-time runs, timed input or timeouts)
# cli_view.sh - the viewer's screenshots under an Xvfb the test starts:
# each camera on a known small maze (PNG of the requested size; wall tops
# in the bird's view, the robot near the centre of the follow and top
# views), the centre post in and out of the picture, IR sensors' beams
# (a robot with IR sensors against one without), flag errors, and a
# clear failure without a display. Skips if no X server can be started.
set -u
S=${MMSIM:-build/mmsim}
P="python3 test/pngcheck.py"
T=$(mktemp -d)
XPID=
cleanup() { [ -n "$XPID" ] && kill "$XPID" 2>/dev/null; rm -rf "$T"; }
trap cleanup EXIT
. "$(dirname "$0")/lib.sh"

start_xvfb cli_view.sh

# sanitized build: Mesa's driver is unloaded at exit, leaving nameless
# frames; preloading it keeps them named for the suppressions
gl_cmd "$S"; SIM=("${GL[@]}")

M=mazes/gen-5x5-s1.txt
for c in 1 2 3; do
  "${SIM[@]}" --maze $M --driver scripted --screenshot "$T/cam$c.png" --camera $c --at 2 --size 320x240 >"$T/out" 2>"$T/err"
  rc=$?; [ $rc -eq 0 ] && ok "camera $c screenshot" || { bad "camera $c: exit $rc"; head -20 "$T/err"; }
done
[ "$($P "$T/cam1.png" size)" = "320 240" ] && [ "$($P "$T/cam2.png" size)" = "320 240" ] && \
  [ "$($P "$T/cam3.png" size)" = "320 240" ] && ok "requested size" || bad "sizes"
# wall tops (SCENE_WALL_TOP d02828) in the bird's view
n=$($P "$T/cam1.png" near:d02828:40); [ "${n:-0}" -gt 300 ] && ok "walls in the bird's view ($n px)" || bad "wall pixels: $n"
# robot body (SCENE_ROBOT 2a5ce0) in the middle of the follow and top views
for c in 2 3; do
  n=$($P "$T/cam$c.png" near:2a5ce0:60:0.4:0.4:0.6:0.6)
  [ "${n:-0}" -gt 200 ] && ok "robot at the centre of camera $c ($n px)" || bad "robot pixels in camera $c: $n"
done

# HUD timers (upper left) turn red (0xFF3030) after the contest limit: a 1 s
# limit ends the run and the screenshot shows that last frame
printf '[sim]\ntime_limit_s = 1\n' >"$T/limit.ini"
"${SIM[@]}" --maze $M --driver scripted --config "$T/limit.ini" --screenshot "$T/over.png" --at 2 --size 320x240 >"$T/out" 2>"$T/err" \
  || { bad "over-time screenshot"; head -5 "$T/err"; }
a=$($P "$T/over.png" near:ff3030:40:0:0:0.5:0.15); b=$($P "$T/cam1.png" near:ff3030:40:0:0:0.5:0.15)
[ "${a:-0}" -gt 100 ] && [ "${b:-1}" -eq 0 ] && ok "timers red after the limit ($a px), not before" || bad "red timer pixels: over $a, in time $b"

# the centre post shows or not (6x6: the post at the maze's centre)
for p in on off; do
  "${SIM[@]}" --maze mazes/gen-6x6-s1.txt --driver scripted --centre-post $p --screenshot "$T/post$p.png" --camera 1 --size 320x240 >"$T/out" 2>"$T/err" \
    || { bad "post $p screenshot"; head -5 "$T/err"; }
done
a=$($P "$T/poston.png" near:d02828:40:0.45:0.4:0.55:0.6); b=$($P "$T/postoff.png" near:d02828:40:0.45:0.4:0.55:0.6)
[ "${a:-0}" -gt "${b:-0}" ] && ok "centre post drawn when present ($a > $b px)" || bad "centre post pixels: on $a, off $b"

# IR sensors' beams: the paper robot and the same robot with four IR sensors
# (test/robots/ir.ini), top view: the pictures differ, the beams' dark colour
# (SCENE_IR_DARK 6070a0: the firmware lights no emitter) only with IR
for r in robots/paper.ini test/robots/ir.ini; do
  "${SIM[@]}" --maze $M --driver firmware --robot $r --screenshot "$T/$(basename $r .ini).png" --camera 3 --at 1 --size 320x240 >"$T/out" 2>"$T/err" \
    || { bad "$r screenshot"; head -5 "$T/err"; }
done
d=$($P "$T/ir.png" diff:"$T/paper.png":40); a=$($P "$T/ir.png" near:6070a0:12); b=$($P "$T/paper.png" near:6070a0:12)
[ "${d:-0}" -gt 200 ] && [ "${a:-0}" -gt 50 ] && [ "${b:-1}" -eq 0 ] \
  && ok "IR beams drawn ($d px differ, $a beam px)" || bad "IR beams: $d px differ, beam px $a with IR, $b without"

# errors: one line, before any run
want2() { local d=$1; shift; "$@" >"$T/out" 2>"$T/err"; local rc=$?
  [ $rc -eq 2 ] && [ "$(wc -l <"$T/err")" -eq 1 ] && ok "$d" || bad "$d: exit $rc $(cat "$T/err")"; }
want2 "bad camera" "$S" --maze $M --screenshot "$T/x.png" --camera 4
want2 "bad size" "$S" --maze $M --screenshot "$T/x.png" --size 10x10
want2 "bad speed" "$S" --maze $M --gui --speed 100
want2 "gui with screenshot" "$S" --maze $M --gui --screenshot "$T/x.png"
want2 "unwritable screenshot" "$S" --maze $M --screenshot "$T/no/dir/x.png"
want2 "screenshot with batch" "$S" --batch mazes --screenshot "$T/x.png"
DISPLAY= "${SIM[@]}" --maze $M --driver scripted --screenshot "$T/nod.png" >"$T/out" 2>"$T/err"; rc=$?
[ $rc -eq 3 ] && [ "$(wc -l <"$T/err")" -eq 1 ] && grep -q '^mmsim: cannot start the viewer' "$T/err" && [ ! -e "$T/nod.png" ] \
  && ok "no display: exit 3, one line" || bad "no display: exit $rc $(cat "$T/err")"
[ -z "$(ls "$T" | grep '\.tmp\.')" ] && ok "no temporaries left" || bad "temporaries: $(ls "$T")"

[ $fails -eq 0 ] || { echo "$fails failed"; exit 1; }

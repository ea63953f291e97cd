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
P="python3 test/tools/pngcheck.py"
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
# robot body (SCENE_ROBOT 2a5ce0) in the middle of the follow and top views: the
# middle of the scene's rectangle (hud_scene_rect, 320x240: x 124..320, y 0..110,
# right of the side panel, above the bottom bar; centre 0.69, 0.23)
SCENE_MID=0.6:0.13:0.8:0.33
for c in 2 3; do
  n=$($P "$T/cam$c.png" near:2a5ce0:60:$SCENE_MID)
  [ "${n:-0}" -gt 200 ] && ok "robot at the centre of camera $c ($n px)" || bad "robot pixels in camera $c: $n"
done

# no 3D geometry under the HUD: the side panel and the bottom bar are opaque and the scene
# is drawn in its own rectangle, so at the same moment the bird's view and the follow view
# (walls across the whole window) differ only there and at the camera buttons (640x480:
# the panel x < 232, the scene y < 350, the camera buttons x < 396)
for c in 1 2; do
  "${SIM[@]}" --maze $M --driver scripted --screenshot "$T/hud$c.png" --camera $c --at 2 --size 640x480 >"$T/out" 2>"$T/err" \
    || { bad "640x480 camera $c screenshot"; head -5 "$T/err"; }
done
p=$($P "$T/hud2.png" diff:"$T/hud1.png":0:0:0:0.36:0.72); b=$($P "$T/hud2.png" diff:"$T/hud1.png":0:0.63:0.74:1:1)
s=$($P "$T/hud2.png" diff:"$T/hud1.png":40:0.37:0:1:0.72)
[ "${p:-1}" -eq 0 ] && [ "${b:-1}" -eq 0 ] && [ "${s:-0}" -gt 20000 ] \
  && ok "HUD text over no 3D geometry (panel and bar the same in cameras 1 and 2; scenes $s px apart)" \
  || bad "3D under the HUD: panel $p px, bar $b px differ between cameras (scenes $s px)"

# HUD timers (upper left) turn red (0xFF3030) after the contest limit: a 1 s
# limit ends the run and the screenshot shows that last frame
printf '[sim]\ntime_limit_s = 1\n' >"$T/limit.ini"
"${SIM[@]}" --maze $M --driver scripted --config "$T/limit.ini" --screenshot "$T/over.png" --at 2 --size 320x240 >"$T/out" 2>"$T/err" \
  || { bad "over-time screenshot"; head -5 "$T/err"; }
a=$($P "$T/over.png" near:ff3030:40:0:0:0.5:0.15); b=$($P "$T/cam1.png" near:ff3030:40:0:0:0.5:0.15)
[ "${a:-0}" -gt 100 ] && [ "${b:-1}" -eq 0 ] && ok "timers red after the limit ($a px), not before" || bad "red timer pixels: over $a, in time $b"

# the centre post shows or not (6x6: the post at the maze's centre)
for p in on off; do
  "${SIM[@]}" --maze mazes/gen-6x6-s1.txt --driver scripted --centre-post $p --screenshot "$T/post$p.png" --camera 1 --size 640x480 >"$T/out" 2>"$T/err" \
    || { bad "post $p screenshot"; head -5 "$T/err"; }
done
POST=0.64:0.28:0.72:0.44 # around the maze's centre in the scene's rectangle (640x480: x 232..640, y 0..350)
a=$($P "$T/poston.png" near:d02828:40:$POST); b=$($P "$T/postoff.png" near:d02828:40:$POST)
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

#!/usr/bin/env bash
# cli_mmview.sh - mmview replays a log of mmsim --lcm-log, under an Xvfb
# the test starts: a firmware contest logged, mmview --screenshot at two
# times shows the robot in two places, and each matches mmsim --screenshot
# --at the same time of the same run (robot at the same pixels, the maze
# area the same but for a few pixels); an IR robot's beams as mmsim draws
# them, lit or dark as MM_PARTS says; flag and log errors (a corrupt
# MM_PARTS among them) get one line
# and exit 2; no display gets exit 3. Skips if no X server can be started.
set -u
S=${MMSIM:-build/mmsim}
V=${MMVIEW:-build/mmview}
P="python3 test/tools/pngcheck.py"
T=$(mktemp -d)
XPID=
cleanup() { [ -n "$XPID" ] && kill "$XPID" 2>/dev/null; rm -rf "$T"; }
trap cleanup EXIT
. "$(dirname "$0")/lib.sh"

start_xvfb cli_mmview.sh

# sanitized build: keep Mesa's frames named for the suppressions (as cli_view.sh)
run() { local b=$1; shift; gl_cmd "$b"; "${GL[@]}" "$@"; }

M=mazes/gen-5x5-s1.txt
want_rc 0 "firmware contest logged" "$S" --maze $M --driver firmware --lcm-log "$T/run.lcmlog"
BOX=0.37:0.2:1:0.72 # the maze area in the scene's rectangle (hud_scene_rect, 640x480: x 232..640, y 0..350), clear of the HUD
for t in 2 5; do
  want_rc 0 "mmview screenshot at $t s" run "$V" "$T/run.lcmlog" --screenshot "$T/view$t.png" --at $t --size 640x480
  want_rc 0 "mmsim screenshot at $t s" run "$S" --maze $M --driver firmware --screenshot "$T/sim$t.png" --at $t --size 640x480
  [ "$($P "$T/view$t.png" size)" = "640 480" ] && ok "size at $t s" || bad "size at $t s"
  read -r vx vy <<<"$($P "$T/view$t.png" centroid:2a5ce0:30:$BOX)"
  read -r sx sy <<<"$($P "$T/sim$t.png" centroid:2a5ce0:30:$BOX)"
  eval "vx$t=$vx vy$t=$vy"
  python3 -c "import sys; sys.exit(0 if abs($vx-$sx) < 1 and abs($vy-$sy) < 1 else 1)" 2>/dev/null \
    && ok "robot where mmsim draws it at $t s ($vx,$vy vs $sx,$sy)" || bad "robot at $t s: mmview $vx,$vy mmsim $sx,$sy"
  d=$($P "$T/view$t.png" diff:"$T/sim$t.png":40:$BOX)
  # measured: 33 and 60 of 184320 px differ (wheel angles to an encoder count, body height)
  [ "${d:-99999}" -lt 500 ] && ok "scene as mmsim's at $t s ($d px differ)" || bad "scene differs from mmsim's at $t s: $d px"
done
python3 -c "import math,sys; sys.exit(0 if math.hypot($vx2-$vx5, $vy2-$vy5) > 20 else 1)" \
  && ok "the robot moved between 2 s and 5 s ($vx2,$vy2 -> $vx5,$vy5)" || bad "robot did not move: $vx2,$vy2 -> $vx5,$vy5"
# the mouse's map overlay (cyan wall bars) is drawn from the log's belief
n=$($P "$T/view5.png" near:30e0ff:40:$BOX); [ "${n:-0}" -gt 200 ] && ok "belief overlay drawn ($n px)" || bad "overlay pixels: $n"
want_rc 0 "follow camera" run "$V" "$T/run.lcmlog" --screenshot "$T/follow.png" --at 5 --camera 2 --size 320x240
n=$($P "$T/follow.png" near:2a5ce0:60:0.6:0.13:0.8:0.33) # the scene's middle (320x240: x 124..320, y 0..110); [ "${n:-0}" -gt 200 ] && ok "robot at the centre of the follow view" || bad "follow view robot pixels: $n"

# a replay makes no link: no Port/Baud fields (their box 303030) nor Connect, which the live
# firmware run (a driver a link could replace) shows in the side panel
a=$($P "$T/view5.png" near:303030:0); b=$($P "$T/sim5.png" near:303030:0)
[ "${a:-1}" -eq 0 ] && [ "${b:-0}" -gt 1000 ] && ok "no Connect panel in mmview ($b px in mmsim's)" || bad "Connect panel px: mmview $a, mmsim $b"
# the lap table: by 5 s the firmware has run a lap: a row " 1  m:ss.mmm *" under the header (white
# text in rows 7-8 of the panel: y 128..168 of 480), none at 0.5 s; the same in mmview
want_rc 0 "mmsim screenshot at 0.5 s" run "$S" --maze $M --driver firmware --screenshot "$T/sim05.png" --at 0.5 --size 640x480
a=$($P "$T/sim5.png" near:ffffff:10:0:0.27:0.36:0.35); v=$($P "$T/view5.png" near:ffffff:10:0:0.27:0.36:0.35)
b=$($P "$T/sim05.png" near:ffffff:10:0:0.27:0.36:0.35)
[ "${a:-0}" -gt 100 ] && [ "${v:-0}" -gt 100 ] && [ "${b:-1}" -lt "${a:-0}" ] \
  && ok "lap table: a lap row at 5 s ($a px; mmview $v), Best - at 0.5 s ($b px)" || bad "lap table px: $a at 5 s (mmview $v), $b at 0.5 s"

# An IR robot (test/robots/ir.ini): its geometry comes from MM_MAZE's robot,
# the emitter groups from MM_PARTS. Beams drawn as mmsim draws them (dark:
# the firmware lights no emitter); the log with every emitter byte of its
# MM_PARTS set to 1 draws them lit (SCENE_IR_LIT ff50c0).
R=test/robots/ir.ini
want_rc 0 "IR robot logged" "$S" --maze $M --driver firmware --robot $R --lcm-log "$T/ir.lcmlog"
# at rest in the start cell (0.2 s): the log holds no pitch, so the replay stands the robot level;
# braking, the live robot tips onto its front caster (3.5 deg nose down) and its tilted beams reach
# elsewhere (at 1 s and 3 s: 3,660-5,614 px differ)
want_rc 0 "mmview IR robot" run "$V" "$T/ir.lcmlog" --screenshot "$T/irview.png" --at 0.2 --camera 2 --size 640x480
want_rc 0 "mmsim IR robot" run "$S" --maze $M --driver firmware --robot $R --screenshot "$T/irsim.png" --at 0.2 --camera 2 --size 640x480
d=$($P "$T/irview.png" diff:"$T/irsim.png":40:$BOX)
dk=$($P "$T/irview.png" near:6070a0:30:$BOX); lt=$($P "$T/irview.png" near:ff50c0:30:$BOX)
[ "${d:-99999}" -lt 500 ] && [ "${dk:-0}" -gt 50 ] && [ "${lt:-1}" -eq 0 ] \
  && ok "IR beams (dark) as mmsim draws them ($d px differ, $dk dark px)" || bad "IR beams: $d px differ, $dk dark, $lt lit"
python3 - "$T/ir.lcmlog" "$T/irlit.lcmlog" "$T/irbad.lcmlog" <<'PY'
import struct, sys
d = bytearray(open(sys.argv[1], 'rb').read()); bad = bytearray(d); at = 0; first = True
while at < len(d):  # event: sync, number, time, channel length, data length, channel, data
    cl, dl = struct.unpack('>II', d[at + 20:at + 28]); ch = bytes(d[at + 28:at + 28 + cl]); data = at + 28 + cl
    if ch == b'MM_PARTS':
        d[data + dl - 4:data + dl] = b'\x01' * 4  # the four emitter groups, lit
        if first: bad[data + 16:data + 18] = b'\x7f\xff'; first = False  # nparts 0x7FFF
    at = data + dl
open(sys.argv[2], 'wb').write(bytes(d)); open(sys.argv[3], 'wb').write(bytes(bad))
PY
want_rc 0 "mmview IR robot, emitters lit" run "$V" "$T/irlit.lcmlog" --screenshot "$T/irlit.png" --at 3 --camera 2 --size 640x480
lt=$($P "$T/irlit.png" near:ff50c0:30:$BOX); dk=$($P "$T/irlit.png" near:6070a0:30:$BOX)
[ "${lt:-0}" -gt 50 ] && [ "${dk:-1}" -eq 0 ] && ok "IR beams lit from MM_PARTS ($lt px)" || bad "lit IR beams: $lt lit, $dk dark px"

# errors: one line, exit 2 (bad flags, bad logs), nothing written
ONE_ERROR_LINE=1
want_rc 2 "no log" "$V"
want_rc 2 "missing log" "$V" "$T/none.lcmlog" --screenshot "$T/x.png" --at 1
want_rc 2 "bad camera" "$V" "$T/run.lcmlog" --screenshot "$T/x.png" --at 1 --camera 4
want_rc 2 "bad size" "$V" "$T/run.lcmlog" --screenshot "$T/x.png" --at 1 --size 10x10
want_rc 2 "bad speed" "$V" "$T/run.lcmlog" --speed 100
want_rc 2 "bad --at" "$V" "$T/run.lcmlog" --screenshot "$T/x.png" --at soon
want_rc 2 "--at after the log's end" "$V" "$T/run.lcmlog" --screenshot "$T/x.png" --at 999
want_rc 2 "--screenshot without --at" "$V" "$T/run.lcmlog" --screenshot "$T/x.png"
want_rc 2 "--at without --screenshot" "$V" "$T/run.lcmlog" --at 1
want_rc 2 "two logs" "$V" "$T/run.lcmlog" "$T/run.lcmlog"
want_rc 2 "unwritable screenshot" "$V" "$T/run.lcmlog" --screenshot "$T/no/dir/x.png" --at 1
printf 'not a log at all\n' >"$T/junk"
want_rc 2 "not a log" "$V" "$T/junk" --screenshot "$T/x.png" --at 1
head -c $(( $(stat -c %s "$T/run.lcmlog") - 7 )) "$T/run.lcmlog" >"$T/cut.lcmlog"
want_rc 2 "truncated log" "$V" "$T/cut.lcmlog" --screenshot "$T/x.png" --at 1
grep -q "cut.lcmlog: event [0-9]* at byte [0-9]*: truncated: " "$T/err" && ok "truncated log named" || bad "truncated message: $(cat "$T/err")"
python3 - "$T/run.lcmlog" "$T/flip.lcmlog" <<'PY'
import sys
d = bytearray(open(sys.argv[1], 'rb').read())
# the first MM_POSE payload's first byte (its type fingerprint): the message no longer decodes
i = d.index(b'MM_POSE') + len('MM_POSE')
d[i] ^= 0xFF
open(sys.argv[2], 'wb').write(bytes(d))
PY
want_rc 2 "corrupt message" "$V" "$T/flip.lcmlog" --screenshot "$T/x.png" --at 1
grep -q "does not decode" "$T/err" && ok "corrupt message named" || bad "corrupt message: $(cat "$T/err")"
want_rc 2 "corrupt MM_PARTS" "$V" "$T/irbad.lcmlog" --screenshot "$T/x.png" --at 1
grep -q "(MM_PARTS): does not decode" "$T/err" && ok "corrupt MM_PARTS named" || bad "corrupt MM_PARTS: $(cat "$T/err")"
[ ! -e "$T/x.png" ] && ok "no picture written on errors" || bad "picture written"
ONE_ERROR_LINE=0
DISPLAY= run "$V" "$T/run.lcmlog" --screenshot "$T/nod.png" --at 1 >"$T/out" 2>"$T/err"; rc=$?
[ $rc -eq 3 ] && [ "$(wc -l <"$T/err")" -eq 1 ] && grep -q '^mmview: cannot start the viewer' "$T/err" && [ ! -e "$T/nod.png" ] \
  && ok "no display: exit 3, one line" || bad "no display: exit $rc $(cat "$T/err")"
DISPLAY= run "$V" "$T/run.lcmlog" >"$T/out" 2>"$T/err"; rc=$?
[ $rc -eq 3 ] && ok "window without a display: exit 3" || bad "window without a display: exit $rc $(cat "$T/err")"
[ -z "$(ls "$T" | grep '\.tmp\.')" ] && ok "no temporaries left" || bad "temporaries: $(ls "$T")"

[ $fails -eq 0 ] || { echo "$fails failed"; exit 1; }

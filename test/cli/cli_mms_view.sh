#!/usr/bin/env bash
# run.sh: alone (timed: real-time runs, timed input or timeouts)
# cli_mms_view.sh - the viewer in an mms run (under an Xvfb the test
# starts): the floor shows the algorithm's cell colours; an algorithm that
# waits for Reset after the goal waits with the clock running until the
# Reset key (X, through XTEST). Skips if no X server can be started.
set -u
S=${MMSIM:-build/mmsim}
T=$(mktemp -d)
XPID= SPID=
cleanup() { [ -n "$SPID" ] && kill "$SPID" 2>/dev/null; [ -n "$XPID" ] && kill "$XPID" 2>/dev/null; rm -rf "$T"; }
trap cleanup EXIT
. "$(dirname "$0")/lib.sh"

start_xvfb cli_mms_view.sh
gl_cmd "$S"; SIM=("${GL[@]}")

# both colour the cells they visit: cyan / green, drawn in the viewer's floor palette
# (scene_cell_rgb: c 2a8c78, g 3c9c3c; never the overlay's bright cyan 30e0ff)
for a in "floodfill.py 2" "wallfollow.py"; do
  col=2a8c78; [ "$a" = wallfollow.py ] && col=3c9c3c
  # the algorithm runs without the sanitized viewer's preloaded ASan and Mesa (gl_cmd): it is not
  # ours to check, and under ASan Python is slow to start and reports its own leaks at exit
  "${SIM[@]}" --maze mazes/gen-8x8-s1.txt --mms "env -u LD_PRELOAD python3 test/mms/$a" --mms-timeout-ms 60000 --screenshot "$T/s.png" --at 4 --camera 1 --size 320x240 --json >"$T/out" 2>"$T/err" \
    || { bad "$a: screenshot failed"; head -5 "$T/err"; continue; }
  reason=$(python3 -c "import json,sys; print(json.loads(open(sys.argv[1]).read().splitlines()[-1])['exit_reason'])" "$T/out")
  n=$(python3 test/tools/pngcheck.py "$T/s.png" near:$col:40)
  [ "$reason" = screenshot ] && [ "${n:-0}" -gt 100 ] && ok "$a: cell colours on the floor ($n pixels)" || bad "$a: $col pixels: $n, run ended by $reason: $(grep '^mmsim' "$T/err")"
done
# without an mms algorithm there is no such colour
"${SIM[@]}" --maze mazes/gen-8x8-s1.txt --screenshot "$T/f.png" --at 4 --camera 1 --size 320x240 >"$T/out" 2>"$T/err" || bad "firmware screenshot"
n=$(python3 test/tools/pngcheck.py "$T/f.png" near:2a8c78:30)
[ "${n:-1}" -eq 0 ] && ok "no cell colours without mms" || bad "cyan without mms: $n"

# the cell numbers readable in the bird's view (800x600): floodfill's distances in white
# (luma of the teal tint under 128) at 3 or more screen pixels per font pixel: over 100 text
# pixels in the scene (right of the side panel: x > 0.3), none of the tint near the overlay's cyan
"${SIM[@]}" --maze mazes/gen-8x8-s1.txt --mms "env -u LD_PRELOAD python3 test/mms/floodfill.py 2" --mms-timeout-ms 60000 --screenshot "$T/big.png" --at 4 --camera 1 --size 800x600 >"$T/out" 2>"$T/err" \
  || bad "800x600 mms screenshot: $(head -3 "$T/err")"
n=$(python3 test/tools/pngcheck.py "$T/big.png" near:ffffff:10:0.3:0:1:0.85); c=$(python3 test/tools/pngcheck.py "$T/big.png" near:2a8c78:30)
[ "${n:-0}" -gt 100 ] && [ "${c:-0}" -gt 1000 ] && ok "cell numbers readable ($n text px on $c tinted px)" || bad "cell numbers: $n text px, $c tinted px"

# an algorithm that waits for Reset (test/mms/resetwait.py: polls wasReset
# after the goal; its stderr comes through as "algo: LINE"): in --gui the contest clock runs while it waits, until the
# user presses Reset (the X key); then it runs again and exits
X=${XINPUT:-build/test/xinput}
if [ -x "$X" ]; then
  "${SIM[@]}" --maze mazes/gen-5x5-s1.txt --mms "env -u LD_PRELOAD python3 test/mms/resetwait.py 2" --mms-timeout-ms 60000 --gui --speed 8 --size 320x240 --json >"$T/r.json" 2>"$T/r.err" &
  SPID=$!
  for _ in $(seq 600); do grep -q "^algo: resetwait: run 1 at the goal" "$T/r.err" && break; sleep 0.1; done
  grep -q "^algo: resetwait: run 1 at the goal" "$T/r.err" || bad "resetwait never reached the goal in 60 s"
  sleep 1 # waiting: the clock runs (x8)
  "$X" key x || bad "XTEST key x failed"
  for _ in $(seq 600); do grep -q "^algo: resetwait: done" "$T/r.err" && break; sleep 0.1; done
  grep -q "^algo: resetwait: done" "$T/r.err" || bad "resetwait not done 60 s after Reset"
  sleep 0.5
  "$X" key Escape
  wait $SPID; SPID=
  got=$(python3 -c "
import json,sys; d=json.loads(open(sys.argv[1]).read().splitlines()[-1]); l=d['laps']
print(d['exit_reason'], len(l), d['mms']['resets'], len(l) == 2 and l[1]['start_s'] - l[0]['end_s'] > 2)" "$T/r.json" 2>&1)
  [ "$got" = "mms_exited 2 1 True" ] && ok "waits for Reset in the viewer: the clock ran, X pressed it, a second run" \
    || bad "Reset in the viewer: $got $(grep -v '^mms ' "$T/r.err" | head -5)"
else
  echo "SKIP cli_mms_view.sh Reset key: $X not built"
fi
[ $fails -eq 0 ]

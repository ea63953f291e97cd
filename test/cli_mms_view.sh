#!/usr/bin/env bash
# cli_mms_view.sh - the viewer in an mms run (under an Xvfb the test
# starts): the floor shows the algorithm's cell colours. Skips if no X
# server can be started.
set -u
S=${MMSIM:-build/mmsim}
T=$(mktemp -d)
XPID=
cleanup() { [ -n "$XPID" ] && kill "$XPID" 2>/dev/null; rm -rf "$T"; }
trap cleanup EXIT
. "$(dirname "$0")/lib.sh"

start_xvfb cli_mms_view.sh
gl_cmd "$S"; SIM=("${GL[@]}")

for a in "floodfill.py 2" "wallfollow.py"; do # both colour the cells they visit: cyan / green
  col=00ffff; [ "$a" = wallfollow.py ] && col=00ff00
  # the algorithm inherits the preloaded ASan and Mesa (gl_cmd): Python then takes ~3 s to start
  # on a loaded machine, so a generous per-command timeout (wall clock)
  "${SIM[@]}" --maze mazes/gen-8x8-s1.txt --mms "python3 test/mms/$a" --mms-timeout-ms 60000 --screenshot "$T/s.png" --at 4 --camera 1 --size 320x240 --json >"$T/out" 2>"$T/err" \
    || { bad "$a: screenshot failed"; head -5 "$T/err"; continue; }
  reason=$(python3 -c "import json,sys; print(json.loads(open(sys.argv[1]).read().splitlines()[-1])['exit_reason'])" "$T/out")
  n=$(python3 test/pngcheck.py "$T/s.png" near:$col:40)
  [ "$reason" = screenshot ] && [ "${n:-0}" -gt 100 ] && ok "$a: cell colours on the floor ($n pixels)" || bad "$a: $col pixels: $n, run ended by $reason: $(grep '^mmsim' "$T/err")"
done
# without an mms algorithm there is no such colour
"${SIM[@]}" --maze mazes/gen-8x8-s1.txt --screenshot "$T/f.png" --at 4 --camera 1 --size 320x240 >"$T/out" 2>"$T/err" || bad "firmware screenshot"
n=$(python3 test/pngcheck.py "$T/f.png" near:00ffff:40)
[ "${n:-1}" -eq 0 ] && ok "no cell colours without mms" || bad "cyan without mms: $n"
[ $fails -eq 0 ]

#!/usr/bin/env bash
# run.sh: alone (timed: real-time runs, timed input or timeouts)
# cli_view_board.sh - the HUD's board panel, under an Xvfb the
# test starts. A sketch of ours (test/firmware/arduino/board/HudPanel.ino: a banner,
# the builtin LED lit, `SW n` each time A6 decodes to another setting) on
# the emulated UKMARSBOT board:
#   - a screenshot shows the console panel (its text colour) and the lit
#     LED; a run without --board has neither;
#   - the viewer never changes the simulation: the JSON is the same with
#     and without --screenshot (apart from the wall time);
#   - live (--gui, clicks through XTEST): switch "1", BUTTON (a click: down
#     for 0.1 s), switch "2" and RESET reach the firmware as --input's
#     actions do (what it prints, the JSON's board.resets).
# Skips without Xvfb, the XTEST helper (the clicks only) or the board emulation.
set -u
B=${BUILD:-build}
S=${MMSIM:-$B/mmsim}
X=${XINPUT:-$B/test/xinput}
P="python3 test/tools/pngcheck.py"
T=$(mktemp -d)
XPID= SPID=
cleanup() { [ -n "$SPID" ] && kill "$SPID" 2>/dev/null; [ -n "$XPID" ] && kill "$XPID" 2>/dev/null; rm -rf "$T"; }
trap cleanup EXIT
. "$(dirname "$0")/lib.sh"
mk() { env -u MAKEFLAGS -u MFLAGS -u MAKELEVEL make --no-print-directory B="$B" "$@"; }

[ -f boards/ukmarsbot-v1.3.ini ] || { echo "SKIP cli_view_board.sh: no boards/ukmarsbot-v1.3.ini"; exit 77; }
ELF=$B/clients/board/HudPanel.elf
[ -s "$ELF" ] || mk "$ELF" >"$T/make.out" 2>&1 || { echo "FAIL: make $ELF: $(tail -3 "$T/make.out")"; exit 1; }
start_xvfb cli_view_board.sh
gl_cmd "$S"; SIM=("${GL[@]}")
M=mazes/gen-5x5-s1.txt
BOARD=(--board ukmarsbot --avr "$ELF" --robot robots/ukmarsbot.ini --maze $M)

# ---- the picture: the console panel (HUD_CONSOLE_TEXT 60f060) and the lit LED (HUD_LED_LIT ff5020)
"${SIM[@]}" "${BOARD[@]}" --screenshot "$T/board.png" --at 1 >"$T/out" 2>"$T/err" || { bad "board screenshot"; head -5 "$T/err"; }
"${SIM[@]}" --robot robots/ukmarsbot.ini --maze $M --screenshot "$T/plain.png" --at 1 >"$T/out" 2>"$T/err" || { bad "plain screenshot"; head -5 "$T/err"; }
d=$($P "$T/board.png" diff:"$T/plain.png":40:0:0:0.6:0.6)
a=$($P "$T/board.png" near:60f060:20); b=$($P "$T/plain.png" near:60f060:20)
[ "${d:-0}" -gt 2000 ] && [ "${a:-0}" -gt 300 ] && [ "${b:-1}" -eq 0 ] \
  && ok "console panel drawn ($d px differ at the upper left, $a text px; none without --board)" \
  || bad "console panel: $d px differ, text px $a with the board, $b without"
a=$($P "$T/board.png" near:ff5020:20:0:0:0.5:0.5); b=$($P "$T/plain.png" near:ff5020:20)
[ "${a:-0}" -gt 100 ] && [ "${b:-1}" -eq 0 ] && ok "the lit LED drawn ($a px)" || bad "LED pixels: $a with the board, $b without"
# the side panel never covers the maze: in the board's picture (1024x720, bird's view) every
# wall top (SCENE_WALL_TOP d02828) and the start cell (SCENE_START 2e8b3e) lie right of the
# panel (hud_panel_w with a board: 316 px) and above the bottom bar, the maze spans most of
# the scene's width, and the console's text stays inside the panel
read -r x0 y0 x1 y1 <<<"$($P "$T/board.png" bbox:d02828:40)"; read -r sx0 _ _ _ <<<"$($P "$T/board.png" bbox:2e8b3e:30)"
read -r _ _ cx1 _ <<<"$($P "$T/board.png" bbox:60f060:20)"
[ "$x0" != - ] && [ "$x0" -gt 318 ] && [ "$y0" -gt 0 ] && [ "$x1" -lt 1023 ] && [ "$y1" -lt 640 ] && [ $((x1 - x0)) -gt 450 ] \
  && [ "$sx0" != - ] && [ "$sx0" -gt 318 ] && [ "$cx1" -lt 316 ] \
  && ok "the maze clear of the side panel (walls x $x0..$x1, y $y0..$y1; start cell from x $sx0; console text to x $cx1)" \
  || bad "maze under the panel: walls x $x0..$x1, y $y0..$y1; start cell from x $sx0; console text to x $cx1"
# no overlay message (the status line's colour ffe080) for a board's image: it publishes no map;
# the in-process firmware does (at 0.1 s, before its first report: the message)
"${SIM[@]}" --robot robots/ukmarsbot.ini --maze $M --screenshot "$T/early.png" --at 0.1 >"$T/out" 2>"$T/err" || bad "early screenshot"
a=$($P "$T/board.png" near:ffe080:30); b=$($P "$T/early.png" near:ffe080:30)
[ "${a:-1}" -eq 0 ] && [ "${b:-0}" -gt 100 ] && ok "no map overlay message on a board ($b px with the firmware)" || bad "overlay message px: board $a, firmware $b"
# no Port/Baud fields (their box 303030) on a board: no link can be made there; the firmware run has them
a=$($P "$T/board.png" near:303030:0); b=$($P "$T/plain.png" near:303030:0)
[ "${a:-1}" -eq 0 ] && [ "${b:-0}" -gt 1000 ] && ok "no Connect panel on a board ($b px without)" || bad "Connect panel px: board $a, firmware $b"
# a small window: the panel shrinks to what fits (480x360: a few console rows; 320x240: none), no error
"${SIM[@]}" "${BOARD[@]}" --screenshot "$T/small.png" --at 0.5 --size 480x360 >"$T/out" 2>"$T/err" \
  && [ "$($P "$T/small.png" near:60f060:20)" -gt 0 ] && ok "480x360: console text shown" || bad "480x360 screenshot: $(head -3 "$T/err")"
"${SIM[@]}" "${BOARD[@]}" --screenshot "$T/tiny.png" --at 0.5 --size 320x240 >"$T/out" 2>"$T/err" \
  && ok "320x240: screenshot" || bad "320x240 screenshot: $(head -3 "$T/err")"

# ---- the viewer never changes the simulation: the same JSON with and without a screenshot
json() { python3 -c "
import json,sys; d=json.loads(open(sys.argv[1]).read().splitlines()[-1])
for k in ('wall_time_s', 'real_time_factor'): d.pop(k)
print(json.dumps(d, sort_keys=True))" "$1"; }
IN=(--time-limit 1.5 --input "0.3 switches=5; 0.6 button; 0.9 reset")
"${SIM[@]}" "${BOARD[@]}" "${IN[@]}" --json >"$T/a.json" 2>"$T/err" ; rc=$?
# the picture at the run's last step (the time limit counts on the contest clock: the run may end after 1.5 s)
AT=$(python3 -c "import json,sys; print(json.loads(open(sys.argv[1]).read().splitlines()[-1])['sim_time_s'])" "$T/a.json" 2>/dev/null)
"${SIM[@]}" "${BOARD[@]}" "${IN[@]}" --json --screenshot "$T/d.png" --at "${AT:-1.5}" >"$T/b.json" 2>"$T/err"
ja=$(json "$T/a.json"); jb=$(json "$T/b.json")
[ $rc -eq 1 ] && [ -n "$ja" ] && [ "$ja" = "$jb" ] && echo "$ja" | grep -q 'SW 5' \
  && ok "the same JSON with and without --screenshot" || bad "JSON differs (exit $rc): $(diff <(echo "$ja" | tr ',' '\n') <(echo "$jb" | tr ',' '\n') | head -5)"

# ---- live clicks (800x600 window at (0, 0); hud_board_layout: switches 8..36, 40..68, .. y 236..264;
# Button x 140..228; Reset x 232..308; test_view.c checks these)
if [ ! -x "$X" ]; then
  echo "SKIP cli_view_board.sh clicks: $X not built"
else
  # waitfor N TEXT: until the firmware has printed TEXT N times (its console echoed by --verbose)
  waitfor() { for _ in $(seq 300); do [ "$(tr -d '\r' <"$T/g.err" | grep -cx "$2")" -ge "$1" ] && return 0; sleep 0.1; done
    bad "no '$2' (x$1) from the firmware: $(tr -d '\r' <"$T/g.err" | tail -3 | tr '\n' '|')"; return 1; }
  "${SIM[@]}" "${BOARD[@]}" --gui --size 800x600 --time-limit 120 --verbose --json >"$T/g.json" 2>"$T/g.err" &
  SPID=$!
  "$X" wait mmsim 30 || bad "no window"
  waitfor 1 "SW 0" &&
  "$X" click 22 250 && waitfor 1 "SW 1" &&      # switch 1: switches=1
  "$X" click 184 250 && waitfor 1 "SW 16" &&    # BUTTON: down (the ladder reads > 800), up after 0.1 s
  waitfor 2 "SW 1" &&
  "$X" click 54 250 && waitfor 1 "SW 3" &&      # switch 2: switches=3
  "$X" click 270 250 && waitfor 2 "HUD PANEL TEST" && waitfor 2 "SW 3" # RESET: the sketch starts again, the switches stay
  "$X" key Escape
  wait $SPID; SPID=
  got=$(python3 -c "
import json,sys; d=json.loads(open(sys.argv[1]).read().splitlines()[-1])
c=[l for l in d['console'].replace('\r','').split('\n') if l.startswith('SW ')]
print(d['exit_reason'], d['board']['resets'], ' '.join(c))" "$T/g.json" 2>&1)
  [ "$got" = "window_closed 1 SW 0 SW 1 SW 16 SW 1 SW 3 SW 3" ] \
    && ok "clicks on switch 1, BUTTON, switch 2 and RESET reach the firmware" || bad "clicks: $got"
fi
[ $fails -eq 0 ] || { echo "$fails failed"; exit 1; }

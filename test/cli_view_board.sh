#!/usr/bin/env bash
# run.sh: alone (timed: real-time runs, timed input or timeouts)
# cli_view_board.sh - the HUD's board panel, under an Xvfb the
# test starts. A sketch of ours (test/arduino/board/HudPanel.ino: a banner,
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
P="python3 test/pngcheck.py"
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
a=$($P "$T/board.png" near:ff5020:20:0:0:0.5:0.3); b=$($P "$T/plain.png" near:ff5020:20)
[ "${a:-0}" -gt 100 ] && [ "${b:-1}" -eq 0 ] && ok "the lit LED drawn ($a px)" || bad "LED pixels: $a with the board, $b without"
# a small window: the panel shrinks to what fits, no error
"${SIM[@]}" "${BOARD[@]}" --screenshot "$T/small.png" --at 0.5 --size 320x240 >"$T/out" 2>"$T/err" \
  && [ "$($P "$T/small.png" near:60f060:20)" -gt 0 ] && ok "320x240: console text shown" || bad "320x240 screenshot: $(head -3 "$T/err")"

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

# ---- live clicks (800x600 window at (0, 0); hud_board_layout: switches 8..36, 40..68, .. y 76..104;
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
  "$X" click 22 90 && waitfor 1 "SW 1" &&      # switch 1: switches=1
  "$X" click 184 90 && waitfor 1 "SW 16" &&    # BUTTON: down (the ladder reads > 800), up after 0.1 s
  waitfor 2 "SW 1" &&
  "$X" click 54 90 && waitfor 1 "SW 3" &&      # switch 2: switches=3
  "$X" click 270 90 && waitfor 2 "HUD PANEL TEST" && waitfor 2 "SW 3" # RESET: the sketch starts again, the switches stay
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

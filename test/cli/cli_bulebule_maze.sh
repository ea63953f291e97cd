#!/usr/bin/env bash
# cli_bulebule_maze.sh - Bulebots' bulebule, built unmodified (`make
# client-bulebule`), searches classic mazes on boards/bulebule.ini and
# robots/bulebule.ini, started as its src/main.c wants it: a press, a long
# press for the classic goal (configure_goal), a long press for the force
# (hmi_configure_force), a hand before its front sensors
# (wait_front_sensor_close_signal). classic/test-maze-classic (the
# shortest search of the classic set: its search.c replayed: 36 moves),
# twice: it reaches the goal, its search ends back in the start cell
# (explore() returns without a collision, src/mmlib/solve.c, and turns to
# its start position), save_maze writes its 256 cells to flash, no front or
# side wall contact, the same JSON and flash twice. classic/001-anomaly-
# test, once: its goal is walled off (mmmaze solve: unreachable); bulebule
# searches the 64 cells it can reach (the west column, the north row, the
# east column, the south-east dead end and the pocket above it; it enters
# 60) with no contact, then, its flood fill finding no path, turns back and
# forth in the pocket's x 14 column (best_neighbor_step returns BACK): the
# side pair's slope and the turn after the dead end. mazes/gen-16x16-s1:
# its search to the goal with no front or side contact. Then the second run
# from test-maze-classic's flash: load_maze, the speed run to the goal with
# no front or side contact, the flash unchanged.
# Slow (about 1 s of CPU per simulated second): four runs side by side.
# Without ../shared: SKIP.
set -u
B=${BUILD:-build}
SHARED=${SHARED:-../shared}
MMSIM=${MMSIM:-$B/mmsim}
ELF=$B/clients/bulebule/src/main.elf
M1=$SHARED/mazes/classic/test-maze-classic.txt
M2=$SHARED/mazes/classic/001-anomaly-test.txt
M3=mazes/gen-16x16-s1.txt
T=$(mktemp -d); trap 'rm -rf "$T"' EXIT
. "$(dirname "$0")/lib.sh"
mk() { env -u MAKEFLAGS -u MFLAGS -u MAKELEVEL make --no-print-directory B="$B" SHARED="$SHARED" "$@"; }
if [ ! -d "$SHARED/clients/bulebule/src" ] || [ ! -f "$M1" ] || [ ! -f "$M2" ]; then
  echo "SKIP cli_bulebule_maze: $SHARED/clients/bulebule, $M1 or $M2 not found (../shared)"; exit 77
fi
[ -s "$ELF" ] || mk client-bulebule >"$T/bb.out" 2>&1 || { bad "make client-bulebule: $(tail -1 "$T/bb.out")"; exit 1; }
IN="1 button; 3 button=1; 7 button=1; 18 occlude=fl; 18.5 occlude=fr; 19 occlude=fl; 20 occlude=fl"
# limits from leaving the start (20.7 s): test-maze-classic's search ends at 39.5 s (its
# "Data logging off", past the 1 MiB of console the JSON keeps, so no --end-on); 001-anomaly-test
# enters its last cell at 50 s and turns back and forth from then on
run() { nice "$MMSIM" --board bulebule --firmware "$ELF" --maze "$2" --json --input "$IN" --time-limit "$3" \
  --flash "$T/$1.bin" >"$T/$1.json" 2>"$T/$1.err"; echo $? >"$T/$1.rc"; }
run a "$M1" 22 & run b "$M1" 22 & run c "$M2" 38 & run e "$M3" 21 & wait
jv() { python3 -c 'import json,sys; d=json.loads(open(sys.argv[1]).read().splitlines()[-1]); print(eval(sys.argv[2]))' "$1" "$2" 2>/dev/null; }
# test-maze-classic: the goal, the whole search, the flash
[ "$(jv "$T/a.json" "(d['exit_reason'], d['reached_goal'])")" = "('time_limit', True)" ] \
  && ok "test-maze-classic: goal reached, no firmware fault" \
  || bad "test-maze-classic: exit $(cat "$T/a.rc"): $(jv "$T/a.json" "(d['exit_reason'], d['reached_goal'])") $(head -1 "$T/a.err")"
[ "$(jv "$T/a.json" "d['contacts']['front'] + d['contacts']['side']")" = 0 ] && ok "test-maze-classic: no front or side wall contact" \
  || bad "test-maze-classic contacts: $(jv "$T/a.json" "d['contacts']")"
# explore() ends with turn_to_start_position: back in the start cell (0.18 m square), not stopped by a collision
[ "$(jv "$T/a.json" "d['final_pose']['x_m'] < 0.18 and d['final_pose']['y_m'] < 0.18")" = True ] \
  && ok "test-maze-classic: back in the start cell: $(jv "$T/a.json" "d['final_pose']")" || bad "final pose: $(jv "$T/a.json" "d['final_pose']")"
# save_maze: its 256 cells in the flash's last page (setup.h FLASH_EEPROM_ADDRESS_MAZE 0x0800fc00)
[ "$(python3 -c 'import sys; print(sum(b != 0xFF for b in open(sys.argv[1], "rb").read()[0xFC00:]))' "$T/a.bin")" = 256 ] \
  && ok "test-maze-classic: its maze saved to flash (256 bytes at 0x0800fc00)" || bad "flash page 0x0800fc00 not written"
# the same JSON twice (each names its own flash file)
[ "$(strip "$T/a.json" | sed "s|$T/a.bin|FLASH|")" = "$(strip "$T/b.json" | sed "s|$T/b.bin|FLASH|")" ] \
  && ok "the same JSON twice" || bad "two runs differ"
cmp -s "$T/a.bin" "$T/b.bin" && ok "the same flash twice" || bad "the flash files differ"
# gen-16x16-s1: the goal 17.2 s after leaving the start, no front or side contact on the way
[ "$(jv "$T/e.json" "(d['reached_goal'], d['contacts']['front'] + d['contacts']['side'])")" = "(True, 0)" ] \
  && ok "gen-16x16-s1: its search reaches the goal in $(jv "$T/e.json" "d['laps'][0]['run_s']") s, no front or side wall contact" \
  || bad "gen-16x16-s1: exit $(cat "$T/e.rc"): $(jv "$T/e.json" "(d['exit_reason'], d['reached_goal'], d['contacts'])") $(head -1 "$T/e.err")"
# the second run (GUIDE-firmware "A second run"): the same flash reloaded (a press opens the reuse
# menu, a short press loads the maze, a long press the lowest force, a hand): its speed run to the goal
cp "$T/a.bin" "$T/d.bin"
IN="1 button; 2 button; 3.5 button=1; 13.5 occlude=fl; 14 occlude=fr; 14.5 occlude=fl; 23 end"
run d "$M1" 30
[ "$(jv "$T/d.json" "(d['reached_goal'], d['laps'][0]['run_s'] < 5.0)")" = "(True, True)" ] \
  && ok "test-maze-classic, second run: the saved maze reloaded, its speed run to the goal in $(jv "$T/d.json" "d['laps'][0]['run_s']") s" \
  || bad "second run: exit $(cat "$T/d.rc"): $(jv "$T/d.json" "(d['exit_reason'], d['reached_goal'], d['laps'])") $(head -1 "$T/d.err")"
[ "$(jv "$T/d.json" "d['contacts']['front'] + d['contacts']['side']")" = 0 ] && ok "second run: no front or side wall contact" \
  || bad "second run contacts: $(jv "$T/d.json" "d['contacts']")"
cmp -s "$T/a.bin" "$T/d.bin" && ok "second run: the flash kept as it was" || bad "the second run changed the flash"
# 001-anomaly-test: every reachable cell, no contact, then turning in the x 14 column (y 7-8)
[ "$(jv "$T/c.json" "d['exit_reason']")" = time_limit ] && ok "001-anomaly-test: no firmware fault" \
  || bad "001-anomaly-test: exit reason $(jv "$T/c.json" "d['exit_reason']") $(head -1 "$T/c.err")"
[ "$(jv "$T/c.json" "d['contacts']['front'] + d['contacts']['side']")" = 0 ] && ok "001-anomaly-test: no front or side wall contact" \
  || bad "001-anomaly-test contacts: $(jv "$T/c.json" "d['contacts']")"
[ "$(jv "$T/c.json" "2.52 < d['final_pose']['x_m'] < 2.70 and 1.26 < d['final_pose']['y_m'] < 1.62")" = True ] \
  && ok "001-anomaly-test: searched what it can reach, at the pocket's end: $(jv "$T/c.json" "d['final_pose']")" \
  || bad "001-anomaly-test final pose: $(jv "$T/c.json" "d['final_pose']")"
[ $fails -eq 0 ]

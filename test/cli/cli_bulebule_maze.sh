#!/usr/bin/env bash
# cli_bulebule_maze.sh - Bulebots' bulebule, built unmodified (`make
# client-bulebule`), explores a classic maze on boards/bulebule.ini and
# robots/bulebule.ini, started as its src/main.c wants it: a press, a long
# press for the classic goal (configure_goal), a long press for the force
# (hmi_configure_force), a hand before its front sensors
# (wait_front_sensor_close_signal). Checked: it leaves the start, runs the
# west column, the north row and the east column into the south-east dead
# end (001-anomaly-test) and turns there with no front or side wall
# contact (the front pair's curve in robots/bulebule.ini), and its
# save_maze (libopencm3's flash_get_status_flags reads the flash size
# register, RM0008 30.1.1) runs without a fault; the same JSON twice.
# Slow (about 1 s of CPU per simulated second): two runs side by side.
# Without ../shared: SKIP.
set -u
B=${BUILD:-build}
SHARED=${SHARED:-../shared}
MMSIM=${MMSIM:-$B/mmsim}
ELF=$B/clients/bulebule/src/main.elf
MAZE=$SHARED/mazes/classic/001-anomaly-test.txt
T=$(mktemp -d); trap 'rm -rf "$T"' EXIT
. "$(dirname "$0")/lib.sh"
mk() { env -u MAKEFLAGS -u MFLAGS -u MAKELEVEL make --no-print-directory B="$B" SHARED="$SHARED" "$@"; }
if [ ! -d "$SHARED/clients/bulebule/src" ] || [ ! -f "$MAZE" ]; then
  echo "SKIP cli_bulebule_maze: $SHARED/clients/bulebule or $MAZE not found (../shared)"; exit 77
fi
[ -s "$ELF" ] || mk client-bulebule >"$T/bb.out" 2>&1 || { bad "make client-bulebule: $(tail -1 "$T/bb.out")"; exit 1; }
IN="1 button; 3 button=1; 7 button=1; 18 occlude=fl; 18.5 occlude=fr; 19 occlude=fl; 20 occlude=fl"
LIMIT=${BULEBULE_LIMIT:-30} # from leaving the start (20.7 s): save_maze runs at 47.3 s
run() { nice "$MMSIM" --board bulebule --firmware "$ELF" --maze "$MAZE" --json --input "$IN" --time-limit "$LIMIT" \
  --flash "$T/$1.bin" >"$T/$1.json" 2>"$T/$1.err"; echo $? >"$T/$1.rc"; }
run a & run b & wait
jv() { python3 -c 'import json,sys; d=json.loads(open(sys.argv[1]).read().splitlines()[-1]); print(eval(sys.argv[2]))' "$1" "$2" 2>/dev/null; }
[ "$(cat "$T/a.rc")" = 1 ] && ok "bulebule runs to the time limit (exit 1: no goal)" || bad "exit $(cat "$T/a.rc"): $(head -2 "$T/a.err")"
[ "$(jv "$T/a.json" "d['exit_reason']")" = time_limit ] && ok "no firmware fault (its save_maze reads the flash size)" \
  || bad "exit reason: $(jv "$T/a.json" "d['exit_reason']") $(head -1 "$T/a.err")"
[ "$(jv "$T/a.json" "d['contacts']['front'] + d['contacts']['side']")" = 0 ] && ok "no front or side wall contact" \
  || bad "contacts: $(jv "$T/a.json" "d['contacts']")"
# through the south-east dead end (x 2.79 m, y 0.06 m) and back north-west
[ "$(jv "$T/a.json" "d['final_pose']['x_m'] > 2.2 and d['final_pose']['y_m'] > 0.4")" = True ] \
  && ok "turned in the south-east dead end and left it: $(jv "$T/a.json" "d['final_pose']")" || bad "final pose: $(jv "$T/a.json" "d['final_pose']")"
# save_maze: its 256 cells in the flash's last page (setup.h FLASH_EEPROM_ADDRESS_MAZE 0x0800fc00)
[ "$(python3 -c 'import sys; print(sum(b != 0xFF for b in open(sys.argv[1], "rb").read()[0xFC00:]))' "$T/a.bin")" = 256 ] \
  && ok "its maze saved to flash (256 bytes at 0x0800fc00)" || bad "flash page 0x0800fc00 not written"
# the same JSON twice (each names its own flash file)
[ "$(strip "$T/a.json" | sed "s|$T/a.bin|FLASH|")" = "$(strip "$T/b.json" | sed "s|$T/b.bin|FLASH|")" ] \
  && ok "the same JSON twice" || bad "two runs differ"
cmp -s "$T/a.bin" "$T/b.bin" && ok "the same flash twice" || bad "the flash files differ"
[ $fails -eq 0 ]

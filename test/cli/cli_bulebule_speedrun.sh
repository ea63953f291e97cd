#!/usr/bin/env bash
# cli_bulebule_speedrun.sh - bulebule's second run: its maze reloaded from
# flash, its speed run to the goal. tools/bulebule-flash writes the flash
# file bulebule's save_maze would leave after seeing every wall of
# mazes/gen-16x16-s1.txt (its run sequence, 256 bytes at 0x0800fc00); mmsim
# runs bulebule (`make client-bulebule`, unmodified) on it, started as its
# src/main.c wants a second run: a press (maze_is_saved: the reuse menu), a
# short press (load_maze), a long press for the lowest force
# (hmi_configure_force), a hand before its front sensors. Checked: the
# tool's output and its bad input (one line, exit 2); the run reaches the
# goal (its diagonals and 90-degree turns, src/mmlib/path.c) and stops in
# the goal with no front or side wall contact, the flash unchanged; the same
# JSON twice. Slow (about 1 s of CPU per simulated second, 23 s each): two
# runs side by side. Without ../shared: SKIP.
set -u
B=${BUILD:-build}
SHARED=${SHARED:-../shared}
MMSIM=${MMSIM:-$B/mmsim}
MMMAZE=${MMMAZE:-$B/mmmaze}
ELF=$B/clients/bulebule/src/main.elf
MAZE=mazes/gen-16x16-s1.txt
T=$(mktemp -d); trap 'rm -rf "$T"' EXIT
. "$(dirname "$0")/lib.sh"
mk() { env -u MAKEFLAGS -u MFLAGS -u MAKELEVEL make --no-print-directory B="$B" SHARED="$SHARED" "$@"; }
if [ ! -d "$SHARED/clients/bulebule/src" ]; then
  echo "SKIP cli_bulebule_speedrun: $SHARED/clients/bulebule not found (../shared)"; exit 77
fi
[ -s "$ELF" ] || mk client-bulebule >"$T/bb.out" 2>&1 || { bad "make client-bulebule: $(tail -1 "$T/bb.out")"; exit 1; }
export MMMAZE
# the tool: bulebule's set_run_sequence on the true walls, erased flash but that page (the sequences below are
# what bulebule's src/mmlib/search.c, compiled on the host with the same walls, builds)
want_rc 0 "bulebule-flash writes the flash file" tools/bulebule-flash "$MAZE" -o "$T/a.bin"
SEQ=BFRFLRLFRLLFRRFFRLLFRFFS
grep -q "$SEQ" "$T/out" && ok "its run sequence printed: $SEQ" || bad "sequence: $(cat "$T/out")"
python3 - "$T/a.bin" "$SEQ" <<'PY' && ok "64 KiB, erased but the sequence and its NUL tail at 0x0800fc00" || bad "flash image: $(python3 -c 'import sys; d=open(sys.argv[1],"rb").read(); print(len(d), d[0xFC00:0xFC20])' "$T/a.bin")"
import sys
d = open(sys.argv[1], "rb").read()
s = sys.argv[2].encode()
page = s + bytes(256 - len(s))
sys.exit(not (len(d) == 65536 and d[0xFC00:0xFD00] == page and d.count(0xFF) == 65536 - 256))
PY
cp "$T/a.bin" "$T/b.bin"
# a sequence with turns both ways in a row, as bulebule's own search.c builds it on the host from the same walls
want_rc 0 "bulebule-flash on classic/AAMC15Maze" tools/bulebule-flash "$SHARED/mazes/classic/AAMC15Maze.txt" -o "$T/d.bin"
grep -q " BFRFFFLLRRLFLFFFRFFRLRLLRRFRLRLRLFFFS " "$T/out" && ok "AAMC15Maze: bulebule's sequence" || bad "AAMC15Maze: $(cat "$T/out")"
ONE_ERROR_LINE=1
printf 'o---o\n| x |\n' >"$T/bad.txt"
want_rc 2 "a bad maze: one line, exit 2" tools/bulebule-flash "$T/bad.txt" -o "$T/c.bin"
grep -q "bad.txt:" "$T/err" && ok "the maze's error names the file" || bad "error: $(cat "$T/err")"
want_rc 2 "a maze bulebule cannot hold (5x5): exit 2" tools/bulebule-flash mazes/gen-5x5-s1.txt -o "$T/c.bin"
want_rc 2 "no output named: exit 2" tools/bulebule-flash "$MAZE"
want_rc 2 "classic/001-anomaly-test, its goal walled off from the start: exit 2" \
  tools/bulebule-flash "$SHARED/mazes/classic/001-anomaly-test.txt" -o "$T/c.bin"
[ ! -e "$T/c.bin" ] && ok "nothing written on bad input" || bad "$T/c.bin written"
ONE_ERROR_LINE=0
# the second run: leaves the start at 16.2 s, reaches the goal 5.7 s later, stops in it by 22.0 s
IN="1 button; 2 button; 3.5 button=1; 13.5 occlude=fl; 14 occlude=fr; 14.5 occlude=fl; 23 end"
run() { nice "$MMSIM" --board bulebule --firmware "$ELF" --maze "$MAZE" --json --input "$IN" --time-limit 30 \
  --flash "$T/$1.bin" >"$T/$1.json" 2>"$T/$1.err"; echo $? >"$T/$1.rc"; }
run a & run b & wait
jv() { python3 -c 'import json,sys; d=json.loads(open(sys.argv[1]).read().splitlines()[-1]); print(eval(sys.argv[2]))' "$1" "$2" 2>/dev/null; }
[ "$(cat "$T/a.rc")" = 0 ] && ok "exit 0: the goal reached" || bad "exit $(cat "$T/a.rc"): $(head -2 "$T/a.err")"
[ "$(jv "$T/a.json" "d['reached_goal'] and d['exit_reason']")" = input_end ] \
  && ok "the speed run reaches the goal in $(jv "$T/a.json" "d['laps'][0]['run_s']") s" \
  || bad "goal: $(jv "$T/a.json" "(d['reached_goal'], d['exit_reason'], d['laps'])")"
[ "$(jv "$T/a.json" "d['contacts']['front'] + d['contacts']['side']")" = 0 ] && ok "no front or side wall contact" \
  || bad "contacts: $(jv "$T/a.json" "d['contacts']")"
# stopped in the goal's square (cells 7-8, 7-8: 1.26-1.62 m)
[ "$(jv "$T/a.json" "all(1.26 < d['final_pose'][k] < 1.62 for k in ('x_m', 'y_m'))")" = True ] \
  && ok "stopped in the goal: $(jv "$T/a.json" "d['final_pose']")" || bad "final pose: $(jv "$T/a.json" "d['final_pose']")"
[ "$(jv "$T/a.json" "d['board']['flash']['changed']")" = False ] && ok "the flash read, not written" || bad "flash: $(jv "$T/a.json" "d['board']['flash']")"
[ "$(strip "$T/a.json" | sed "s|$T/a.bin|FLASH|")" = "$(strip "$T/b.json" | sed "s|$T/b.bin|FLASH|")" ] \
  && ok "the same JSON twice" || bad "two runs differ"
[ $fails -eq 0 ]

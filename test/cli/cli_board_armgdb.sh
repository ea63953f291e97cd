#!/usr/bin/env bash
# cli_board_armgdb.sh - the debugging flags of an ARM image on an STM32
# board (`mmsim --board bulebule --firmware IMAGE.elf`, sim/contest/run_armboard.c):
#   --gdb PORT   gdb-multiarch in batch mode attaches to the stub (sim/arm/armgdb.c)
#                while our firmware test/firmware/arm/boardtest.c runs a maze on the
#                board: it breaks in the SysTick handler, reads the tick counter at
#                two hits, steps back into main, and the run's JSON equals the run's
#                without --gdb (but the wall-time fields). A bad PORT is one line,
#                exit 2; a port in use one line, exit 3.
#   --watch NAME boardtest's tick counter (a static in SRAM, typed u32 from DWARF)
#                on MM_WATCH (mmlog --dump) at every telemetry sample: the
#                milliseconds since SysTick started, the JSON unchanged; in
#                --report's JSON; a name the image lacks, a flash constant: one line, exit 2.
# SKIP only without gdb-multiarch or arm-none-eabi-gcc.
set -u
B=${BUILD:-build}
MMSIM=${MMSIM:-$B/mmsim}
FW=$B/arm/boardtest.elf
T=$(mktemp -d)
MPID=
trap '[ -n "$MPID" ] && kill "$MPID" 2>/dev/null; rm -rf "$T"' EXIT
. "$(dirname "$0")/lib.sh"
command -v gdb-multiarch >/dev/null || { echo "SKIP cli_board_armgdb: gdb-multiarch not installed (Debian package gdb-multiarch)"; exit 77; }
command -v arm-none-eabi-gcc >/dev/null || { echo "SKIP cli_board_armgdb: arm-none-eabi-gcc not installed"; exit 77; }
mk() { env -u MAKEFLAGS -u MFLAGS -u MAKELEVEL make --no-print-directory B="$B" "$@"; }
[ -s "$FW" ] || mk "$FW" >"$T/make.out" 2>&1 || bad "make $FW: $(tail -1 "$T/make.out")"
open_mazes "$T"
MAZE=$T/open.txt
free_port() { python3 -c "import socket; s=socket.socket(); s.bind(('127.0.0.1', 0)); print(s.getsockname()[1])"; }
IN="0.45 button=down; 0.6 button=up; 0.7 end"
arm() { "$MMSIM" --board bulebule --maze "$MAZE" --time-limit 2 --json --firmware "$FW" --input "$IN" "$@"; }

want_rc 1 "boardtest on bulebule without --gdb" arm
cp "$T/out" "$T/plain.json"

# ---- --gdb: break, read, step, continue to the end; the same JSON ----
PORT=$(free_port)
timeout 300 "$MMSIM" --board bulebule --maze "$MAZE" --time-limit 2 --json --firmware "$FW" --input "$IN" --gdb "$PORT" \
  >"$T/gdb.json" 2>"$T/gdb.err" &
MPID=$!
for _ in $(seq 600); do grep -q "halted until" "$T/gdb.err" 2>/dev/null && break; sleep 0.1; done
grep -q "^mmsim: --gdb: the firmware is halted until gdb-multiarch attaches to 127.0.0.1:$PORT (target remote :$PORT)" "$T/gdb.err" \
  && ok "mmsim waits for gdb on 127.0.0.1:$PORT" || bad "mmsim's line: $(head -2 "$T/gdb.err")"
timeout 300 gdb-multiarch -batch -nx -ex 'set confirm off' -ex 'set pagination off' -ex 'set osabi none' -ex "target remote :$PORT" \
  -ex 'break systick_handler' -ex continue -ex 'print ticks' -ex continue -ex 'print ticks' -ex step -ex 'print $xpsr & 0x1ff' \
  -ex 'delete' -ex continue "$FW" >"$T/gdb.out" 2>&1
echo $? >"$T/gdb.rc"
wait "$MPID"; echo $? >"$T/mmsim.rc"; MPID=
has() { grep -q -- "$1" "$T/gdb.out" && ok "gdb: $2" || bad "gdb: $2: no '$1' in: $(tail -20 "$T/gdb.out")"; }
[ "$(cat "$T/gdb.rc")" = 0 ] && ok "gdb-multiarch's script ran (exit 0)" || bad "gdb exit $(cat "$T/gdb.rc"): $(tail -5 "$T/gdb.out")"
has '^reset_handler () at test/firmware/arm/startup.c:' "halted at the first instruction (the reset handler)"
[ "$(grep -c '^Breakpoint 1, systick_handler () at test/firmware/arm/boardtest.c:31' "$T/gdb.out")" = 2 ] \
  && ok "gdb: stopped in the SysTick handler twice" || bad "gdb: breakpoint hits: $(grep Breakpoint "$T/gdb.out")"
has '^\$1 = 0$' "ticks 0 at the first tick's handler"
has '^\$2 = 1$' "ticks 1 at the second"
has '^main () at test/firmware/arm/boardtest.c:116' "step: out of the handler, back in main's loop after its WFI"
has '^\$3 = 0$' "IPSR 0 (thread mode) after the step"
has '^\[Inferior 1 (Remote target) exited normally\]' "continue to the run's end: exited normally"
[ "$(cat "$T/mmsim.rc")" = 1 ] && ok "mmsim --gdb: exit 1 (input_end, no lap), as without" || bad "mmsim --gdb exit $(cat "$T/mmsim.rc"): $(cat "$T/gdb.err")"
[ "$(strip "$T/plain.json")" = "$(strip "$T/gdb.json")" ] && ok "the JSON with --gdb equals the JSON without" \
  || bad "--gdb changed the JSON: $(diff <(strip "$T/plain.json" | tr , '\n') <(strip "$T/gdb.json" | tr , '\n') | head -10)"

# ---- --watch: the tick counter on MM_WATCH and in the report, the JSON unchanged ----
MMLOG=${MMLOG:-$B/mmlog}
want_rc 1 "--watch ticks --lcm-log" arm --watch ticks --lcm-log "$T/w.lcm" --report "$T/w.png"
[ "$(strip "$T/plain.json")" = "$(strip "$T/out")" ] && ok "--watch: the JSON equals the run's without" || bad "--watch changed the JSON"
"$MMLOG" --dump MM_WATCH "$T/w.lcm" >"$T/w.jsonl" 2>"$T/w.err" || bad "mmlog --dump MM_WATCH: $(cat "$T/w.err")"
python3 - "$T/w.jsonl" "$T/w.json" <<'PY' && ok "MM_WATCH: ticks (u32) each 10 ms sample, 10 more each time, 697 at 0.7 s (SysTick on at 3 ms); the report's rows too" || bad "MM_WATCH: $(head -3 "$T/w.jsonl")"
import json, sys
m = [json.loads(l) for l in open(sys.argv[1])]
ok = len(m) == 70 and all(x["name"] == ["ticks"] and x["type"] == ["u32"] for x in m)
ok = ok and all(int(x["value"][0]) == x["utime"] // 1000 - 3 for x in m) and m[-1]["value"] == [697.0]
rep = json.load(open(sys.argv[2]))
w = rep.get("watch", {})
ok = ok and w.get("columns", [])[-1:] == ["ticks"] and len(w["rows"]) > 100
ok = ok and all(int(r[-1]) == max(0, round(r[0] * 1000) - 3) for r in w.get("rows", []))
sys.exit(0 if ok else 1)
PY

# ---- bad ports: one line, exit 2; a port in use: one line, exit 3 ----
ONE_ERROR_LINE=1
want_rc 2 "--gdb 0: exit 2" arm --gdb 0
grep -q "expected a number\|from 1 to 65535\|--gdb" "$T/err" && ok "--gdb 0: names the flag" || bad "--gdb 0: $(cat "$T/err")"
want_rc 2 "--gdb 70000: exit 2" arm --gdb 70000
want_rc 2 "--gdb on a run without an image: exit 2" "$MMSIM" --maze "$MAZE" --gdb 4444
PORT=$(free_port)
python3 -c "
import socket, sys, time
s = socket.socket(); s.bind(('127.0.0.1', int(sys.argv[1]))); s.listen(1); open(sys.argv[2], 'w').close(); time.sleep(60)" "$PORT" "$T/held" &
HOLD=$!
for _ in $(seq 100); do [ -f "$T/held" ] && break; sleep 0.1; done
want_rc 3 "--gdb on a port in use: exit 3" timeout 120 "$MMSIM" --board bulebule --maze "$MAZE" --json --firmware "$FW" --gdb "$PORT"
grep -q "^mmsim: --gdb $PORT: cannot listen on 127.0.0.1:$PORT: Address already in use$" "$T/err" \
  && ok "a port in use: says so" || bad "a port in use: $(cat "$T/err")"
kill $HOLD 2>/dev/null; wait $HOLD 2>/dev/null
want_rc 2 "--watch nope: exit 2" arm --watch ticks,nope
grep -q "^mmsim: --watch: no global variable 'nope' in $FW$" "$T/err" && ok "--watch nope: says so" || bad "--watch nope: $(cat "$T/err")"
want_rc 2 "--watch on a run without an image: exit 2" "$MMSIM" --maze "$MAZE" --watch ticks
ONE_ERROR_LINE=0

[ $fails -eq 0 ] || { echo "$fails failed"; exit 1; }
echo "all passed"

#!/usr/bin/env bash
# run.sh: alone (timed: real-time runs, timed input or timeouts)
# cli_gdb.sh - debugging the firmware in the simulator: mmsim --gdb PORT
# starts simavr's gdb stub on 127.0.0.1:PORT and a scripted avr-gdb (batch
# mode) attaches. Our sketch GdbProbe (test/firmware/arduino/board, built with
# debug info) on the emulated board: break on probe_tick, read
# probe_count (0), `next` over its increment and read it again (1), `next`
# to the println, `step` into the core's Print::println (its DWARF too),
# continue to the next hit (1 still: the firmware waited for gdb), wall
# time passes while it is halted, then disconnect; the run finishes and its
# JSON equals the run's without --gdb (but wall_time_s / real_time_factor):
# the whole simulation waited in lockstep. Also: the stub listens on the
# loopback interface only; a `kill` from gdb and the same image as a link
# MCU (--avr alone) end with the same JSON, and so does a gdb killed by a
# signal at a breakpoint; halted, mmsim uses next to no CPU; bad ports are one line and
# exit 2, a port in use one line and exit 3. Every process under timeout:
# the test never hangs. SKIP only without avr-gdb (Debian's gdb-avr).
set -u
B=${BUILD:-build}
MMSIM=${MMSIM:-$B/mmsim}
T=$(mktemp -d)
MPID=
trap '[ -n "$MPID" ] && kill "$MPID" 2>/dev/null; rm -rf "$T"' EXIT
. "$(dirname "$0")/lib.sh"
command -v avr-gdb >/dev/null || { echo "SKIP cli_gdb: avr-gdb not installed (Debian package gdb-avr)"; exit 77; }
mk() { env -u MAKEFLAGS -u MFLAGS -u MAKELEVEL make --no-print-directory B="$B" "$@"; }
ELF=$B/clients/board/GdbProbe.elf
want_rc 0 "GdbProbe builds for the Nano" mk "$ELF"
python3 - "$T/open.txt" <<'PY'
import sys
n = 16; rows = ["o" + "---o" * n]
for r in range(n):
    rows += ["|" + "    " * (n - 1) + "   |", "o" + ("---o" * n if r == n - 1 else "   o" * n)]
open(sys.argv[1], "w").write("\n".join(rows) + "\n")
PY
BOARD=(--maze "$T/open.txt" --board ukmarsbot --robot robots/ukmarsbot.ini --avr "$ELF" --time-limit 1 --json)
free_port() { python3 -c "import socket; s=socket.socket(); s.bind(('127.0.0.1', 0)); print(s.getsockname()[1])"; }

# ---- bad ports: one line, exit 2; --gdb needs --avr ----
ONE_ERROR_LINE=1
for p in 0 65536 abc 1.5 -3 ""; do
  want_rc 2 "--gdb '$p': exit 2" "$MMSIM" "${BOARD[@]}" --gdb "$p"
  grep -q -- "--gdb" "$T/err" || bad "--gdb '$p': the line names --gdb: $(cat "$T/err")"
done
want_rc 2 "--gdb without --avr: exit 2" "$MMSIM" --maze "$T/open.txt" --gdb 1234 --json
grep -q -- "--gdb PORT needs --avr" "$T/err" && ok "--gdb without --avr: says why" || bad "--gdb without --avr: $(cat "$T/err")"
# a port in use: the machine's state, not the input: exit 3
PORT=$(free_port)
python3 -c "
import socket, sys, time
s = socket.socket(); s.bind(('127.0.0.1', int(sys.argv[1]))); s.listen(1); open(sys.argv[2], 'w').close(); time.sleep(30)" "$PORT" "$T/held" &
HOLD=$!
for _ in $(seq 100); do [ -f "$T/held" ] && break; sleep 0.1; done
want_rc 3 "--gdb on a port in use: exit 3" timeout 60 "$MMSIM" "${BOARD[@]}" --gdb "$PORT"
grep -q "mmsim: --gdb $PORT: cannot listen on 127.0.0.1:$PORT: Address already in use" "$T/err" \
  && ok "--gdb on a port in use: says so" || bad "--gdb on a port in use: $(cat "$T/err")"
kill $HOLD 2>/dev/null; wait $HOLD 2>/dev/null
ONE_ERROR_LINE=0

# session NAME GDB-COMMANDS MMSIM-ARGS...: mmsim with --gdb on a free port in
# the background, avr-gdb's commands after `target remote`; gdb's output in
# $T/NAME.gdb, its exit code in $T/NAME.gdbrc, mmsim's JSON, stderr and exit
# code in $T/NAME.json, .err, .rc
session() { local name=$1 cmds=$2; shift 2
  local port; port=$(free_port)
  timeout 60 "$MMSIM" "$@" --gdb "$port" >"$T/$name.json" 2>"$T/$name.err" &
  MPID=$!
  for _ in $(seq 300); do grep -q "halted until avr-gdb attaches" "$T/$name.err" 2>/dev/null && break; sleep 0.1; done
  grep -q "halted until avr-gdb attaches to 127.0.0.1:$port (target remote :$port)" "$T/$name.err" \
    && ok "$name: mmsim waits for gdb on 127.0.0.1:$port" || bad "$name: mmsim's line: $(head -2 "$T/$name.err")"
  # the stub listens on the loopback interface only (IPv4: simavr's stub has no IPv6)
  python3 - "$port" <<'PY' && ok "$name: listening on 127.0.0.1 only" || bad "$name: not on 127.0.0.1 only"
import sys
port = "%04X" % int(sys.argv[1])
addrs = [l.split()[1].split(":")[0] for l in open("/proc/net/tcp").read().splitlines()[1:]
         if l.split()[1].endswith(":" + port) and l.split()[3] == "0A"]
sys.exit(0 if addrs == ["0100007F"] else 1)
PY
  # halted, waiting for gdb: no busy loop (CPU time of mmsim over a second of wall time)
  if [ "$name" = board ]; then
    local pid t0 t1
    pid=$(pgrep -P "$MPID" | head -1)
    t0=$(awk '{print $14 + $15}' "/proc/$pid/stat" 2>/dev/null || echo 0); sleep 1
    t1=$(awk '{print $14 + $15}' "/proc/$pid/stat" 2>/dev/null || echo 999)
    [ $((t1 - t0)) -le 20 ] && ok "$name: halted, mmsim used $((t1 - t0)) clock ticks of CPU in 1 s (no busy loop)" \
      || bad "$name: halted, mmsim used $((t1 - t0)) clock ticks of CPU in 1 s"
  fi
  printf 'set confirm off\nset pagination off\ntarget remote :%s\n%s\n' "$port" "$cmds" >"$T/$name.cmds"
  if [ "$name" = gone ]; then # gdb killed by a signal at the breakpoint: its socket closes
    timeout 60 avr-gdb -batch -nx -x "$T/$name.cmds" "$ELF" >"$T/$name.gdb" 2>&1 &
    local gpid=$!
    for _ in $(seq 300); do grep -q '^Breakpoint 1,' "$T/$name.gdb" 2>/dev/null && break; sleep 0.1; done
    kill -9 $(pgrep -P $gpid) 2>/dev/null; wait $gpid 2>/dev/null
  else
    timeout 60 avr-gdb -batch -nx -x "$T/$name.cmds" "$ELF" >"$T/$name.gdb" 2>&1
  fi
  echo $? >"$T/$name.gdbrc"
  wait $MPID
  echo $? >"$T/$name.rc"
  MPID=; }
# same NAME PLAIN: the session's JSON equals the plain run's, but for the wall clock
same() { local a b
  a=$(strip "$T/$1.json" 2>&1); b=$(strip "$T/$2.json" 2>&1)
  [ -n "$a" ] && [ "$a" = "$b" ] && ok "$1: the JSON equals the run's without --gdb" \
    || bad "$1: the JSON differs from the run's without --gdb: $(diff <(echo "$a" | tr , '\n') <(echo "$b" | tr , '\n') | head -6)"
  [ "$(cat "$T/$1.rc")" = "$(cat "$T/$2.rc")" ] && ok "$1: mmsim's exit code as without --gdb ($(cat "$T/$2.rc"))" \
    || bad "$1: mmsim exit $(cat "$T/$1.rc"), without --gdb $(cat "$T/$2.rc")"; }

"$MMSIM" "${BOARD[@]}" >"$T/plain.json" 2>"$T/plain.err"; echo $? >"$T/plain.rc"
grep -q '"COUNT 1\\r\\nCOUNT 2' "$T/plain.json" && ok "GdbProbe prints its counts" || bad "GdbProbe's console: $(head -c 300 "$T/plain.json")"

# ---- the board: break, read, next, step, continue, halted in wall time, disconnect ----
session board "break probe_tick
continue
print probe_count
next
next
print probe_count
next
step
continue
print probe_count
shell sleep 1
delete
disconnect" "${BOARD[@]}"
[ "$(cat "$T/board.gdbrc")" = 0 ] && ok "board: avr-gdb's script ran (exit 0)" || bad "board: avr-gdb exit $(cat "$T/board.gdbrc"): $(tail -3 "$T/board.gdb")"
[ "$(grep -c '^Breakpoint 1, probe_tick () at test/firmware/arduino/board/GdbProbe.ino:11' "$T/board.gdb")" = 2 ] \
  && ok "board: stopped at probe_tick twice, by file and line" || bad "board: breakpoint hits: $(grep -m3 'Breakpoint' "$T/board.gdb")"
grep -q '^\$1 = 0$' "$T/board.gdb" && ok "board: probe_count 0 at the first hit" || bad "board: \$1: $(grep -m1 '^\$1' "$T/board.gdb")"
grep -q '^\$2 = 1$' "$T/board.gdb" && ok "board: 1 after next over its increment" || bad "board: \$2: $(grep -m1 '^\$2' "$T/board.gdb")"
grep -q '^14	  Serial.println(probe_count);$' "$T/board.gdb" && ok "board: next went to line 14" || bad "board: next: $(cat "$T/board.gdb")"
grep -q '^println (.*) at .*/cores/arduino/Print.cpp:[0-9]*$' "$T/board.gdb" && ok "board: step went into the core's Print::println" \
  || bad "board: step: $(cat "$T/board.gdb")"
grep -q '^\$3 = 1$' "$T/board.gdb" && ok "board: 1 at the second hit (before its increment)" || bad "board: \$3: $(grep -m1 '^\$3' "$T/board.gdb")"
same board plain

# ---- kill from gdb: simavr's stub ignores it, gdb closes: the run goes on to its end ----
session kill "break probe_tick
continue
kill" "${BOARD[@]}"
grep -q "killed" "$T/kill.gdb" && ok "kill: gdb killed the session" || bad "kill: $(tail -2 "$T/kill.gdb")"
same kill plain

# ---- gdb killed by a signal while the firmware is halted: the run goes on to its end ----
session gone "break probe_tick
continue
python import time; time.sleep(30)" "${BOARD[@]}"
grep -q '^Breakpoint 1,' "$T/gone.gdb" && ok "gone: gdb was at the breakpoint when killed" || bad "gone: $(tail -2 "$T/gone.gdb")"
same gone plain

# ---- the same image as a link MCU (--avr alone, pil.c): continue, stepi, disconnect ----
PIL=(--maze "$T/open.txt" --avr "$ELF" --time-limit 1 --json)
"$MMSIM" "${PIL[@]}" >"$T/pilplain.json" 2>"$T/pilplain.err"; echo $? >"$T/pilplain.rc"
session pil "break probe_tick
continue
stepi
print probe_count
disconnect" "${PIL[@]}"
grep -q '^\$1 = 0$' "$T/pil.gdb" && ok "pil: probe_count 0 at the first hit" || bad "pil: $(tail -3 "$T/pil.gdb")"
same pil pilplain

grep -q 'Sanitizer\|runtime error' "$T"/*.err && bad "a sanitizer report: $(grep -h -m1 'ERROR\|runtime error' "$T"/*.err)"
[ $fails -eq 0 ] || { echo "cli_gdb: $fails failed"; exit 1; }
echo "cli_gdb: all passed"

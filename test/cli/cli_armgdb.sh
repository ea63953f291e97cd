#!/usr/bin/env bash
# cli_armgdb.sh - the gdb stub of the ARM core (sim/arm/armgdb.c) driven by
# Debian's gdb-multiarch in batch mode and by a raw client. Our firmware
# test/firmware/arm/gdbtest.c runs on the core alone (test/tools/armgdb_probe.c, 1 ms
# steps as a physics loop takes them) with --gdb on a free port: gdb reads
# the m-profile target description, breaks on gdb_tick, reads globals of
# four types, steps and nexts by line, breaks in the SysTick handler (IPSR
# 15), is refused peripheral and PPB reads and flash writes, and waits a
# second halted (no busy loop); the probe's final state (cycles, registers,
# an SRAM hash) equals the run's without gdb. Also: the stub listens on
# 127.0.0.1 only; gdb's kill, continuing to the run's end (exited
# normally), an hbreak (Z1) and a stepi over WFI (into the handler that woke
# it), stepping by breakpoints (osabi GNU/Linux) and a raw client's
# interrupt (0x03) while the core runs leave the run as it was; a crash
# halts for gdb (SIGSEGV) and then ends as without it, its cause decoded;
# SRAM writes are seen; a port in use is one line, exit 3. Every process
# under timeout. SKIP only without gdb-multiarch or arm-none-eabi-gcc.
set -u
B=${BUILD:-build}
T=$(mktemp -d)
PPID_=
trap '[ -n "$PPID_" ] && kill "$PPID_" 2>/dev/null; rm -rf "$T"' EXIT
. "$(dirname "$0")/lib.sh"
command -v gdb-multiarch >/dev/null || { echo "SKIP cli_armgdb: gdb-multiarch not installed (Debian package gdb-multiarch)"; exit 77; }
command -v arm-none-eabi-gcc >/dev/null || { echo "SKIP cli_armgdb: arm-none-eabi-gcc not installed"; exit 77; }
mk() { env -u MAKEFLAGS -u MFLAGS -u MAKELEVEL make --no-print-directory B="$B" "$@"; }
ELF=$B/arm/gdbtest.elf
PROBE=$B/test/armgdb_probe
want_rc 0 "gdbtest.elf and armgdb_probe build" mk "$ELF" "$PROBE"
free_port() { python3 -c "import socket; s=socket.socket(); s.bind(('127.0.0.1', 0)); print(s.getsockname()[1])"; }
MS=50

# start NAME MS: the probe with --gdb on a free port in the background (PORT, PPID_), once it listens
start() { PORT=$(free_port)
  timeout 120 "$PROBE" "$ELF" "$2" --gdb "$PORT" >"$T/$1.out" 2>"$T/$1.err" &
  PPID_=$!
  for _ in $(seq 300); do grep -q "halted until gdb attaches" "$T/$1.err" 2>/dev/null && break; sleep 0.1; done
  grep -q "halted until gdb attaches to 127.0.0.1:$PORT" "$T/$1.err" && ok "$1: the probe waits for gdb on 127.0.0.1:$PORT" \
    || bad "$1: the probe's line: $(head -2 "$T/$1.err")"; }
# finish NAME: the probe's exit code into NAME.rc
finish() { wait "$PPID_"; echo $? >"$T/$1.rc"; PPID_=; }
# run_gdb NAME GDB-COMMANDS: gdb-multiarch's commands (one a line, each an -ex: an error does not end the
# script) after `target remote :PORT`, its output in NAME.gdb, its exit code in NAME.gdbrc. `set osabi
# none` (OSABI= to change it): Debian's gdb-multiarch otherwise takes the image for GNU/Linux and
# single-steps by breakpoints; with none it steps with the stub's s (vCont;s).
run_gdb() { local args=() line
  while IFS= read -r line; do args+=(-ex "$line"); done <<<"$2"
  timeout 120 gdb-multiarch -batch -nx -ex 'set confirm off' -ex 'set pagination off' -ex "set osabi ${OSABI:-none}" \
    -ex "target remote :$PORT" "${args[@]}" "$ELF" \
    >"$T/$1.gdb" 2>&1
  echo $? >"$T/$1.gdbrc"; }
# session NAME MS GDB-COMMANDS: the probe for MS ms with gdb's commands
session() { start "$1" "$2"; run_gdb "$1" "$3"; finish "$1"; }
# same NAME PLAIN: the probe's final state and exit code as without gdb
same() { [ -s "$T/$2.out" ] && cmp -s "$T/$1.out" "$T/$2.out" && [ "$(cat "$T/$1.rc")" = "$(cat "$T/$2.rc")" ] \
    && ok "$1: the final state (cycles, registers, SRAM hash) equals the run's without gdb" \
    || bad "$1: the final state differs: $(cat "$T/$1.out") vs $(cat "$T/$2.out") (exit $(cat "$T/$1.rc") vs $(cat "$T/$2.rc"))"; }
has() { grep -q -- "$2" "$T/$1.gdb" && ok "$1: $3" || bad "$1: $3: no '$2' in: $(tail -20 "$T/$1.gdb")"; }

"$PROBE" "$ELF" $MS >"$T/plain.out" 2>"$T/plain.err"; echo $? >"$T/plain.rc"
grep -q "^cycles 400000 time_ps 50000000000 " "$T/plain.out" && ok "plain: 50 ms at 8 MHz: 400000 cycles" || bad "plain: $(cat "$T/plain.out" "$T/plain.err")"

# ---- break, read, step, next, the handler, refused memory, halted in wall time ----
start main $MS
python3 - "$PORT" <<'PY' && ok "main: listening on 127.0.0.1 only" || bad "main: not on 127.0.0.1 only"
import sys
port = "%04X" % int(sys.argv[1])
addrs = [l.split()[1].split(":")[0] for l in open("/proc/net/tcp").read().splitlines()[1:]
         if l.split()[1].endswith(":" + port) and l.split()[3] == "0A"]
sys.exit(0 if addrs == ["0100007F"] else 1)
PY
pid=$(pgrep -P "$PPID_" | head -1)
t0=$(awk '{print $14 + $15}' "/proc/$pid/stat" 2>/dev/null || echo 0); sleep 1
t1=$(awk '{print $14 + $15}' "/proc/$pid/stat" 2>/dev/null || echo 999)
[ $((t1 - t0)) -le 20 ] && ok "main: halted, the probe used $((t1 - t0)) clock ticks of CPU in 1 s (no busy loop)" \
  || bad "main: halted, the probe used $((t1 - t0)) clock ticks of CPU in 1 s"
run_gdb main "info registers
break gdb_tick
continue
print g_count
print k
continue
print g_count
print g_speed
print g_gain
step
next
print g_count
print/x \$pc
x/1xw 0x40010800
x/1xw 0xE000E010
print gains[1]
print gains[1] = 7
break systick_handler
continue
print \$xpsr & 0x1ff
print g_ticks
shell sleep 1
delete
disconnect"
finish main
[ "$(cat "$T/main.gdbrc")" = 0 ] && ok "main: gdb-multiarch's script ran (exit 0)" || bad "main: gdb exit $(cat "$T/main.gdbrc"): $(tail -5 "$T/main.gdb")"
has main '^reset_handler () at test/firmware/arm/startup.c:' "halted at the first instruction (the reset handler)"
has main '^xpsr  *0x1000000 ' "the m-profile registers (xpsr: the Thumb bit)"
has main '^sp  *0x20005000 ' "sp from the vector table"
[ "$(grep -c '^Breakpoint 1, gdb_tick (k=k@entry=[12]) at test/firmware/arm/gdbtest.c:19' "$T/main.gdb")" = 2 ] \
  && ok "main: stopped at gdb_tick twice (k 1, 2), by file and line" || bad "main: breakpoint hits: $(grep 'Breakpoint' "$T/main.gdb")"
has main '^\$1 = 0$' "g_count 0 at the first hit"
has main '^\$2 = 1$' "the argument k = 1"
has main '^\$3 = 1$' "g_count 1 at the second hit"
has main '^\$4 = -2$' "g_speed (int16_t) -2"
has main '^\$5 = 1.25$' "g_gain (float) 1.25"
has main '^20	    g_speed = (int16_t)(g_speed + 3);$' "step went to line 20"
has main '^21	    g_gain = gains\[k & 3u\];$' "next went to line 21"
has main '^\$6 = 3$' "g_count 3 after its line"
grep -q '^0x40010800:	Cannot access memory at address 0x40010800' "$T/main.gdb" && grep -q '^0xe000e010:	Cannot access memory at address 0xe000e010' "$T/main.gdb" \
  && ok "main: peripheral and PPB memory refused (reading a model could change it)" || bad "main: peripheral reads: $(grep -i -A1 '0x40010800\|0xe000e010' "$T/main.gdb")"
has main '^\$8 = 1.25$' "flash read (a const table)"
has main '^Cannot access memory at address 0x80001c8' "flash write refused"
has main '^Breakpoint 2, systick_handler () at test/firmware/arm/gdbtest.c:' "a breakpoint in the SysTick handler"
has main '^\$9 = 15$' "IPSR 15 (SysTick) in the handler"
has main '^\$10 = 1$' "g_ticks 1 at the second tick's handler (before its increment)"
same main plain

# ---- gdb's kill: the connection ends, the run goes on to its end ----
session kill $MS "break gdb_tick
continue
kill"
has kill '^Breakpoint 1, gdb_tick' "stopped at gdb_tick"
OSABI=GNU/Linux session linux $MS "break gdb_tick
continue
next
next
print g_speed
delete
disconnect"
has linux '^\$1 = -2$' "osabi GNU/Linux (gdb steps by breakpoints): next, next: g_speed -2"
same kill plain

# ---- continue to the run's end: gdb is told the program exited ----
session end $MS "continue"
has end '^\[Inferior 1 (Remote target) exited normally\]' "the run's end: exited normally (W00)"
same end plain

# ---- a crash halts for gdb (SIGSEGV, registers readable), then the run ends as without gdb ----
session crash $MS "break gdb_tick
continue
set var \$pc = 0x60000000
continue
print/x \$pc
continue"
has crash '^Program received signal SIGSEGV' "a bus fault fetching 0x60000000: gdb sees SIGSEGV"
has crash '^\$1 = 0x60000000$' "the PC readable at the crash"
has crash '^Program terminated with signal SIGSEGV' "continue: the program terminated (X0b)"
[ "$(cat "$T/crash.rc")" = 1 ] && grep -q '^crashed at 0x60000000: HardFault: bus fault fetching 0x60000000 .*(CFSR 0x00000100: IBUSERR, HFSR 0x40000000: FORCED; stacked PC 0x60000000)$' "$T/crash.out" \
  && ok "crash: the probe's cause decodes CFSR (IBUSERR) and HFSR (FORCED) with the stacked PC, exit 1" || bad "crash: exit $(cat "$T/crash.rc"): $(cat "$T/crash.out")"

# ---- hbreak (Z1) at the WFI; stepi over it ends when the core wakes: in the SysTick handler ----
session wfi $MS "hbreak *0x080001bc
continue
stepi
print \$xpsr & 0x1ff
delete
disconnect"
has wfi '^Hardware assisted breakpoint 1 at 0x80001bc' "hbreak: a Z1 breakpoint"
has wfi '^Breakpoint 1, main () at test/firmware/arm/gdbtest.c:33' "stopped at the WFI (0x080001bc)"
has wfi '^systick_handler () at test/firmware/arm/gdbtest.c:24' "stepi over the WFI: the SysTick handler's first instruction"
has wfi '^\$1 = 15$' "IPSR 15"
same wfi plain

# ---- an SRAM write is seen by the firmware ----
session write $MS "break gdb_tick
continue
set var g_count = 1000
continue
print g_count
delete
disconnect"
has write '^\$1 = 1001$' "g_count written 1000, then 1001 at the next hit"
grep -q "^cycles 400000 " "$T/write.out" && ! cmp -s "$T/write.out" "$T/plain.out" && ok "write: the run went on with the written SRAM" \
  || bad "write: $(cat "$T/write.out")"

# ---- a raw client: bad checksum answered -, the interrupt byte while running, D ----
start raw 4000
"$PROBE" "$ELF" 4000 >"$T/plain4000.out" 2>/dev/null; echo $? >"$T/plain4000.rc"
timeout 60 python3 - "$PORT" >"$T/raw.py" 2>&1 <<'PY'
import socket, sys, time
s = socket.create_connection(("127.0.0.1", int(sys.argv[1])))
def pkt(d): return b"$" + d + b"#%02x" % (sum(d) & 0xFF)
def read_reply():
    buf = b""
    while not (b"$" in buf and b"#" in buf[buf.index(b"$"):] and len(buf) >= buf.rindex(b"#") + 3):
        c = s.recv(4096)
        if not c: sys.exit("closed")
        buf += c
    s.sendall(b"+")
    return buf[buf.index(b"$") + 1:buf.rindex(b"#")]
s.sendall(b"$g#00"); ack = s.recv(1); print("bad checksum:", ack.decode())
s.sendall(pkt(b"?")); print("stop:", read_reply().decode())
s.sendall(pkt(b"qXfer:features:read:target.xml:0,fff")); x = read_reply(); print("tdesc:", x[:1].decode(), b"org.gnu.gdb.arm.m-profile" in x)
s.sendall(pkt(b"c")); time.sleep(0.05); s.sendall(b"\x03"); print("interrupt:", read_reply().decode())
s.sendall(pkt(b"p10")); print("xpsr:", read_reply().decode())
s.sendall(pkt(b"m40000000,4")); print("periph:", read_reply().decode())
s.sendall(pkt(b"D")); print("detach:", read_reply().decode())
PY
finish raw
grep -q '^bad checksum: -$' "$T/raw.py" && ok "raw: a bad checksum is answered -" || bad "raw: $(cat "$T/raw.py")"
grep -q '^stop: S05$' "$T/raw.py" && ok "raw: ? answers S05" || bad "raw: $(cat "$T/raw.py")"
grep -q '^tdesc: l True$' "$T/raw.py" && ok "raw: the target description, whole in one reply" || bad "raw: $(cat "$T/raw.py")"
grep -q '^interrupt: S02$' "$T/raw.py" && ok "raw: the interrupt byte halts the running core (S02)" || bad "raw: $(cat "$T/raw.py")"
grep -q '^xpsr: ........$' "$T/raw.py" && ok "raw: p 16 is xpsr" || bad "raw: $(cat "$T/raw.py")"
grep -q '^periph: E01$' "$T/raw.py" && ok "raw: a peripheral read refused (E01)" || bad "raw: $(cat "$T/raw.py")"
grep -q '^detach: OK$' "$T/raw.py" && ok "raw: D answers OK" || bad "raw: $(cat "$T/raw.py")"
same raw plain4000

# ---- 1,000 seeded random packets (framed or not, over-long ones, bad numbers), then D: no sanitizer report ----
start fuzz $MS
timeout 120 python3 - "$PORT" >"$T/fuzz.py" 2>&1 <<'PY'
import random, socket, sys
random.seed(39)
s = socket.create_connection(("127.0.0.1", int(sys.argv[1])))
s.settimeout(0.02)
def pkt(d): return b"$" + d + b"#%02x" % (sum(d) & 0xFF)
heads = [b"g", b"G", b"p", b"P", b"m", b"M", b"Z", b"z", b"q", b"qXfer:features:read:", b"qXfer:features:read:target.xml:",
         b"v", b"vCont", b"H", b"?", b"X", b"T", b"-"]
for _ in range(1000):
    d = random.choice(heads) + bytes(random.choice(b"0123456789abcdefABCDEF,:;=xyz-}*") for _ in range(random.randint(0, 40)))
    if random.random() < 0.03: d = random.choice(heads) + b"f" * random.randint(4000, 9000)
    s.sendall(pkt(d) if random.random() > 0.05 else d)
    try: s.recv(100000)
    except socket.timeout: pass
s.settimeout(10)
s.sendall(pkt(b"D"))
buf = b""
while b"$OK#9a" not in buf:
    c = s.recv(100)
    if not c: break
    buf += c
print("detach:", b"$OK#9a" in buf)
PY
finish fuzz
grep -q '^detach: True$' "$T/fuzz.py" && ok "fuzz: 1,000 random packets, then D answered OK" || bad "fuzz: $(tail -3 "$T/fuzz.py")"
grep -q 'runtime error\|Sanitizer' "$T/fuzz.err" && bad "fuzz: $(grep -m3 'runtime error\|Sanitizer' "$T/fuzz.err")" \
  || { [ "$(cat "$T/fuzz.rc")" -le 1 ] && ok "fuzz: no sanitizer report, the run ended (exit $(cat "$T/fuzz.rc"))" || bad "fuzz: exit $(cat "$T/fuzz.rc")"; }

# ---- a port in use: one line, exit 3 ----
PORT=$(free_port)
python3 -c "
import socket, sys, time
s = socket.socket(); s.bind(('127.0.0.1', int(sys.argv[1]))); s.listen(1); open(sys.argv[2], 'w').close(); time.sleep(30)" "$PORT" "$T/held" &
HOLD=$!
for _ in $(seq 100); do [ -f "$T/held" ] && break; sleep 0.1; done
ONE_ERROR_LINE=1 want_rc 3 "a port in use: exit 3" timeout 60 "$PROBE" "$ELF" $MS --gdb "$PORT"
grep -q "armgdb_probe: --gdb $PORT: cannot listen on 127.0.0.1:$PORT: Address already in use" "$T/err" \
  && ok "a port in use: says so" || bad "a port in use: $(cat "$T/err")"
kill $HOLD 2>/dev/null; wait $HOLD 2>/dev/null

[ $fails -eq 0 ] || { echo "$fails failed"; exit 1; }
echo "all passed"

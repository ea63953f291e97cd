#!/usr/bin/env bash
# cli_watch.sh - the firmware's global variables by name (mmsim --board ...
# --watch NAME[,NAME...], sim/board/watch.c) on LCM channel MM_WATCH and in
# the report. WatchProbe (test/firmware/arduino/board) counts `ticks` up every 10 ms
# by millis() and prints "TICK n ms". Sampled every step (--lcm-rate 1000):
# ticks never goes back nor jumps, takes each printed value within one step
# and one millis() tick of the millis() printed with it; the float, the
# int32, the int8 and a C++ static's int16 derived from it decode exactly
# (types from DWARF); the
# run's JSON is the same with and without --watch; the report's table
# holds the variables beside the pose. The same with --avr alone
# (processor in the loop). An image without DWARF is read by size (one note
# line, the same ticks); bad names and images, crafted symbol tables and
# DWARF: one line, exit 2. WatchLto (an -flto build whose statics the
# linker renamed NAME.lto_priv.N): by the source name and by the symbol, a
# float from DWARF; two statics of one name: one line, exit 2.
set -u
B=${BUILD:-build}
SHARED=${SHARED:-../shared}
MMSIM=${MMSIM:-$B/mmsim}
MMLOG=${MMLOG:-$B/mmlog}
T=$(mktemp -d); trap 'rm -rf "$T"' EXIT
. "$(dirname "$0")/lib.sh"
mk() { env -u MAKEFLAGS -u MFLAGS -u MAKELEVEL make --no-print-directory B="$B" SHARED="$SHARED" "$@"; }
SK=$B/clients/board
IMG=$SK/WatchProbe.elf
VARS=ticks,ratio,offset,small,down

want_rc 0 "WatchProbe builds for the Nano" mk "$IMG"
run() { "$MMSIM" --maze mazes/gen-5x5-s1.txt --board ukmarsbot --robot robots/ukmarsbot.ini --time-limit 2 --json "$@"; }

want_rc 1 "--watch with LCM telemetry and --report" run --avr "$IMG" --watch "$VARS" --lcm-log "$T/w.lcmlog" \
  --lcm-rate 1000 --report "$T/rep.png"
cp "$T/out" "$T/watch.json"
[ -s "$T/err" ] && bad "--watch with DWARF: no note expected: $(cat "$T/err")"
want_rc 1 "the same run without --watch, telemetry or report" run --avr "$IMG"
[ "$(strip "$T/watch.json")" = "$(strip "$T/out")" ] && ok "the JSON is the same with and without --watch" \
  || bad "the JSON differs with --watch"
want_rc 0 "mmlog decodes MM_WATCH" "$MMLOG" --json "$T/w.lcmlog"
cp "$T/out" "$T/sum.json"
"$MMLOG" --dump MM_WATCH "$T/w.lcmlog" >"$T/watch.jsonl"

python3 - "$T" <<'EOF' && ok "ticks each step = the console's; float, int32, int8 decode; report table" || bad "watched values"
import json, sys
T = sys.argv[1]
run = json.loads(open(T + "/watch.json").read().splitlines()[-1])
summ = json.loads(open(T + "/sum.json").read())
msgs = [json.loads(l) for l in open(T + "/watch.jsonl")]
rep = json.load(open(T + "/rep.json"))
fails = []
def check(cond, what):
    if not cond: fails.append(what)
steps = round(run["sim_time_s"] * 1000)  # 1 ms physics steps, all sampled at --lcm-rate 1000
check(summ["MM_WATCH"]["count"] == steps and summ["MM_WATCH"]["bad"] == 0, "MM_WATCH %s, want %d" % (summ["MM_WATCH"], steps))
check([m["utime"] for m in msgs] == [1000 * (i + 1) for i in range(steps)], "one MM_WATCH per step, at the step's time")
check(all(m["name"] == ["ticks", "ratio", "offset", "small", "down"] for m in msgs), "names")
check(all(m["type"] == ["u16", "f32", "i32", "i8", "i16"] for m in msgs), "types from DWARF: %s" % msgs[0]["type"])
ticks = [m["value"][0] for m in msgs]
check(ticks[0] in (0, 1) and all(b - a in (0, 1) for a, b in zip(ticks, ticks[1:])), "ticks monotonic by one")
printed = [tuple(int(x) for x in l.split()[1:3]) for l in run["console"].splitlines() if l.startswith("TICK ")]
check(len(printed) > 150 and [n for n, _ in printed] == list(range(1, len(printed) + 1)), "the console's counts")
first = {}
for m in msgs: first.setdefault(int(m["value"][0]), m["utime"])
# the firmware counts at millis() = ms, which lags the simulated time by less than one millis()
# tick (1024 us); the next step's sample shows it, at most one step (1000 us) later
for n, ms in printed:
    check(n in first and ms * 1000 < first[n] <= ms * 1000 + 1024 + 1000,
          "ticks %d printed at millis %d, first sampled at %s us" % (n, ms, first.get(n)))
check(int(ticks[-1]) in (printed[-1][0], printed[-1][0] + 1), "the last sample %d, the last print %d" % (ticks[-1], printed[-1][0]))
check(set(first) - {0} <= {n for n, _ in printed} | {printed[-1][0] + 1}, "a sampled value the firmware never printed")
def derived(t): return [t / 8.0, -100000.0 - 3 * t, float(-(t % 100)), float(-t)]
exact = sum(m["value"][1:] == derived(m["value"][0]) for m in msgs)
# a step may end between the firmware's writes of ticks and of the rest: then the rest not yet written is the last count's
def plausible(v):
    now, last = derived(v[0]), derived(max(v[0] - 1, 0))
    return all(x in (a, b) for x, a, b in zip(v[1:], now, last))
check(all(plausible(m["value"]) for m in msgs), "derived values: %s" % [m for m in msgs if not plausible(m["value"])][:2])
check(exact >= 0.95 * len(msgs), "derived values exact in %d of %d samples" % (exact, len(msgs)))
w = rep.get("watch", {})
check(w.get("columns") == ["t_s", "x_m", "y_m", "heading_rad", "ticks", "ratio", "offset", "small", "down"], "report columns %s" % w.get("columns"))
rows = w.get("rows", [])
check(len(rows) == rep["trajectory_samples"] and len(rows) > 300, "report rows %d" % len(rows))
by_t = {round(m["utime"] * 1e-6, 6): m["value"] for m in msgs}
check(all(by_t.get(round(r[0], 6)) == r[4:] for r in rows), "report rows = MM_WATCH at their times")
for f in fails: print("  " + f)
sys.exit(1 if fails else 0)
EOF

# ---- --avr without a board (processor in the loop): the same sampling ----
pil() { "$MMSIM" --maze mazes/gen-5x5-s1.txt --avr "$IMG" --time-limit 1 --json "$@"; }
want_rc 1 "--avr --watch" pil --watch ticks,ratio --lcm-log "$T/p.lcmlog" --lcm-rate 1000
cp "$T/out" "$T/pil.json"
want_rc 1 "--avr without --watch" pil
[ "$(strip "$T/pil.json")" = "$(strip "$T/out")" ] && ok "--avr: the JSON is the same with and without --watch" \
  || bad "--avr: the JSON differs with --watch"
"$MMLOG" --dump MM_WATCH "$T/p.lcmlog" >"$T/p.jsonl"
python3 - "$T" <<'PY' && ok "--avr: ticks each step, by one, the float with it" || bad "--avr: watched values"
import json, sys
m = [json.loads(l) for l in open(sys.argv[1] + "/p.jsonl")]
t = [x["value"][0] for x in m]
ok = len(m) == 1000 and [x["utime"] for x in m] == [1000 * (i + 1) for i in range(1000)]
ok = ok and all(b - a in (0, 1) for a, b in zip(t, t[1:])) and 97 <= t[-1] <= 100
ok = ok and all(x["value"][1] in (x["value"][0] / 8, (x["value"][0] - 1) / 8) for x in m)
sys.exit(0 if ok else 1)
PY

# ---- no DWARF: read by size, said once per variable on stderr ----
avr-objcopy --strip-debug "$IMG" "$T/nodwarf.elf"
want_rc 1 "an image without DWARF" run --avr "$T/nodwarf.elf" --watch ticks,ratio --lcm-log "$T/n.lcmlog" --lcm-rate 1000
grep -q "^mmsim: --watch: $T/nodwarf.elf has no DWARF type for 'ratio': read as u32 (an unsigned integer of its size)$" "$T/err" \
  && [ "$(wc -l <"$T/err")" -eq 2 ] && ok "without DWARF: one note per variable" || bad "without DWARF: note: $(cat "$T/err")"
"$MMLOG" --dump MM_WATCH "$T/n.lcmlog" >"$T/n.jsonl"
python3 - "$T" <<'EOF' && ok "without DWARF: the same ticks, the float's raw bits" || bad "without DWARF: values"
import json, struct, sys
T = sys.argv[1]
a = [json.loads(l)["value"] for l in open(T + "/watch.jsonl")]
b = [json.loads(l) for l in open(T + "/n.jsonl")]
ok = len(a) == len(b) and all(x[0] == y["value"][0] for x, y in zip(a, b)) and b[0]["type"] == ["u16", "u32"]
ok = ok and all(struct.unpack("<f", struct.pack("<I", int(y["value"][1])))[0] == x[1] for x, y in zip(a, b))
sys.exit(0 if ok else 1)
EOF

# ---- bad input: one line, exit 2 ----
ONE_ERROR_LINE=1
avr-objcopy -O ihex "$IMG" "$T/probe.hex"
avr-strip -s -o "$T/stripped.elf" "$IMG"
want_rc 2 "an unknown name" run --avr "$IMG" --watch ticks,foo
grep -qx "mmsim: --watch: no global variable 'foo' in $IMG" "$T/err" && ok "unknown name: its line" || bad "unknown name: $(cat "$T/err")"
want_rc 2 "a HEX image" run --avr "$T/probe.hex" --watch ticks
grep -q "Intel HEX: --watch needs the ELF image" "$T/err" && ok "HEX: its line" || bad "HEX: $(cat "$T/err")"
want_rc 2 "a stripped ELF" run --avr "$T/stripped.elf" --watch ticks
grep -q "has no symbol table" "$T/err" && ok "stripped: its line" || bad "stripped: $(cat "$T/err")"
want_rc 2 "an array" run --avr "$IMG" --watch history
grep -q "'history' in .*: its type is an array: --watch reads 8/16/32-bit integers and floats" "$T/err" \
  && ok "array: its line" || bad "array: $(cat "$T/err")"
want_rc 2 "a variable in flash" run --avr "$IMG" --watch banner
grep -q "'banner' in .* is not in SRAM" "$T/err" && ok "flash: its line" || bad "flash: $(cat "$T/err")"
want_rc 2 "an empty name" run --avr "$IMG" --watch ticks,,ratio
# crafted images: bytes of the symbol table, its strings and the DWARF changed
# (a fixed seed); each run looks up two names (the DWARF walked) then one that
# is not there: exit 2 with one line, never a signal or a sanitizer's report
python3 - "$IMG" "$T" <<'PY'
import random, struct, sys
b = open(sys.argv[1], "rb").read()
shoff, = struct.unpack_from("<I", b, 0x20)
shentsize, shnum, shstrndx = struct.unpack_from("<HHH", b, 0x2E)
sh = [struct.unpack_from("<IIIIII", b, shoff + i * shentsize) for i in range(shnum)]
strs = b[sh[shstrndx][4]:]
secs = {strs[h[0]:strs.index(b"\0", h[0])].decode(): (h[4], h[5]) for h in sh}
rng = random.Random(23)
for k in range(40):
    off, size = secs[[".symtab", ".strtab", ".debug_info", ".debug_abbrev", ".debug_str"][k % 5]]
    m = bytearray(b)
    for _ in range(1 + k % 4):
        m[off + rng.randrange(size)] = rng.randrange(256)
    open("%s/mut%02d.elf" % (sys.argv[2], k), "wb").write(m)
PY
for f in "$T"/mut*.elf; do
  want_rc 2 "crafted image $(basename "$f")" run --avr "$f" --watch ratio,offset,nope
  grep -q "AddressSanitizer\|runtime error" "$T/err" && bad "$(basename "$f"): a sanitizer's report"
done
want_rc 2 "--watch without --avr" "$MMSIM" --maze mazes/gen-5x5-s1.txt --watch ticks

# ---- an LTO build (test/firmware/arduino/board/WatchLto): -flto renames each file-scope static whose
# name two files share NAME.lto_priv.N; --watch finds it by its source name in DWARF (its
# DW_AT_location, its float type) and types its renamed symbol from DWARF too ----
ONE_ERROR_LINE=
want_rc 0 "WatchLto builds (-flto)" python3 tools/arduino-build test/firmware/arduino/board/WatchLto --board nano \
  -o "$T/lto/WatchLto.elf" --cache "$B/arduino-build" --warnings more
LTO=$T/lto/WatchLto.elf
SYM=$(avr-nm "$LTO" | awk '$2 == "b" && $3 ~ /^_ZL13s_robot_angle\.lto_priv\./ {print $3}')
[ -n "$SYM" ] && ok "the SRAM static's symbol is renamed: $SYM" || bad "no _ZL13s_robot_angle.lto_priv.N in SRAM: $(avr-nm "$LTO" | grep s_robot)"
for name in s_robot_angle "$SYM"; do
  want_rc 1 "--watch $name (LTO)" run --avr "$LTO" --watch "$name" --lcm-log "$T/l.lcmlog" --lcm-rate 1000
  [ -s "$T/err" ] && bad "--watch $name: no note expected: $(cat "$T/err")"
  "$MMLOG" --dump MM_WATCH "$T/l.lcmlog" >"$T/l.jsonl"
  python3 - "$T/l.jsonl" "$T/out" "$name" <<'PY' && ok "--watch $name: f32 from DWARF, the angles the console printed" || bad "--watch $name: values"
import json, sys
m = [json.loads(l) for l in open(sys.argv[1])]
con = json.loads(open(sys.argv[2]).read().splitlines()[-1])["console"]
printed = {float(l.split()[1]) for l in con.splitlines() if l.startswith("ANGLE ")}
v = [x["value"][0] for x in m]
ok = len(m) == 2000 and all(x["type"] == ["f32"] and x["name"] == [sys.argv[3]] for x in m)
ok = ok and len(printed) > 150 and v[-1] in printed | {max(printed) + 0.5} and set(v) - {0.0} <= printed | {max(printed) + 0.5}
ok = ok and all(b - a in (0, 0.5) for a, b in zip(v, v[1:]))
print(m[0]["type"], v[-1], max(printed)); sys.exit(0 if ok else 1)
PY
done
ONE_ERROR_LINE=1
want_rc 2 "--watch s_count: two SRAM statics of that name (LTO)" run --avr "$LTO" --watch s_count
grep -q "^mmsim: --watch: 's_count' in .*: its DWARF has two variables of that name (at 0x8001.. and 0x8001..): watch one by its symbol" "$T/err" \
  && ok "two statics of one name: its line" || bad "two statics: $(cat "$T/err")"
echo "$fails failed"
[ "$fails" -eq 0 ]

#!/usr/bin/env bash
# cli_armwatch.sh - --watch on an ARM image (sim/arm/armwatch.c on the
# shared sim/io/elfvar.c): our firmware test/firmware/arm/gdbtest.c on the core
# alone (test/tools/armgdb_probe.c) for 50 ms; its globals read from SRAM with
# their DWARF types (u32, i16, f32) hold what the firmware computed after
# 50 calls of gdb_tick and 49 SysTick interrupts, and the run's final state
# (cycles, registers, SRAM hash) is the same as without --watch. Without
# DWARF the sizes type them (a note each); a struct, a flash constant, an
# unknown name and a stripped image are one line, exit 2.
set -u
B=${BUILD:-build}
T=$(mktemp -d)
trap 'rm -rf "$T"' EXIT
. "$(dirname "$0")/lib.sh"
command -v arm-none-eabi-gcc >/dev/null || { echo "SKIP cli_armwatch: arm-none-eabi-gcc not installed"; exit 77; }
mk() { env -u MAKEFLAGS -u MFLAGS -u MAKELEVEL make --no-print-directory B="$B" "$@"; }
ELF=$B/arm/gdbtest.elf
PROBE=$B/test/armgdb_probe
want_rc 0 "gdbtest.elf and armgdb_probe build" mk "$ELF" "$PROBE"

"$PROBE" "$ELF" 50 >"$T/plain.out" 2>&1 || bad "the plain run: $(cat "$T/plain.out")"
want_rc 0 "--watch g_count,g_speed,g_gain,g_ticks" "$PROBE" "$ELF" 50 --watch g_count,g_speed,g_gain,g_ticks
[ "$(grep '^watch ' "$T/out")" = "watch g_count u32 1275
watch g_speed i16 145
watch g_gain f32 -2
watch g_ticks u32 49" ] && ok "the values and DWARF types: 1+...+50, -5+3*50, gains[50 & 3], 49 ticks" || bad "watch: $(cat "$T/out" "$T/err")"
[ ! -s "$T/err" ] && ok "typed from DWARF: no note" || bad "a note: $(cat "$T/err")"
grep -v '^watch ' "$T/out" | cmp -s - "$T/plain.out" && ok "the final state equals the run's without --watch" \
  || bad "the state differs: $(head -1 "$T/out") vs $(cat "$T/plain.out")"

arm-none-eabi-strip -g -o "$T/nodebug.elf" "$ELF"
want_rc 0 "--watch on an image without DWARF" "$PROBE" "$T/nodebug.elf" 50 --watch g_speed
grep -q '^watch g_speed u16 145$' "$T/out" && grep -q "has no DWARF type for 'g_speed': read as u16" "$T/err" \
  && ok "without DWARF: typed by its size, with a note" || bad "no DWARF: $(cat "$T/out" "$T/err")"

ONE_ERROR_LINE=1
want_rc 2 "--watch mb (a struct): exit 2" "$PROBE" "$ELF" 50 --watch mb
grep -q "'mb' in $ELF: its type is a struct" "$T/err" && ok "a struct: says so" || bad "struct: $(cat "$T/err")"
want_rc 2 "--watch gains (a flash constant): exit 2" "$PROBE" "$ELF" 50 --watch gains
grep -q "'gains' in $ELF is not in SRAM (address 0x80001" "$T/err" && ok "a flash constant: not in SRAM" || bad "flash: $(cat "$T/err")"
want_rc 2 "--watch nope: exit 2" "$PROBE" "$ELF" 50 --watch nope
grep -q "no global variable 'nope' in $ELF" "$T/err" && ok "an unknown name: says so" || bad "unknown: $(cat "$T/err")"
arm-none-eabi-strip -o "$T/stripped.elf" "$ELF"
want_rc 2 "--watch on a stripped image: exit 2" "$PROBE" "$T/stripped.elf" 50 --watch g_count
grep -q "has no symbol table (a stripped image?)" "$T/err" && ok "a stripped image: says so" || bad "stripped: $(cat "$T/err")"

[ $fails -eq 0 ] || { echo "$fails failed"; exit 1; }
echo "all passed"

#!/usr/bin/env bash
# cli_client_bulebule.sh - Bulebots' bulebule (STM32F103, libopencm3) built
# unmodified from ../shared/clients/bulebule by `make client-bulebule`
# (tools/build-bulebule.sh), in a copy: an ARM ELF for a Cortex-M3 whose
# vector table sits at the start of flash and whose code and data fit the
# 63 KiB its linker script gives it (newlib-nano); the files the snapshot
# lost (tools/opencm3-compat) are added to the copy only. A missing source
# folder is one line and exit 3. Without ../shared: SKIP.
set -u
B=${BUILD:-build}
SHARED=${SHARED:-../shared}
SRC=$SHARED/clients/bulebule
T=$(mktemp -d); trap 'rm -rf "$T"' EXIT
. "$(dirname "$0")/lib.sh"
mk() { env -u MAKEFLAGS -u MFLAGS -u MAKELEVEL make --no-print-directory B="$B" SHARED="$SHARED" "$@"; }

want_rc 3 "build-bulebule without sources" tools/build-bulebule.sh "$T/none" "$T/out-none"
[ "$(wc -l < "$T/err")" = 1 ] && grep -q "^build-bulebule: $T/none: missing" "$T/err" \
  && ok "one line naming the folder" || bad "message: $(cat "$T/err")"

if [ ! -d "$SRC/src" ]; then
  echo "SKIP cli_client_bulebule: $SRC not found (../shared/clients)"
  [ $fails -eq 0 ] && exit 77 || exit 1
fi

want_rc 0 "make client-bulebule" mk client-bulebule
ELF=$B/clients/bulebule/src/main.elf
[ -s "$ELF" ] && ok "main.elf built" || { bad "no $ELF"; exit 1; }
readelf -h "$ELF" | grep -q "Machine: *ARM" && ok "an ARM ELF" || bad "not an ARM ELF"
readelf -A "$ELF" | grep -q "Tag_CPU_arch: v7" && ok "built for ARMv7 (Cortex-M3)" || bad "CPU arch: $(readelf -A "$ELF" | grep CPU_arch)"
readelf -l "$ELF" | awk '/LOAD/ && $3 == "0x08000000" {f=1} END {exit !f}' && ok "loaded at the start of flash (0x08000000)" || bad "no segment at 0x08000000"
read -r text data bss _ < <(arm-none-eabi-size "$ELF" | awk 'NR==2 {print $1, $2, $3}')
[ $((text + data)) -le $((63 * 1024)) ] && ok "flash: $((text + data)) B within its 63 KiB rom region" || bad "flash $((text + data)) B"
[ $((data + bss)) -le $((20 * 1024)) ] && ok "RAM: $((data + bss)) B within 20 KiB" || bad "RAM $((data + bss)) B"
# the sources untouched: every file of the source tree is in the copy, equal
diff -rq -x '*.o' -x '*.d' -x '*.a' -x '*.elf' -x '*.bin' -x '*.map' "$SRC" "$B/clients/bulebule" 2>&1 \
  | grep -v "^Only in $B/clients/bulebule" > "$T/diff"
[ ! -s "$T/diff" ] && ok "the copy differs from the source only by files added" || bad "changed: $(head -3 "$T/diff")"
# a second make does nothing (the target is up to date)
mk -n client-bulebule | grep -q build-bulebule && bad "client-bulebule rebuilds every time" || ok "up to date after one build"
[ $fails -eq 0 ]

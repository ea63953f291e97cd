#!/usr/bin/env bash
# cli_mazerunner.sh - a real client's firmware:
# `make client-mazerunner` builds UKMARSBOT's mazerunner-core from ../shared
# (or MRC_DIR) for the Nano, as shipped and set for EVENT_UK; both images are
# ATmega328P ELFs that fit the Nano (30 KB flash, 2 KB RAM); each boots in
# simavr (test/tools/mrc_boot.c, no board yet) to its banner and prompt and
# answers '?' with its help. Without the sources: the target's SKIP line is
# checked and the rest skips.
set -u
B=${BUILD:-build}
SHARED=${SHARED:-../shared}
MRC_DIR=${MRC_DIR:-$SHARED/clients/mazerunner-core}
BOOT=${MRC_BOOT:-$B/test/mrc_boot}
T=$(mktemp -d); trap 'rm -rf "$T"' EXIT
. "$(dirname "$0")/lib.sh"
# make from inside `make test`: a make of its own, not the caller's jobserver
mk() { env -u MAKEFLAGS -u MFLAGS -u MAKELEVEL make --no-print-directory B="$B" SHARED="$SHARED" "$@"; }

# no sources: one SKIP line, exit 0
want_rc 0 "client-mazerunner without sources" mk client-mazerunner MRC_DIR="$T/none"
[ "$(cat "$T/out")" = "SKIP client-mazerunner: $T/none not found" ] && ok "its one SKIP line" \
  || bad "SKIP line: $(cat "$T/out" "$T/err")"

if [ ! -f "$MRC_DIR/mazerunner-core/mazerunner-core.ino" ] && [ ! -f "$MRC_DIR/mazerunner-core.ino" ]; then
  echo "SKIP cli_mazerunner: $MRC_DIR not found (git clone https://github.com/ukmars/mazerunner-core, then MRC_DIR=that folder)"
  [ $fails -eq 0 ] && exit 77 || exit 1
fi

want_rc 0 "make client-mazerunner" mk client-mazerunner MRC_DIR="$MRC_DIR"
grep -q "^SKIP" "$T/out" && bad "SKIP with the sources: $(cat "$T/out")" || ok "no SKIP with the sources"
[ -x "$BOOT" ] || mk "$BOOT" >/dev/null 2>&1
SRC=$(dirname "$(ls "$MRC_DIR"/mazerunner-core/mazerunner-core.ino "$MRC_DIR"/mazerunner-core.ino 2>/dev/null | head -1)")
grep -q '^#define EVENT EVENT_HOME' "$SRC/config.h" && ok "the sources untouched (config.h: EVENT_HOME)" || bad "$SRC/config.h changed"
# the -uk copy: the client's files unchanged but its robot header, which
# is ours (EVENT_UK, goal (7,7)); the images differing shows it took effect
UK=$B/clients/mazerunner-core-uk/mazerunner-core changed=
for f in "$SRC"/*.h "$SRC"/*.ino; do
  n=$(basename "$f"); [ "$n" = config-robot-orion.h ] && continue
  cmp -s "$f" "$UK/$n" || changed="$changed $n"
done
[ -z "$changed" ] && ok "the -uk copy: the client's files unchanged" || bad "the -uk copy changed:$changed"
cmp -s test/firmware/mazerunner-core/config-robot-orion.h "$UK/config-robot-orion.h" && grep -q '^#define EVENT EVENT_UK' "$UK/config-robot-orion.h" \
  && ok "the -uk copy: our config-robot-orion.h (EVENT_UK)" || bad "the -uk copy: its config-robot-orion.h is not ours"
cmp -s "$B/clients/mazerunner-core.elf" "$B/clients/mazerunner-core-uk.elf" && bad "the two images are the same" || ok "the two images differ"

for img in mazerunner-core mazerunner-core-uk; do
  elf=$B/clients/$img.elf
  [ -s "$elf" ] && [ -s "$B/clients/$img.hex" ] && ok "$img: .elf and .hex" || { bad "$img: .elf or .hex missing"; continue; }
  readelf -h "$elf" 2>/dev/null | grep -q 'Machine: *Atmel AVR' && ok "$img: an AVR ELF" || bad "$img: not an AVR ELF: $(file "$elf")"
  # the linker's device note names the MCU it was linked for
  avr-objdump -s -j .note.gnu.avr.deviceinfo "$elf" 2>/dev/null | grep -q 'atmega328p' \
    && ok "$img: linked for the ATmega328P" || bad "$img: no atmega328p device note"
  read -r flash ram < <(avr-size -A "$elf" | awk '$1==".text"||$1==".data" {f+=$2} $1==".data"||$1==".bss"||$1==".noinit" {r+=$2} END {print f+0, r+0}')
  [ "$flash" -gt 0 ] && [ "$flash" -le 30720 ] && ok "$img: $flash bytes of flash (Nano: 30720)" || bad "$img: flash $flash bytes"
  [ "$ram" -gt 0 ] && [ "$ram" -lt 2048 ] && ok "$img: $ram bytes of static RAM (2048)" || bad "$img: static RAM $ram bytes"

  # boot: banner, RDY, prompt; '?' at 0.5 s answers with the help
  if [ ! -x "$BOOT" ]; then bad "$BOOT not built"; continue; fi
  timeout 60 "$BOOT" "$elf" 1 0.5=? >"$T/$img.uart" 2>"$T/$img.err"; rc=$?
  tr -d '\r' <"$T/$img.uart" >"$T/$img.txt"
  [ $rc -eq 0 ] && ok "$img: ran 1 s in simavr" || bad "$img: mrc_boot exit $rc: $(head -3 "$T/$img.err")"
  grep -q '^MAZERUNNER-CORE$' "$T/$img.txt" && ok "$img: banner MAZERUNNER-CORE" || bad "$img: no banner: $(head -c 300 "$T/$img.txt" | cat -v)"
  awk '/^MAZERUNNER-CORE$/ {b=1} b && /^RDY$/ {r=1} r && /^> / {p=1} END {exit !p}' "$T/$img.txt" \
    && ok "$img: RDY and the prompt after the banner" || bad "$img: no RDY and prompt: $(head -c 300 "$T/$img.txt" | cat -v)"
  grep -q '^> ?$' "$T/$img.txt" && grep -q '^?   : this text$' "$T/$img.txt" && grep -q '^SEARCH x y' "$T/$img.txt" \
    && ok "$img: '?' answered with its help" || bad "$img: no help after '?': $(tail -c 300 "$T/$img.txt" | cat -v)"
  grep -q 'UART0 at 117647 baud' "$T/$img.err" && ok "$img: UART0 at 115200 as the Nano makes it (117647)" \
    || bad "$img: baud: $(grep mrc_boot "$T/$img.err")"
  grep -q '^simavr: ' "$T/$img.err" && bad "$img: simavr said: $(grep '^simavr: ' "$T/$img.err" | head -3)" || ok "$img: no simavr warnings"
done
[ $fails -eq 0 ]

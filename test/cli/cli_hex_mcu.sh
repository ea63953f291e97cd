#!/usr/bin/env bash
# cli_hex_mcu.sh - an image built for another MCU than the board's (an Intel
# HEX says nothing of its MCU but its bytes: sim/board/image_mcu.c) is one
# line and exit 2 before the run, never run as ATmega328P code. One tiny C
# file built here with avr-gcc -mmcu=... for the ATmega8, 32, 88, 168 and
# 2560 and the ATtiny85, each as HEX on the UKMARSBOT board (and as ELF with
# --avr, where the architecture check does not tell the 168 or the 32 from
# the 328P): its vector table (19/21/26/57/15 entries, rjmp or jmp) or its
# start-up stack (the 168's RAMEND 0x04FF) named, and the MCU it fits; the
# Mega2560's is no stack_overflow. Made from the ATmega328P's: a vector
# past its 32 KiB of flash and a start-up write to the 2560's EIND (I/O
# 0x3C, which the 328P lacks) are refused the same way; the 328P's own
# image runs (exit 1 at the time limit).
set -u
B=${BUILD:-build}
MMSIM=${MMSIM:-$B/mmsim}
T=$(mktemp -d); trap 'rm -rf "$T"' EXIT
. "$(dirname "$0")/lib.sh"
command -v avr-gcc >/dev/null || { echo "SKIP cli_hex_mcu: avr-gcc not installed"; exit 77; }
"$MMSIM" --help 2>&1 | grep -q -- '--board' || { echo "SKIP cli_hex_mcu: this mmsim has no board emulation"; exit 77; }
MAZE=mazes/gen-5x5-s1.txt
BOARD=(--board ukmarsbot --robot robots/ukmarsbot.ini)
cat >"$T/t.c" <<'EOF'
#include <avr/io.h>
#include <avr/pgmspace.h>
volatile unsigned char n;
const char msg[] PROGMEM = "hello";
int main(void) { for (;;) n += pgm_read_byte(&msg[n & 3]); }
EOF
cat >"$T/eind.c" <<'EOF'
volatile unsigned char n;
/* in the start-up code (.init3, between the stack's setup and the data's copy): the 2560's EIND */
__attribute__((naked, used, section(".init3"))) void eind(void) { __asm__ volatile("out 0x3c, r1"); }
int main(void) { for (;;) n++; }
EOF
for m in atmega328p atmega8 atmega32 atmega88 atmega168 atmega2560 attiny85; do
  avr-gcc -mmcu=$m -Os -o "$T/$m.elf" "$T/t.c" 2>"$T/cc.err" && avr-objcopy -O ihex "$T/$m.elf" "$T/$m.hex" \
    || bad "avr-gcc -mmcu=$m: $(head -2 "$T/cc.err")"
done
avr-gcc -mmcu=atmega328p -Os -o "$T/eind.elf" "$T/eind.c" && avr-objcopy -O ihex "$T/eind.elf" "$T/eind.hex" || bad "avr-gcc eind.c"
# the 328P's image with vector 5 (bytes 20-23: jmp __bad_interrupt) sent to word 0x9000 (byte 0x12000: past 32 KiB)
avr-objcopy -O binary "$T/atmega328p.elf" "$T/far.bin"
python3 - "$T/far.bin" <<'EOF'
import struct, sys
b = bytearray(open(sys.argv[1], "rb").read())
assert struct.unpack_from("<H", b, 20)[0] == 0x940C
b[20:24] = struct.pack("<HH", 0x940C, 0x9000)
open(sys.argv[1], "wb").write(b)
EOF
avr-objcopy -I binary -O ihex "$T/far.bin" "$T/far.hex"

ONE_ERROR_LINE=1
want_rc 1 "atmega328p HEX: runs to the time limit" "$MMSIM" --maze $MAZE "${BOARD[@]}" --avr "$T/atmega328p.hex" --time-limit 1 --json
# NAME WHAT FITS: the HEX on the board, then the ELF with --avr alone
for c in "atmega8|19 rjmp's 2 bytes apart|the atmega8" "atmega32|21 jmp's 4 bytes apart|the atmega32" \
         "atmega88|26 rjmp's 2 bytes apart|the atmega88 or the atmega88p" \
         "atmega168|sets the stack to 0x04FF (the atmega328p's RAMEND: 0x08FF)|the atmega168 or the atmega168p" \
         "atmega2560|57 jmp's 4 bytes apart|the atmega1280 or the atmega2560" "attiny85|15 rjmp's 2 bytes apart|the attiny85"; do
  IFS='|' read -r m what fits <<<"$c"
  want_rc 2 "$m HEX on the board: exit 2" "$MMSIM" --maze $MAZE "${BOARD[@]}" --avr "$T/$m.hex" --time-limit 1 --json
  grep -qx "mmsim: $T/$m.hex: built for another MCU than the atmega328p: .*$what.*; it fits $fits" "$T/err" \
    && ok "$m HEX: $(cut -d: -f3- "$T/err" | cut -c2-)" || bad "$m HEX: $(cat "$T/err")"
  [ -s "$T/out" ] && bad "$m HEX: a run's output: $(head -c 200 "$T/out")"
  want_rc 2 "$m ELF with --avr: exit 2" "$MMSIM" --maze $MAZE --avr "$T/$m.elf" --time-limit 1 --json
  grep -q "built for another MCU" "$T/err" && ok "$m ELF: another MCU" || bad "$m ELF: $(cat "$T/err")"
done
grep -q stack_overflow "$T/err" && bad "atmega2560: stack_overflow reported"
want_rc 2 "a vector past the 328P's flash: exit 2" "$MMSIM" --maze $MAZE "${BOARD[@]}" --avr "$T/far.hex" --time-limit 1 --json
grep -qx "mmsim: $T/far.hex: built for another MCU than the atmega328p: a vector jumps to 0x12000, past the atmega328p's 32768 bytes of flash; it fits .*" "$T/err" \
  && ok "a vector past the flash: its line" || bad "far vector: $(cat "$T/err")"
want_rc 2 "EIND written by the start-up code: exit 2" "$MMSIM" --maze $MAZE "${BOARD[@]}" --avr "$T/eind.hex" --time-limit 1 --json
grep -qx "mmsim: $T/eind.hex: built for another MCU than the atmega328p: its start-up code uses I/O register 0x3C, which the atmega328p does not have; it fits .*" "$T/err" \
  && ok "EIND: its line" || bad "EIND: $(cat "$T/err")"
[ $fails -eq 0 ] && echo "cli_hex_mcu: all passed" || { echo "cli_hex_mcu: $fails failed"; exit 1; }

#!/usr/bin/env bash
# cli_arduino_build.sh - tools/arduino-build builds sketch folders as the
# Arduino IDE does, and what it builds runs on the emulated UKMARSBOT board:
# MultiTab (test/firmware/arduino/board/MultiTab: two .ino tabs, one function used
# before its definition, a .cpp/.h in the folder and in src/util, a table
# that only -flto drops) prints what its code says; EepromRoundTrip (the
# core's EEPROM library) run twice on one `mmsim --eeprom FILE` prints boot
# 0 then 1; the core's Wire, SPI and SoftwareSerial; a library folder given
# with --library; the Uno; bad input (a missing folder, no .ino, no main
# tab, an unknown board) is one line and exit 2; a compile error names the .ino tab and line, exit 1.
# Without avr-gcc, Debian's Arduino core or Universal Ctags: one SKIP line.
set -u
B=${BUILD:-build}
MMSIM=${MMSIM:-$B/mmsim}
AB="python3 tools/arduino-build"
SK=test/firmware/arduino/board
ROBOT=robots/ukmarsbot.ini
T=$(mktemp -d); trap 'rm -rf "$T"' EXIT
. "$(dirname "$0")/lib.sh"
command -v avr-gcc >/dev/null || { echo "SKIP cli_arduino_build: avr-gcc not installed"; exit 77; }
command -v ctags-universal >/dev/null || command -v ctags >/dev/null || { echo "SKIP cli_arduino_build: universal-ctags not installed"; exit 77; }
[ -f /usr/share/arduino/hardware/arduino/avr/platform.txt ] || { echo "SKIP cli_arduino_build: arduino-core-avr not installed"; exit 77; }
ab() { $AB "$@" --cache "$B/arduino-build"; }
# jv FILE EXPR: a Python expression over d, the last JSON line of FILE
jv() { python3 -c 'import json,sys; d=json.loads(open(sys.argv[1]).read().splitlines()[-1]); print(eval(sys.argv[2]))' "$1" "$2" 2>/dev/null; }
board() { "$MMSIM" --board ukmarsbot --robot "$ROBOT" --maze mazes/gen-16x16-s1.txt --time-limit 2 --input "0.5 end" --json "$@"; }
con() { jv "$1" "d['console'].replace(chr(13), '')"; }

# ---- MultiTab: tabs, prototypes, folder and src/ sources, -flto
want_rc 0 "MultiTab builds" ab $SK/MultiTab --board nano -o "$T/mt/MultiTab.elf"
[ -s "$T/mt/MultiTab.elf" ] && [ -s "$T/mt/MultiTab.hex" ] && ok "MultiTab: ELF and HEX written" || bad "MultiTab: no ELF/HEX in $(ls "$T/mt")"
grep -q '^MultiTab: program [0-9]* bytes of 30720' "$T/out" && grep -q 'text.*data.*bss' "$T/out" \
  && ok "MultiTab: avr-size printed ($(grep '^MultiTab:' "$T/out"))" || bad "MultiTab: no size: $(cat "$T/out")"
CPP=$T/mt/MultiTab.build/sketch/MultiTab.ino.cpp
python3 - "$CPP" >"$T/pp.txt" 2>&1 <<'PY' && ok "MultiTab: tabs joined in order, prototype before use, #line per tab ($(cat "$T/pp.txt"))" || bad "MultiTab preprocessing: $(tail -3 "$T/pp.txt")"
import sys
L = open(sys.argv[1]).read().splitlines()
assert L[0] == '#include <Arduino.h>', L[0]
assert L[1] == '#line 1 "test/firmware/arduino/board/MultiTab/MultiTab.ino"', L[1]
proto = L.index('void report(const __FlashStringHelper * what,unsigned n);')
assert proto < L.index('void setup() {'), 'prototype after setup'
assert not any(l.startswith('long sum_values(unsigned first') and l.endswith(';') for l in L), 'a prototype with a default argument'
tab2 = L.index('#line 1 "test/firmware/arduino/board/MultiTab/Report.ino"')
assert tab2 > L.index('void loop() {}'), 'Report.ino before the main tab'
print('prototype line %d, Report.ino from line %d' % (proto + 1, tab2 + 1))
PY
avr-objdump -h "$T/mt/MultiTab.elf" | grep -q debug_info && ok "MultiTab: debug information kept (-g)" || bad "MultiTab: no .debug_info"
want_rc 1 "MultiTab without -flto does not fit the Nano (the table stays)" ab $SK/MultiTab --board nano -o "$T/nolto/MultiTab.elf" --no-lto
grep -q "region .text' overflowed" "$T/err" && ok "MultiTab without -flto: the linker's overflow message" || bad "MultiTab --no-lto: $(tail -3 "$T/err")"
want_rc 1 "MultiTab runs on the board" board --avr "$T/mt/MultiTab.elf"
[ "$(con "$T/out")" = "$(printf 'MULTITAB twice 21 scale 250 table 0\nREPORT count 3 sum 42')" ] \
  && ok "MultiTab prints what its code says" || bad "MultiTab console: $(con "$T/out" | cat -v)"

# ---- EepromRoundTrip: the core's EEPROM library, kept across two runs
want_rc 0 "EepromRoundTrip builds" ab $SK/EepromRoundTrip --board nano -o "$T/ee/EepromRoundTrip.elf"
grep -q "^EepromRoundTrip: library EEPROM (/usr/share/arduino/hardware/arduino/avr/libraries/EEPROM/src)" "$T/out" \
  && ok "EepromRoundTrip: the EEPROM library found from its #include" || bad "EepromRoundTrip: no EEPROM library"
EE=$T/round.eeprom
for n in 0 1; do
  want_rc 1 "EepromRoundTrip run $((n + 1))" board --avr "$T/ee/EepromRoundTrip.elf" --eeprom "$EE"
  [ "$(con "$T/out")" = "$(printf 'EEPROM boot %d value %d\nEEPROM saved %d' $n $((100 << n)) $((n + 1)))" ] \
    && ok "EepromRoundTrip run $((n + 1)): boot $n value $((100 << n))" || bad "EepromRoundTrip run $((n + 1)): $(con "$T/out" | cat -v)"
  [ "$(jv "$T/out" "d['board']['eeprom']['written'], d['board']['eeprom']['saved']")" = "(True, True)" ] \
    && ok "EepromRoundTrip run $((n + 1)): the JSON says the firmware wrote the EEPROM" || bad "EepromRoundTrip run $((n + 1)): $(jv "$T/out" "d['board'].get('eeprom')")"
done
[ "$(od -An -tx1 -N8 "$EE" | tr -d ' ')" = 4d4d020090010000 ] \
  && ok "EepromRoundTrip: the file holds marker, count 2, value 400" || bad "EepromRoundTrip file: $(od -An -tx1 -N8 "$EE")"

# ---- a library folder (--library), the Uno
mkdir -p "$T/libs/Tiny/src" "$T/UseTiny"
printf '#pragma once\nint tiny_answer();\n' >"$T/libs/Tiny/src/Tiny.h"
printf '#include "Tiny.h"\nint tiny_answer() { return 42; }\n' >"$T/libs/Tiny/src/Tiny.cpp"
printf '#include <Tiny.h>\nvoid setup() { Serial.begin(115200); Serial.println(tiny_answer()); }\nvoid loop() {}\n' >"$T/UseTiny/UseTiny.ino"
want_rc 0 "a sketch using a --library folder builds" ab "$T/UseTiny" --library "$T/libs/Tiny" -o "$T/tiny/UseTiny.elf"
grep -q "^UseTiny: library Tiny ($T/libs/Tiny/src)" "$T/out" && ok "the --library folder used" || bad "UseTiny: $(cat "$T/out")"
want_rc 1 "the --library sketch runs" board --avr "$T/tiny/UseTiny.elf"
[ "$(con "$T/out")" = 42 ] && ok "the --library sketch prints the library's 42" || bad "UseTiny console: $(con "$T/out" | cat -v)"
mkdir -p "$T/Libs"
cat >"$T/Libs/Libs.ino" <<'INO'
#include <Wire.h>
#include <SPI.h>
#include <SoftwareSerial.h>
SoftwareSerial soft(10, 11);
void setup() { Wire.begin(); SPI.begin(); soft.begin(9600); }
void loop() { Wire.beginTransmission(8); Wire.write(1); Wire.endTransmission(); SPI.transfer(0x55); soft.write('x'); }
INO
want_rc 0 "a sketch using Wire, SPI and SoftwareSerial builds" ab "$T/Libs" -o "$T/libs-out/Libs.elf"
[ "$(grep -c '^Libs: library \(Wire\|SPI\|SoftwareSerial\) (/usr/share/arduino/hardware/arduino/avr/libraries/' "$T/out")" = 3 ] \
  && ok "Wire, SPI and SoftwareSerial: the core's libraries added" || bad "core libraries: $(cat "$T/out")"
want_rc 0 "EepromRoundTrip builds for the Uno" ab $SK/EepromRoundTrip --board uno -o "$T/uno/EepromRoundTrip.elf"
grep -q '^EepromRoundTrip: program [0-9]* bytes of 32256' "$T/out" && ok "the Uno's flash limit (32256 bytes)" || bad "Uno size line: $(cat "$T/out")"

# ---- bad input: one line, exit 2
ONE_ERROR_LINE=1
mkdir -p "$T/Empty" "$T/Named"; : >"$T/Named/other.ino"
want_rc 2 "a missing sketch folder" ab "$T/NoSuch" -o "$T/x.elf"
grep -q "NoSuch: no such sketch folder" "$T/err" && ok "missing folder: named" || bad "missing folder: $(cat "$T/err")"
want_rc 2 "a folder without .ino" ab "$T/Empty" -o "$T/x.elf"
grep -q "Empty: no .ino file" "$T/err" && ok "no .ino: said" || bad "no .ino: $(cat "$T/err")"
want_rc 2 "a folder without its main tab" ab "$T/Named" -o "$T/x.elf"
grep -q "no Named.ino" "$T/err" && ok "no main tab: said" || bad "no main tab: $(cat "$T/err")"
want_rc 2 "an unknown board" ab $SK/MultiTab --board mega -o "$T/x.elf"
grep -q "unknown board" "$T/err" && ok "unknown board: said" || bad "unknown board: $(cat "$T/err")"
want_rc 2 "no sketch given" ab
: >"$T/file"
want_rc 2 "an output folder that cannot be made" ab $SK/EepromRoundTrip -o "$T/file/x.elf"
ONE_ERROR_LINE=0

# ---- a compile error points at the tab and line
cp -r $SK/MultiTab "$T/MultiTab"
sed -i '17s/.*/  long s = undeclared_thing;/' "$T/MultiTab/Report.ino"
want_rc 1 "an error in the second tab fails the build" ab "$T/MultiTab" -o "$T/broken/MultiTab.elf"
grep -q "MultiTab/Report.ino:17:[0-9]*: error: .undeclared_thing. was not declared" "$T/err" \
  && ok "the compiler's error names Report.ino:17" || bad "compile error: $(grep -m2 error "$T/err")"
tail -1 "$T/err" | grep -q "^arduino-build: 1 file(s) did not compile: MultiTab.ino" && ok "then one summary line" || bad "summary: $(tail -1 "$T/err")"

[ $fails -eq 0 ]

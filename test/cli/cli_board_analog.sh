#!/usr/bin/env bash
# cli_board_analog.sh - A4 and A5 as the board file wires them ([analog]),
# with test/firmware/arduino/board/AdcOpen.ino on boards/ukmarsbot-v1.3.ini: open
# (UKMARSBOT V1.3 with the advanced sensor board: not connected) reads 0
# before any conversion, then what the sample-and-hold kept from the last
# conversion (A4 after A7 reads A7's count, A5 after A6 reads A6's), VCC
# (1023) with the pull-up on, 0 driven low; a copy of the board file with
# a4 = 2.5 V reads 2.5 V's count; a voltage above VCC is one line, exit 2.
set -u
B=${BUILD:-build}
MMSIM=${MMSIM:-$B/mmsim}
SK=$B/clients/board
ROBOT=robots/ukmarsbot.ini
T=$(mktemp -d); trap 'rm -rf "$T"' EXIT
. "$(dirname "$0")/lib.sh"
mk() { env -u MAKEFLAGS -u MFLAGS -u MAKELEVEL make --no-print-directory B="$B" "$@"; }
[ -s "$SK/AdcOpen.elf" ] || { mk "$SK/AdcOpen.elf" >"$T/make.out" 2>&1 || bad "make AdcOpen.elf: $(tail -3 "$T/make.out")"; }
MAZE=mazes/gen-16x16-s1.txt
# probe BOARD: the sketch's line, "FIRST a4 BAT a7 A4 a4 SW a6 A5 a5 PULLUP a4 LOW a5", into $T/line
probe() { want_rc 1 "AdcOpen on $1 runs" "$MMSIM" --board "$1" --avr "$SK/AdcOpen.elf" --robot "$ROBOT" --maze "$MAZE" --time-limit 1 \
    --input "0.3 end" --json
  tail -1 "$T/out" | python3 -c 'import json,sys; print([l for l in json.load(sys.stdin)["console"].replace("\r", "").splitlines() if l.startswith("FIRST")][-1])' \
    >"$T/line" 2>/dev/null || echo "no FIRST line" >"$T/line"; }

probe ukmarsbot
read -r _ first _ bat _ a4 _ sw _ a5 _ up _ low <"$T/line"
[ "$first" = 0 ] && ok "open A4 before any conversion: 0" || bad "open A4 first: $(cat "$T/line")"
[ "$a4" = "$bat" ] && [ "$bat" -gt 500 ] && ok "open A4 after A7: $a4 (A7's $bat, the held charge)" || bad "open A4 after A7: $(cat "$T/line")"
[ "$a5" = "$sw" ] && [ "$sw" -gt 100 ] && ok "open A5 after A6: $a5 (A6's $sw)" || bad "open A5 after A6: $(cat "$T/line")"
[ "$up" = 1023 ] && ok "A4 with its pull-up on: 1023" || bad "A4 pull-up: $(cat "$T/line")"
[ "$low" = 0 ] && ok "A5 driven low: 0 (after A7)" || bad "A5 low: $(cat "$T/line")"

mkdir -p "$T/parts" && cp boards/parts/*.ini "$T/parts/"  # the mainboard's parts, named from the board file's folder
sed 's/^a4 = open/a4 = 2.5/' boards/ukmarsbot-v1.3.ini >"$T/fixed.ini"
probe "$T/fixed.ini"
read -r _ first _ bat _ a4 _ <"$T/line"
[ "$first" = 511 ] && [ "$a4" = 511 ] && ok "a4 = 2.5 V: reads 511 (2.5 / 5 x 1023)" || bad "a4 = 2.5 V: $(cat "$T/line")"

sed 's/^a5 = open/a5 = 5.2/' boards/ukmarsbot-v1.3.ini >"$T/over.ini"
ONE_ERROR_LINE=1 want_rc 2 "a5 above vcc_v: exit 2" "$MMSIM" --board "$T/over.ini" --avr "$SK/AdcOpen.elf" --robot "$ROBOT" --maze "$MAZE" --json
grep -q "over.ini:[0-9]*: analog.a5: 5.2 V is above vcc_v" "$T/err" && ok "a5 above vcc_v: $(cat "$T/err")" || bad "a5 above vcc_v: $(cat "$T/err")"
sed 's/^a4 = open/a4 = floating/' boards/ukmarsbot-v1.3.ini >"$T/word.ini"
ONE_ERROR_LINE=1 want_rc 2 "a4 = floating: exit 2" "$MMSIM" --board "$T/word.ini" --avr "$SK/AdcOpen.elf" --robot "$ROBOT" --maze "$MAZE" --json
grep -q "word.ini:[0-9]*: .*a4.*expected 'open' or a voltage" "$T/err" && ok "a4 = floating: $(cat "$T/err")" || bad "a4 = floating: $(cat "$T/err")"

[ $fails -eq 0 ] && echo "PASS cli_board_analog" || { echo "FAIL cli_board_analog ($fails)"; exit 1; }

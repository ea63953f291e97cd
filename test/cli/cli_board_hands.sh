#!/usr/bin/env bash
# cli_board_hands.sh - the person's side of a board run, with our sketches
# (test/firmware/arduino/board, `make periph-sketches`) on boards/ukmarsbot-v1.3.ini:
# several --input flags add up in time order; bytes typed before the
# firmware enables its receiver are lost and reported as
# board.uart_bytes_dropped (not in uart_bytes_in); --eeprom FILE keeps the
# EEPROM across runs (Persist counts its boots at address 0: EE 1, then 2),
# a missing file is a blank chip, a file of the wrong size one line, exit 2;
# --board NAME and --robot NAME are found from any working directory (the
# source tree the program was built from; after `make install PREFIX=DIR`,
# DIR/share/mmsim).
set -u
B=${BUILD:-build}
MMSIM=${MMSIM:-$B/mmsim}
SK=$B/arduino/nano/board
ROBOT=robots/ukmarsbot.ini
T=$(mktemp -d); trap 'rm -rf "$T"' EXIT
. "$(dirname "$0")/lib.sh"
mk() { env -u MAKEFLAGS -u MFLAGS -u MAKELEVEL make --no-print-directory B="$B" "$@"; }
for s in UartEcho Persist; do
  [ -s "$SK/$s.elf" ] || { mk periph-sketches >"$T/make.out" 2>&1 || bad "make periph-sketches: $(tail -3 "$T/make.out")"; break; }
done
# An open 16x16 maze (the outer walls only)
python3 - >"$T/open16.txt" <<'PY'
n = 16
rows = ["o" + "---o" * n]
for y in range(n - 1, -1, -1):
    rows.append("|" + "".join((" S " if (x, y) == (0, 0) else "   ") + ("|" if x == n - 1 else " ") for x in range(n)))
    rows.append("o" + ("---o" if y == 0 else "   o") * n)
print("\n".join(rows))
PY
MAZE=$T/open16.txt
# jv FILE EXPR: a Python expression over d, the last JSON line of FILE
jv() { python3 -c 'import json,sys; d=json.loads(open(sys.argv[1]).read().splitlines()[-1]); print(eval(sys.argv[2]))' "$1" "$2" 2>/dev/null; }
board() { "$MMSIM" --board ukmarsbot --robot "$ROBOT" --maze "$MAZE" --time-limit 2 --json "$@"; }

# ---- several --input flags: merged in time order, each one's actions kept
want_rc 1 "two --input flags run" board --avr "$SK/UartEcho.elf" --input "0.6 send=second; 0.9 end" --input "0.3 send=first"
cp "$T/out" "$T/two.json"
[ "$(jv "$T/two.json" "[l for l in d['console'].replace(chr(13), '').splitlines() if l.startswith('ECHO')]")" = "['ECHO first', 'ECHO second']" ] \
  && ok "two --input flags: both lines echoed, in time order" || bad "two --input flags: console $(jv "$T/two.json" "repr(d.get('console'))")"
[ "$(jv "$T/two.json" "(d['sim_time_s'], d['exit_reason'])")" = "(0.9, 'input_end')" ] && ok "two --input flags: the first flag's end stops the run at 0.9 s" \
  || bad "two --input flags: $(jv "$T/two.json" "(d.get('sim_time_s'), d.get('exit_reason'))")"
ONE_ERROR_LINE=1 want_rc 2 "a bad second --input: exit 2" board --avr "$SK/UartEcho.elf" --input "0.3 end" --input "1 wave"
grep -q -- "--input:2:3: unknown action" "$T/err" && ok "a bad second --input: its number and column" || bad "bad second --input: $(cat "$T/err")"

# ---- typed before the receiver is on: lost, and said so
want_rc 1 "send at t = 0 runs" board --avr "$SK/UartEcho.elf" --input "0 send=AB; 0.4 send=hi; 0.7 end"
cp "$T/out" "$T/early.json"
[ "$(jv "$T/early.json" "(d['board'].get('uart_bytes_dropped'), d['board']['uart_bytes_in'])")" = "(3, 3)" ] \
  && ok "send at t = 0: 3 bytes (AB and the newline) dropped, 3 (hi) taken" \
  || bad "send at t = 0: board $(jv "$T/early.json" "d.get('board')")"
[ "$(jv "$T/early.json" "[l for l in d['console'].replace(chr(13), '').splitlines() if l.startswith('ECHO')]")" = "['ECHO hi']" ] \
  && ok "send at t = 0: only the later line echoed" || bad "send at t = 0: console $(jv "$T/early.json" "repr(d.get('console'))")"
[ "$(jv "$T/two.json" "'uart_bytes_dropped' in d['board'] or 'console_dropped' in d['board']")" = False ] \
  && ok "nothing lost: no *_dropped keys" || bad "nothing lost, yet: $(jv "$T/two.json" "d.get('board')")"

# ---- --eeprom FILE: a round trip across two runs
EE=$T/persist.eeprom
for n in 1 2; do
  want_rc 1 "Persist with --eeprom, run $n" board --avr "$SK/Persist.elf" --input "0.5 end" --eeprom "$EE"
  cp "$T/out" "$T/ee$n.json"
  [ "$(jv "$T/ee$n.json" "[l for l in d['console'].replace(chr(13), '').splitlines() if l.startswith('EE ')]")" = "['EE $n']" ] \
    && ok "Persist with --eeprom, run $n: EE $n" || bad "Persist run $n: console $(jv "$T/ee$n.json" "repr(d.get('console'))")"
  [ "$(jv "$T/ee$n.json" "d['board']['eeprom']")" = "{'file': '$EE', 'written': True, 'changed': True, 'saved': True}" ] \
    && ok "Persist run $n: the JSON says the firmware wrote the EEPROM" || bad "Persist run $n: $(jv "$T/ee$n.json" "d['board'].get('eeprom')")"
done
[ "$(stat -c %s "$EE" 2>/dev/null)" = 1024 ] && [ "$(od -An -tx1 -N4 "$EE" | tr -d ' ')" = 0200ffff ] \
  && ok "--eeprom: the file is the whole 1024-byte EEPROM, the count 2 at address 0, the rest erased" \
  || bad "--eeprom file: $(stat -c %s "$EE" 2>&1) bytes, starts $(od -An -tx1 -N4 "$EE" 2>&1)"
want_rc 1 "UartEcho with --eeprom (a missing file)" board --avr "$SK/UartEcho.elf" --input "0.5 end" --eeprom "$T/blank.eeprom"
[ "$(jv "$T/out" "d['board']['eeprom']['written'], d['board']['eeprom']['changed']")" = "(False, False)" ] \
  && ok "--eeprom: a firmware that never writes it: written false" || bad "UartEcho --eeprom: $(jv "$T/out" "d['board'].get('eeprom')")"
[ "$(od -An -tx1 -v "$T/blank.eeprom" | tr -s ' \n' ' ' | tr -d ' ' | tr -d f | wc -c)" = 0 ] && [ "$(stat -c %s "$T/blank.eeprom")" = 1024 ] \
  && ok "--eeprom: a missing file is a blank chip (1024 bytes of 0xFF saved)" || bad "--eeprom blank: $(od -An -tx1 "$T/blank.eeprom" | head -2)"
head -c 10 "$EE" >"$T/short.eeprom"
ONE_ERROR_LINE=1 want_rc 2 "--eeprom: a 10-byte file: exit 2" board --avr "$SK/Persist.elf" --eeprom "$T/short.eeprom"
grep -q "short.eeprom: 10 bytes, the atmega328p's EEPROM holds 1024" "$T/err" && ok "--eeprom: the wrong size said in one line" || bad "--eeprom short: $(cat "$T/err")"
[ "$(stat -c %s "$T/short.eeprom")" = 10 ] && ok "--eeprom: a refused file is left as it was" || bad "--eeprom: the short file was changed"
ONE_ERROR_LINE=1 want_rc 2 "--eeprom without --board: exit 2" "$MMSIM" --maze "$MAZE" --eeprom "$EE"

# ---- boards and robots by name, from another working directory
REPO=$PWD; ABS_MMSIM=$(cd "$(dirname "$MMSIM")" && pwd)/$(basename "$MMSIM")
mkdir -p "$T/elsewhere"
(cd "$T/elsewhere" && "$ABS_MMSIM" --board ukmarsbot --robot ukmarsbot --avr "$REPO/$SK/UartEcho.elf" --maze "$MAZE" \
  --time-limit 1 --input "0.5 end" --json >"$T/out" 2>"$T/err"); rc=$?
[ $rc = 1 ] && [ "$(jv "$T/out" "d['board']['file'], d['robot']")" = "('$REPO/boards/ukmarsbot-v1.3.ini', '$REPO/robots/ukmarsbot.ini')" ] \
  && ok "from another directory: --board ukmarsbot and --robot ukmarsbot found in the source tree" \
  || bad "from another directory: exit $rc, $(jv "$T/out" "d['board']['file'], d['robot']") $(head -2 "$T/err")"
(cd "$T/elsewhere" && ONE_ERROR_LINE=1 want_rc 2 "--board nosuch: exit 2" "$ABS_MMSIM" --board nosuch --avr "$REPO/$SK/UartEcho.elf" --maze "$MAZE")
(cd "$T/elsewhere" && ONE_ERROR_LINE=1 want_rc 2 "--robot nosuch: exit 2" "$ABS_MMSIM" --robot nosuch --print-robot)
if mk install PREFIX="$T/prefix" >"$T/make.out" 2>&1; then
  (cd "$T/elsewhere" && "$T/prefix/bin/mmsim" --board ukmarsbot --robot ukmarsbot --avr "$REPO/$SK/UartEcho.elf" --maze "$MAZE" \
    --time-limit 1 --input "0.5 end" --json >"$T/out" 2>"$T/err")
  [ "$(jv "$T/out" "d['board']['file'], d['robot']")" = "('$T/prefix/share/mmsim/boards/ukmarsbot-v1.3.ini', '$T/prefix/share/mmsim/robots/ukmarsbot.ini')" ] \
    && ok "make install PREFIX: the installed mmsim finds its board and robot files in PREFIX/share/mmsim" \
    || bad "installed mmsim: $(jv "$T/out" "d['board']['file'], d['robot']") $(head -2 "$T/err")"
else
  bad "make install PREFIX=...: $(tail -3 "$T/make.out")"
fi

[ $fails -eq 0 ]

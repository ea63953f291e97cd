#!/usr/bin/env bash
# cli_crash.sh - a crashing firmware ends its run, never the simulator. Tiny
# ATmega328P programs built here with avr-gcc, each run on the emulated
# board (--board ukmarsbot) and as a link MCU (--avr alone):
#   recursion  infinite recursion with a stack frame (SP set by the firmware)
#   call       `rcall` to itself (SP moved only by the pushes)
#   jump       icall to a word address past the 32 KiB flash
#   sleep      cli(); sleep_cpu();
#   wdt        the watchdog enabled and never fed: resets forever
#   erased     icall to erased flash inside the 32 KiB (opcode 0xFFFF)
#   jmp0       `jmp 0` at the end of main: starts over forever, no reset
#   badisr     Timer0's overflow interrupt enabled without a handler:
#              avr-libc's __bad_interrupt jumps to 0, forever
# Each: exit 1, exit_reason firmware_crashed, the cause and PC in the JSON
# ("board"/"avr": {"crash": {...}}), one error line, no signal and no
# sanitizer report (run it with the sanitized build: MMSIM=build/san-tools/mmsim
# LSAN_OPTIONS=suppressions=test/tools/lsan-simavr.supp). A firmware that resets
# itself once by the watchdog runs on: time_limit, one watchdog reset counted.
set -u
B=${BUILD:-build}
MMSIM=${MMSIM:-$B/mmsim}
# simavr's own leaks are suppressed (test/tools/lsan-simavr.supp): no summary of them in the one error line
export LSAN_OPTIONS="${LSAN_OPTIONS:+$LSAN_OPTIONS:}print_suppressions=0"
T=$(mktemp -d); trap 'rm -rf "$T"' EXIT
. "$(dirname "$0")/lib.sh"
command -v avr-gcc >/dev/null || { echo "SKIP cli_crash: avr-gcc not installed"; exit 77; }
"$MMSIM" --help 2>&1 | grep -q -- '--board' || { echo "SKIP cli_crash: this mmsim has no board emulation"; exit 77; }
MAZE=mazes/gen-16x16-s1.txt

cat >"$T/recursion.c" <<'EOF'
volatile unsigned char sink;
__attribute__((noinline)) unsigned rec(unsigned n)
{
    volatile unsigned char pad[8];
    pad[0] = (unsigned char)n;
    sink = pad[0];
    return rec(n + 1) + pad[0];
}
int main(void) { return (int)rec(0); }
EOF
cat >"$T/call.c" <<'EOF'
int main(void) { __asm__ volatile("1: rcall 1b"); for (;;) {} }
EOF
cat >"$T/jump.c" <<'EOF'
/* word address 0x7FF0 = byte 0xFFE0: past the ATmega328P's 32 KiB flash */
int main(void) { void (*f)(void) = (void (*)(void))0x7FF0u; f(); for (;;) {} }
EOF
cat >"$T/sleep.c" <<'EOF'
#include <avr/interrupt.h>
#include <avr/sleep.h>
int main(void) { set_sleep_mode(SLEEP_MODE_PWR_DOWN); cli(); sleep_enable(); sleep_cpu(); for (;;) {} }
EOF
cat >"$T/wdt.c" <<'EOF'
#include <avr/wdt.h>
int main(void) { wdt_enable(WDTO_15MS); for (;;) {} }
EOF
cat >"$T/wdt_once.c" <<'EOF'
#include <avr/io.h>
#include <avr/wdt.h>
/* reset once by the watchdog (a software reset), then run */
int main(void)
{
    unsigned char why = MCUSR;
    MCUSR = 0;
    wdt_disable();
    if (!(why & (1 << WDRF))) { wdt_enable(WDTO_15MS); for (;;) {} }
    for (;;) {}
}
EOF
cat >"$T/erased.c" <<'EOF'
/* word address 0x3000 = byte 0x6000: inside the 32 KiB flash, past the program: erased (0xFFFF) */
int main(void) { void (*f)(void) = (void (*)(void))0x3000u; f(); for (;;) {} }
EOF
cat >"$T/jmp0.c" <<'EOF'
volatile unsigned char n;
int main(void) { n++; __asm__ volatile("jmp 0"); for (;;) {} }
EOF
cat >"$T/badisr.c" <<'EOF'
#include <avr/interrupt.h>
#include <avr/io.h>
int main(void) { TCCR0B = 1 << CS00; TIMSK0 = 1 << TOIE0; sei(); for (;;) {} }
EOF
for p in recursion call jump sleep wdt wdt_once erased jmp0 badisr; do
  avr-gcc -mmcu=atmega328p -Os -o "$T/$p.elf" "$T/$p.c" 2>"$T/cc.err" || bad "avr-gcc $p: $(head -2 "$T/cc.err")"
done

# check NAME KEY CAUSE PC_OR_EMPTY: the run in $T/out/$T/err ended as a crash of CAUSE
check() { local name=$1 key=$2 cause=$3 pc=$4
  grep -q 'Sanitizer\|runtime error' "$T/err" && bad "$name: sanitizer report: $(grep -m1 'ERROR\|runtime error' "$T/err")"
  [ "$(wc -l <"$T/err")" -le 1 ] || bad "$name: more than one error line: $(head -3 "$T/err")"
  grep -q "firmware crashed at cycle [0-9]*, PC 0x[0-9A-F]*: $cause" "$T/err" && ok "$name: the error line names $cause" \
    || bad "$name: error line: $(head -1 "$T/err")"
  local got
  got=$(python3 -c "
import json,sys
d=json.loads(open(sys.argv[1]).read().splitlines()[-1]); c=d[sys.argv[2]].get('crash') or {}
print(d['exit_reason'], c.get('cause'), c.get('pc') if sys.argv[3] == '' else c.get('pc') == int(sys.argv[3], 0))" \
    "$T/out" "$key" "$pc" 2>&1)
  case "$got" in
    "firmware_crashed $cause "[0-9]*|"firmware_crashed $cause True") ok "$name: firmware_crashed, cause $cause, PC in the JSON" ;;
    *) bad "$name: JSON: $got" ;;
  esac; }

for mode in board avr; do
  if [ $mode = board ]; then args=(--board ukmarsbot --robot robots/ukmarsbot.ini); key=board; else args=(); key=avr; fi
  for p in recursion:stack_overflow: call:stack_overflow: jump:bad_jump: sleep:sleep_with_interrupts_off: \
           erased:erased_flash: jmp0:reset_loop: badisr:reset_loop: wdt:watchdog_reset_loop:; do
    IFS=: read -r name cause pc <<<"$p"
    want_rc 1 "$mode $name: exit 1" "$MMSIM" --maze $MAZE "${args[@]}" --avr "$T/$name.elf" --time-limit 3 --json
    check "$mode $name" $key "$cause" "$pc"
    # erased flash is seen where a batch of simavr's instructions ends: between the jump's target and the flash's end
    [ $name = erased ] && { python3 -c "
import json,sys; d=json.loads(open(sys.argv[1]).read().splitlines()[-1]); sys.exit(not 0x6000 <= d[sys.argv[2]]['crash']['pc'] < 0x8000)" \
      "$T/out" $key && ok "$mode erased: the PC in the erased flash" || bad "$mode erased: PC $(tail -c 200 "$T/out")"; }
  done
  got=$(python3 -c "
import json,sys; d=json.loads(open(sys.argv[1]).read().splitlines()[-1]); print(d['exit_reason'], d[sys.argv[2]].get('watchdog_resets'))" \
    "$T/out" $key 2>&1)
  [ "$got" = "firmware_crashed 8" ] && ok "$mode wdt: 8 watchdog resets counted" || bad "$mode wdt: $got"
  want_rc 1 "$mode wdt_once: runs to the time limit" "$MMSIM" --maze $MAZE "${args[@]}" --avr "$T/wdt_once.elf" --time-limit 1 --json
  got=$(python3 -c "
import json,sys; d=json.loads(open(sys.argv[1]).read().splitlines()[-1]); a=d[sys.argv[2]]
print(d['exit_reason'], a.get('watchdog_resets'), a.get('crash'))" "$T/out" $key 2>&1)
  [ "$got" = "time_limit 1 None" ] && ok "$mode wdt_once: one watchdog reset counted, no crash" || bad "$mode wdt_once: $got"
done
# the reset button is no watchdog reset: it clears MCUSR, so the firmware resets itself once more
want_rc 1 "board wdt_once with the reset button" "$MMSIM" --maze $MAZE --board ukmarsbot --robot robots/ukmarsbot.ini \
  --avr "$T/wdt_once.elf" --time-limit 1 --input "0.5 reset" --json
got=$(python3 -c "
import json,sys; d=json.loads(open(sys.argv[1]).read().splitlines()[-1]); b=d['board']
print(d['exit_reason'], b['resets'], b.get('watchdog_resets'), b.get('crash'))" "$T/out" 2>&1)
[ "$got" = "time_limit 1 2 None" ] && ok "reset button: 1 reset, 2 watchdog resets, no crash" || bad "reset button: $got"
got=$(python3 -c "
import json,sys; print(sorted(json.loads(open(sys.argv[1]).read().splitlines()[-1])['board'].get('reset_causes', {}).items()))" "$T/out" 2>&1)
[ "$got" = "[('brown_out', 0), ('external', 1), ('power_on', 1), ('watchdog', 2)]" ] \
  && ok "reset button: the resets by cause (power-on 1, external 1, watchdog 2)" || bad "reset causes: $got"

[ $fails -eq 0 ] && echo "cli_crash: all passed" || { echo "cli_crash: $fails failed"; exit 1; }

#!/usr/bin/env bash
# cli_board_arm.sh - an ARM image on an emulated STM32 board:
# `mmsim --board bulebule --firmware IMAGE.elf` (sim/arm/armboard.c). Our own
# firmware (test/firmware/arm/boardtest.c, `make arm-test-firmware`) prints on USART3,
# drives the motors forward while the button is held (--input button=down /
# up), reads the encoders, the front-left IR (a hand before it: --input
# occlude=fl) and the battery: the JSON's "board" and "console" say so, the
# same JSON twice; --batch; test/firmware/arm/crashtest.c's bus fault ends the run as
# firmware_crashed with its PC and cause. Bad input is one line, exit 2: an image for another
# architecture, --firmware on an AVR board, --avr on an STM32 board,
# --flash without --firmware. --flash FILE keeps the flash (the soc's own
# test checks its bytes). With bulebule built (`make client-bulebule`), it
# boots and answers its console's `battery` command.
set -u
B=${BUILD:-build}
SHARED=${SHARED:-../shared}
MMSIM=${MMSIM:-$B/mmsim}
FW=$B/arm/boardtest.elf
BULEBULE=$B/clients/bulebule/src/main.elf
T=$(mktemp -d); trap 'rm -rf "$T"' EXIT
. "$(dirname "$0")/lib.sh"
mk() { env -u MAKEFLAGS -u MFLAGS -u MAKELEVEL make --no-print-directory B="$B" SHARED="$SHARED" "$@"; }
[ -s "$FW" ] || mk "$FW" >"$T/make.out" 2>&1 || { echo "SKIP cli_board_arm: make $FW: $(tail -1 "$T/make.out")"; exit 77; }
python3 - >"$T/open16.txt" <<'PY'
n = 16
rows = ["o" + "---o" * n]
for y in range(n - 1, -1, -1):
    rows.append("|" + "".join((" S " if (x, y) == (0, 0) else "   ") + ("|" if x == n - 1 else " ") for x in range(n)))
    rows.append("o" + ("---o" if y == 0 else "   o") * n)
print("\n".join(rows))
PY
MAZE=$T/open16.txt
jv() { python3 -c 'import json,sys; d=json.loads(open(sys.argv[1]).read().splitlines()[-1]); print(eval(sys.argv[2]))' "$1" "$2" 2>/dev/null; }
arm() { "$MMSIM" --board bulebule --maze "$MAZE" --time-limit 2 --json "$@"; }

# ---- our firmware: console, PWM, encoders, IR with a hand, determinism
IN="0.25 occlude=fl; 0.45 button=down; 0.95 button=up; 1.3 end"
want_rc 1 "boardtest runs on the bulebule board" arm --firmware "$FW" --input "$IN"
cp "$T/out" "$T/a.json"
[ "$(jv "$T/a.json" "d['driver'], d['board']['mcu'], d['exit_reason']")" = "('board', 'stm32f103c8', 'input_end')" ] \
  && ok "driver board, mcu stm32f103c8, ended by --input end" || bad "driver/mcu/exit: $(head -c 300 "$T/a.json")"
[ "$(jv "$T/a.json" "d['console'].splitlines()[0]")" = "boardtest" ] && ok "console: the firmware's banner on USART3" \
  || bad "console: $(jv "$T/a.json" "d['console'][:200]")"
# 72 MHz from the 8 MHz crystal's PLL: 1.3 s is about 93.6 M cycles (the first instructions at HSI's 8 MHz)
[ "$(jv "$T/a.json" "abs(d['board']['cycles'] - 1.3 * 72e6) < 1e6")" = True ] && ok "cycles at 72 MHz" \
  || bad "cycles: $(jv "$T/a.json" "d['board']['cycles']")"
[ "$(jv "$T/a.json" "d['board']['pwm_duty']['left'][1] > 0.45 and d['board']['pwm_duty']['right'][1] > 0.45")" = True ] \
  && ok "the button held: both bridges forward at about half duty" || bad "pwm_duty: $(jv "$T/a.json" "d['board']['pwm_duty']")"
[ "$(jv "$T/a.json" "d['board']['encoder_edges']['left'] > 1000 and d['final_pose']['y_m'] > 0.2")" = True ] \
  && ok "the robot drove forward, its encoders counting" || bad "encoders/pose: $(jv "$T/a.json" "d['board']['encoder_edges'], d['final_pose']")"
# the encoder counts the firmware read rise (forward) in both timers (the first moving line: 16 bits wrap soon)
[ "$(jv "$T/a.json" "[int(l.split()[3]) > 0 and int(l.split()[4]) > 0 for l in d['console'].splitlines()[1:] if l.split()[3] != '0'][0]")" = True ] \
  && ok "TIM2 and TIM4 count up for a forward turn (ch1_leads)" || bad "encoder counts: $(jv "$T/a.json" "d['console'][:600]")"
# the hand at 0.25-0.55 s: the front-left IR saturates; before it, the dark reading
[ "$(jv "$T/a.json" "[int(l.split()[6]) for l in d['console'].splitlines()[1:5]]")" = "[41, 40, 4095, 4095]" ] \
  && ok "IR: dark, then the hand before fl saturates the 12-bit ADC" || bad "IR: $(jv "$T/a.json" "d['console'][:400]")"
[ "$(jv "$T/a.json" "d['board']['led_changes']['bluepill'] >= 10 and d['board']['unmodeled'] == [] and 'crash' not in d['board']")" = True ] \
  && ok "the Blue Pill's LED followed; no unmodeled register; no crash" || bad "leds/unmodeled: $(jv "$T/a.json" "d['board']")"
[ "$(jv "$T/a.json" "sorted(d['board']['adc_samples']), d['board']['adc_samples']['IN5'] == d['board']['adc_samples']['IN0'], d['board']['interrupt_requests']")" = "(['IN0', 'IN5'], True, {})" ] \
  && ok "ADC2 sampled IN5 (fl) and IN0 (battery) once a line; no NVIC line (SysTick only)" || bad "adc/irq: $(jv "$T/a.json" "d['board']")"
want_rc 1 "the same run again" arm --firmware "$FW" --input "$IN"
[ "$(strip "$T/a.json")" = "$(strip "$T/out")" ] && ok "same JSON twice" || bad "two runs differ"

# ---- a fault ends the run: exit_reason firmware_crashed, exit 1, the PC and cause in board.crash
CR=$B/arm/crashtest.elf
[ -s "$CR" ] || mk "$CR" >"$T/make.out" 2>&1 || bad "make $CR: $(tail -1 "$T/make.out")"
want_rc 1 "a firmware that faults" arm --firmware "$CR"
[ "$(jv "$T/out" "d['exit_reason'], d['board']['crash']['cause'].startswith('HardFault: bus fault writing 0x60000000'), 0x08000000 <= d['board']['crash']['pc'] < 0x08010000, d['sim_time_s'] < 0.02")" = "('firmware_crashed', True, True, True)" ] \
  && ok "crash: firmware_crashed at its 10 ms store, PC in flash, the cause" || bad "crash: $(jv "$T/out" "d['exit_reason'], d['board']")"
[ "$(wc -l <"$T/err")" = 1 ] && grep -q "the firmware crashed at 0x0800" "$T/err" && ok "crash: one line on stderr" || bad "crash stderr: $(cat "$T/err")"

# ---- --input reset: the reset button, the firmware starts over (SRAM kept)
want_rc 1 "--input reset" arm --firmware "$FW" --input "0.35 reset; 0.5 end"
[ "$(jv "$T/out" "d['console'].count('boardtest'), d['board']['resets']")" = "(2, 1)" ] && ok "reset: the banner again, resets 1" \
  || bad "reset: $(jv "$T/out" "d['console'], d['board']['resets']")"

# ---- --batch: each maze its own board, one JSON line each
mkdir -p "$T/batch" && cp "$MAZE" "$T/batch/a.txt" && cp "$MAZE" "$T/batch/b.txt"
want_rc 1 "--batch DIR on the STM32 board" "$MMSIM" --board bulebule --batch "$T/batch" --jobs 2 --firmware "$FW" --time-limit 1 --input "0.4 end"
[ "$(grep -c '"console":"boardtest' "$T/out")" = 2 ] && ok "--batch: two runs, each with its console" || bad "--batch: $(head -c 300 "$T/out")"

# ---- --flash FILE: created at the end, the run's own flash
want_rc 1 "--flash FILE" arm --firmware "$FW" --flash "$T/flash.bin" --input "0.2 end"
[ "$(stat -c %s "$T/flash.bin" 2>/dev/null)" = 65536 ] || [ "$(jv "$T/out" "d['board']['flash']['changed']")" = False ] \
  && ok "--flash: saved when changed (boardtest writes none: $(jv "$T/out" "d['board']['flash']"))" || bad "--flash: $(jv "$T/out" "d['board']")"

# ---- bad input: one line, exit 2
ONE_ERROR_LINE=1
printf 'not an elf' >"$T/bad.elf"
want_rc 2 "a file that is no ELF" arm --firmware "$T/bad.elf"
grep -q "bad.elf" "$T/err" && ok "... names the image" || bad "message: $(cat "$T/err")"
want_rc 2 "--firmware on an AVR board" "$MMSIM" --board ukmarsbot --maze "$MAZE" --firmware "$FW"
want_rc 2 "an STM32 board without --firmware" "$MMSIM" --board bulebule --maze "$MAZE" --avr "$FW"
want_rc 2 "--flash without --firmware" "$MMSIM" --maze "$MAZE" --flash "$T/x.bin"
want_rc 2 "--firmware without --board" "$MMSIM" --maze "$MAZE" --firmware "$FW"
ONE_ERROR_LINE=0

# ---- bulebule itself (make client-bulebule), whenever ../shared has its sources
[ -d "$SHARED/clients/bulebule/src" ] && { [ -s "$BULEBULE" ] || mk client-bulebule >"$T/bb.out" 2>&1 || bad "make client-bulebule: $(tail -1 "$T/bb.out")"; }
if [ -s "$BULEBULE" ]; then
  want_rc 1 "bulebule boots on its board" arm --firmware "$BULEBULE" --input "0.4 send=x; 0.6 send=x; 0.8 send=battery; 1.0 end"
  grep -q 'Processing \\"battery\\"' "$T/out" && grep -q "log_battery_voltage" "$T/out" \
    && ok "bulebule answers its console's battery command" || bad "bulebule console: $(jv "$T/out" "d['console'][:300]")"
  [ "$(jv "$T/out" "d['board']['interrupt_requests']['TIM1_UP'] > 5000, 'DMA1_Channel2' in d['board']['interrupt_requests'], d['board']['exceptions'] > 5000")" = "(True, True, True)" ] \
    && ok "bulebule: TIM1_UP and SysTick run, its console sent by DMA1 channel 2" || bad "bulebule irqs: $(jv "$T/out" "d['board']")"
else
  echo "SKIP bulebule part: $SHARED/clients/bulebule not found"
fi
[ $fails -eq 0 ]

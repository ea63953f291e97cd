# firmware.mk - our firmware (firmware/) built for the ATmega328P: its size,
# the image for UKMARSBOT's Nano (hal/ukmarsbot), the wire codec's self-test.

# ---- AVR build of the firmware (ATmega328P) ----
AVR_CC    := avr-gcc
AVR_FLAGS := -mmcu=atmega328p -DF_CPU=16000000L -Os -std=c99 -Wall -Wextra -DMAZE_MAX_SIZE=16 \
	-ffunction-sections -fdata-sections -Ifirmware -Ihal -I$(B)/gen/paper
firmware-size: | deps
	@mkdir -p $(B)/avr
	$(AVR_CC) $(AVR_FLAGS) -Wl,--gc-sections $(FW_SRC) test/firmware/avr/avr_main.c -o $(B)/avr/firmware.elf
	avr-size $(B)/avr/firmware.elf
	@avr-nm -S --size-sort $(B)/avr/firmware.elf | grep -i ' [bd] ' | tail -8
firmware: firmware-size arduino
# ---- the firmware on UKMARSBOT's Nano: firmware/ + hal/ukmarsbot, plain avr-libc ----
# `make firmware-ukmarsbot` builds $(B)/ukmarsbot/mouse.elf and .hex (the image
# a user flashes; mmsim --board ukmarsbot --avr runs the ELF) and prints its
# flash (limit UKB_FLASH_MAX: the Nano's 32 KB less its 2 KB bootloader) and
# static RAM. UKB_SENSOR_BOARD=basic builds for the BASIC wall sensor board.
# platformio.ini [env:ukmarsbot] builds the same files (UKB_SRC; test/cli/cli_ukmarsbot_fw.sh).
UKB_SRC       := $(FW_SRC) $(sort $(wildcard hal/ukmarsbot/*.c))
UKB_FLASH_MAX := 30720
UKB_SENSOR_BOARD ?= advanced
UKB_PROFILE   := $(B)/gen/ukmarsbot$(if $(filter basic,$(UKB_SENSOR_BOARD)),-basic-12)
UKB_FLAGS     := -I$(UKB_PROFILE) $(AVR_FLAGS) -Ihal/ukmarsbot -DHAL_IR_LIT_MINUS_DARK -DHAL_LOG_MAX=50 -fno-inline-functions -fno-inline-small-functions -fno-inline-functions-called-once $(if $(filter basic,$(UKB_SENSOR_BOARD)),-DUKB_SENSOR_BOARD_BASIC)
UKB_OUT       := $(B)/ukmarsbot$(if $(filter basic,$(UKB_SENSOR_BOARD)),-basic)
$(UKB_OUT)/mouse.elf: $(UKB_SRC) $(wildcard hal/ukmarsbot/*.h firmware/*.h) hal/hal.h | deps
	@mkdir -p $(dir $@)
	$(AVR_CC) $(UKB_FLAGS) -Wl,--gc-sections $(UKB_SRC) -o $@
$(UKB_OUT)/mouse.hex: $(UKB_OUT)/mouse.elf
	avr-objcopy -O ihex -R .eeprom $< $@
UKB_BOARD     := ukmarsbot$(if $(filter basic,$(UKB_SENSOR_BOARD)),-basic)
UKB_ROBOT     := robots/ukmarsbot$(if $(filter basic,$(UKB_SENSOR_BOARD)),-basic-12).ini
# The stack's headroom measured at the deepest point of a contest: the image
# on its emulated board (mmsim, the board and robot files of the build)
# searches mazes/gen-16x16-s1.txt, returns and makes its three speed runs;
# the firmware's `k` command then reports the painted RAM never written
# (hal/ukmarsbot: the stack paint). Measured once per image (about a
# minute), kept beside it.
$(UKB_OUT)/stack.txt: $(UKB_OUT)/mouse.elf $(B)/mmsim $(UKB_ROBOT) boards/$(UKB_BOARD)-v1.3.ini
	@bash tools/make/ukb-stack.sh $(B)/mmsim $< $(UKB_BOARD) $(UKB_ROBOT) $@
firmware-ukmarsbot: $(UKB_OUT)/mouse.elf $(UKB_OUT)/mouse.hex $(UKB_OUT)/stack.txt
	@bash tools/make/ukb-size.sh $< $(UKB_FLASH_MAX) $(UKB_OUT)/stack.txt
ukmarsbot-stack: $(UKB_OUT)/stack.txt
	@echo "ukmarsbot: stack never used after a contest: $$(cat $<) B"
# the source list, one a line (test/cli/cli_ukmarsbot_fw.sh compares platformio.ini's)
ukmarsbot-src:
	@printf '%s\n' $(UKB_SRC)
.PHONY: firmware-ukmarsbot ukmarsbot-src ukmarsbot-stack
# The wire codec's shared vectors on the ATmega328P, run in simavr by test/cli/cli_hil.sh.
$(B)/avr/wire_selftest.elf: test/firmware/avr/avr_wire.c test/unit/wire_vectors.c hal/wire/wire.c hal/wire/wire.h | deps
	@mkdir -p $(dir $@)
	$(AVR_CC) -mmcu=atmega328p -DF_CPU=16000000L -Os -std=c99 -Wall -Wextra -ffunction-sections -fdata-sections $(MCU_RX_FLAGS) \
	  -Ihal/wire -Itest/unit -Wl,--gc-sections test/firmware/avr/avr_wire.c test/unit/wire_vectors.c hal/wire/wire.c -o $@

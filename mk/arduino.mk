# arduino.mk - hal/arduino: our Arduino library with every example sketch
# for the Uno and the Mega 2560, the test sketches built on it, the
# installable library (make arduino-lib).

# ---- Arduino builds: hal/arduino + firmware/ + Debian's arduino-core-avr, for the
# Uno (ATmega328P) and the Mega 2560, every example sketch; flags as the core's
# platform.txt/boards.txt. `make arduino` (part of `make firmware`) prints avr-size.
# These keep their own rules rather than tools/arduino-build: they build for
# the Mega 2560 too, link our library from hal/ and firmware/ as one archive
# without -flto (the Uno's RAM budget and the PIL runs' timing are measured on
# these images), and need no `make arduino-lib` copy (hal/arduino/README.md).
ARD_DIR      := /usr/share/arduino/hardware/arduino/avr
ARD_CORE     := $(ARD_DIR)/cores/arduino
ARD_BOARDS   := uno mega2560
ARD_EXAMPLES := Mouse DriveToWall
# SRAM for the Uno (hal/arduino/README.md), on every board so they behave alike:
# the link's decoder holds the sim's messages only (20 B, not 86: no LOG),
# the core's serial transmit buffer is 32 B (the receive buffer stays 64: up
# to ~60 B of sensor frames arrive per 4 ms tick)
ARD_RAM      := $(MCU_RX_FLAGS) -DSERIAL_TX_BUFFER_SIZE=32
# ARD_BASE: the core's own flags (platform.txt, less -g and -flto); ARD_COMMON adds ours.
ARD_BASE     := -DF_CPU=16000000L -DARDUINO=10819 -DARDUINO_ARCH_AVR -Os -ffunction-sections -fdata-sections -I$(ARD_CORE)
ARD_COMMON   := $(ARD_BASE) -DMAZE_MAX_SIZE=16 $(ARD_RAM) -Ihal -Ihal/wire -Ihal/arduino/src -Ifirmware -I$(B)/gen/paper
ARD_CXX      := -std=gnu++11 -fno-exceptions -fno-threadsafe-statics -fpermissive -DDECIMAL_DIG=__DECIMAL_DIG__
ARD_uno      := -mmcu=atmega328p -DARDUINO_AVR_UNO -I$(ARD_DIR)/variants/standard
ARD_mega2560 := -mmcu=atmega2560 -DARDUINO_AVR_MEGA2560 -I$(ARD_DIR)/variants/mega
ARD_LIB_SRC  := $(wildcard hal/arduino/src/*.cpp) hal/wire/wire.c $(FW_SRC)
ARD_CORE_SRC := $(wildcard $(ARD_CORE)/*.c $(ARD_CORE)/*.cpp) $(ARD_CORE)/wiring_pulse.S
ARD_HDRS     := $(wildcard hal/arduino/src/*.h firmware/*.h) hal/hal.h hal/wire/wire.h

# the flags in a file rewritten when they change: the core and library rebuild
# (SERIAL_TX_BUFFER_SIZE and WIRE_RX_LOG_MAX size structs that every object shares)
ARD_STAMP := $(B)/arduino/.flags
$(ARD_STAMP): FORCE
	@mkdir -p $(dir $@); echo '$(ARD_COMMON) $(ARD_CXX)' | cmp -s - $@ || echo '$(ARD_COMMON) $(ARD_CXX)' >$@
.PHONY: FORCE
define ARD_BOARD_RULES
$(B)/arduino/$(1)/core/%.c.o: $(ARD_CORE)/%.c $(ARD_STAMP) | deps
	@mkdir -p $$(dir $$@)
	@avr-gcc $(ARD_$(1)) $(ARD_COMMON) -std=gnu11 -c $$< -o $$@
$(B)/arduino/$(1)/core/%.cpp.o: $(ARD_CORE)/%.cpp $(ARD_STAMP) | deps
	@mkdir -p $$(dir $$@)
	@avr-g++ $(ARD_$(1)) $(ARD_COMMON) $(ARD_CXX) -c $$< -o $$@
$(B)/arduino/$(1)/core/%.S.o: $(ARD_CORE)/%.S $(ARD_STAMP) | deps
	@mkdir -p $$(dir $$@)
	@avr-gcc $(ARD_$(1)) $(ARD_COMMON) -x assembler-with-cpp -c $$< -o $$@
$(B)/arduino/$(1)/core.a: $(patsubst $(ARD_CORE)/%,$(B)/arduino/$(1)/core/%.o,$(ARD_CORE_SRC))
	@rm -f $$@; avr-gcc-ar rcs $$@ $$^
$(B)/arduino/$(1)/lib/%.c.o: %.c $(ARD_HDRS) $(ARD_STAMP) | deps
	@mkdir -p $$(dir $$@)
	avr-gcc $(ARD_$(1)) $(ARD_COMMON) -std=c99 -Wall -Wextra -c $$< -o $$@
$(B)/arduino/$(1)/lib/%.cpp.o: %.cpp $(ARD_HDRS) $(ARD_STAMP) | deps
	@mkdir -p $$(dir $$@)
	avr-g++ $(ARD_$(1)) $(ARD_COMMON) $(ARD_CXX) -Wall -Wextra -c $$< -o $$@
$(B)/arduino/$(1)/libmicromouse.a: $(patsubst %,$(B)/arduino/$(1)/lib/%.o,$(ARD_LIB_SRC))
	@rm -f $$@; avr-gcc-ar rcs $$@ $$^
$(foreach e,$(ARD_EXAMPLES),
$(B)/arduino/$(1)/$(e).elf: hal/arduino/examples/$(e)/$(e).ino $(B)/arduino/$(1)/libmicromouse.a $(B)/arduino/$(1)/core.a $(ARD_HDRS)
	avr-g++ $(ARD_$(1)) $(ARD_COMMON) $(ARD_CXX) -Wall -x c++ -include Arduino.h -c $$< -o $$@.o
	avr-gcc $(ARD_$(1)) -Os -Wl,--gc-sections $$@.o $(B)/arduino/$(1)/libmicromouse.a $(B)/arduino/$(1)/core.a -lm -o $$@
	avr-objcopy -O ihex -R .eeprom $$@ $$(@:.elf=.hex)
)
endef
$(foreach b,$(ARD_BOARDS),$(eval $(call ARD_BOARD_RULES,$(b))))
ARD_ELFS := $(foreach b,$(ARD_BOARDS),$(foreach e,$(ARD_EXAMPLES),$(B)/arduino/$(b)/$(e).elf))
# The processor-in-the-loop test image: the Mouse sketch on a 5x5 maze (test/cli/cli_pil.sh).
$(B)/arduino/%/Mouse-5x5.elf: hal/arduino/examples/Mouse/Mouse.ino $(B)/arduino/%/libmicromouse.a $(B)/arduino/%/core.a $(ARD_HDRS)
	avr-g++ $(ARD_$*) $(ARD_COMMON) $(ARD_CXX) -DMM_MAZE_SIZE=5 -Wall -x c++ -include Arduino.h -c $< -o $@.o
	avr-gcc $(ARD_$*) -Os -Wl,--gc-sections $@.o $(B)/arduino/$*/libmicromouse.a $(B)/arduino/$*/core.a -lm -o $@
# A test sketch (test/cli/cli_pil.sh): one motor command, then only reads, as a
# sketch of the paper's library that sets its motors once.
$(B)/arduino/uno/OneCommand.elf: test/firmware/arduino/OneCommand/OneCommand.ino $(B)/arduino/uno/libmicromouse.a $(B)/arduino/uno/core.a $(ARD_HDRS)
	avr-g++ $(ARD_uno) $(ARD_COMMON) $(ARD_CXX) -Wall -x c++ -include Arduino.h -c $< -o $@.o
	avr-gcc $(ARD_uno) -Os -Wl,--gc-sections $@.o $(B)/arduino/uno/libmicromouse.a $(B)/arduino/uno/core.a -lm -o $@
# A test sketch (test/cli/cli_pil.sh): the runner with a stand-in firmware that
# calls hal_emitter / hal_ir_raw / hal_gyro_* / hal_battery_mv (protocol
# version 2), framed and compat.
IRPROBE_SRC := test/firmware/arduino/IrProbe/IrProbe.ino $(B)/arduino/uno/libmicromouse.a $(B)/arduino/uno/core.a $(ARD_HDRS)
$(B)/arduino/uno/IrProbe.elf $(B)/arduino/uno/IrProbe-compat.elf: $(B)/arduino/uno/IrProbe%.elf: $(IRPROBE_SRC)
	avr-g++ $(ARD_uno) $(ARD_COMMON) $(ARD_CXX) $(if $*,-DIRPROBE_COMPAT) -Wall -x c++ -include Arduino.h -c $< -o $@.o
	avr-gcc $(ARD_uno) -Os -Wl,--gc-sections $@.o $(B)/arduino/uno/libmicromouse.a $(B)/arduino/uno/core.a -lm -o $@
arduino: $(ARD_ELFS)
	@avr-size $(ARD_ELFS)
# The installable Arduino library (copy to ~/Arduino/libraries/): hal/arduino
# plus the HAL contract, the wire codec and the firmware, assembled here (a
# build product: never committed).
arduino-lib: $(B)/gen/paper/robot_profile.h
	@bash tools/make/arduino-lib.sh $(B)/arduino-lib $(B)/gen/paper/robot_profile.h


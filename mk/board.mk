# board.mk - our sketches for the emulated AVR boards (test/firmware/arduino/board),
# built for the Nano by tools/arduino-build as the Arduino IDE builds them.

# SKETCH_BUILD (sketch folder or .ino, image, more arguments): tools/arduino-build
# for the Nano, the core kept in $(B)/arduino-build. It also writes the .hex.
SKETCH_BUILD = python3 tools/arduino-build $(1) --board nano -o $(2) --cache $(B)/arduino-build $(3)
# Our sketches for the board emulation (test/cli/cli_board.sh, test/unit/test_board.c), built for the Nano.
BOARD_SKETCHES := $(patsubst test/firmware/arduino/board/%.ino,$(B)/clients/board/%.elf,$(wildcard test/firmware/arduino/board/*.ino))
# Our test sketches for the board emulation (test/cli/cli_board.sh), one .ino each,
# built for the Nano with -Wall.
board-sketches: $(BOARD_SKETCHES)
$(B)/clients/board/%.elf: test/firmware/arduino/board/%.ino tools/arduino-build | deps
	$(call SKETCH_BUILD,$<,$@,--warnings more)
# EncPoll with INT0/INT1 in edge mode: the other half of the benchmark pair (bench/run.sh)
$(B)/clients/board/EncPollEdge.elf: test/firmware/arduino/board/EncPoll.ino tools/arduino-build | deps
	$(call SKETCH_BUILD,$<,$@,--warnings more -DENCPOLL_EDGE)

# Our sketches for the UKMARSBOT board's peripherals, one folder each in
# test/firmware/arduino/board (rules below)
PERIPH_SKETCHES := MotorPwm Encoders AdcIr Switches Battery UartEcho Persist
PERIPH_ELFS     := $(patsubst %,$(B)/arduino/nano/board/%.elf,$(PERIPH_SKETCHES) UartEcho9600)

# ---- our sketches for the UKMARSBOT board's peripherals (test/firmware/arduino/board,
# test/cli/cli_board_periph.sh): sketch folders built for the Nano by
# tools/arduino-build, as the mazerunner-core images are. UartEcho9600:
# UartEcho at 9600 baud.
.PHONY: periph-sketches
periph-sketches: $(PERIPH_ELFS)
	@avr-size $(PERIPH_ELFS)
# PERIPH_SKETCH (image name, sketch folder, extra flags)
define PERIPH_SKETCH
$(B)/arduino/nano/board/$(1).elf: $(wildcard test/firmware/arduino/board/$(2)/*) tools/arduino-build | deps
	$$(call SKETCH_BUILD,test/firmware/arduino/board/$(2),$$@,--warnings more $(3))
endef
$(foreach s,$(PERIPH_SKETCHES),$(eval $(call PERIPH_SKETCH,$(s),$(s),)))
$(eval $(call PERIPH_SKETCH,UartEcho9600,UartEcho,-DECHO_BAUD=9600))

# clients.mk - real clients: firmware that others wrote, built from its own
# folder (../shared/clients or a clone: never copied into the repo) into $(B)/clients.

# mazerunner-core, UKMARSBOT's contest firmware for the Arduino Nano, built by
# tools/arduino-build as the Arduino IDE builds it (its .ino with prototypes,
# the core in an archive so Tone.cpp, which also defines TIMER2_COMPA_vect,
# stays out; -flto).
# Two images: as shipped (config.h: EVENT_HOME, goal (1,0)) and -uk, set up
# for a contest as its README says (EVENT_UK, goal (7,7)) by our header
# test/firmware/mazerunner-core/config-robot-orion.h in place of the
# client's in a copy of its files in $(B) (the client's own header is read
# from its folder: MRC_ROBOT_CONFIG). MRC_DIR: a clone of
# github.com/ukmars/mazerunner-core.
MRC_DIR    ?= $(SHARED)/clients/mazerunner-core
MRC_SKETCH := $(firstword $(wildcard $(MRC_DIR)/mazerunner-core/mazerunner-core.ino $(MRC_DIR)/mazerunner-core.ino))
MRC_SRC    := $(dir $(MRC_SKETCH))
MRC_FILES  := $(wildcard $(MRC_SRC)*.h $(MRC_SRC)*.ino)
MRC_ELFS   := $(B)/clients/mazerunner-core.elf $(B)/clients/mazerunner-core-uk.elf
ifeq ($(MRC_SKETCH),)
client-mazerunner: | deps
	@echo "SKIP client-mazerunner: $(MRC_DIR) not found"
else
client-mazerunner: mrc-images | deps
	@bash tools/make/avr-sizes.sh $(MRC_ELFS)
endif
mrc-images: $(MRC_ELFS) $(MRC_ELFS:.elf=.hex)
	@:
# MRC_BUILD (sketch folder, image): quiet (-w) as the IDE's default.
MRC_BUILD = $(call SKETCH_BUILD,$(1),$(2),)
$(B)/clients/mazerunner-core.elf: $(MRC_FILES) tools/arduino-build | deps
	$(call MRC_BUILD,$(MRC_SRC),$@)
MRC_UK_DIR  := $(B)/clients/mazerunner-core-uk/mazerunner-core
MRC_UK_CONF := test/firmware/mazerunner-core/config-robot-orion.h
MRC_UK_DEFS := -D 'MRC_ROBOT_CONFIG="$(abspath $(MRC_SRC))/config-robot-orion.h"'
$(MRC_UK_DIR)/config-robot-orion.h: $(MRC_FILES) $(MRC_UK_CONF)
	@rm -rf $(dir $@); mkdir -p $(dir $@); cp $(filter-out %/config-robot-orion.h,$(MRC_FILES)) $(dir $@)
	cp $(MRC_UK_CONF) $@
$(B)/clients/mazerunner-core-uk.elf: $(MRC_UK_DIR)/config-robot-orion.h tools/arduino-build
	$(call SKETCH_BUILD,$(dir $<),$@,$(MRC_UK_DEFS))
$(B)/clients/%.hex: $(B)/clients/%.elf
	avr-objcopy -O ihex -R .eeprom $< $@

# ---- Bulebots' bulebule (STM32F103, libopencm3), unmodified, built in a copy
# under $(B)/clients/bulebule by tools/build-bulebule.sh as ../shared/clients/README.md
# says (libopencm3's stm32/f1 target, then the firmware with newlib-nano); the
# files the snapshot lost come from tools/opencm3-compat ----
BULEBULE_SRC := $(SHARED)/clients/bulebule
BULEBULE_ELF := $(B)/clients/bulebule/src/main.elf
$(BULEBULE_ELF): tools/build-bulebule.sh $(wildcard tools/opencm3-compat/*/*/* tools/opencm3-compat/*/*/*/* tools/opencm3-compat/*.mk) | deps
	tools/build-bulebule.sh $(BULEBULE_SRC) $(B)/clients/bulebule
# Without ../shared's sources: one SKIP line (the tests that run it say SKIP too)
client-bulebule:
	@if [ -d $(BULEBULE_SRC)/src ]; then $(MAKE) --no-print-directory $(BULEBULE_ELF); else echo "SKIP client-bulebule: $(BULEBULE_SRC) not found"; fi
.PHONY: client-bulebule


# clients.mk - real clients: firmware that others wrote, built from its own
# folder (../shared/clients or a clone: never copied into the repo) into $(B)/clients.

# mazerunner-core, UKMARSBOT's contest firmware for the Arduino Nano, built by
# tools/arduino-build as the Arduino IDE builds it (its .ino with prototypes,
# the core in an archive so Tone.cpp, which also defines TIMER2_COMPA_vect,
# stays out; -flto).
# Two images: as shipped (config.h: EVENT_HOME, goal (1,0)) and -uk, set up
# for a contest as its README says (config.h's EVENT = EVENT_UK, goal (7,7)),
# on a copy in $(B). MRC_DIR: a clone of github.com/ukmars/mazerunner-core.
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
mrc-images: $(MRC_ELFS) $(MRC_ELFS:.elf=.hex) $(B)/clients/mazerunner-core-uk-mended.elf
	@:
# MRC_BUILD (sketch folder, image): quiet (-w) as the IDE's default.
MRC_BUILD = $(call SKETCH_BUILD,$(1),$(2),)
$(B)/clients/mazerunner-core.elf: $(MRC_FILES) tools/arduino-build | deps
	$(call MRC_BUILD,$(MRC_SRC),$@)
$(B)/clients/mazerunner-core-uk/mazerunner-core/config.h: $(MRC_FILES)
	@rm -rf $(dir $@); mkdir -p $(dir $@); cp $(MRC_FILES) $(dir $@)
	sed -i 's/^#define EVENT EVENT_HOME\b/#define EVENT EVENT_UK/' $@
	@grep -q '^#define EVENT EVENT_UK' $@ || { echo "client-mazerunner: no '#define EVENT EVENT_HOME' line in config.h to set to EVENT_UK" >&2; exit 1; }
$(B)/clients/mazerunner-core-uk.elf: $(B)/clients/mazerunner-core-uk/mazerunner-core/config.h tools/arduino-build
	$(call MRC_BUILD,$(dir $<),$@)
# For tests only, never shipped: the EVENT_UK copy with one firmware bug
# mended. search_to() checks heading_to_smallest() for BLOCKED before it
# checks for the target, and the target's cost is 0 with no smaller
# neighbour, so every search panics "ERR: no route to target" on entering
# its target (the simulator shows it). The mend: that
# check only short of the target. The rest of the search (home, the map)
# is tested with this image; the shipped ones stay untouched.
$(B)/clients/mazerunner-core-uk-mended/mazerunner-core/mouse.h: $(B)/clients/mazerunner-core-uk/mazerunner-core/config.h
	@rm -rf $(dir $@); mkdir -p $(dir $@); cp $(dir $<)*.h $(dir $<)*.ino $(dir $@)
	sed -i 's/^\( *\)if (newHeading == BLOCKED) {/\1if (newHeading == BLOCKED \&\& m_location != target) {/' $@
	@grep -q 'newHeading == BLOCKED && m_location != target' $@ || { echo "client-mazerunner: search_to's BLOCKED check not found in mouse.h" >&2; exit 1; }
$(B)/clients/mazerunner-core-uk-mended.elf: $(B)/clients/mazerunner-core-uk-mended/mazerunner-core/mouse.h tools/arduino-build
	$(call MRC_BUILD,$(dir $<),$@)
$(B)/clients/%.hex: $(B)/clients/%.elf
	avr-objcopy -O ihex -R .eeprom $< $@

# ---- Bulebots' bulebule (STM32F103, libopencm3), unmodified, built in a copy
# under $(B)/clients/bulebule as ../shared/clients/README.md says: libopencm3's
# stm32/f1 target, then the firmware with newlib-nano (the full newlib
# overflows its 63 KB flash region) ----
BULEBULE_SRC := $(SHARED)/clients/bulebule
BULEBULE_ELF := $(B)/clients/bulebule/src/main.elf
$(BULEBULE_ELF): | deps
	@[ -d $(BULEBULE_SRC)/src ] || { echo "make: $(BULEBULE_SRC) missing (../shared/clients)" >&2; exit 3; }
	@[ -f $(BULEBULE_SRC)/src/opencm3/libopencm3/include/libopencm3/cm3/nvic.h ] || { echo "make: $(BULEBULE_SRC)/src/opencm3/libopencm3/include/libopencm3/cm3/nvic.h missing (libopencm3's .gitignore names it; the copy in ../shared lost it)" >&2; exit 3; }
	rm -rf $(B)/clients/bulebule && mkdir -p $(B)/clients && cp -r $(BULEBULE_SRC) $(B)/clients/bulebule && chmod -R u+w $(B)/clients/bulebule
	$(MAKE) -s -C $(B)/clients/bulebule/src/opencm3/libopencm3 TARGETS=stm32/f1 SRCLIBDIR=$(CURDIR)/$(B)/clients/bulebule/src/opencm3/libopencm3/lib
	$(MAKE) -s -C $(B)/clients/bulebule/src LDFLAGS="-L./ -Lopencm3/libopencm3/lib --specs=nano.specs"
	arm-none-eabi-size $@
client-bulebule: $(BULEBULE_ELF)
.PHONY: client-bulebule


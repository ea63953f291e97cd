# tests.mk - `make test [ONLY=NAME]`: the unit tests (test/unit/test_*.c,
# cmocka, built with the sanitizers), the CLI tests (test/cli/cli_*.sh), the
# programs they call (test/tools), run by test/run.sh; the last line it
# prints: N passed, M failed, K skipped.

# Every test/unit/test_NAME.c is one program $(B)/test/test_NAME. A test_*.c
# or cli_*.sh left in test/ itself is still built and run, with a warning.
TEST_SRC  := $(wildcard test/unit/test_*.c test/test_*.c)
CLI_TESTS := $(wildcard test/cli/cli_*.sh test/cli_*.sh)
ifeq ($(MAKELEVEL),0)
$(if $(wildcard test/test_*.c test/cli_*.sh),$(warning $(wildcard test/test_*.c test/cli_*.sh): tests live in test/unit/ (test_*.c) and test/cli/ (cli_*.sh): git mv them there))
endif
TESTS    := $(patsubst %.c,$(B)/test/%,$(notdir $(TEST_SRC))) $(B)/test/test_flood_ref16

# Link-time mocks: a test that wraps HAL calls names them here.
WRAP_test_explore := -Wl,--wrap=hal_log -Wl,--wrap=hal_micros
WRAP_test_firmware := -Wl,--wrap=hal_log -Wl,--wrap=hal_micros -Wl,--wrap=hal_motor_set \
	-Wl,--wrap=hal_encoder -Wl,--wrap=hal_distance -Wl,--wrap=hal_maze
# Extra sources a test links (shared test vectors).
EXTRA_test_wire := test/unit/wire_vectors.c
# test_wire again with the MCU's decoder buffers, so its fault runs check the
# decoder as shipped: its own wire.c with the flag (libmm_san's has the host's).
TESTS += $(B)/test/test_wire_rx14

UNIT_LINK = $(CC) $(STD) $(WARN) $(INC) -O1 -g $(SAN) $< $(EXTRA_$*) $(WRAP_$*) $(B)/libmm_san.a -lcmocka $(LIBS) -o $@
$(B)/test/%: test/unit/%.c $(B)/libmm_san.a test/unit/wire_vectors.c
	@mkdir -p $(dir $@)
	$(UNIT_LINK)
$(B)/test/%: test/%.c $(B)/libmm_san.a test/unit/wire_vectors.c
	@mkdir -p $(dir $@)
	$(UNIT_LINK)
$(B)/test/test_wire_rx14: test/unit/test_wire.c $(B)/libmm_san.a test/unit/wire_vectors.c hal/wire/wire.c hal/wire/wire.h
	@mkdir -p $(dir $@)
	$(CC) $(STD) $(WARN) $(INC) -O1 -g $(SAN) $(MCU_RX_FLAGS) test/unit/test_wire.c $(EXTRA_test_wire) hal/wire/wire.c \
	  $(B)/libmm_san.a -lcmocka $(LIBS) -o $@
# The flood against its reference again with the AVR's 16x16 maximum, where
# maze_cell_t is uint8_t (the host library is built for 32x32)
FLOOD16_SRC := test/unit/test_flood_ref.c firmware/flood.c firmware/maze.c sim/maze/mazefile.c sim/maze/truemaze.c sim/maze/truebelief.c sim/io/infile.c
$(B)/test/test_flood_ref16: $(FLOOD16_SRC) $(wildcard firmware/*.h) sim/maze/mazefile.h sim/maze/truemaze.h sim/maze/truebelief.h sim/io/infile.h | deps
	@mkdir -p $(dir $@)
	$(CC) $(STD) $(WARN) -Ifirmware -Isim -O1 -g $(SAN) -DMAZE_MAX_SIZE=16 $(FLOOD16_SRC) -lcmocka -o $@

# test_slalom for UKMARSBOT's turns (robots/ukmarsbot.ini's [firmware] host
# figures): its firmware objects, and robots/ukmarsbot.ini's body (65 x 100
# mm, 64 mm of it ahead of the axle, taken on both sides; 10 mm wheels on a
# 77.4 mm track, out to 43.7 mm, 34 mm across)
UKB_BODY := -DBODY_X_MM=32.5 -DBODY_Y_MM=64.0 -DWHEEL_X_MM=43.7 -DWHEEL_Y_MM=17.0 -DDIAG_CLEAR_MM=3.0
$(B)/test/test_slalom_ukb: test/unit/test_slalom.c $(ukb_SAN_OBJ) $(B)/libmm_san.a
	@mkdir -p $(dir $@)
	$(CC) $(STD) $(WARN) -I$(B)/gen/ukmarsbot $(INC) -O1 -g $(SAN) $(UKB_BODY) $< $(ukb_SAN_OBJ) $(B)/libmm_san.a -lcmocka $(LIBS) -o $@
TESTS += $(B)/test/test_slalom_ukb

# XTEST input for test/cli/cli_connect.sh (libxtst-dev)
$(B)/test/xinput: test/tools/xinput.c | deps
	@mkdir -p $(dir $@)
	$(CC) $(STD) $(WARN) -O1 $< -lX11 -lXtst -o $@
# Boots an AVR image in simavr and prints its UART0 (test/cli/cli_mazerunner.sh)
$(B)/test/mrc_boot: test/tools/mrc_boot.c | deps
	@mkdir -p $(dir $@)
	$(CC) $(STD) $(WARN) -O1 -g $(SAN) $< -lsimavr -lelf -o $@

# The gdb stub's probe (test/cli/cli_armgdb.sh, cli_armwatch.sh): an ARM
# image on the core alone, with or without --gdb
$(B)/test/armgdb_probe: test/tools/armgdb_probe.c $(B)/libmm_san.a
	@mkdir -p $(dir $@)
	$(CC) $(STD) $(WARN) $(INC) -O1 -g $(SAN) $< $(B)/libmm_san.a $(LIBS) -o $@

# What the tests need built: the tools plain and sanitized, the images the
# CLI tests run. The unit tests read only the ARM image and the board sketches.
TEST_NEEDS := $(B)/pio/bin/pio $(TESTS) $(addprefix $(B)/,$(TOOLS)) $(addprefix $(B)/san-tools/,$(TOOLS)) $(B)/san-tools/half/mmsim $(B)/san-tools/ukb/mmsim $(B)/test/xinput firmware-size $(LCM_JAR) $(B)/avr/wire_selftest.elf arduino \
	$(B)/arduino/mega2560/Mouse-5x5.elf $(B)/arduino/uno/Mouse-5x5.elf $(B)/arduino/uno/OneCommand.elf $(B)/test/mrc_boot \
	$(B)/arduino/uno/IrProbe.elf $(B)/arduino/uno/IrProbe-compat.elf $(BOARD_SKETCHES) $(PERIPH_ELFS) $(ARM_TEST_ELFS) \
	client-mazerunner client-bulebule firmware-ukmarsbot $(B)/test/armgdb_probe
UNIT_NEEDS := $(ARM_TEST_ELFS) $(BOARD_SKETCHES)

# make test ONLY=NAME: the test of that name, with or without its prefix or
# folder: test_wire, wire or test/unit/test_wire.c; cli_mms, mms or
# test/cli/cli_mms.sh (a bare name that is both runs both).
ONLY_BASE  := $(basename $(notdir $(ONLY)))
ONLY_NAMES := $(ONLY_BASE) test_$(ONLY_BASE) cli_$(ONLY_BASE)
ifeq ($(ONLY),)
TEST_RUN   := $(TESTS) $(CLI_TESTS)
TEST_DEPS  := $(TEST_NEEDS)
else
ONLY_UNIT  := $(filter $(addprefix $(B)/test/,$(ONLY_NAMES)),$(TESTS))
ONLY_CLI   := $(filter $(foreach n,$(ONLY_NAMES),%/$(n).sh),$(CLI_TESTS))
TEST_RUN   := $(ONLY_UNIT) $(ONLY_CLI)
TEST_DEPS  := $(if $(ONLY_CLI),$(TEST_NEEDS),$(if $(ONLY_UNIT),$(ONLY_UNIT) $(UNIT_NEEDS)))
endif

# deps first, then a fresh make: on a new machine the packages (and the Arduino
# core's files that the wildcards below list) only exist once deps has run.
# The build and the tests use every core (TEST_JOBS=1: one test at a time).
NPROC := $(shell nproc 2>/dev/null || echo 1)
test: deps
	@$(MAKE) -j$(NPROC) --no-print-directory test-run
test-run: $(TEST_DEPS)
	@$(if $(strip $(TEST_RUN)),,echo "make test: no test named '$(ONLY)' (test/unit/test_NAME.c, test/cli/cli_NAME.sh)" >&2; exit 2;) \
	LSAN_OPTIONS=suppressions=$(CURDIR)/test/tools/lsan-simavr.supp MMMAZE=$(B)/san-tools/mmmaze MMSIM=$(B)/san-tools/mmsim HALF_MMSIM=$(B)/san-tools/half/mmsim UKB_MMSIM=$(B)/san-tools/ukb/mmsim MMLOG=$(B)/san-tools/mmlog MMVIEW=$(B)/san-tools/mmview XINPUT=$(B)/test/xinput LCM_JAR=$(LCM_JAR) SHARED=$${SHARED:-../shared} bash test/run.sh $(TEST_RUN)

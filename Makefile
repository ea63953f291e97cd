# mmsim - micromouse simulator. `make test` and `make sim` are all a newcomer needs.
.DEFAULT_GOAL := all
SHELL := /bin/bash

# Debian packages the build and tests need; `make deps` installs the missing ones.
# default-jre: lcm-spy is a Swing window (the headless JDK has no AWT);
# iproute2: `ip` for the udpm test's network namespace; universal-ctags: the
# function prototypes tools/arduino-build generates for a sketch's tabs;
# gdb: avr-gdb (gdb-avr) reads its Python scripts from gdb's data directory
# (/usr/share/gdb), without which it prints a Python error at every stop;
# python3-matplotlib: tools/mmplot draws a run's log against time;
# python3-dask, python3-distributed, python3-pandas, python3-pytest: the
# python/mmsim package and tools/mmsweep (sweeps on Dask, their tests).
# gcc-arm-none-eabi, libnewlib-arm-none-eabi, libstdc++-arm-none-eabi-newlib:
# our ARM test firmware (test/arm) and bulebule's build; libunicorn-dev: the
# Cortex-M core (sim/arm); gdb-multiarch: gdb for an ARM image.
DEB_PKGS := build-essential pkg-config libode-dev libcmocka-dev libjansson-dev libinih-dev \
	gcc-avr avr-libc arduino-core-avr simavr libsimavr-dev libelf-dev libdw-dev \
	liblcm-dev liblcm-bin libglib2.0-dev clang libclang-rt-14-dev \
	liblcm-java default-jdk-headless default-jre libjchart2d-java xvfb iproute2 \
	libpng-dev libglfw3-dev libgl-dev python3-venv libx11-dev libxtst-dev gdb-avr gdb universal-ctags \
	python3-matplotlib python3-dask python3-distributed python3-pandas python3-pytest valgrind \
	gcc-arm-none-eabi libnewlib-arm-none-eabi libstdc++-arm-none-eabi-newlib libunicorn-dev gdb-multiarch

CC      ?= gcc
STD     := -std=c99 -D_POSIX_C_SOURCE=200809L -D_DEFAULT_SOURCE
WARN    := -Wall -Wextra -Wshadow -Wstrict-prototypes -Wno-unused-parameter
INC      = -Ifirmware -Ihal -Ihal/sim -Ihal/wire -Isim -I$(B)/lcmgen $(shell pkg-config --cflags glib-2.0 ode libpng unicorn 2>/dev/null)
CFLAGS  ?= -O2 -g
SAN     := -fsanitize=address,undefined -fno-omit-frame-pointer -fno-sanitize-recover=undefined
LIBS     = -ljansson -linih -llcm $(shell pkg-config --libs glib-2.0 ode libpng glfw3 gl unicorn 2>/dev/null) -lsimavr -ldw -lelf -lm
B       := build
# ../shared: the maze database and the real clients (tests skip what is absent)
SHARED  ?= ../shared

# LCM message types (package mmlcm): C and Java generated at build time into
# $(B)/lcmgen and $(B)/lcmjava, never committed.
LCM_TYPES := $(wildcard lcm/*.lcm)
LCM_C     := $(patsubst lcm/%.lcm,$(B)/lcmgen/mmlcm_%.c,$(LCM_TYPES))
LCM_STAMP := $(B)/lcmgen/.stamp
LCM_JAR   := $(B)/lcmjava/mmlcm-types.jar
JAVA_CP   := /usr/share/java/lcm.jar:/usr/share/java/jchart2d.jar:$(LCM_JAR)

FW_SRC   := $(wildcard firmware/*.c)
SIM_SRC  := $(sort $(shell find sim -name '*.c'))
HOST_SRC := $(SIM_SRC) tools/cli.c hal/sim/hal_sim.c hal/wire/wire.c $(LCM_C) $(B)/gen/robot_paper.c
LIB_SRC  := $(FW_SRC) $(HOST_SRC)
TOOLS    := mmmaze mmsim mmlog mmview
TEST_SRC := $(wildcard test/test_*.c)
TESTS    := $(patsubst test/%.c,$(B)/test/%,$(TEST_SRC)) $(B)/test/test_flood_ref16

# Link-time mocks: a test that wraps HAL calls names them here.
WRAP_test_explore := -Wl,--wrap=hal_log -Wl,--wrap=hal_micros
WRAP_test_firmware := -Wl,--wrap=hal_log -Wl,--wrap=hal_micros -Wl,--wrap=hal_motor_set \
	-Wl,--wrap=hal_encoder -Wl,--wrap=hal_distance -Wl,--wrap=hal_maze
# Extra sources a test links (shared test vectors).
EXTRA_test_wire := test/wire_vectors.c
# The MCU's decoder buffers (see ARD_RAM): a build for an MCU takes no LOG.
MCU_RX_FLAGS := -DWIRE_RX_LOG_MAX=14
# test_wire again with the MCU's decoder buffers, so its fault runs check the
# decoder as shipped: its own wire.c with the flag (libmm_san's has the host's).
TESTS += $(B)/test/test_wire_rx14
# Our sketches for the board emulation (test/cli_board.sh, test/test_board.c), built for the Nano.
BOARD_SKETCHES := $(patsubst test/arduino/board/%.ino,$(B)/clients/board/%.elf,$(wildcard test/arduino/board/*.ino))

.PHONY: help all deps test test-run client-mazerunner mrc-images board-sketches sim sim-run bench bench-run fuzz firmware firmware-size arduino arduino-lib mazes clean tools spy replay view docs-img
all: tools

# make help: the targets a user types, one line each
help:
	@echo "make sim         install what is missing, build every tool, run a contest (MAZE=, SEED=, DRIVER=, GUI=1)"
	@echo "make test        install what is missing, build, run every test (one line each; the last: N passed, M failed, K skipped)"
	@echo "make             build every tool: build/mmsim, build/mmmaze, build/mmlog, build/mmview"
	@echo "make deps        install the Debian packages that are missing (idempotent)"
	@echo "make docs        rewrite the figures and pictures the docs show (docs/VALIDATION.md, docs/img) from the code"
	@echo "make bench       the speed and memory benchmarks (docs/BENCHMARKS.md)"
	@echo "make firmware    our mouse for the ATmega328P and the Arduino library's sketches (sizes printed)"
	@echo "make arduino     the Arduino sketches (hal/arduino) for the Uno, Mega and Nano"
	@echo "make client-mazerunner   UKMARSBOT's mazerunner-core images from ../shared/clients"
	@echo "make client-bulebule     Bulebots' bulebule (STM32F103) from ../shared/clients, in a copy"
	@echo "make view LOG=F  a log in the 3D viewer      make spy [LOG=F]   lcm-spy on a log or a live URL"
	@echo "make replay LOG=F  a log replayed on LCM     make install PREFIX=DIR   the tools and their files"
	@echo "make fuzz        the parsers under libFuzzer (FUZZ_SECONDS=)"
	@echo "make mazes       clone the micromouseonline maze database (the tests read ../shared/mazes)"
	@echo "make clean       remove build/"

deps:
	@missing=""; for p in $(DEB_PKGS); do \
	  dpkg-query -W -f='$${Status}\n' $$p 2>/dev/null | grep -q '^install ok installed' || missing="$$missing $$p"; \
	done; \
	if [ -n "$$missing" ]; then \
	  echo "make deps: installing$$missing"; \
	  SUDO=""; [ "$$(id -u)" = 0 ] || SUDO=sudo; \
	  $$SUDO apt-get update -qq && DEBIAN_FRONTEND=noninteractive $$SUDO apt-get install -y -qq $$missing >/dev/null || { echo "make deps: apt-get failed" >&2; exit 3; }; \
	fi
	@$(MAKE) -s --no-print-directory $(VENV_STAMP) \
	  || echo "make deps: no project venv ($(VENV)): tools/mmsweep needs it and test/cli_sweep.sh skips" >&2

# The project venv: Debian's python3 (/usr/bin/python3) with its site
# packages (dask, distributed, pandas, matplotlib) visible, plus the pinned
# packages Debian lacks (python/requirements.txt: pyarrow, for the sweeps'
# Parquet results). Rebuilt only when the requirements file changes. A pip
# that cannot reach its index leaves the rest of make deps (and the build)
# going: only the sweeps need the venv.
VENV       := $(B)/venv
VENV_STAMP := $(VENV)/.requirements-installed
$(VENV_STAMP): python/requirements.txt
	@[ -x $(VENV)/bin/python ] || /usr/bin/python3 -m venv --system-site-packages $(VENV) \
	  || { echo "make deps: python3 -m venv failed (python3-venv)" >&2; exit 3; }
	@$(VENV)/bin/python -m pip install -q -r python/requirements.txt \
	  || { echo "make deps: pip install -r python/requirements.txt failed" >&2; exit 3; }
	@touch $@

# ---- LCM types ----
$(LCM_STAMP): $(LCM_TYPES) | deps
	@mkdir -p $(dir $@)
	lcm-gen -c --c-cpath $(B)/lcmgen --c-hpath $(B)/lcmgen $(LCM_TYPES)
	@touch $@
$(LCM_C): $(LCM_STAMP)
$(LCM_JAR): $(LCM_TYPES) | deps
	@rm -rf $(B)/lcmjava; mkdir -p $(B)/lcmjava/classes
	lcm-gen -j --jpath $(B)/lcmjava/src $(LCM_TYPES)
	javac -nowarn -cp /usr/share/java/lcm.jar -d $(B)/lcmjava/classes $$(find $(B)/lcmjava/src -name '*.java')
	jar cf $@ -C $(B)/lcmjava/classes .

# ---- the built-in robot: robots/paper.ini as a C string ----
$(B)/gen/robot_paper.c: robots/paper.ini
	@mkdir -p $(dir $@)
	{ echo '/* generated by the Makefile from robots/paper.ini: the default robot */'; \
	  echo 'const char robot_paper_ini[] ='; \
	  sed -e 's/\\/\\\\/g' -e 's/"/\\"/g' -e 's/^/    "/' -e 's/$$/\\n"/' $<; echo ';'; } > $@.tmp && mv $@.tmp $@

# ---- host library and tools (optimised, no sanitizers) ----
$(B)/host/%.o: %.c | deps $(LCM_STAMP)
	@mkdir -p $(dir $@)
	$(CC) $(STD) $(WARN) $(INC) $(CFLAGS) -MMD -MP -c $< -o $@
$(B)/libmm.a: $(patsubst %.c,$(B)/host/%.o,$(LIB_SRC))
	@rm -f $@; ar rcs $@ $^
$(B)/%: tools/%.c $(B)/libmm.a
	$(CC) $(STD) $(WARN) $(INC) $(CFLAGS) $< $(B)/libmm.a $(LIBS) -o $@
tools: $(addprefix $(B)/,$(TOOLS))

# mmsim builds whose in-process firmware is built for another robot than
# the paper's: the half-size build for KERISE v5 in 90 mm cells
# (firmware/robot_kerise.h, robots/kerise-v5.ini) and the UKMARSBOT build
# for ORION with the host's planner (firmware/robot_ukmarsbot.h,
# robots/ukmarsbot.ini), each plain ($(B)/NAME/mmsim) and sanitized
# ($(B)/san-tools/NAME/mmsim, for test/cli_halfsize.sh, cli_ukbhost.sh).
# Their own firmware objects come before the library, so the library's
# are not linked. ROBOT_MMSIM: $(1) the build's name, $(2) its header.
define ROBOT_MMSIM
$(1)_FW_OBJ := $$(patsubst firmware/%.c,$$(B)/$(1)/firmware/%.o,$$(FW_SRC))
$$(B)/$(1)/firmware/%.o: firmware/%.c | deps $$(LCM_STAMP)
	@mkdir -p $$(dir $$@)
	$$(CC) $$(STD) $$(WARN) $$(INC) $$(CFLAGS) -include $(2) -MMD -MP -c $$< -o $$@
$$(B)/$(1)/mmsim: tools/mmsim.c $$($(1)_FW_OBJ) $$(B)/libmm.a
	$$(CC) $$(STD) $$(WARN) $$(INC) $$(CFLAGS) $$< $$($(1)_FW_OBJ) $$(B)/libmm.a $$(LIBS) -o $$@
$(1)_SAN_OBJ := $$(patsubst firmware/%.c,$$(B)/san/$(1)/firmware/%.o,$$(FW_SRC))
$$(B)/san/$(1)/firmware/%.o: firmware/%.c | deps $$(LCM_STAMP)
	@mkdir -p $$(dir $$@)
	$$(CC) $$(STD) $$(WARN) $$(INC) -O1 -g $$(SAN) -include $(2) -MMD -MP -c $$< -o $$@
$$(B)/san-tools/$(1)/mmsim: tools/mmsim.c $$($(1)_SAN_OBJ) $$(B)/libmm_san.a
	@mkdir -p $$(dir $$@)
	$$(CC) $$(STD) $$(WARN) $$(INC) -O1 -g $$(SAN) $$< $$($(1)_SAN_OBJ) $$(B)/libmm_san.a $$(LIBS) -o $$@
endef
$(eval $(call ROBOT_MMSIM,half,robot_kerise.h))
$(eval $(call ROBOT_MMSIM,ukb,robot_ukmarsbot.h))

# The source tree's absolute path, where a program built here finds boards/,
# robots/ and contests/ from any working directory (sim/io/datadir.h).
$(B)/host/sim/io/datadir.o $(B)/san/sim/io/datadir.o: INC += -DMMSIM_DATADIR='"$(CURDIR)"'

# `make install PREFIX=DIR`: the tools in DIR/bin, the board, robot and contest files in
# DIR/share/mmsim, where DIR/bin/mmsim finds them from any working directory.
PREFIX ?= /usr/local
install: $(addprefix $(B)/,$(TOOLS))
	install -d $(DESTDIR)$(PREFIX)/bin $(DESTDIR)$(PREFIX)/share/mmsim/boards/parts $(DESTDIR)$(PREFIX)/share/mmsim/robots $(DESTDIR)$(PREFIX)/share/mmsim/contests
	install -m 755 $^ $(DESTDIR)$(PREFIX)/bin
	install -m 644 boards/*.ini $(DESTDIR)$(PREFIX)/share/mmsim/boards
	install -m 644 boards/parts/*.ini $(DESTDIR)$(PREFIX)/share/mmsim/boards/parts
	install -m 644 robots/*.ini $(DESTDIR)$(PREFIX)/share/mmsim/robots
	install -m 644 contests/*.ini $(DESTDIR)$(PREFIX)/share/mmsim/contests
.PHONY: install

# ---- tests (sanitized) ----
$(B)/san/%.o: %.c | deps $(LCM_STAMP)
	@mkdir -p $(dir $@)
	$(CC) $(STD) $(WARN) $(INC) -O1 -g $(SAN) -MMD -MP -c $< -o $@
$(B)/libmm_san.a: $(patsubst %.c,$(B)/san/%.o,$(LIB_SRC))
	@rm -f $@; ar rcs $@ $^
$(B)/test/%: test/%.c $(B)/libmm_san.a test/wire_vectors.c
	@mkdir -p $(dir $@)
	$(CC) $(STD) $(WARN) $(INC) -O1 -g $(SAN) $< $(EXTRA_$*) $(WRAP_$*) $(B)/libmm_san.a -lcmocka $(LIBS) -o $@
$(B)/test/test_wire_rx14: test/test_wire.c $(B)/libmm_san.a test/wire_vectors.c hal/wire/wire.c hal/wire/wire.h
	@mkdir -p $(dir $@)
	$(CC) $(STD) $(WARN) $(INC) -O1 -g $(SAN) $(MCU_RX_FLAGS) test/test_wire.c $(EXTRA_test_wire) hal/wire/wire.c \
	  $(B)/libmm_san.a -lcmocka $(LIBS) -o $@
# The flood against its reference again with the AVR's 16x16 maximum, where
# maze_cell_t is uint8_t (the host library is built for 32x32)
FLOOD16_SRC := test/test_flood_ref.c firmware/flood.c firmware/maze.c sim/maze/mazefile.c sim/io/infile.c
$(B)/test/test_flood_ref16: $(FLOOD16_SRC) $(wildcard firmware/*.h) sim/maze/mazefile.h sim/io/infile.h | deps
	@mkdir -p $(dir $@)
	$(CC) $(STD) $(WARN) -Ifirmware -Isim -O1 -g $(SAN) -DMAZE_MAX_SIZE=16 $(FLOOD16_SRC) -lcmocka -o $@
$(B)/san-tools/%: tools/%.c $(B)/libmm_san.a
	@mkdir -p $(dir $@)
	$(CC) $(STD) $(WARN) $(INC) -O1 -g $(SAN) $< $(B)/libmm_san.a $(LIBS) -o $@

# test_slalom for UKMARSBOT's turns (firmware/robot_ukmarsbot.h's host
# figures): its firmware objects, and robots/ukmarsbot.ini's body (65 x 100
# mm, 64 mm of it ahead of the axle, taken on both sides; 10 mm wheels on a
# 77.4 mm track, out to 43.7 mm, 34 mm across)
UKB_BODY := -DBODY_X_MM=32.5 -DBODY_Y_MM=64.0 -DWHEEL_X_MM=43.7 -DWHEEL_Y_MM=17.0 -DDIAG_CLEAR_MM=3.0
$(B)/test/test_slalom_ukb: test/test_slalom.c $(ukb_SAN_OBJ) $(B)/libmm_san.a
	@mkdir -p $(dir $@)
	$(CC) $(STD) $(WARN) $(INC) -O1 -g $(SAN) -include robot_ukmarsbot.h $(UKB_BODY) $< $(ukb_SAN_OBJ) $(B)/libmm_san.a -lcmocka $(LIBS) -o $@
TESTS += $(B)/test/test_slalom_ukb

# XTEST input for test/cli_connect.sh (libxtst-dev)
$(B)/test/xinput: test/xinput.c | deps
	@mkdir -p $(dir $@)
	$(CC) $(STD) $(WARN) -O1 $< -lX11 -lXtst -o $@

# ---- our ARM test firmware (test/arm: register-level C, our own startup and
# linker script) for the Cortex-M core's tests (test/test_armcore.c,
# test/test_armimage.c), built with Debian's arm-none-eabi-gcc ----
ARM_CC    := arm-none-eabi-gcc
ARM_FLAGS := -mcpu=cortex-m3 -mthumb -std=gnu99 -Os -g -Wall -Wextra -ffreestanding -nostdlib -Wl,--gc-sections
ARM_TEST_ELFS := $(B)/arm/coretest.elf $(B)/arm/gdbtest.elf
# the gdb stub's probe (test/cli_armgdb.sh): an ARM image on the core alone, with or without --gdb
test-run: $(B)/test/armgdb_probe
$(B)/arm/%.elf: test/arm/%.c test/arm/startup.c test/arm/armtest.h test/arm/link.ld | deps
	@mkdir -p $(dir $@)
	$(ARM_CC) $(ARM_FLAGS) -T test/arm/link.ld test/arm/startup.c $< -o $@
arm-test-firmware: $(ARM_TEST_ELFS)
.PHONY: arm-test-firmware

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

# Boots an AVR image in simavr and prints its UART0 (test/cli_mazerunner.sh)
$(B)/test/mrc_boot: test/mrc_boot.c | deps
	@mkdir -p $(dir $@)
	$(CC) $(STD) $(WARN) -O1 -g $(SAN) $< -lsimavr -lelf -o $@

# Our sketches for the UKMARSBOT board's peripherals, one folder each in
# test/arduino/board (rules below, by the clients')
PERIPH_SKETCHES := MotorPwm Encoders AdcIr Switches Battery UartEcho Persist
PERIPH_ELFS     := $(patsubst %,$(B)/arduino/nano/board/%.elf,$(PERIPH_SKETCHES) UartEcho9600)

# deps first, then a fresh make: on a new machine the packages (and the Arduino
# core's files that the wildcards below list) only exist once deps has run.
# The build and the tests use every core (TEST_JOBS=1: one test at a time).
NPROC := $(shell nproc 2>/dev/null || echo 1)
test: deps
	@$(MAKE) -j$(NPROC) --no-print-directory test-run
test-run: $(B)/pio/bin/pio $(TESTS) $(addprefix $(B)/,$(TOOLS)) $(addprefix $(B)/san-tools/,$(TOOLS)) $(B)/san-tools/half/mmsim $(B)/san-tools/ukb/mmsim $(B)/test/xinput firmware-size $(LCM_JAR) $(B)/avr/wire_selftest.elf arduino \
	$(B)/arduino/mega2560/Mouse-5x5.elf $(B)/arduino/uno/Mouse-5x5.elf $(B)/arduino/uno/OneCommand.elf $(B)/test/mrc_boot \
	$(B)/arduino/uno/IrProbe.elf $(B)/arduino/uno/IrProbe-compat.elf $(BOARD_SKETCHES) $(PERIPH_ELFS) $(ARM_TEST_ELFS) \
	client-mazerunner firmware-ukmarsbot
	@LSAN_OPTIONS=suppressions=$(CURDIR)/test/lsan-simavr.supp MMMAZE=$(B)/san-tools/mmmaze MMSIM=$(B)/san-tools/mmsim HALF_MMSIM=$(B)/san-tools/half/mmsim UKB_MMSIM=$(B)/san-tools/ukb/mmsim MMLOG=$(B)/san-tools/mmlog MMVIEW=$(B)/san-tools/mmview XINPUT=$(B)/test/xinput LCM_JAR=$(LCM_JAR) SHARED=$${SHARED:-../shared} bash test/run.sh $(TESTS) $(wildcard test/cli_*.sh)

# PlatformIO from PyPI in a venv, only to check that platformio.ini parses
# (`pio run` cannot download its platforms here). No PyPI: the check skips.
PIO_VERSION := 6.2.0
$(B)/pio/bin/pio: | deps
	@python3 -m venv $(B)/pio && $(B)/pio/bin/pip install -q platformio==$(PIO_VERSION) >/dev/null 2>&1 \
	  || { echo "make: platformio $(PIO_VERSION) not installed from PyPI: its check will be skipped"; rm -f $@; }

# ---- AVR build of the firmware (ATmega328P) ----
AVR_CC    := avr-gcc
AVR_FLAGS := -mmcu=atmega328p -DF_CPU=16000000L -Os -std=c99 -Wall -Wextra -DMAZE_MAX_SIZE=16 \
	-ffunction-sections -fdata-sections -Ifirmware -Ihal
firmware-size: | deps
	@mkdir -p $(B)/avr
	$(AVR_CC) $(AVR_FLAGS) -Wl,--gc-sections $(FW_SRC) test/avr_main.c -o $(B)/avr/firmware.elf
	avr-size $(B)/avr/firmware.elf
	@avr-nm -S --size-sort $(B)/avr/firmware.elf | grep -i ' [bd] ' | tail -8
firmware: firmware-size arduino
# ---- the firmware on UKMARSBOT's Nano: firmware/ + hal/ukmarsbot, plain avr-libc ----
# `make firmware-ukmarsbot` builds $(B)/ukmarsbot/mouse.elf and .hex (the image
# a user flashes; mmsim --board ukmarsbot --avr runs the ELF) and prints its
# flash (limit UKB_FLASH_MAX: the Nano's 32 KB less its 2 KB bootloader) and
# static RAM. UKB_SENSOR_BOARD=basic builds for the BASIC wall sensor board.
# platformio.ini [env:ukmarsbot] builds the same files (UKB_SRC; test/cli_ukmarsbot_fw.sh).
UKB_SRC       := $(FW_SRC) $(sort $(wildcard hal/ukmarsbot/*.c))
UKB_FLASH_MAX := 30720
UKB_SENSOR_BOARD ?= advanced
UKB_FLAGS     := $(AVR_FLAGS) -Ihal/ukmarsbot -include robot_ukmarsbot.h -DHAL_IR_LIT_MINUS_DARK -DHAL_LOG_MAX=50 -fno-inline-functions -fno-inline-small-functions -fno-inline-functions-called-once $(if $(filter basic,$(UKB_SENSOR_BOARD)),-DUKB_SENSOR_BOARD_BASIC)
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
	@$(B)/mmsim --board $(UKB_BOARD) --avr $< --robot $(UKB_ROBOT) --maze mazes/gen-16x16-s1.txt \
	  --input "0.3 send=g; 240 send=k; 241 end" --json > $@.json; rc=$$?; [ $$rc -le 1 ] || { rm -f $@.json; exit 3; }
	@python3 -c 'import json, sys; \
	c = json.loads(open(sys.argv[1]).read().splitlines()[-1])["console"].replace("\r", ""); \
	k = [l for l in c.splitlines() if l.startswith("stack unused")]; \
	k or sys.exit("ukmarsbot: no stack report in the console (the k command)"); \
	print(k[-1].split(",")[0].split()[-2])' $@.json > $@.tmp && mv $@.tmp $@; rc=$$?; rm -f $@.json $@.tmp; exit $$rc
firmware-ukmarsbot: $(UKB_OUT)/mouse.elf $(UKB_OUT)/mouse.hex $(UKB_OUT)/stack.txt
	@avr-size $< | awk -v max=$(UKB_FLASH_MAX) -v stack="$$(cat $(UKB_OUT)/stack.txt)" 'NR == 2 { f = $$1 + $$2; r = $$2 + $$3; \
	  printf "ukmarsbot: flash %d B of %d, static RAM %d B of 2048 (%d B left for the stack)\n", f, max, r, 2048 - r; \
	  printf "ukmarsbot: stack headroom %d B: RAM never written during a contest on mazes/gen-16x16-s1.txt (measured on the emulated board)\n", stack; \
	  if (f > max) { print "ukmarsbot: flash over the limit"; exit 1 } }'
ukmarsbot-stack: $(UKB_OUT)/stack.txt
	@echo "ukmarsbot: stack never used after a contest: $$(cat $<) B"
# the source list, one a line (test/cli_ukmarsbot_fw.sh compares platformio.ini's)
ukmarsbot-src:
	@printf '%s\n' $(UKB_SRC)
.PHONY: firmware-ukmarsbot ukmarsbot-src ukmarsbot-stack
# The wire codec's shared vectors on the ATmega328P, run in simavr by test/cli_hil.sh.
$(B)/avr/wire_selftest.elf: test/avr_wire.c test/wire_vectors.c hal/wire/wire.c hal/wire/wire.h | deps
	@mkdir -p $(dir $@)
	$(AVR_CC) -mmcu=atmega328p -DF_CPU=16000000L -Os -std=c99 -Wall -Wextra -ffunction-sections -fdata-sections $(MCU_RX_FLAGS) \
	  -Ihal/wire -Itest -Wl,--gc-sections test/avr_wire.c test/wire_vectors.c hal/wire/wire.c -o $@

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
ARD_COMMON   := $(ARD_BASE) -DMAZE_MAX_SIZE=16 $(ARD_RAM) -Ihal -Ihal/wire -Ihal/arduino/src -Ifirmware
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
# The processor-in-the-loop test image: the Mouse sketch on a 5x5 maze (test/cli_pil.sh).
$(B)/arduino/%/Mouse-5x5.elf: hal/arduino/examples/Mouse/Mouse.ino $(B)/arduino/%/libmicromouse.a $(B)/arduino/%/core.a $(ARD_HDRS)
	avr-g++ $(ARD_$*) $(ARD_COMMON) $(ARD_CXX) -DMM_MAZE_SIZE=5 -Wall -x c++ -include Arduino.h -c $< -o $@.o
	avr-gcc $(ARD_$*) -Os -Wl,--gc-sections $@.o $(B)/arduino/$*/libmicromouse.a $(B)/arduino/$*/core.a -lm -o $@
# A test sketch (test/cli_pil.sh): one motor command, then only reads, as a
# sketch of the paper's library that sets its motors once.
$(B)/arduino/uno/OneCommand.elf: test/arduino/OneCommand/OneCommand.ino $(B)/arduino/uno/libmicromouse.a $(B)/arduino/uno/core.a $(ARD_HDRS)
	avr-g++ $(ARD_uno) $(ARD_COMMON) $(ARD_CXX) -Wall -x c++ -include Arduino.h -c $< -o $@.o
	avr-gcc $(ARD_uno) -Os -Wl,--gc-sections $@.o $(B)/arduino/uno/libmicromouse.a $(B)/arduino/uno/core.a -lm -o $@
# A test sketch (test/cli_pil.sh): the runner with a stand-in firmware that
# calls hal_emitter / hal_ir_raw / hal_gyro_* / hal_battery_mv (protocol
# version 2), framed and compat.
IRPROBE_SRC := test/arduino/IrProbe/IrProbe.ino $(B)/arduino/uno/libmicromouse.a $(B)/arduino/uno/core.a $(ARD_HDRS)
$(B)/arduino/uno/IrProbe.elf $(B)/arduino/uno/IrProbe-compat.elf: $(B)/arduino/uno/IrProbe%.elf: $(IRPROBE_SRC)
	avr-g++ $(ARD_uno) $(ARD_COMMON) $(ARD_CXX) $(if $*,-DIRPROBE_COMPAT) -Wall -x c++ -include Arduino.h -c $< -o $@.o
	avr-gcc $(ARD_uno) -Os -Wl,--gc-sections $@.o $(B)/arduino/uno/libmicromouse.a $(B)/arduino/uno/core.a -lm -o $@
arduino: $(ARD_ELFS)
	@avr-size $(ARD_ELFS)
# The installable Arduino library (copy to ~/Arduino/libraries/): hal/arduino
# plus the HAL contract, the wire codec and the firmware, assembled here (a
# build product: never committed).
arduino-lib:
	@rm -rf $(B)/arduino-lib/Micromouse; mkdir -p $(B)/arduino-lib/Micromouse/src
	cp -r hal/arduino/library.properties hal/arduino/README.md hal/arduino/examples $(B)/arduino-lib/Micromouse/
	cp hal/arduino/src/* hal/hal.h hal/wire/wire.c hal/wire/wire.h $(B)/arduino-lib/Micromouse/src/
	cp firmware/*.c firmware/*.h $(B)/arduino-lib/Micromouse/src/
	@echo "$(B)/arduino-lib/Micromouse: copy it to your Arduino libraries folder (see hal/arduino/README.md)"

# ---- real clients: firmware that others wrote, built from its own folder
# (../shared/clients or a clone: never copied into the repo) into $(B)/clients.
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
client-mazerunner: | deps
	@if [ -z "$(MRC_SKETCH)" ]; then echo "SKIP client-mazerunner: $(MRC_DIR) not found"; exit 0; fi; \
	$(MAKE) --no-print-directory mrc-images && avr-size $(MRC_ELFS) && \
	for e in $(MRC_ELFS); do echo "$$e: $$(avr-size -C --mcu=atmega328p $$e | grep '^Program:\|^Data:' | tr -s ' ' | paste -sd' ')"; done
mrc-images: $(MRC_ELFS) $(MRC_ELFS:.elf=.hex) $(B)/clients/mazerunner-core-uk-mended.elf
	@:
# SKETCH_BUILD (sketch folder or .ino, image, more arguments): tools/arduino-build
# for the Nano, the core kept in $(B)/arduino-build. It also writes the .hex.
SKETCH_BUILD = python3 tools/arduino-build $(1) --board nano -o $(2) --cache $(B)/arduino-build $(3)
# MRC_BUILD (sketch folder, image): quiet (-w) as the IDE's default.
MRC_BUILD = $(call SKETCH_BUILD,$(1),$(2),)
# Our test sketches for the board emulation (test/cli_board.sh), one .ino each,
# built for the Nano with -Wall.
board-sketches: $(BOARD_SKETCHES)
$(B)/clients/board/%.elf: test/arduino/board/%.ino tools/arduino-build | deps
	$(call SKETCH_BUILD,$<,$@,--warnings more)
# EncPoll with INT0/INT1 in edge mode: the other half of the benchmark pair (bench/run.sh)
$(B)/clients/board/EncPollEdge.elf: test/arduino/board/EncPoll.ino tools/arduino-build | deps
	$(call SKETCH_BUILD,$<,$@,--warnings more -DENCPOLL_EDGE)
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

# ---- our sketches for the UKMARSBOT board's peripherals (test/arduino/board,
# test/cli_board_periph.sh): sketch folders built for the Nano by
# tools/arduino-build, as the mazerunner-core images are. UartEcho9600:
# UartEcho at 9600 baud.
.PHONY: periph-sketches
periph-sketches: $(PERIPH_ELFS)
	@avr-size $(PERIPH_ELFS)
# PERIPH_SKETCH (image name, sketch folder, extra flags)
define PERIPH_SKETCH
$(B)/arduino/nano/board/$(1).elf: $(wildcard test/arduino/board/$(2)/*) tools/arduino-build | deps
	$$(call SKETCH_BUILD,test/arduino/board/$(2),$$@,--warnings more $(3))
endef
$(foreach s,$(PERIPH_SKETCHES),$(eval $(call PERIPH_SKETCH,$(s),$(s),)))
$(eval $(call PERIPH_SKETCH,UartEcho9600,UartEcho,-DECHO_BAUD=9600))

# ---- simulation: a whole contest with the firmware in the loop (search,
# proof, return, speed runs); DRIVER=scripted drives the true best path ----
MAZE ?= mazes/gen-16x16-s1.txt
SEED ?= 1
DRIVER ?= firmware
# GUI=1: the same run live in the 3D viewer at x8 (a whole contest in ~75 s)
sim: deps
	@$(MAKE) --no-print-directory sim-run
sim-run: $(addprefix $(B)/,$(TOOLS))
	$(B)/mmsim --maze $(MAZE) --seed $(SEED) --driver $(DRIVER) $(if $(GUI),--gui --speed 8)

# ---- LCM tools: the spy on a live URL or a log, a log replayed in real time ----
# make spy [LCM_URL=udpm://...] [LOG=run.lcmlog]    make replay LOG=run.lcmlog [SPEED=1]
# make view LOG=run.lcmlog [SPEED=1]
LCM_URL ?=
SPEED ?= 1
spy: $(LCM_JAR)
	java -Djava.net.preferIPv4Stack=true -cp $(JAVA_CP) lcm.spy.Spy \
	  $(if $(LOG),--lcm-url='file://$(abspath $(LOG))?speed=$(SPEED)',$(if $(LCM_URL),--lcm-url='$(LCM_URL)'))
replay:
	@[ -n "$(LOG)" ] || { echo "make replay: LOG=FILE is required" >&2; exit 2; }
	lcm-logplayer --speed=$(SPEED) $(if $(LCM_URL),--lcm-url='$(LCM_URL)') $(LOG)
# make view LOG=run.lcmlog [SPEED=1]: the log in the 3D viewer with a time slider (mmview)
view: $(B)/mmview
	@[ -n "$(LOG)" ] || { echo "make view: LOG=FILE is required" >&2; exit 2; }
	$(B)/mmview $(LOG) --speed $(SPEED)

X_RUN = $(if $(DISPLAY),,xvfb-run -a -s '-screen 0 1024x768x24 -nolisten tcp')
# The figures and pictures the docs show, written by the programs that make
# them: docs/VALIDATION.md's --validate tables (tools/docs-validation;
# test/cli_validate.sh checks them) and the README's three pictures with the
# README's commands (docs-img, into IMG_DIR; without a display under
# xvfb-run; test/cli_docs_img.sh checks them)
.PHONY: docs
docs: $(B)/mmsim $(B)/mmview
	python3 tools/docs-validation --mmsim $(B)/mmsim
	@$(MAKE) --no-print-directory docs-img

IMG_DIR ?= docs/img
docs-img: $(B)/mmsim $(B)/mmview
	@mkdir -p $(IMG_DIR); tmp=$$(mktemp -d); trap 'rm -rf "$$tmp"' EXIT; \
	$(X_RUN) $(B)/mmsim --maze mazes/gen-16x16-s1.txt --driver firmware --screenshot $(IMG_DIR)/viewer.png --at 40 --size 800x600 >/dev/null && \
	$(B)/mmsim --maze mazes/gen-16x16-s1.txt --driver firmware --report "$$tmp/report.png" >/dev/null && mv "$$tmp/report.png" $(IMG_DIR)/report.png && \
	$(B)/mmsim --maze mazes/gen-16x16-s1.txt --driver firmware --lcm-log "$$tmp/run.lcmlog" >/dev/null && \
	$(X_RUN) $(B)/mmview "$$tmp/run.lcmlog" --screenshot $(IMG_DIR)/mmview.png --at 30 --camera 2 --size 800x600 && \
	echo "$(IMG_DIR): viewer.png report.png mmview.png"

# ---- benchmarks ----
bench: deps
	@$(MAKE) --no-print-directory bench-run
bench-run: $(B)/mmmaze $(B)/mmsim $(B)/bench_flood $(B)/simavr_cycles $(B)/avr/flood.elf \
	$(B)/avr/tick0.elf $(B)/avr/tick100.elf arduino $(B)/clients/board/EncPoll.elf $(B)/clients/board/EncPollEdge.elf $(B)/ode_rows \
	$(B)/armcore_speed $(ARM_TEST_ELFS)
	BENCH_MAZE=$(BENCH_MAZE) bash bench/run.sh
$(B)/armcore_speed: bench/armcore_speed.c $(B)/libmm.a
	$(CC) $(STD) $(WARN) $(INC) $(CFLAGS) $< $(B)/libmm.a $(LIBS) -o $@
$(B)/ode_rows: bench/ode_rows.c | deps
	$(CC) -O2 $< $$(pkg-config --cflags --libs ode) -lm -o $@
$(B)/simavr_cycles: bench/simavr_cycles.c | deps
	$(CC) -O2 $< $$(pkg-config --cflags --libs simavr) -o $@
# The AVR flood benchmark's true map: japan2018 from the database, else a
# generated 16x16 from mazes/ (bench/avr_flood.c)
BENCH_MAZE ?= $(firstword $(wildcard $(SHARED)/mazes/classic/japan2018.txt) mazes/gen-16x16-s1.txt)
$(B)/maze_header: bench/maze_header.c $(B)/libmm.a
	$(CC) $(STD) $(WARN) $(INC) $(CFLAGS) $< $(B)/libmm.a $(LIBS) -o $@
$(B)/avr/bench_maze.h: $(B)/maze_header $(BENCH_MAZE)
	@mkdir -p $(dir $@)
	$(B)/maze_header $(BENCH_MAZE) > $@.tmp && mv $@.tmp $@
$(B)/avr/flood.elf: bench/avr_flood.c $(B)/avr/bench_maze.h $(FW_SRC) | deps
	$(AVR_CC) $(AVR_FLAGS) -I$(B)/avr -Wl,--gc-sections -Wl,--wrap=flood_run bench/avr_flood.c \
	  firmware/explore.c firmware/flood.c firmware/maze.c -o $@
$(B)/avr/tick%.elf: bench/avr_tick.c $(FW_SRC) | deps
	@mkdir -p $(dir $@)
	$(AVR_CC) $(AVR_FLAGS) -DREPS=$* -Wl,--gc-sections bench/avr_tick.c firmware/motion.c firmware/odom.c \
	  firmware/profile.c -lm -o $@
$(B)/bench_flood: bench/bench_flood.c $(B)/libmm.a
	$(CC) $(STD) $(WARN) $(INC) $(CFLAGS) $< $(B)/libmm.a $(LIBS) -o $@

# ---- fuzzing (clang libFuzzer + ASan; bounded; not in CI) ----
# make fuzz [FUZZ="mazefile wire lcmlog config robot contest"] [FUZZ_SECONDS=60]: each target
# in turn for FUZZ_SECONDS; corpora in $(B)/fuzz/corpus_NAME, findings
# (crash-*, leak-*) in $(B)/fuzz.
FUZZ_SECONDS ?= 60
FUZZ ?= mazefile wire lcmlog config robot contest
FUZZ_CC := clang -g -O1 -fsanitize=fuzzer,address,undefined -D_POSIX_C_SOURCE=200809L -D_DEFAULT_SOURCE
FUZZ_SRC_mazefile := sim/maze/mazefile.c sim/io/infile.c firmware/maze.c
FUZZ_SRC_wire     := hal/wire/wire.c
FUZZ_SRC_lcmlog   := sim/telemetry/lcmlog.c sim/io/infile.c $(LCM_C)
# the config loads the built-in robot: the robot file's loader, its sensor
# kinds and what they use of the world
FUZZ_SRC_robot    := sim/world/config.c sim/world/robot.c sim/world/keytab.c sim/world/inifile.c sim/io/infile.c \
	$(wildcard sim/world/sensors/*.c) $(wildcard sim/world/world*.c) sim/world/wallgrid.c sim/world/rng.c firmware/maze.c $(B)/gen/robot_paper.c
FUZZ_SRC_config   := $(FUZZ_SRC_robot)
FUZZ_SRC_contest  := sim/contest/contest.c sim/contest/score.c sim/world/keytab.c sim/world/inifile.c sim/io/infile.c sim/io/datadir.c firmware/maze.c
FUZZ_LIBS_contest := -linih -ljansson $(shell pkg-config --libs glib-2.0 2>/dev/null) -lm
FUZZ_LEN_contest  := 4096
FUZZ_LIBS_lcmlog  := -llcm
FUZZ_LIBS_config  := -linih $(shell pkg-config --libs glib-2.0 ode 2>/dev/null) -lm
FUZZ_LIBS_robot   := $(FUZZ_LIBS_config)
FUZZ_LEN_mazefile := 8192
FUZZ_LEN_wire     := 512
FUZZ_LEN_lcmlog   := 16384
FUZZ_LEN_config   := 4096
FUZZ_LEN_robot    := 16384
$(B)/fuzz/fuzz_%: test/fuzz_%.c $(LCM_STAMP) | deps
	@mkdir -p $(dir $@)
	$(FUZZ_CC) $(INC) $< $(FUZZ_SRC_$*) $(FUZZ_LIBS_$*) -o $@
$(B)/fuzz/fuzz_config $(B)/fuzz/fuzz_robot: $(B)/gen/robot_paper.c
# seeds: our mazes, a short logged contest, --print-config and a small
# config, our robot files and --print-robot, our contest files
$(B)/fuzz/seeds: $(B)/mmsim
	@mkdir -p $(B)/fuzz/corpus_mazefile $(B)/fuzz/corpus_wire $(B)/fuzz/corpus_lcmlog $(B)/fuzz/corpus_config $(B)/fuzz/corpus_robot $(B)/fuzz/corpus_contest
	cp -n contests/*.ini $(B)/fuzz/corpus_contest/ 2>/dev/null || true
	cp -n mazes/*.txt $(B)/fuzz/corpus_mazefile/ 2>/dev/null || true
	$(B)/mmsim --maze mazes/gen-5x5-s1.txt --driver firmware --time-limit 1 --lcm-rate 10 \
	  --lcm-log $(B)/fuzz/corpus_lcmlog/seed.lcmlog >/dev/null || [ $$? = 1 ]
	$(B)/mmsim --print-config >$(B)/fuzz/corpus_config/print-config.ini
	printf '[world]\ncell_m = 0.18 ; m\n[sim]\nstep_s = 0.0005\nsolver = quickstep\n' >$(B)/fuzz/corpus_config/small.ini
	cp -n robots/*.ini $(B)/fuzz/corpus_robot/ 2>/dev/null || true
	$(B)/mmsim --print-robot >$(B)/fuzz/corpus_robot/print-robot.ini
	@touch $@
fuzz: $(addprefix $(B)/fuzz/fuzz_,$(FUZZ)) $(B)/fuzz/seeds
	cd $(B)/fuzz && for t in $(FUZZ); do \
	  ./fuzz_$$t -max_total_time=$(FUZZ_SECONDS) -max_len=$$(case $$t in mazefile) echo $(FUZZ_LEN_mazefile);; \
	    wire) echo $(FUZZ_LEN_wire);; lcmlog) echo $(FUZZ_LEN_lcmlog);; config) echo $(FUZZ_LEN_config);; robot) echo $(FUZZ_LEN_robot);; contest) echo $(FUZZ_LEN_contest);; esac) \
	    -malloc_limit_mb=512 corpus_$$t || exit 1; done

mazes:
	@if [ -d $(B)/mazefiles ]; then echo "$(B)/mazefiles exists"; else \
	  git clone --depth 1 https://github.com/micromouseonline/mazefiles $(B)/mazefiles || \
	  { echo "make mazes: clone failed (needs internet)" >&2; exit 3; }; fi

clean:
	rm -rf $(B)

-include $(shell find $(B) -name '*.d' 2>/dev/null)

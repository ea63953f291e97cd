# mmsim - micromouse simulator. `make test` and `make sim` are all a newcomer needs.
# The rules live in mk/, one fragment per subsystem (docs/ARCHITECTURE.md,
# "Folders"); shell logic longer than a line lives in tools/make/ and test/.
.DEFAULT_GOAL := all
SHELL := /bin/bash
.PHONY: help all deps test test-run client-mazerunner mrc-images board-sketches sim sim-run bench bench-run fuzz firmware firmware-size arduino arduino-lib mazes clean tools spy replay view docs-img
all: tools

# make help: the targets a user types, one line each
help:
	@echo "make sim         install what is missing, build every tool, run a contest (MAZE=, SEED=, DRIVER=, GUI=1)"
	@echo "make test        install what is missing, build, run every test (one line each; the last: N passed, M failed, K skipped)"
	@echo "make test ONLY=NAME   one test: test_wire or wire (test/unit/test_wire.c), cli_contest or contest (test/cli/cli_contest.sh)"
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

# In this order: a fragment's rules name variables of the ones before it.
include mk/config.mk    # compilers, flags, sources, build/ and ../shared
include mk/deps.mk      # make deps: Debian packages, the project venv, PlatformIO, make mazes
include mk/host.mk      # LCM types, the host library and tools (plain and sanitized), install
include mk/firmware.mk  # the firmware for the ATmega328P and for UKMARSBOT's Nano
include mk/arduino.mk   # hal/arduino: the Arduino library and its sketches (Uno, Mega)
include mk/arm.mk       # our ARM test firmware (Cortex-M core's tests)
include mk/board.mk     # our sketches for the emulated AVR boards (Nano)
include mk/clients.mk   # real clients from ../shared/clients: mazerunner-core, bulebule
include mk/tests.mk     # make test [ONLY=NAME]: unit tests, CLI tests, their helpers
include mk/fuzz.mk      # make fuzz
include mk/bench.mk     # make bench
include mk/docs.mk      # make docs
include mk/sim.mk       # make sim, spy, replay, view
include mk/profile.mk   # the firmware's robot profiles from robots/*.ini (last: it adds prerequisites)

clean:
	rm -rf $(B)

-include $(shell find $(B) -name '*.d' 2>/dev/null)

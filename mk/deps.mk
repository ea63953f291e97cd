# deps.mk - what the build needs from outside: `make deps` (the Debian
# packages, the project venv), PlatformIO for its check, `make mazes`.

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
# our ARM test firmware (test/firmware/arm) and bulebule's build; libunicorn-dev: the
# Cortex-M core (sim/arm); gdb-multiarch: gdb for an ARM image.
DEB_PKGS := build-essential pkg-config libode-dev libcmocka-dev libjansson-dev libinih-dev \
	gcc-avr avr-libc arduino-core-avr simavr libsimavr-dev libelf-dev libdw-dev \
	liblcm-dev liblcm-bin libglib2.0-dev clang libclang-rt-14-dev \
	liblcm-java default-jdk-headless default-jre libjchart2d-java xvfb iproute2 \
	libpng-dev libglfw3-dev libgl-dev python3-venv libx11-dev libxtst-dev gdb-avr gdb universal-ctags \
	python3-matplotlib python3-dask python3-distributed python3-pandas python3-pytest valgrind \
	gcc-arm-none-eabi libnewlib-arm-none-eabi libstdc++-arm-none-eabi-newlib libunicorn-dev gdb-multiarch

deps:
	@bash tools/make/deps.sh $(DEB_PKGS)
	@$(MAKE) -s --no-print-directory $(VENV_STAMP) \
	  || echo "make deps: no project venv ($(VENV)): tools/mmsweep needs it and test/cli/cli_sweep.sh skips" >&2

# The project venv: Debian's python3 (/usr/bin/python3) with its site
# packages (dask, distributed, pandas, matplotlib) visible, plus the pinned
# packages Debian lacks (python/requirements.txt: pyarrow, for the sweeps'
# Parquet results). Rebuilt only when the requirements file changes. A pip
# that cannot reach its index leaves the rest of make deps (and the build)
# going: only the sweeps need the venv.
VENV       := $(B)/venv
VENV_STAMP := $(VENV)/.requirements-installed
$(VENV_STAMP): python/requirements.txt
	@bash tools/make/venv.sh $(VENV) $< $@

# PlatformIO from PyPI in a venv, only to check that platformio.ini parses
# (`pio run` cannot download its platforms here). No PyPI: the check skips.
PIO_VERSION := 6.2.0
$(B)/pio/bin/pio: | deps
	@bash tools/make/pio.sh $(B)/pio $(PIO_VERSION)

mazes:
	@bash tools/make/mazes.sh $(B)/mazefiles

# config.mk - the compilers, flags and sources every fragment uses.
CC      ?= gcc
STD     := -std=c99 -D_POSIX_C_SOURCE=200809L -D_DEFAULT_SOURCE
WARN    := -Wall -Wextra -Wshadow -Wstrict-prototypes -Wno-unused-parameter
INC      = -Ifirmware -Ihal -Ihal/sim -Ihal/wire -Isim -I$(B)/lcmgen -I$(B)/gen/paper $(shell pkg-config --cflags glib-2.0 ode libpng unicorn 2>/dev/null)
CFLAGS  ?= -O2 -g
SAN     := -fsanitize=address,undefined -fno-omit-frame-pointer -fno-sanitize-recover=undefined
# libunicorn is not linked: sim/arm/ucdl.c loads it (dlopen) when an ARM core is made
LIBS     = -ljansson -linih -llcm $(shell pkg-config --libs glib-2.0 ode libpng glfw3 gl 2>/dev/null) -lsimavr -ldw -lelf -lm -ldl
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
# The MCU's decoder buffers (see ARD_RAM): a build for an MCU takes no LOG.
MCU_RX_FLAGS := -DWIRE_RX_LOG_MAX=14

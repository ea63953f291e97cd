# libopencm3.rules.mk - the build rules a libopencm3 project's Makefile
# includes last (bulebule's src/Makefile: `include opencm3/libopencm3.rules.mk`),
# written for mmsim's client builds. The project sets BINARY, OBJS,
# OPENCM3_DIR, LDSCRIPT, LIBNAME, DEFS, ARCH_FLAGS, LDFLAGS, LDLIBS; this
# file compiles each object and links $(BINARY).elf against libopencm3's
# $(LIBNAME) with newlib. Flags: the usual ones for libopencm3 firmware
# (size-optimised C99, one section per function and object so that
# --gc-sections drops what is unused, no start files: libopencm3's
# vector.c is the start-up code). See tools/opencm3-compat/README.md.

PREFIX   ?= arm-none-eabi-
CC       := $(PREFIX)gcc
OBJCOPY  := $(PREFIX)objcopy

OPT      ?= -Os
DEBUG    ?= -ggdb3
CSTD     ?= -std=c99

DEFS     += -I$(OPENCM3_DIR)/include
LDFLAGS  += -L$(OPENCM3_DIR)/lib

RULES_CFLAGS   := $(OPT) $(CSTD) $(DEBUG) $(ARCH_FLAGS) \
                  -Wextra -Wshadow -Wimplicit-function-declaration \
                  -Wredundant-decls -Wmissing-prototypes -Wstrict-prototypes \
                  -fno-common -ffunction-sections -fdata-sections
RULES_CPPFLAGS := -MD -Wall -Wundef $(DEFS)
RULES_LDFLAGS  := --static -nostartfiles -T$(LDSCRIPT) $(ARCH_FLAGS) $(DEBUG) \
                  -Wl,-Map=$(BINARY).map -Wl,--cref -Wl,--gc-sections
RULES_LDLIBS   := -l$(LIBNAME) -Wl,--start-group -lc -lgcc -lnosys -Wl,--end-group

all: $(BINARY).elf $(BINARY).bin

%.o: %.c
	$(CC) $(RULES_CFLAGS) $(CFLAGS) $(RULES_CPPFLAGS) $(CPPFLAGS) -o $@ -c $<

$(BINARY).elf: $(OBJS) $(BINARY).o $(LDSCRIPT)
	$(CC) $(RULES_LDFLAGS) $(LDFLAGS) $(OBJS) $(BINARY).o $(LDLIBS) $(RULES_LDLIBS) -o $@

%.bin: %.elf
	$(OBJCOPY) -Obinary $< $@

clean:
	rm -f $(OBJS) $(BINARY).o $(OBJS:.o=.d) $(BINARY).d $(BINARY).elf $(BINARY).bin $(BINARY).map

.PHONY: all clean
-include $(OBJS:.o=.d) $(BINARY).d

# host.mk - the host side: the LCM types, the built-in robot, the library
# of firmware + simulator and the tools built on it, plain (optimised) and
# sanitized (for the tests), the robot-specific mmsim builds, make install.

# ---- LCM types ----
$(LCM_STAMP): $(LCM_TYPES) | deps
	@mkdir -p $(dir $@)
	lcm-gen -c --c-cpath $(B)/lcmgen --c-hpath $(B)/lcmgen $(LCM_TYPES)
	@touch $@
$(LCM_C): $(LCM_STAMP)
$(LCM_JAR): $(LCM_TYPES) | deps
	@bash tools/make/lcm-java.sh $(B)/lcmjava $@ $(LCM_TYPES)

# ---- the built-in robot: robots/paper.ini as a C string ----
$(B)/gen/robot_paper.c: robots/paper.ini
	@mkdir -p $(dir $@)
	@bash tools/make/ini-to-c.sh robot_paper_ini $< $@

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
# (robots/kerise-v5.ini's [firmware]) and the UKMARSBOT build for ORION
# with the host's planner (robots/ukmarsbot.ini's), each plain
# ($(B)/NAME/mmsim) and sanitized ($(B)/san-tools/NAME/mmsim, for
# test/cli/cli_halfsize.sh, cli_ukbhost.sh). Their own firmware objects come
# before the library, so the library's are not linked. ROBOT_MMSIM: $(1)
# the build's name, $(2) its robot file's name (its profile's -I first).
define ROBOT_MMSIM
$(1)_FW_OBJ := $$(patsubst firmware/%.c,$$(B)/$(1)/firmware/%.o,$$(FW_SRC))
$$(B)/$(1)/firmware/%.o: firmware/%.c | deps $$(LCM_STAMP)
	@mkdir -p $$(dir $$@)
	$$(CC) $$(STD) $$(WARN) -I$$(B)/gen/$(2) $$(INC) $$(CFLAGS) -MMD -MP -c $$< -o $$@
$$(B)/$(1)/mmsim: tools/mmsim.c $$($(1)_FW_OBJ) $$(B)/libmm.a
	$$(CC) $$(STD) $$(WARN) $$(INC) $$(CFLAGS) $$< $$($(1)_FW_OBJ) $$(B)/libmm.a $$(LIBS) -o $$@
$(1)_SAN_OBJ := $$(patsubst firmware/%.c,$$(B)/san/$(1)/firmware/%.o,$$(FW_SRC))
$$(B)/san/$(1)/firmware/%.o: firmware/%.c | deps $$(LCM_STAMP)
	@mkdir -p $$(dir $$@)
	$$(CC) $$(STD) $$(WARN) -I$$(B)/gen/$(2) $$(INC) -O1 -g $$(SAN) -MMD -MP -c $$< -o $$@
$$(B)/san-tools/$(1)/mmsim: tools/mmsim.c $$($(1)_SAN_OBJ) $$(B)/libmm_san.a
	@mkdir -p $$(dir $$@)
	$$(CC) $$(STD) $$(WARN) $$(INC) -O1 -g $$(SAN) $$< $$($(1)_SAN_OBJ) $$(B)/libmm_san.a $$(LIBS) -o $$@
endef
$(eval $(call ROBOT_MMSIM,half,kerise-v5))
$(eval $(call ROBOT_MMSIM,ukb,ukmarsbot))

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


# ---- the same library sanitized, and the tools on it (the tests run these) ----
$(B)/san/%.o: %.c | deps $(LCM_STAMP)
	@mkdir -p $(dir $@)
	$(CC) $(STD) $(WARN) $(INC) -O1 -g $(SAN) -MMD -MP -c $< -o $@
$(B)/libmm_san.a: $(patsubst %.c,$(B)/san/%.o,$(LIB_SRC))
	@rm -f $@; ar rcs $@ $^
$(B)/san-tools/%: tools/%.c $(B)/libmm_san.a
	@mkdir -p $(dir $@)
	$(CC) $(STD) $(WARN) $(INC) -O1 -g $(SAN) $< $(B)/libmm_san.a $(LIBS) -o $@

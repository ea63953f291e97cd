# profile.mk - the firmware's robot profile: a robot file's [firmware]
# section as $(B)/gen/NAME/robot_profile.h (tools/mkprofile.c), found by the
# firmware's robot_config.h on the include path: -I$(B)/gen/NAME picks the
# robot (INC, AVR_FLAGS and ARD_COMMON: the paper's; ROBOT_MMSIM and
# UKB_FLAGS their own, first). Rewritten only when its text changes.
# Included last: it attaches prerequisites to the other fragments' lists.
PROFILE_SRC := tools/mkprofile.c sim/world/fwprofile.c sim/world/inifile.c sim/io/infile.c sim/io/number.c sim/io/outfile.c
PROFILES    := $(patsubst %,$(B)/gen/%/robot_profile.h,paper kerise-v5 ukmarsbot ukmarsbot-basic-12)
$(B)/mkprofile: $(PROFILE_SRC) $(wildcard sim/world/fwprofile.h sim/world/inifile.h) | deps
	$(CC) $(STD) $(WARN) -Isim $(shell pkg-config --cflags glib-2.0) $(CFLAGS) $(PROFILE_SRC) -linih $(shell pkg-config --libs glib-2.0) -lm -o $@
$(B)/gen/%/robot_profile.h: robots/%.ini $(B)/mkprofile
	@mkdir -p $(dir $@)
	@$(B)/mkprofile $< $@.new && { cmp -s $@.new $@ && rm -f $@.new || mv -f $@.new $@; }
profiles: $(PROFILES)
.PHONY: profiles
# everything that compiles the firmware waits for them (the .d files of -MMD,
# the rules' own prerequisites below, rebuild it when one changes)
$(patsubst %.c,$(B)/host/%.o,$(LIB_SRC)) $(patsubst %.c,$(B)/san/%.o,$(LIB_SRC)) $(TESTS) $(half_FW_OBJ) $(half_SAN_OBJ) \
  $(ukb_FW_OBJ) $(ukb_SAN_OBJ) firmware-size $(B)/avr/flood.elf $(B)/avr/tick0.elf $(B)/avr/tick100.elf: | $(PROFILES)
$(UKB_OUT)/mouse.elf: $(UKB_PROFILE)/robot_profile.h
$(foreach b,$(ARD_BOARDS),$(patsubst %,$(B)/arduino/$(b)/lib/%.o,$(ARD_LIB_SRC))): $(B)/gen/paper/robot_profile.h

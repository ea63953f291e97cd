# fuzz.mk - make fuzz: the parsers under clang's libFuzzer (test/fuzz).

# ---- fuzzing (clang libFuzzer + ASan; bounded; not in CI) ----
# make fuzz [FUZZ="mazefile wire lcmlog config robot contest"] [FUZZ_SECONDS=60]: each target
# in turn for FUZZ_SECONDS; corpora in $(B)/fuzz/corpus_NAME, findings
# (crash-*, leak-*) in $(B)/fuzz.
FUZZ_SECONDS ?= 60
FUZZ ?= mazefile wire lcmlog config robot contest
FUZZ_CC := clang -g -O1 -fsanitize=fuzzer,address,undefined -D_POSIX_C_SOURCE=200809L -D_DEFAULT_SOURCE
FUZZ_SRC_mazefile := sim/maze/mazefile.c sim/io/infile.c sim/maze/truemaze.c
FUZZ_SRC_wire     := hal/wire/wire.c
FUZZ_SRC_lcmlog   := sim/telemetry/lcmlog.c sim/io/infile.c $(LCM_C)
# the config loads the built-in robot: the robot file's loader, its sensor
# kinds and what they use of the world
FUZZ_SRC_robot    := sim/world/config.c sim/world/robot.c sim/world/keytab.c sim/world/inifile.c sim/io/infile.c \
	sim/world/fwprofile.c sim/io/number.c \
	$(wildcard sim/world/sensors/*.c) $(wildcard sim/world/world*.c) sim/world/wallgrid.c sim/world/rng.c sim/maze/truemaze.c $(B)/gen/robot_paper.c
FUZZ_SRC_config   := $(FUZZ_SRC_robot)
FUZZ_SRC_contest  := sim/contest/contest.c sim/contest/score.c sim/world/keytab.c sim/world/inifile.c sim/io/infile.c sim/io/datadir.c sim/maze/truemaze.c
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
$(B)/fuzz/fuzz_%: test/fuzz/fuzz_%.c $(LCM_STAMP) | deps
	@mkdir -p $(dir $@)
	$(FUZZ_CC) $(INC) $< $(FUZZ_SRC_$*) $(FUZZ_LIBS_$*) -o $@
$(B)/fuzz/fuzz_config $(B)/fuzz/fuzz_robot: $(B)/gen/robot_paper.c
# seeds: our mazes, a short logged contest, --print-config and a small
# config, our robot files and --print-robot, our contest files
$(B)/fuzz/seeds: $(B)/mmsim
	bash test/fuzz/seeds.sh $(B)/fuzz $(B)/mmsim
	@touch $@
fuzz: $(addprefix $(B)/fuzz/fuzz_,$(FUZZ)) $(B)/fuzz/seeds
	bash test/fuzz/run.sh $(B)/fuzz $(FUZZ_SECONDS) $(foreach t,$(FUZZ),$(t):$(FUZZ_LEN_$(t)))

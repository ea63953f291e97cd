# sim.mk - make sim (a whole contest), and the LCM tools on a run: spy, replay, view.

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


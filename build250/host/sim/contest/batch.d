build250/host/sim/contest/batch.o: sim/contest/batch.c \
 sim/contest/batch.h sim/contest/run.h sim/link/link.h hal/wire/wire.h \
 sim/mms/mms.h firmware/maze.h sim/telemetry/telem.h sim/world/sim.h \
 sim/world/config.h sim/world/encoder.h sim/world/motor.h \
 sim/world/race.h sim/world/sensors/tof.h sim/world/config.h \
 sim/world/rng.h sim/world/world.h sim/view/view.h sim/view/replay.h \
 build250/lcmgen/mmlcm_pose_t.h build250/lcmgen/mmlcm_race_event_t.h \
 build250/lcmgen/mmlcm_race_t.h build250/lcmgen/mmlcm_sensors_t.h \
 sim/view/scene.h sim/maze/mazedir.h
sim/contest/batch.h:
sim/contest/run.h:
sim/link/link.h:
hal/wire/wire.h:
sim/mms/mms.h:
firmware/maze.h:
sim/telemetry/telem.h:
sim/world/sim.h:
sim/world/config.h:
sim/world/encoder.h:
sim/world/motor.h:
sim/world/race.h:
sim/world/sensors/tof.h:
sim/world/config.h:
sim/world/rng.h:
sim/world/world.h:
sim/view/view.h:
sim/view/replay.h:
build250/lcmgen/mmlcm_pose_t.h:
build250/lcmgen/mmlcm_race_event_t.h:
build250/lcmgen/mmlcm_race_t.h:
build250/lcmgen/mmlcm_sensors_t.h:
sim/view/scene.h:
sim/maze/mazedir.h:

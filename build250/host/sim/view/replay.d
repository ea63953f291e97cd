build250/host/sim/view/replay.o: sim/view/replay.c sim/view/replay.h \
 build250/lcmgen/mmlcm_pose_t.h build250/lcmgen/mmlcm_race_event_t.h \
 build250/lcmgen/mmlcm_race_t.h build250/lcmgen/mmlcm_sensors_t.h \
 sim/view/scene.h sim/world/sim.h sim/world/config.h sim/world/encoder.h \
 firmware/maze.h sim/world/motor.h sim/world/race.h \
 sim/world/sensors/tof.h sim/world/config.h sim/world/rng.h \
 sim/world/world.h sim/telemetry/lcmlog.h \
 build250/lcmgen/mmlcm_belief_t.h build250/lcmgen/mmlcm_maze_t.h
sim/view/replay.h:
build250/lcmgen/mmlcm_pose_t.h:
build250/lcmgen/mmlcm_race_event_t.h:
build250/lcmgen/mmlcm_race_t.h:
build250/lcmgen/mmlcm_sensors_t.h:
sim/view/scene.h:
sim/world/sim.h:
sim/world/config.h:
sim/world/encoder.h:
firmware/maze.h:
sim/world/motor.h:
sim/world/race.h:
sim/world/sensors/tof.h:
sim/world/config.h:
sim/world/rng.h:
sim/world/world.h:
sim/telemetry/lcmlog.h:
build250/lcmgen/mmlcm_belief_t.h:
build250/lcmgen/mmlcm_maze_t.h:

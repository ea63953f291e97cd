build250/host/sim/telemetry/telem.o: sim/telemetry/telem.c \
 sim/telemetry/telem.h sim/world/sim.h sim/world/config.h \
 sim/world/encoder.h firmware/maze.h sim/world/motor.h sim/world/race.h \
 sim/world/sensors/tof.h sim/world/config.h sim/world/rng.h \
 sim/world/world.h hal/sim/hal_sim.h sim/link/link.h hal/wire/wire.h \
 build250/lcmgen/mmlcm_belief_t.h build250/lcmgen/mmlcm_link_t.h \
 build250/lcmgen/mmlcm_maze_t.h build250/lcmgen/mmlcm_motors_t.h \
 build250/lcmgen/mmlcm_pose_t.h build250/lcmgen/mmlcm_race_event_t.h \
 build250/lcmgen/mmlcm_race_t.h build250/lcmgen/mmlcm_sensors_t.h \
 sim/maze/solve.h
sim/telemetry/telem.h:
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
hal/sim/hal_sim.h:
sim/link/link.h:
hal/wire/wire.h:
build250/lcmgen/mmlcm_belief_t.h:
build250/lcmgen/mmlcm_link_t.h:
build250/lcmgen/mmlcm_maze_t.h:
build250/lcmgen/mmlcm_motors_t.h:
build250/lcmgen/mmlcm_pose_t.h:
build250/lcmgen/mmlcm_race_event_t.h:
build250/lcmgen/mmlcm_race_t.h:
build250/lcmgen/mmlcm_sensors_t.h:
sim/maze/solve.h:

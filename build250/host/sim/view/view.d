build250/host/sim/view/view.o: sim/view/view.c sim/view/view.h \
 sim/view/replay.h build250/lcmgen/mmlcm_pose_t.h \
 build250/lcmgen/mmlcm_race_event_t.h build250/lcmgen/mmlcm_race_t.h \
 build250/lcmgen/mmlcm_sensors_t.h sim/view/scene.h sim/world/sim.h \
 sim/world/config.h sim/world/encoder.h firmware/maze.h sim/world/motor.h \
 sim/world/race.h sim/world/sensors/tof.h sim/world/config.h \
 sim/world/rng.h sim/world/world.h hal/sim/hal_sim.h sim/view/hud.h \
 sim/view/image.h sim/link/serial.h
sim/view/view.h:
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
hal/sim/hal_sim.h:
sim/view/hud.h:
sim/view/image.h:
sim/link/serial.h:

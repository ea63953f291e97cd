build250/host/sim/contest/run_firmware.o: sim/contest/run_firmware.c \
 sim/contest/run_driver.h sim/board/pil.h sim/contest/driver.h \
 sim/world/sim.h sim/world/config.h sim/world/encoder.h firmware/maze.h \
 sim/world/motor.h sim/world/race.h sim/world/sensors/tof.h \
 sim/world/config.h sim/world/rng.h sim/world/world.h sim/maze/solve.h \
 sim/contest/run.h sim/link/link.h hal/wire/wire.h sim/mms/mms.h \
 sim/telemetry/telem.h sim/view/view.h sim/view/replay.h \
 build250/lcmgen/mmlcm_pose_t.h build250/lcmgen/mmlcm_race_event_t.h \
 build250/lcmgen/mmlcm_race_t.h build250/lcmgen/mmlcm_sensors_t.h \
 sim/view/scene.h sim/view/report.h hal/hal.h hal/sim/hal_sim.h \
 firmware/mouse.h firmware/maze.h
sim/contest/run_driver.h:
sim/board/pil.h:
sim/contest/driver.h:
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
sim/maze/solve.h:
sim/contest/run.h:
sim/link/link.h:
hal/wire/wire.h:
sim/mms/mms.h:
sim/telemetry/telem.h:
sim/view/view.h:
sim/view/replay.h:
build250/lcmgen/mmlcm_pose_t.h:
build250/lcmgen/mmlcm_race_event_t.h:
build250/lcmgen/mmlcm_race_t.h:
build250/lcmgen/mmlcm_sensors_t.h:
sim/view/scene.h:
sim/view/report.h:
hal/hal.h:
hal/sim/hal_sim.h:
firmware/mouse.h:
firmware/maze.h:

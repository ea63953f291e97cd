build250/host/hal/sim/hal_sim.o: hal/sim/hal_sim.c hal/hal.h \
 hal/sim/hal_sim.h firmware/maze.h sim/world/sim.h sim/world/config.h \
 sim/world/encoder.h sim/world/motor.h sim/world/race.h \
 sim/world/sensors/tof.h sim/world/config.h sim/world/rng.h \
 sim/world/world.h
hal/hal.h:
hal/sim/hal_sim.h:
firmware/maze.h:
sim/world/sim.h:
sim/world/config.h:
sim/world/encoder.h:
sim/world/motor.h:
sim/world/race.h:
sim/world/sensors/tof.h:
sim/world/config.h:
sim/world/rng.h:
sim/world/world.h:

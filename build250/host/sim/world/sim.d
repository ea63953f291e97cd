build250/host/sim/world/sim.o: sim/world/sim.c sim/world/sim.h \
 sim/world/config.h sim/world/encoder.h firmware/maze.h sim/world/motor.h \
 sim/world/race.h sim/world/sensors/tof.h sim/world/config.h \
 sim/world/rng.h sim/world/world.h
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

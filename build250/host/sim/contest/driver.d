build250/host/sim/contest/driver.o: sim/contest/driver.c \
 sim/contest/driver.h sim/world/sim.h sim/world/config.h \
 sim/world/encoder.h firmware/maze.h sim/world/motor.h sim/world/race.h \
 sim/world/sensors/tof.h sim/world/config.h sim/world/rng.h \
 sim/world/world.h sim/maze/solve.h
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

build250/host/sim/mms/mms.o: sim/mms/mms.c sim/mms/mms.h firmware/maze.h \
 firmware/mouse.h firmware/maze.h sim/world/sim.h sim/world/config.h \
 sim/world/encoder.h sim/world/motor.h sim/world/race.h \
 sim/world/sensors/tof.h sim/world/config.h sim/world/rng.h \
 sim/world/world.h sim/world/world.h
sim/mms/mms.h:
firmware/maze.h:
firmware/mouse.h:
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
sim/world/world.h:

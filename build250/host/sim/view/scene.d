build250/host/sim/view/scene.o: sim/view/scene.c sim/view/scene.h \
 sim/world/sim.h sim/world/config.h sim/world/encoder.h firmware/maze.h \
 sim/world/motor.h sim/world/race.h sim/world/sensors/tof.h \
 sim/world/config.h sim/world/rng.h sim/world/world.h sim/view/font.h \
 sim/mms/mms.h sim/maze/solve.h
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
sim/view/font.h:
sim/mms/mms.h:
sim/maze/solve.h:

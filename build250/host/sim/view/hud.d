build250/host/sim/view/hud.o: sim/view/hud.c sim/view/hud.h \
 sim/world/sim.h sim/world/config.h sim/world/encoder.h firmware/maze.h \
 sim/world/motor.h sim/world/race.h sim/world/sensors/tof.h \
 sim/world/config.h sim/world/rng.h sim/world/world.h sim/view/font.h
sim/view/hud.h:
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

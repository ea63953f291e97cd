build250/host/sim/world/world.o: sim/world/world.c sim/world/world.h \
 sim/world/config.h firmware/maze.h sim/world/motor.h
sim/world/world.h:
sim/world/config.h:
firmware/maze.h:
sim/world/motor.h:

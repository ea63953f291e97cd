build250/host/sim/world/race.o: sim/world/race.c sim/world/race.h \
 firmware/maze.h
sim/world/race.h:
firmware/maze.h:

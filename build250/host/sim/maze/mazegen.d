build250/host/sim/maze/mazegen.o: sim/maze/mazegen.c sim/maze/mazegen.h \
 firmware/maze.h
sim/maze/mazegen.h:
firmware/maze.h:

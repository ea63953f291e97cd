build250/host/sim/maze/solve.o: sim/maze/solve.c sim/maze/solve.h \
 firmware/maze.h
sim/maze/solve.h:
firmware/maze.h:

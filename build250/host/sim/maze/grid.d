build250/host/sim/maze/grid.o: sim/maze/grid.c sim/maze/grid.h \
 firmware/maze.h firmware/explore.h firmware/maze.h firmware/flood.h \
 sim/maze/solve.h
sim/maze/grid.h:
firmware/maze.h:
firmware/explore.h:
firmware/maze.h:
firmware/flood.h:
sim/maze/solve.h:

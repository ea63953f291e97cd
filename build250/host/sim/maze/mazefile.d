build250/host/sim/maze/mazefile.o: sim/maze/mazefile.c \
 sim/maze/mazefile.h firmware/maze.h
sim/maze/mazefile.h:
firmware/maze.h:

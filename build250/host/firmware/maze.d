build250/host/firmware/maze.o: firmware/maze.c firmware/maze.h
firmware/maze.h:

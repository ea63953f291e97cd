build250/host/firmware/flood.o: firmware/flood.c firmware/flood.h \
 firmware/maze.h
firmware/flood.h:
firmware/maze.h:

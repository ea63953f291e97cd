build250/host/firmware/explore.o: firmware/explore.c firmware/explore.h \
 firmware/maze.h firmware/flood.h hal/hal.h
firmware/explore.h:
firmware/maze.h:
firmware/flood.h:
hal/hal.h:

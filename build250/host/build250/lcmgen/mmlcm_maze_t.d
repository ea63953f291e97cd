build250/host/build250/lcmgen/mmlcm_maze_t.o: \
 build250/lcmgen/mmlcm_maze_t.c build250/lcmgen/mmlcm_maze_t.h
build250/lcmgen/mmlcm_maze_t.h:

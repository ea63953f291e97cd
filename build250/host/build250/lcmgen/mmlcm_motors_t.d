build250/host/build250/lcmgen/mmlcm_motors_t.o: \
 build250/lcmgen/mmlcm_motors_t.c build250/lcmgen/mmlcm_motors_t.h
build250/lcmgen/mmlcm_motors_t.h:

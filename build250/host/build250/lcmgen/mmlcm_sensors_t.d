build250/host/build250/lcmgen/mmlcm_sensors_t.o: \
 build250/lcmgen/mmlcm_sensors_t.c build250/lcmgen/mmlcm_sensors_t.h
build250/lcmgen/mmlcm_sensors_t.h:

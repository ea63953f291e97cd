build250/host/build250/lcmgen/mmlcm_race_t.o: \
 build250/lcmgen/mmlcm_race_t.c build250/lcmgen/mmlcm_race_t.h
build250/lcmgen/mmlcm_race_t.h:

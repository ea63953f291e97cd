build250/host/build250/lcmgen/mmlcm_link_t.o: \
 build250/lcmgen/mmlcm_link_t.c build250/lcmgen/mmlcm_link_t.h
build250/lcmgen/mmlcm_link_t.h:

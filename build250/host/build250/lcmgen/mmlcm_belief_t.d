build250/host/build250/lcmgen/mmlcm_belief_t.o: \
 build250/lcmgen/mmlcm_belief_t.c build250/lcmgen/mmlcm_belief_t.h
build250/lcmgen/mmlcm_belief_t.h:

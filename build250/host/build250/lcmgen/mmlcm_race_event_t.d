build250/host/build250/lcmgen/mmlcm_race_event_t.o: \
 build250/lcmgen/mmlcm_race_event_t.c \
 build250/lcmgen/mmlcm_race_event_t.h
build250/lcmgen/mmlcm_race_event_t.h:

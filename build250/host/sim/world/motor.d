build250/host/sim/world/motor.o: sim/world/motor.c sim/world/motor.h \
 sim/world/config.h
sim/world/motor.h:
sim/world/config.h:

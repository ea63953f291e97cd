build250/host/sim/world/sensors/tof.o: sim/world/sensors/tof.c \
 sim/world/sensors/tof.h sim/world/config.h sim/world/rng.h
sim/world/sensors/tof.h:
sim/world/config.h:
sim/world/rng.h:

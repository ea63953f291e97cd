build250/host/sim/world/rng.o: sim/world/rng.c sim/world/rng.h
sim/world/rng.h:

build250/host/sim/world/encoder.o: sim/world/encoder.c \
 sim/world/encoder.h
sim/world/encoder.h:

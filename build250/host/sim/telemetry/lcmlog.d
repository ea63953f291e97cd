build250/host/sim/telemetry/lcmlog.o: sim/telemetry/lcmlog.c \
 sim/telemetry/lcmlog.h
sim/telemetry/lcmlog.h:

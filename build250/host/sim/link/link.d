build250/host/sim/link/link.o: sim/link/link.c sim/link/link.h \
 hal/wire/wire.h sim/link/serial.h
sim/link/link.h:
hal/wire/wire.h:
sim/link/serial.h:

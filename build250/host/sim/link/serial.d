build250/host/sim/link/serial.o: sim/link/serial.c sim/link/serial.h
sim/link/serial.h:

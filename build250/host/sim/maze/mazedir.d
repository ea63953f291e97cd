build250/host/sim/maze/mazedir.o: sim/maze/mazedir.c sim/maze/mazedir.h
sim/maze/mazedir.h:

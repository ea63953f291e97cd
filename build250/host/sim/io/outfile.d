build250/host/sim/io/outfile.o: sim/io/outfile.c sim/io/outfile.h
sim/io/outfile.h:

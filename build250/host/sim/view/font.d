build250/host/sim/view/font.o: sim/view/font.c sim/view/font.h
sim/view/font.h:

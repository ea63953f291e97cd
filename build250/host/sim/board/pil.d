build250/host/sim/board/pil.o: sim/board/pil.c sim/board/pil.h
sim/board/pil.h:

build250/host/hal/wire/wire.o: hal/wire/wire.c hal/wire/wire.h
hal/wire/wire.h:

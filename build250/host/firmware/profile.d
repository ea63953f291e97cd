build250/host/firmware/profile.o: firmware/profile.c firmware/profile.h
firmware/profile.h:

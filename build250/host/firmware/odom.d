build250/host/firmware/odom.o: firmware/odom.c firmware/odom.h \
 firmware/robot_config.h
firmware/odom.h:
firmware/robot_config.h:

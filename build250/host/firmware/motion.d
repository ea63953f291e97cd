build250/host/firmware/motion.o: firmware/motion.c firmware/motion.h \
 firmware/odom.h firmware/profile.h hal/hal.h firmware/robot_config.h
firmware/motion.h:
firmware/odom.h:
firmware/profile.h:
hal/hal.h:
firmware/robot_config.h:

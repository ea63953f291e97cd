build250/host/firmware/mouse.o: firmware/mouse.c firmware/mouse.h \
 firmware/maze.h firmware/explore.h firmware/flood.h hal/hal.h \
 firmware/motion.h firmware/odom.h firmware/profile.h \
 firmware/robot_config.h
firmware/mouse.h:
firmware/maze.h:
firmware/explore.h:
firmware/flood.h:
hal/hal.h:
firmware/motion.h:
firmware/odom.h:
firmware/profile.h:
firmware/robot_config.h:

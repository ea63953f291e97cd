build250/host/sim/view/report.o: sim/view/report.c sim/view/report.h \
 sim/world/sim.h sim/world/config.h sim/world/encoder.h firmware/maze.h \
 sim/world/motor.h sim/world/race.h sim/world/sensors/tof.h \
 sim/world/config.h sim/world/rng.h sim/world/world.h sim/view/font.h \
 sim/mms/mms.h sim/view/image.h sim/io/outfile.h sim/maze/solve.h
sim/view/report.h:
sim/world/sim.h:
sim/world/config.h:
sim/world/encoder.h:
firmware/maze.h:
sim/world/motor.h:
sim/world/race.h:
sim/world/sensors/tof.h:
sim/world/config.h:
sim/world/rng.h:
sim/world/world.h:
sim/view/font.h:
sim/mms/mms.h:
sim/view/image.h:
sim/io/outfile.h:
sim/maze/solve.h:

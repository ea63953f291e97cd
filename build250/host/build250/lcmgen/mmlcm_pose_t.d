build250/host/build250/lcmgen/mmlcm_pose_t.o: \
 build250/lcmgen/mmlcm_pose_t.c build250/lcmgen/mmlcm_pose_t.h
build250/lcmgen/mmlcm_pose_t.h:

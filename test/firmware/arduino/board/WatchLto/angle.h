// angle.h - WatchLto's two files.
#ifndef ANGLE_H
#define ANGLE_H
void angle_step(void);  // s_robot_angle += 0.5 (degrees), s_count += 1
float angle_now(void);  // s_robot_angle, degrees
float other_offset(void);  // 0 (other.cpp's flash constant minus itself), s_count += 2
#endif

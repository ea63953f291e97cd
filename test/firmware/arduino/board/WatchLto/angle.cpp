// angle.cpp - WatchLto's SRAM statics.
#include "angle.h"

static volatile float s_robot_angle;  // degrees: 0.5 per step
static volatile int s_count;          // steps

void angle_step(void) {
  s_robot_angle = s_robot_angle + 0.5f;
  s_count = s_count + 1;
}

float angle_now(void) { return s_robot_angle; }

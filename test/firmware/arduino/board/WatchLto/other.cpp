// other.cpp - the same static names in another file: s_robot_angle in
// flash (not a variable --watch reads), s_count in SRAM.
#include <avr/pgmspace.h>

#include "angle.h"

static const float s_robot_angle PROGMEM = 1.5f;  // degrees
static volatile int s_count;                      // 2 per step

float other_offset(void) {
  s_count = s_count + 2;
  return pgm_read_float(&s_robot_angle) - 1.5f;
}

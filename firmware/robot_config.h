/* robot_config.h - the firmware's robot: every figure and behaviour option
 * is a value of the robot file's [firmware] section (robots/NAME.ini,
 * docs/ROBOTS.md), which the build writes into robot_profile.h
 * (build/gen/NAME/, tools/mkprofile.c; the include path picks the robot),
 * and here what follows from them. Port the firmware to another mouse by
 * writing its robot file. */
#ifndef ROBOT_CONFIG_H
#define ROBOT_CONFIG_H

#include "robot_profile.h"

/* mm per encoder count of a wheel of RC_WHEEL_DIAMETER_MM */
#define RC_MM_PER_COUNT (3.14159265f * RC_WHEEL_DIAMETER_MM / RC_COUNTS_PER_REV)
/* distance from the front sensor to the wall ahead when centred in a cell, mm */
#define RC_FRONT_AT_CENTRE_MM (RC_CELL_MM / 2 - RC_WALL_MM / 2 - RC_TOF_FRONT_Y_MM)

#endif

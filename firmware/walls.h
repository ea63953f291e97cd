/* walls.h - the mouse's wall sensors, ToF or IR, as three distance readings.
 *
 * drive.c judges walls, centres and aligns on the wall ahead from three
 * readings in mm (HAL_TOF_LEFT, _FRONT, _RIGHT). walls_distance gives them
 * from the robot's sensors:
 *   - RC_WALLS_IR 0 (ToF robots): hal_distance itself;
 *   - RC_WALLS_IR 1, chosen at run time: hal_distance on a robot without
 *     IR sensors (hal_ir_count() == 0), else each role's lit-minus-dark
 *     reading (walls_ir.h's roles and
 *     calibration) turned into a distance:
 *       left, right: the side sensor's distance to its side wall along
 *         its axis, RC_SIDE_WALL_MM * sqrt(calibrated reading / reading)
 *         (the far field's 1/d^2: sim/world/sensors/README.md), timeout when
 *         the reading is below the calibration's side threshold (no wall);
 *       front: the forward sensors' distance to the wall ahead, from the
 *         sum of the pair against its calibrated sum through the robot's
 *         response curve (RC_IR_FRONT_CURVE_*), timeout below its last point.
 *     seq counts the backend's sensor passes (hal_ir_seq).
 * Robot numbers come from the robot's configuration header. */
#ifndef WALLS_H
#define WALLS_H

#include <stdint.h>

#include "hal.h"
#include "robot_config.h"

/* Standing in a cell, its far wall reads at most this far (mm): 60 mm
 * beyond where it reads from the cell's centre. */
#define WALLS_HERE_FRONT_MM (RC_FRONT_AT_CENTRE_MM + 60)

/* The wall decision (the search's, the speed runs', command mode's and
 * the console's): EXPLORE_WALL_LEFT, _FRONT, _RIGHT bits (explore.h),
 * relative to the robot. A side wall: a side reading (not timed out)
 * nearer than RC_SIDE_THRESHOLD_MM; the wall ahead: a front reading
 * nearer than front_limit_mm (where the far wall of the cell ahead, or of
 * this one, stands: WALLS_HERE_FRONT_MM standing in a cell). walls_ahead
 * reads the front sensor only. */
uint8_t walls_around(float front_limit_mm);
uint8_t walls_ahead(float front_limit_mm);
/* Switches on the emitters of the robot's IR sensors (if any); from fw_setup. */
void walls_setup(void);
/* The latest reading of role HAL_TOF_LEFT, _FRONT or _RIGHT (see above). */
hal_distance_t walls_distance(uint8_t sensor);

#endif

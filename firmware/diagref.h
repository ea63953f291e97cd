/* diagref.h - a position reference on diagonal straights from the two
 * diagonal ToF sensors. On a diagonal each of them looks along a maze axis
 * (45 degrees off the heading), so a reading of a known wall face across
 * that axis gives the robot's position along the axis. The expected
 * reading is the sensor's cone (RC_TOF_FOV_DEG, RC_TOF_RAYS rays, the
 * nearest hit) cast on the known map: closed walls and the posts. A reading
 * is used only where the model says the nearest ray meets a face square to
 * the axis, far enough from every other surface that a few mm of position
 * error cannot change which one the sensor sees. Host builds only
 * (PLAN_ENABLED). */
#ifndef DIAGREF_H
#define DIAGREF_H

#include "maze.h"

/* The expected reading, mm, of a sensor at (x_mm, y_mm) in the maze frame
 * (origin at the outer corner of cell (0, 0) at the wall lines' centre,
 * x along the maze's east, y along north), its axis ang_rad
 * counter-clockwise from east; -1 if it cannot be trusted: nothing known
 * within max_mm, an unknown wall as near as the nearest hit, the nearest
 * ray not on a face square to the axis, or another surface within
 * margin_mm of it. */
float diagref_expect(const maze_t *m, float x_mm, float y_mm, float ang_rad, float max_mm, float margin_mm);

#endif

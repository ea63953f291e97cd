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

#include <stdint.h>

#include "maze.h"
#include "motion.h"

/* The reference's state on one diagonal straight (diagref_anchor). */
typedef struct {
    float px, py;   /* the estimate at the diagonal's start, mm */
    float ox, oy;   /* odometry's position then, mm */
    float psi;      /* the maze's frame turned from odometry's, rad */
    float lx, ly;   /* a point of the diagonal's line, mm */
    float a;        /* its heading, rad counter-clockwise from east */
    uint8_t seq[2]; /* the side readings last looked at */
    float var[2];   /* the variance of px and py, mm^2 */
    float dist_mm;  /* odometry's distance when they last grew */
} diagref_t;

/* The expected reading, mm, of a sensor at (x_mm, y_mm) in the maze frame
 * (origin at the outer corner of cell (0, 0) at the wall lines' centre,
 * x along the maze's east, y along north), its axis ang_rad
 * counter-clockwise from east; -1 if it cannot be trusted: nothing known
 * within max_mm, an unknown wall as near as the nearest hit, the nearest
 * ray not on a face square to the axis, or another surface within
 * margin_mm of it. */
float diagref_expect(const maze_t *m, float x_mm, float y_mm, float ang_rad, float max_mm, float margin_mm);

/* A diagonal straight starts from the node (x2, y2) (half units: cell
 * (x, y)'s centre at (2x, 2y)) heading h8 (eighths clockwise from north),
 * the robot carry_mm short of it: the reference's starting point. */
void diagref_anchor(diagref_t *g, const motion_t *mo, int16_t x2, int16_t y2, uint8_t h8, float carry_mm);
/* On that diagonal: trusted side readings move the estimate; its offset
 * right of the diagonal's line steers (mo->lateral_mm, lateral_valid). */
void diagref_centring(diagref_t *g, motion_t *mo, const maze_t *map);

#endif

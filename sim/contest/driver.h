/* driver.h - the built-in scripted driver: drives the best path of the
 * TRUE maze from the start to the goal and back, a given number of runs,
 * with the robot's TRUE pose. A stand-in for the firmware (which senses,
 * maps and estimates its pose itself) to exercise the physics until the
 * firmware's motion layer lands; also a reference for what the robot can
 * do. Commands go straight to the motors (no speed loop). */
#ifndef DRIVER_H
#define DRIVER_H

#include "world/sim.h"
#include "maze/solve.h"

typedef struct {
    double wx[TRUEMAZE_MAX_CELLS + 1], wy[TRUEMAZE_MAX_CELLS + 1]; /* corner waypoints, m */
    int n;           /* waypoints */
    int idx, dir;    /* next waypoint, +1 towards the goal, -1 back */
    int runs_left;   /* runs to the goal still to make */
    int done;        /* 1 = finished all runs (stopped at the start) */
    int reachable;   /* the goal can be reached at all */
    double v_per_cmd; /* no-load m/s per command step */
    double decel_m_s2; /* braking into corners, from the tyre friction */
    double vref;      /* speed reference, ramped */
} driver_t;

/* Plan on the true maze for the robot of model md; runs = number of
 * start-to-goal runs. */
void driver_init(driver_t *d, const truemaze_t *m, const sim_model_t *md, int runs);
/* Set s->cmd from the true pose; call once per physics step. */
void driver_update(driver_t *d, sim_state_t *s);

#endif

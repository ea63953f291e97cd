/* runs.h - speed runs on the proven path and the way back to the start
 * (runs.c), on drive.h's moves. */
#ifndef RUNS_H
#define RUNS_H

#include "drive.h"

/* One loop of a speed run (to_goal 1: ends in MOUSE_RETURN at the goal)
 * or of the way back (0: ends in MOUSE_TO_RUN at the start). */
void runs_step(drive_t *dr, int to_goal);

#endif

/* race.h - competition timers and laps.
 *
 * Rules (from the maze's start cell and goal cells; positions are the robot
 * body's centre, in metres, origin at the south-west corner of the maze):
 * - the global timer starts when the robot first leaves the start cell;
 * - a run starts when the robot leaves the start cell and ends when it
 *   enters a goal cell (a completed lap); the robot must then come back to
 *   the start cell before the next run can start. A run abandoned by
 *   returning to the start without reaching the goal is not a lap;
 * - after the contest limit the timers are flagged over time; a lap that
 *   ends after the limit is still recorded, flagged, and never "best".
 * Best run = the fastest completed lap inside the limit. */
#ifndef RACE_H
#define RACE_H

#include <stdio.h>

#include "maze/truemaze.h"

#define RACE_MAX_LAPS 64

typedef struct {
    double start_s, end_s;
    int over_time;
} race_lap_t;

typedef struct {
    const truemaze_t *maze;
    double cell_m, limit_s;
    int started;          /* global timer running */
    double global_start_s;
    int in_run;           /* a run is under way */
    int armed;            /* at (or back at) the start: next exit starts a run */
    double run_start_s;
    race_lap_t laps[RACE_MAX_LAPS];
    int nlaps;
    int best;             /* index into laps, -1 none */
    int over_time;
} race_t;

void race_init(race_t *r, const truemaze_t *m, double cell_m, double limit_s);
/* Feed the body centre at time t_s; returns 1 when this call completed a lap. */
int race_update(race_t *r, double t_s, double x_m, double y_m);
/* Global timer (s since the first exit from the start; 0 before). */
double race_global_s(const race_t *r, double t_s);
/* Print the lap table in the paper's format (Tables 4 and 5). */
void race_print_table(const race_t *r, FILE *out);

#endif

/* slalomrun.h - speed runs on the planner's moves (plan.h, slalom.h):
 * orthogonal and diagonal straights joined by slaloms, each turn kind at
 * its own speed. The runs climb from the safe figures (RC_RUN_MM_S,
 * RC_DIAG_SAFE_MM_S, ...) on the first run to the fast ones, and fall back
 * after a run whose tracking error reached RC_RUN_CLEAN_MM. Host builds
 * (PLAN_ENABLED); without the planner every speed run is runs.h's. */
#ifndef SLALOMRUN_H
#define SLALOMRUN_H

#include "drive.h"

/* At the start of a speed run: plan it (RC_DIAG_RUNS); none found, or
 * refused by the robot's diagonal rules: slalomrun_active() is 0 and the
 * run is runs.h's orthogonal one. */
void slalomrun_begin(drive_t *dr);
int slalomrun_active(void);
/* One loop of a planned run; at the goal: dr->st.mode = MOUSE_RETURN. */
void slalomrun_step(drive_t *dr);

#endif

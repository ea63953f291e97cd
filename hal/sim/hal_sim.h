/* hal_sim.h - the simulator backend of hal/hal.h (host, in-process).
 * Attach a running simulation and the HAL reads its encoders and ToF
 * readings, sets its motor commands and reports its time. */
#ifndef HAL_SIM_H
#define HAL_SIM_H

#include <stdint.h>
#include <stdio.h>

#include "world/belief.h"

struct sim_state_s;

/* Serve the HAL from this simulation (NULL detaches). */
void hal_sim_attach(struct sim_state_s *s);
/* What hal_maze announces: the size, start and goal of this maze (the goal
 * as the rectangle that holds its goal cells); NULL: nothing (the firmware
 * then assumes a classic contest). Copied: m need not outlive the call. */
void hal_sim_set_maze(const struct maze_s *m);
/* Where hal_log lines go: a stream (NULL = dropped, the default). */
void hal_sim_set_log(FILE *out);
/* The firmware's latest hal_belief call, copied (seq counts the calls since
 * hal_sim_attach, 0 until the first). The pointer stays valid for the
 * process; the contest hands it to its observers. */
const sim_belief_t *hal_sim_belief(void);

#endif

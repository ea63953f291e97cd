/* hal_sim.h - the simulator backend of hal/hal.h (host, in-process).
 * Attach a running simulation and the HAL reads its encoders and ToF
 * readings, sets its motor commands and reports its time. */
#ifndef HAL_SIM_H
#define HAL_SIM_H

#include <stdint.h>
#include <stdio.h>

#include "maze.h"

struct sim_state_s;

/* The firmware's latest hal_belief call, copied (telemetry reads it). */
typedef struct {
    uint32_t seq;     /* calls since hal_sim_attach; 0 = none yet */
    uint64_t t_us;    /* simulation time of the call, microseconds */
    maze_t map;       /* the mouse's map */
    uint16_t cell;    /* the cell it is in or heading into */
    uint8_t heading;  /* MAZE_NORTH.. */
    uint8_t state;    /* the firmware's state machine (mouse.h MOUSE_*) */
} hal_sim_belief_t;

/* Serve the HAL from this simulation (NULL detaches). */
void hal_sim_attach(struct sim_state_s *s);
/* Where hal_log lines go: a stream (NULL = dropped, the default). */
void hal_sim_set_log(FILE *out);
/* The latest belief the firmware reported (seq 0 until the first). */
const hal_sim_belief_t *hal_sim_belief(void);

#endif

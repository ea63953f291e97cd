/* belief.h - what a mouse's firmware believes, as it last reported it: its
 * map, the cell it is in, its heading and its state machine's state. Plain
 * data that the backend running the firmware fills (hal/sim, from the
 * firmware's hal_belief calls) and the contest hands to its observers
 * (telemetry's MM_BELIEF, the viewer's overlay). It lives here, beside the
 * run's state, so that both sides include it and no observer includes a
 * backend. */
#ifndef BELIEF_H
#define BELIEF_H

#include <stdint.h>

#include "maze.h"

typedef struct {
    uint32_t seq;     /* reports since the firmware started; 0 = none yet */
    uint64_t t_us;    /* simulation time of the report, microseconds */
    maze_t map;       /* the mouse's map */
    uint16_t cell;    /* the cell it is in or heading into */
    uint8_t heading;  /* MAZE_NORTH.. */
    uint8_t state;    /* the firmware's state machine (mouse.h MOUSE_*) */
} sim_belief_t;

#endif

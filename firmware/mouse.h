/* mouse.h - the contest application on top of explore, motion and the HAL.
 * The backend calls fw_setup, fw_tick (control rate) and fw_loop (hal.h). */
#ifndef MOUSE_H
#define MOUSE_H

#include <stdint.h>

#include "maze.h"

#define MOUSE_SPEED_RUNS 3        /* speed runs after the search */
#define MOUSE_RUN_DEADLINE_S 540u /* no new run after 9 of the 10 minutes */

enum {
    MOUSE_SEARCH = 0, /* exploring until the path is proven, then home */
    MOUSE_TO_RUN,     /* at the start, deciding on a speed run */
    MOUSE_RUN,        /* speed run to the goal */
    MOUSE_RETURN,     /* driving back to the start */
    MOUSE_DONE,
    MOUSE_NO_GOAL,    /* the goal cannot be reached: stopped */
    MOUSE_CRASHED     /* stuck: motors off */
};

typedef struct {
    uint8_t mode;     /* MOUSE_* */
    uint8_t runs;     /* speed runs completed */
    maze_cell_t cell; /* the cell the mouse is in or heading into */
    uint8_t heading;  /* the way it faces, MAZE_NORTH.. */
} mouse_status_t;

/* Before fw_setup: the maze's size, start and goal (walls are ignored).
 * Without it the mouse expects a classic 16x16 with the centre goal. */
void fw_set_maze(const struct maze_s *m);
const mouse_status_t *mouse_status(void);
/* The mouse's map (for reports and tests). */
const maze_t *mouse_map(void);
uint16_t mouse_proven_at_step(void);
struct motion_s;
/* The motion layer's state (odometry, profiles), for telemetry and tests. */
const struct motion_s *mouse_motion(void);

#endif

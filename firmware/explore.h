/* explore.h - the search strategy, independent of how the mouse moves.
 *
 * The caller (grid mode in sim/maze/grid.c, the motion layer on the robot) runs:
 *   explore_init(&e, &blank_map);
 *   loop: explore_sense(&e, walls) with the walls seen from the current cell;
 *         d = explore_next(&e); if (d < 0) stop;
 *         move one cell towards heading d; explore_moved(&e, d);
 *
 * Strategy: go to the goal with the heading-aware flood (unknown walls
 * open); then keep exploring the cells next to unknown walls on the best
 * optimistic path from the start, until the best path through known-open
 * walls costs as much as the best path with every unknown wall open: then
 * the run path is proven optimal (logged through hal_log). Finally return
 * to the start cell. An unreachable goal ends the run, never a loop.
 */
#ifndef EXPLORE_H
#define EXPLORE_H

#include <stdint.h>
#include "maze.h"
#include "flood.h"

enum {
    EXPLORE_TO_GOAL = 0, /* heading for the goal for the first time */
    EXPLORE_PROVE,       /* exploring until the run path is proven */
    EXPLORE_RETURN,      /* proven; driving back to the start cell */
    EXPLORE_DONE,        /* back at the start with the path proven */
    EXPLORE_NO_GOAL      /* the goal cannot be reached */
};

#define EXPLORE_NEVER 0xFFFFu /* proven_at_step when not proven */

/* Walls seen from the current cell, relative to the mouse's heading. */
#define EXPLORE_WALL_FRONT 1u
#define EXPLORE_WALL_RIGHT 2u
#define EXPLORE_WALL_LEFT 4u

typedef struct {
    maze_cell_t cell;        /* where the mouse is */
    uint8_t heading;         /* MAZE_NORTH.. */
    uint8_t phase;           /* EXPLORE_TO_GOAL.. */
    uint16_t steps;          /* cell moves made so far */
    uint16_t proven_at_step; /* step when the path was proven, or EXPLORE_NEVER */
    uint16_t goal_at_step;   /* step when the goal was first entered, or EXPLORE_NEVER */
    uint16_t run_cost;       /* cost of the proven run path */
    uint16_t path_cost;      /* cost from where the last explore_run/home_dir asked */
    uint32_t plan_us_max;    /* longest explore_next so far, hal_micros us */
    maze_t map;              /* the mouse's belief */
    flood_t flood;           /* scratch for every flood */
} explore_t;

/* Start exploring with a map holding size, start and goal (walls ignored:
 * the mouse knows only the boundary). */
void explore_init(explore_t *e, const maze_t *blank);
/* Record the walls seen from the current cell (EXPLORE_WALL_* bits set =
 * wall present, clear = open; the wall behind is not sensed). */
void explore_sense(explore_t *e, uint8_t walls);
/* The heading of the next cell to move into, or -1 when the run has ended
 * (phase EXPLORE_DONE or EXPLORE_NO_GOAL). */
int explore_next(explore_t *e);
/* The mouse has moved one cell towards heading d. */
void explore_moved(explore_t *e, uint8_t d);

/* After a proven run: the heading to leave cell c in, facing h, along the
 * best path through known-open walls (the speed-run path); -1 at the goal. */
int explore_run_dir(explore_t *e, maze_cell_t c, uint8_t h);
/* The same towards the start cell (for the way back after a speed run). */
int explore_home_dir(explore_t *e, maze_cell_t c, uint8_t h);
/* After explore_run_dir or explore_home_dir from (c0, h): the heading to
 * leave cell c in, c being `cells` straight moves on from c0 facing h.
 * No new flood: it walks the last one's cost field (a flood per cell of a
 * straight takes 10-40 ms on a 16 MHz AVR while the robot rolls on). */
int explore_dir_ahead(const explore_t *e, maze_cell_t c, uint8_t h, uint8_t cells);

#endif

/* grid.h - grid-mode runs: the firmware's exploration drives an abstract
 * mouse through a true maze cell by cell, sensing only the walls a real
 * mouse sees from its cell (front, left, right). */
#ifndef GRID_H
#define GRID_H

#include <stdint.h>
#include "truemaze.h"

typedef struct {
    uint32_t steps;          /* cell moves from leaving the start until back */
    uint32_t steps_forward, steps_right, steps_left, steps_back;
    uint32_t cells_visited;  /* distinct cells entered, start included */
    int32_t proven_at_step;  /* step when the run path was proven, -1 never */
    int32_t goal_at_step;    /* step when the goal was first entered, -1 never */
    int goal_reachable;      /* the goal can be reached in the true maze */
    int final_path_optimal;  /* proven run path has the true best cost */
    uint16_t run_cost;       /* heading-aware cost of the mouse's run path */
    uint16_t true_cost;      /* best cost on the true maze (0xFFFF none) */
    int ended_at_start;      /* the mouse is back in the start cell */
} grid_result_t;

/* The walls a mouse at (c, facing h) sees in truth: EXPLORE_WALL_* bits. */
uint8_t grid_sense(const truemaze_t *truth, truemaze_cell_t c, uint8_t h);

/* Explore truth from an empty map (the firmware's, made at the seam by
 * truebelief.h). Returns 0 when the mouse is back at the start with its path
 * proven, 1 otherwise (goal unreachable, the step limit of 16 moves per cell
 * hit, or a maze larger than the firmware's MAZE_MAX_SIZE). */
int grid_explore(const truemaze_t *truth, grid_result_t *r);

#endif

/* solve.h - exact best path on the host (no memory limits): the reference
 * the firmware's flood and exploration are judged against.
 *
 * Best = least heading-aware cost (forward one cell 1, 90-degree turn 1)
 * from the start cell facing the start heading to any goal cell; ties
 * broken by fewest cells, then by going straight as early as possible.
 */
#ifndef SOLVE_H
#define SOLVE_H

#include <stdint.h>
#include "truemaze.h"

#define SOLVE_NONE 0xFFFFu

typedef struct {
    int reachable;       /* goal reachable from the start */
    uint16_t cost;       /* heading-aware cost, SOLVE_NONE if unreachable */
    uint16_t cells;      /* cell moves on the best path */
    uint16_t turns;      /* 90-degree turns on it (a 180 counts 2) */
    uint16_t min_cells;  /* fewest cell moves of any path */
    uint16_t len;        /* cells in path[], start and goal included */
    truemaze_cell_t path[TRUEMAZE_MAX_CELLS + 1];
} solve_path_t;

/* Solve on m (a mouse's map: truebelief.h's truemaze_from_belief first).
 * Returns 0, or -1 if the goal is unreachable (out->reachable = 0). */
int solve_best(const truemaze_t *m, solve_path_t *out);

/* Heading-aware cost of the best path from (cell, heading) to the goal on
 * m, or SOLVE_NONE. */
uint16_t solve_cost_from(const truemaze_t *m, truemaze_cell_t cell, uint8_t heading);

#endif

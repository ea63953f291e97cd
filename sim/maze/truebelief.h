/* truebelief.h - the seam between the simulator's truth (truemaze_t) and the
 * firmware's map type (firmware/maze.h's maze_t): used only where the
 * firmware's own code runs on the truth (grid mode's exploration, the
 * in-process firmware's announced maze, mms's walls) or where a mouse's
 * reported map is drawn or solved with the simulator's tools. */
#ifndef TRUEBELIEF_H
#define TRUEBELIEF_H

#include "maze.h"
#include "truemaze.h"

/* b = t with every wall known: the map of a mouse that has seen it all.
 * Returns 0, or -1 (b untouched) if t is larger than the firmware's
 * compile-time MAZE_MAX_SIZE. */
int truemaze_to_belief(const truemaze_t *t, maze_t *b);

/* t = the mouse's map b, unknown walls taken as absent if unknown_open,
 * present otherwise (the solver's view of a map still being learned). */
void truemaze_from_belief(truemaze_t *t, const maze_t *b, int unknown_open);

#endif

/* truebelief.c - converting between the truth and the firmware's map. */
#include "truebelief.h"

#include <string.h>

int truemaze_to_belief(const truemaze_t *t, maze_t *b)
{
    if (maze_init(b, t->width, t->height) != 0) return -1;
    for (uint16_t c = 0; c < truemaze_cells(t); c++)
        for (uint8_t d = 0; d < 4; d++)
            maze_set_wall(b, (maze_cell_t)c, d, truemaze_wall(t, c, d) ? MAZE_WALL_CLOSED : MAZE_WALL_OPEN);
    maze_clear_goals(b);
    for (uint16_t c = 0; c < truemaze_cells(t); c++)
        if (truemaze_is_goal(t, c)) maze_set_goal(b, (maze_cell_t)c, 1);
    b->start = (maze_cell_t)t->start;
    b->start_heading = t->start_heading;
    return 0;
}

void truemaze_from_belief(truemaze_t *t, const maze_t *b, int unknown_open)
{
    truemaze_init(t, b->width, b->height);
    for (uint16_t c = 0; c < maze_cells(b); c++)
        for (uint8_t d = 0; d < 4; d++)
            if (maze_passable(b, (maze_cell_t)c, d, unknown_open)) t->cell[c] &= (uint8_t)~(1u << d);
    truemaze_clear_goals(t);
    for (uint16_t c = 0; c < maze_cells(b); c++)
        if (maze_is_goal(b, (maze_cell_t)c)) truemaze_set_goal(t, c, 1);
    t->start = b->start;
    t->start_heading = b->start_heading;
}

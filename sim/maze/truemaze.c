/* truemaze.c - the simulator's ground truth: walls present or absent,
 * start, goal. */
#include "truemaze.h"

#include <string.h>

int truemaze_init(truemaze_t *m, uint8_t width, uint8_t height)
{
    if (width == 0 || height == 0 || width > TRUEMAZE_MAX_SIZE || height > TRUEMAZE_MAX_SIZE) return -1;
    memset(m, 0, sizeof *m);
    m->width = width;
    m->height = height;
    memset(m->cell, 0x0F, truemaze_cells(m)); /* all four walls of every cell */
    m->start = truemaze_cell(m, 0, 0);
    m->start_heading = TRUEMAZE_NORTH;
    /* Centre goal: cells (w-1)/2..w/2 on x, likewise on y. */
    truemaze_set_goal_rect(m, (uint8_t)((width - 1) / 2), (uint8_t)((height - 1) / 2), (uint8_t)(width / 2),
                           (uint8_t)(height / 2));
    return 0;
}

int truemaze_neighbour(const truemaze_t *m, truemaze_cell_t c, uint8_t d, truemaze_cell_t *out)
{
    uint8_t x = truemaze_x(m, c), y = truemaze_y(m, c);
    switch (d & 3) {
    case TRUEMAZE_NORTH: if (y + 1 >= m->height) return 0; y++; break;
    case TRUEMAZE_EAST: if (x + 1 >= m->width) return 0; x++; break;
    case TRUEMAZE_SOUTH: if (y == 0) return 0; y--; break;
    default: if (x == 0) return 0; x--; break;
    }
    *out = truemaze_cell(m, x, y);
    return 1;
}

static void set_side(truemaze_t *m, truemaze_cell_t c, uint8_t d, int present)
{
    if (present) m->cell[c] |= (uint8_t)(1u << d);
    else m->cell[c] &= (uint8_t)~(1u << d);
}

void truemaze_set_wall(truemaze_t *m, truemaze_cell_t c, uint8_t d, int present)
{
    truemaze_cell_t n;
    d &= 3;
    if (!truemaze_neighbour(m, c, d, &n)) return; /* boundary: always closed */
    set_side(m, c, d, present);
    set_side(m, n, truemaze_turn(d, 2), present);
}

int truemaze_is_goal(const truemaze_t *m, truemaze_cell_t c)
{
    return (m->goal[c >> 3] >> (c & 7)) & 1;
}

void truemaze_set_goal(truemaze_t *m, truemaze_cell_t c, int on)
{
    if (on) m->goal[c >> 3] |= (uint8_t)(1u << (c & 7));
    else m->goal[c >> 3] &= (uint8_t)~(1u << (c & 7));
}

void truemaze_clear_goals(truemaze_t *m)
{
    memset(m->goal, 0, sizeof m->goal);
}

int truemaze_set_goal_rect(truemaze_t *m, uint8_t x0, uint8_t y0, uint8_t x1, uint8_t y1)
{
    if (x0 > x1 || y0 > y1 || x1 >= m->width || y1 >= m->height) return -1;
    truemaze_clear_goals(m);
    for (uint8_t y = y0; y <= y1; y++)
        for (uint8_t x = x0; x <= x1; x++) truemaze_set_goal(m, truemaze_cell(m, x, y), 1);
    return 0;
}

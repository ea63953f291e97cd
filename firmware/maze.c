/* maze.c - the mouse's map: walls with known/unknown state, start, goal. */
#include "maze.h"

#include <string.h>

#define WALL_BIT(d) ((uint8_t)(1u << (d)))
#define KNOWN_BIT(d) ((uint8_t)(0x10u << (d)))

int maze_init(maze_t *m, uint8_t width, uint8_t height)
{
    if (width == 0 || height == 0 || width > MAZE_MAX_W || height > MAZE_MAX_H)
        return -1;
    memset(m, 0, sizeof *m);
    m->width = width;
    m->height = height;
    for (uint8_t y = 0; y < height; y++) {
        for (uint8_t x = 0; x < width; x++) {
            maze_cell_t c = maze_cell(m, x, y);
            if (y == height - 1) m->cell[c] |= WALL_BIT(MAZE_NORTH) | KNOWN_BIT(MAZE_NORTH);
            if (x == width - 1) m->cell[c] |= WALL_BIT(MAZE_EAST) | KNOWN_BIT(MAZE_EAST);
            if (y == 0) m->cell[c] |= WALL_BIT(MAZE_SOUTH) | KNOWN_BIT(MAZE_SOUTH);
            if (x == 0) m->cell[c] |= WALL_BIT(MAZE_WEST) | KNOWN_BIT(MAZE_WEST);
        }
    }
    m->start = maze_cell(m, 0, 0);
    m->start_heading = MAZE_NORTH;
    /* Centre goal: cells (w-1)/2..w/2 on x, likewise on y. */
    maze_set_goal_rect(m, (uint8_t)((width - 1) / 2), (uint8_t)((height - 1) / 2), (uint8_t)(width / 2),
                       (uint8_t)(height / 2));
    return 0;
}

int maze_neighbour(const maze_t *m, maze_cell_t c, uint8_t d, maze_cell_t *out)
{
    uint8_t x = maze_x(m, c), y = maze_y(m, c);
    switch (d & 3) {
    case MAZE_NORTH: if (y + 1 >= m->height) return 0; y++; break;
    case MAZE_EAST: if (x + 1 >= m->width) return 0; x++; break;
    case MAZE_SOUTH: if (y == 0) return 0; y--; break;
    default: if (x == 0) return 0; x--; break;
    }
    *out = maze_cell(m, x, y);
    return 1;
}

uint8_t maze_wall(const maze_t *m, maze_cell_t c, uint8_t d)
{
    uint8_t v = m->cell[c];
    if (!(v & KNOWN_BIT(d & 3))) return MAZE_WALL_UNKNOWN;
    return (v & WALL_BIT(d & 3)) ? MAZE_WALL_CLOSED : MAZE_WALL_OPEN;
}

static void set_side(maze_t *m, maze_cell_t c, uint8_t d, uint8_t state)
{
    uint8_t v = (uint8_t)(m->cell[c] & ~(WALL_BIT(d) | KNOWN_BIT(d)));
    if (state == MAZE_WALL_CLOSED) v |= WALL_BIT(d) | KNOWN_BIT(d);
    else if (state == MAZE_WALL_OPEN) v |= KNOWN_BIT(d);
    m->cell[c] = v;
}

void maze_set_wall(maze_t *m, maze_cell_t c, uint8_t d, uint8_t state)
{
    maze_cell_t n;
    d &= 3;
    if (!maze_neighbour(m, c, d, &n)) return; /* boundary: always closed */
    set_side(m, c, d, state);
    set_side(m, n, maze_turn(d, 2), state);
}

int maze_passable(const maze_t *m, maze_cell_t c, uint8_t d, int unknown_open)
{
    uint8_t v = m->cell[c];
    d &= 3;
    if (v & KNOWN_BIT(d)) return !(v & WALL_BIT(d));
    return unknown_open;
}

int maze_is_goal(const maze_t *m, maze_cell_t c)
{
    return (m->goal[c >> 3] >> (c & 7)) & 1;
}

void maze_set_goal(maze_t *m, maze_cell_t c, int on)
{
    if (on) m->goal[c >> 3] |= (uint8_t)(1u << (c & 7));
    else m->goal[c >> 3] &= (uint8_t)~(1u << (c & 7));
}

void maze_clear_goals(maze_t *m)
{
    memset(m->goal, 0, sizeof m->goal);
}

int maze_set_goal_rect(maze_t *m, uint8_t x0, uint8_t y0, uint8_t x1, uint8_t y1)
{
    if (x0 > x1 || y0 > y1 || x1 >= m->width || y1 >= m->height) return -1;
    maze_clear_goals(m);
    for (uint8_t y = y0; y <= y1; y++)
        for (uint8_t x = x0; x <= x1; x++) maze_set_goal(m, maze_cell(m, x, y), 1);
    return 0;
}

void maze_close_unknown(maze_t *m)
{
    uint16_t n = maze_cells(m);
    for (uint16_t c = 0; c < n; c++)
        for (uint8_t d = 0; d < 4; d++)
            if (maze_wall(m, (maze_cell_t)c, d) == MAZE_WALL_UNKNOWN)
                set_side(m, (maze_cell_t)c, d, MAZE_WALL_CLOSED);
}

void maze_forget(maze_t *dst, const maze_t *src)
{
    maze_init(dst, src->width, src->height); /* dst may be src: then a blank maze of its size */
    memmove(dst->goal, src->goal, sizeof dst->goal);
    dst->start = src->start;
    dst->start_heading = src->start_heading;
}

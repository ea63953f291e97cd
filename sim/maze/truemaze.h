/* truemaze.h - the simulator's ground truth: a maze as it is, every wall
 * present or absent (the truth has no unknown walls), start cell and
 * heading, goal cells. The mouse's belief, with its known/unknown walls and
 * the AVR's compile-time size, is firmware/maze.h's maze_t; the two meet
 * only in truebelief.h, where the firmware's own code runs on the truth.
 *
 * Sizes up to TRUEMAZE_MAX_SIZE cells a side: the largest maze of the
 * database (32x32 half-size). Coordinates: x grows east, y grows north,
 * cell (0,0) is the south-west corner. Headings: 0 north, 1 east, 2 south,
 * 3 west (clockwise), the same numbers as the firmware's MAZE_NORTH..
 */
#ifndef TRUEMAZE_H
#define TRUEMAZE_H

#include <stdint.h>

#define TRUEMAZE_MAX_SIZE 32 /* cells per side: the database's half-size mazes */
#define TRUEMAZE_MAX_CELLS (TRUEMAZE_MAX_SIZE * TRUEMAZE_MAX_SIZE)

typedef uint16_t truemaze_cell_t; /* cell index y * width + x */

enum { TRUEMAZE_NORTH = 0, TRUEMAZE_EAST = 1, TRUEMAZE_SOUTH = 2, TRUEMAZE_WEST = 3 };

typedef struct truemaze_s {
    uint8_t width, height; /* cells, 1..TRUEMAZE_MAX_SIZE */
    /* One byte per cell: bit d = wall present on side d. Each interior wall
     * is stored in both cells it separates; truemaze_set_wall keeps the two
     * copies equal. */
    uint8_t cell[TRUEMAZE_MAX_CELLS];
    uint8_t goal[(TRUEMAZE_MAX_CELLS + 7) / 8]; /* bitset of goal cells */
    truemaze_cell_t start;                      /* start cell index */
    uint8_t start_heading;                      /* TRUEMAZE_NORTH.. */
} truemaze_t;

/* A maze of closed cells: every wall present, start (0,0) facing north,
 * goal = centre (2x2 for even sizes, 1 cell for odd; per axis). Returns 0,
 * or -1 if a size is 0 or above TRUEMAZE_MAX_SIZE. */
int truemaze_init(truemaze_t *m, uint8_t width, uint8_t height);

static inline truemaze_cell_t truemaze_cell(const truemaze_t *m, uint8_t x, uint8_t y)
{
    return (truemaze_cell_t)((uint16_t)y * m->width + x);
}
static inline uint8_t truemaze_x(const truemaze_t *m, truemaze_cell_t c) { return (uint8_t)(c % m->width); }
static inline uint8_t truemaze_y(const truemaze_t *m, truemaze_cell_t c) { return (uint8_t)(c / m->width); }
static inline uint16_t truemaze_cells(const truemaze_t *m) { return (uint16_t)m->width * m->height; }

/* Heading arithmetic: d turned by q quarter turns clockwise. */
static inline uint8_t truemaze_turn(uint8_t d, int q) { return (uint8_t)((d + q + 4) & 3); }

/* The neighbour of c across side d; returns 0 if that leaves the maze. */
int truemaze_neighbour(const truemaze_t *m, truemaze_cell_t c, uint8_t d, truemaze_cell_t *out);

/* 1 if the wall on side d of c is present, 0 if the side is open. */
static inline int truemaze_wall(const truemaze_t *m, truemaze_cell_t c, uint8_t d)
{
    return (m->cell[c] >> (d & 3)) & 1;
}
/* 1 if side d of c can be driven through (no wall). */
static inline int truemaze_open(const truemaze_t *m, truemaze_cell_t c, uint8_t d) { return !truemaze_wall(m, c, d); }

/* Put (present != 0) or take away the wall on side d of c, and the same
 * wall seen from the neighbour. The boundary stays closed whatever is asked. */
void truemaze_set_wall(truemaze_t *m, truemaze_cell_t c, uint8_t d, int present);

int truemaze_is_goal(const truemaze_t *m, truemaze_cell_t c);
void truemaze_set_goal(truemaze_t *m, truemaze_cell_t c, int on);
void truemaze_clear_goals(truemaze_t *m);
/* The goal = the rectangle of cells x0..x1, y0..y1 (inclusive), nothing
 * else. Returns 0, or -1 (the goal unchanged) if it is empty or leaves
 * the maze. */
int truemaze_set_goal_rect(truemaze_t *m, uint8_t x0, uint8_t y0, uint8_t x1, uint8_t y1);

#endif

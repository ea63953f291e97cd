/* maze.h - the mouse's map of the maze: walls with known/unknown state,
 * start cell and heading, goal cell set.
 *
 * Portable C99, no allocation. Sizes up to MAZE_MAX_W x MAZE_MAX_H cells,
 * fixed at compile time: 32x32 on the host (half-size mazes), 16x16 on the
 * AVR (build with -DMAZE_MAX_SIZE=16) where every byte of SRAM counts.
 *
 * Coordinates: x grows east, y grows north, cell (0,0) is the south-west
 * corner. Headings: 0 north, 1 east, 2 south, 3 west (clockwise).
 */
#ifndef MAZE_H
#define MAZE_H

#include <stdint.h>

#ifndef MAZE_MAX_SIZE
#define MAZE_MAX_SIZE 32 /* cells per side, compile-time maximum */
#endif
#define MAZE_MAX_W MAZE_MAX_SIZE
#define MAZE_MAX_H MAZE_MAX_SIZE
#define MAZE_MAX_CELLS (MAZE_MAX_W * MAZE_MAX_H)

#if MAZE_MAX_CELLS <= 256
typedef uint8_t maze_cell_t; /* cell index y * width + x */
#else
typedef uint16_t maze_cell_t;
#endif

enum { MAZE_NORTH = 0, MAZE_EAST = 1, MAZE_SOUTH = 2, MAZE_WEST = 3 };

/* Wall state as seen by the mouse. */
enum { MAZE_WALL_UNKNOWN = 0, MAZE_WALL_OPEN = 1, MAZE_WALL_CLOSED = 2 };

typedef struct maze_s {
    uint8_t width, height;   /* cells, 1..MAZE_MAX_W / MAZE_MAX_H */
    /* One byte per cell: bit d = wall present on side d, bit 4+d = that
     * wall is known. Each interior wall is stored in both cells it
     * separates; maze_set_wall keeps the two copies equal. */
    uint8_t cell[MAZE_MAX_CELLS];
    uint8_t goal[(MAZE_MAX_CELLS + 7) / 8]; /* bitset of goal cells */
    maze_cell_t start;       /* start cell index */
    uint8_t start_heading;   /* MAZE_NORTH.. */
} maze_t;

/* An empty map: every interior wall unknown, the boundary known closed,
 * start (0,0) facing north, goal = centre (2x2 for even sizes, 1 cell for
 * odd; for a mixed size the 2 or 1 centre cells on each axis). Returns 0,
 * or -1 if a size is 0 or above the compile-time maximum. */
int maze_init(maze_t *m, uint8_t width, uint8_t height);

static inline maze_cell_t maze_cell(const maze_t *m, uint8_t x, uint8_t y)
{
    return (maze_cell_t)((uint16_t)y * m->width + x);
}
static inline uint8_t maze_x(const maze_t *m, maze_cell_t c) { return (uint8_t)(c % m->width); }
static inline uint8_t maze_y(const maze_t *m, maze_cell_t c) { return (uint8_t)(c / m->width); }
static inline uint16_t maze_cells(const maze_t *m) { return (uint16_t)m->width * m->height; }

/* The neighbour of c across side d; returns 0 if that leaves the maze. */
int maze_neighbour(const maze_t *m, maze_cell_t c, uint8_t d, maze_cell_t *out);

/* The neighbour across side d of c, for a side known to be passable: the
 * boundary is always known closed, so no bounds check (and no division,
 * which costs ~200 cycles on the AVR) is needed. */
static inline maze_cell_t maze_step(const maze_t *m, maze_cell_t c, uint8_t d)
{
    switch (d & 3) {
    case MAZE_NORTH: return (maze_cell_t)(c + m->width);
    case MAZE_EAST: return (maze_cell_t)(c + 1);
    case MAZE_SOUTH: return (maze_cell_t)(c - m->width);
    default: return (maze_cell_t)(c - 1);
    }
}

/* Wall on side d of cell c: MAZE_WALL_UNKNOWN/OPEN/CLOSED. */
uint8_t maze_wall(const maze_t *m, maze_cell_t c, uint8_t d);
/* Set the wall on side d of c (and the same wall seen from the neighbour).
 * state is MAZE_WALL_OPEN, MAZE_WALL_CLOSED or MAZE_WALL_UNKNOWN. Boundary
 * walls stay closed whatever is asked. */
void maze_set_wall(maze_t *m, maze_cell_t c, uint8_t d, uint8_t state);
/* Is side d of c passable? Unknown counts as open if unknown_open != 0. */
int maze_passable(const maze_t *m, maze_cell_t c, uint8_t d, int unknown_open);

int maze_is_goal(const maze_t *m, maze_cell_t c);
void maze_set_goal(maze_t *m, maze_cell_t c, int on);
void maze_clear_goals(maze_t *m);
/* The goal = the rectangle of cells x0..x1, y0..y1 (inclusive), nothing
 * else. Returns 0, or -1 (the goal unchanged) if it is empty or leaves
 * the maze. */
int maze_set_goal_rect(maze_t *m, uint8_t x0, uint8_t y0, uint8_t x1, uint8_t y1);

/* Mark every wall known (unknown ones become closed): a true maze. */
void maze_close_unknown(maze_t *m);

/* Copy the map without knowledge: same size, start and goal, all interior
 * walls unknown. Used to give a mouse an empty map of a known maze. */
void maze_forget(maze_t *dst, const maze_t *src);

/* Heading arithmetic: d turned by q quarter turns clockwise. */
static inline uint8_t maze_turn(uint8_t d, int8_t q) { return (uint8_t)((d + q + 4) & 3); }

#endif

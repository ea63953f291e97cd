/* flood.h - floodfill on the mouse's map.
 *
 * Two floods share one flood_t:
 * - classic: cell distances, BFS from the target cells over open walls;
 * - heading-aware ("modified", the paper's Algorithm 1): a configuration is
 *   (cell, heading); a forward move into the next cell and a 90-degree
 *   rotation each cost 1; costs grow from the target configurations (all
 *   headings of every target cell, cost 0) outward over predecessors.
 *
 * Memory, the reason for this layout: a uint16 per configuration would take
 * 2 KB for 16x16, the whole SRAM of an ATmega328P. Neighbouring
 * configurations differ little in cost (a rotation changes it by at most 1,
 * a forward move by -1..+5, because turning round, stepping back and turning
 * round again costs 5), so a configuration stores its cost modulo 15 in a
 * nibble and the absolute value is recovered next to a known one
 * (flood_cost). Nibble 15 = not reached; visited = nibble != 15.
 *
 * The BFS keeps no FIFO of configurations: it runs level by level over
 * cells, all four headings of a cell at once. Its frontier is two bitsets
 * of cells (levels k and k+1, each maze row starting a byte) and, for each,
 * the list of its non-zero bytes, so a level touches only the bytes that
 * hold cells. For 16x16: cost field 512 B + frontiers 64 B + lists 64 B +
 * target set 32 B. On a 16 MHz ATmega328P a full heading-aware flood takes
 * 138,418 cycles (8.7 ms) on a blank map, 178,933 (11.2 ms) on japan2018's
 * true map (docs/BENCHMARKS.md).
 */
#ifndef FLOOD_H
#define FLOOD_H

#include <stdint.h>
#include "maze.h"

#define FLOOD_UNREACHABLE 0xFFFFu
#define FLOOD_CONFIGS (MAZE_MAX_CELLS * 4)
#define FLOOD_ROW_BYTES ((MAZE_MAX_W + 7) / 8) /* frontier bytes per maze row */
#define FLOOD_FRONT_BYTES (MAZE_MAX_H * FLOOD_ROW_BYTES) /* 1 bit per cell */
#if FLOOD_FRONT_BYTES > 255
#error "flood: frontier byte indices and counts are uint8_t: MAZE_MAX_SIZE too large"
#endif

/* flags for flood_run / flood_cells */
#define FLOOD_UNKNOWN_OPEN 1u /* unknown walls count as open (searching) */
#define FLOOD_FULL 2u         /* fill the whole field, do not stop at src */
#define FLOOD_PREFER_KNOWN 4u /* flood_next_dir: known-open walls win ties */

typedef struct {
    uint8_t cost[FLOOD_CONFIGS / 2];        /* nibble per (cell, heading) */
    uint8_t front[2 * FLOOD_FRONT_BYTES];   /* BFS frontiers, levels k, k+1 */
    uint8_t list[2][FLOOD_FRONT_BYTES];     /* their non-zero bytes, by index */
    uint8_t target[(MAZE_MAX_CELLS + 7) / 8]; /* target cells, 1 bit each */
} flood_t;

void flood_target_clear(flood_t *f);
void flood_target_add(flood_t *f, maze_cell_t c);
void flood_target_goal(flood_t *f, const maze_t *m); /* targets = goal set */
int flood_is_target(const flood_t *f, maze_cell_t c);

/* Heading-aware flood towards the target cells. Returns the absolute cost
 * of configuration (src, src_heading), FLOOD_UNREACHABLE if no target can be
 * reached from it. Without FLOOD_FULL the flood stops after the BFS level
 * that costs src: every configuration up to src's cost is then costed,
 * none dearer, which is all that flood_next_dir needs from src onward. */
uint16_t flood_run(flood_t *f, const maze_t *m, maze_cell_t src,
                   uint8_t src_heading, uint8_t flags);

/* Absolute cost of (c, h) after flood_run, recovered next to `near`, the
 * known absolute cost of a configuration within 7 of it. */
uint16_t flood_cost(const flood_t *f, maze_cell_t c, uint8_t h, uint16_t near);

/* The heading to leave cell c in, for a mouse at (c, h) whose cost is k:
 * the neighbour that keeps the cost falling, preferring straight on, then
 * right, then left, then back. Returns -1 if c is a target or unreachable. */
int flood_next_dir(const flood_t *f, const maze_t *m, maze_cell_t c,
                   uint8_t h, uint16_t k, uint8_t flags);

/* Classic floodfill: cell distances to the targets. Returns the distance
 * of cell src (FLOOD_UNREACHABLE if none); FLOOD_FULL as above. */
uint16_t flood_cells(flood_t *f, const maze_t *m, maze_cell_t src, uint8_t flags);
/* Distance of cell c after flood_cells, next to a known distance within 7. */
uint16_t flood_cell_dist(const flood_t *f, maze_cell_t c, uint16_t near);
/* The heading to leave c in (facing h, distance k) towards a neighbour at
 * distance k-1, preferring straight, right, left, back; -1 if none. */
int flood_next_cell_dir(const flood_t *f, const maze_t *m, maze_cell_t c, uint8_t h, uint16_t k, uint8_t flags);

#endif

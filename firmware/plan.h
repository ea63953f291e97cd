/* plan.h - the speed run's path: the fastest sequence of slalom.h's moves
 * over the walls the map knows to be open, by time.
 *
 * Cost model (exact: the search proves the path optimal in it). Each turn
 * kind k is driven at its own speed v_turn_mm_s[k] from its start to its
 * end; its straight legs (before_mm[k] from its entry node to its start,
 * after_mm[k] from its end to its exit node) belong to the straights on
 * either side. A straight between turn a (or the start: at rest, no leg)
 * and turn b (or the stop at a goal cell's centre: at rest, no leg) is
 * after_mm[a] + n * cell_mm / 2 (n * cell_mm / 2 * sqrt(2) diagonal) +
 * before_mm[b] long and goes from v_turn_mm_s[a] to v_turn_mm_s[b],
 * speeding up at accel_mm_s2 to at most v_max_mm_s (v_diag_mm_s on
 * diagonals; never below its end speeds) and braking at accel_mm_s2: a
 * trapezoid, or a triangle where the top speed is not reached; one too
 * short to change speed as asked is not driven. A turn costs turn_s[kind]
 * between its legs. With every leg 0, turn_s is a turn's whole time from
 * entry node to exit node.
 *
 * Search: Dijkstra over states (node of the half-cell grid, heading in
 * 45-degree steps, the kind of the turn that led there: it sets the speed
 * and the leg the next straight starts with) where the robot stands right
 * after a turn, plus the start.
 * An edge is one maximal straight (0 or more half units) and the turn that
 * ends it, or a last straight into a goal cell's centre, so two straights
 * never follow each other. A move is legal only where every side middle it
 * crosses (slalom_geom's list, and every side a straight crosses) is
 * MAZE_WALL_OPEN in the map; the boundary is closed, so the robot stays in
 * the maze.
 *
 * Memory: static arrays of 18 B per state, (2 W + 1) (2 H + 1) 8 8 states
 * for MAZE_MAX_SIZE W = H: 1,254,528 B for 16x16, 4,867,200 B for 32x32
 * (the search touches only the states of the map's size). That does
 * not fit an AVR (2-8 KB of SRAM), so the planner compiles to nothing
 * there (PLAN_ENABLED 0); the host builds it, and a target with the RAM
 * can define PLAN_ENABLED 1. Portable C99, no
 * allocation, not reentrant (one search at a time). */
#ifndef PLAN_H
#define PLAN_H

#include "maze.h"
#include "slalom.h"

#ifndef PLAN_ENABLED
#if !defined(__AVR__)
#define PLAN_ENABLED 1
#else
#define PLAN_ENABLED 0
#endif
#endif

#define PLAN_MAX_MOVES 128

typedef struct {
    float cell_mm;              /* maze pitch (180 classic, 90 half-size) */
    float v_max_mm_s;           /* orthogonal straights' top speed */
    float v_diag_mm_s;          /* diagonal straights' top speed */
    float accel_mm_s2;          /* speeding up and braking on straights */
    float v_turn_mm_s[SLALOM_KINDS]; /* each turn kind's speed from its start to its end, mm/s */
    float before_mm[SLALOM_KINDS];   /* each turn's straight leg from its entry node to its start, mm */
    float after_mm[SLALOM_KINDS];    /* each turn's straight leg from its end to its exit node, mm */
    float turn_s[SLALOM_KINDS]; /* each turn's time between its legs at its speed, s; <= 0: that turn is not used */
} plan_costs_t;

/* The fastest run over the walls `map` knows to be open (unknown = closed): from the start cell's centre at rest,
 * facing map->start_heading, to the centre of any goal cell, at rest there, arriving orthogonally. Writes the moves
 * (a turn's n is 1; ORTHO n half units; DIAG n half steps); returns their count, 0 if there is no path, -1 if more
 * than max. *time_s: the path's cost. Every path it returns is optimal in this cost (see above).
 * No path: 0 and *time_s = -1. The start cell a goal cell: 0 and *time_s = 0. A speed, the acceleration or cell_mm
 * not above 0 (a turn's speed: for a turn that is used), a leg below 0, or a map larger than MAZE_MAX_SIZE: 0 and *time_s = -1. */
int plan_run(const maze_t *map, const plan_costs_t *c, slalom_move_t *moves, int max, float *time_s);

#endif

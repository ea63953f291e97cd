/* solve.c - exact lexicographic best path over (cell, heading) configs.
 *
 * Two BFS passes from the goal over predecessors, with full uint16 costs:
 * cost-to-goal by level, then fewest forward moves among cost-optimal
 * continuations, computed in order of increasing cost. */
#include "solve.h"

#include <string.h>

#define NCONF (TRUEMAZE_MAX_CELLS * 4)

typedef struct {
    uint16_t cost[NCONF];
    uint16_t cells[NCONF];
    uint16_t queue[NCONF];
} solve_work_t;

static solve_work_t work; /* host only: one solver at a time */

static int forward(const truemaze_t *m, truemaze_cell_t c, uint8_t h, truemaze_cell_t *n)
{
    return truemaze_open(m, c, h) && truemaze_neighbour(m, c, h, n);
}

/* cost-to-goal for every config; returns the number queued (BFS order). */
static uint16_t flood_all(const truemaze_t *m)
{
    uint16_t n = (uint16_t)(truemaze_cells(m) * 4u), head = 0, tail = 0;
    for (uint16_t i = 0; i < n; i++) work.cost[i] = SOLVE_NONE;
    for (uint16_t c = 0; c < truemaze_cells(m); c++)
        if (truemaze_is_goal(m, (truemaze_cell_t)c))
            for (uint8_t h = 0; h < 4; h++) {
                work.cost[c * 4 + h] = 0;
                work.queue[tail++] = (uint16_t)(c * 4 + h);
            }
    while (head < tail) {
        uint16_t i = work.queue[head++];
        truemaze_cell_t c = (truemaze_cell_t)(i / 4), b;
        uint8_t h = (uint8_t)(i % 4);
        uint16_t p[3];
        uint8_t np = 0;
        p[np++] = (uint16_t)(c * 4 + truemaze_turn(h, 1));
        p[np++] = (uint16_t)(c * 4 + truemaze_turn(h, -1));
        if (forward(m, c, truemaze_turn(h, 2), &b)) p[np++] = (uint16_t)(b * 4 + h);
        for (uint8_t k = 0; k < np; k++)
            if (work.cost[p[k]] == SOLVE_NONE) {
                work.cost[p[k]] = (uint16_t)(work.cost[i] + 1);
                work.queue[tail++] = p[k];
            }
    }
    /* fewest cells among cost-optimal continuations, by increasing cost */
    for (uint16_t j = 0; j < tail; j++) {
        uint16_t i = work.queue[j];
        truemaze_cell_t c = (truemaze_cell_t)(i / 4), nx;
        uint8_t h = (uint8_t)(i % 4);
        uint16_t best = SOLVE_NONE;
        if (work.cost[i] == 0) { work.cells[i] = 0; continue; }
        if (forward(m, c, h, &nx) && work.cost[nx * 4 + h] + 1u == work.cost[i])
            best = (uint16_t)(work.cells[nx * 4 + h] + 1);
        for (int8_t r = -1; r <= 1; r += 2) {
            uint16_t q = (uint16_t)(c * 4 + truemaze_turn(h, r));
            if (work.cost[q] + 1u == work.cost[i] && work.cells[q] < best) best = work.cells[q];
        }
        work.cells[i] = best;
    }
    return tail;
}

uint16_t solve_cost_from(const truemaze_t *m, truemaze_cell_t cell, uint8_t heading)
{
    flood_all(m);
    return work.cost[cell * 4 + (heading & 3)];
}

static uint16_t min_cells(const truemaze_t *m)
{
    uint16_t n = truemaze_cells(m), head = 0, tail = 0;
    for (uint16_t c = 0; c < n; c++) work.cost[c] = SOLVE_NONE;
    work.cost[m->start] = 0;
    work.queue[tail++] = m->start;
    while (head < tail) {
        truemaze_cell_t c = (truemaze_cell_t)work.queue[head++], nx;
        if (truemaze_is_goal(m, c)) return work.cost[c];
        for (uint8_t d = 0; d < 4; d++)
            if (forward(m, c, d, &nx) && work.cost[nx] == SOLVE_NONE) {
                work.cost[nx] = (uint16_t)(work.cost[c] + 1);
                work.queue[tail++] = nx;
            }
    }
    return SOLVE_NONE;
}

int solve_best(const truemaze_t *m, solve_path_t *out)
{
    truemaze_cell_t c = m->start;
    uint8_t h = m->start_heading;

    memset(out, 0, sizeof *out);
    out->min_cells = min_cells(m);
    flood_all(m);
    out->cost = work.cost[c * 4 + h];
    if (out->cost == SOLVE_NONE) {
        out->cells = out->turns = SOLVE_NONE;
        return -1;
    }
    out->reachable = 1;
    out->path[out->len++] = c;
    while (work.cost[c * 4 + h] != 0) {
        uint16_t i = (uint16_t)(c * 4 + h);
        truemaze_cell_t nx;
        if (forward(m, c, h, &nx) && work.cost[nx * 4 + h] + 1u == work.cost[i] &&
            work.cells[nx * 4 + h] + 1u == work.cells[i]) {
            c = nx;
            out->path[out->len++] = c;
            out->cells++;
            continue;
        }
        /* turn: prefer the side that leads to a straight move soonest */
        int8_t pick = 0;
        for (int8_t r = 1; r >= -1; r -= 2) {
            uint16_t q = (uint16_t)(c * 4 + truemaze_turn(h, r));
            if (work.cost[q] + 1u == work.cost[i] && work.cells[q] == work.cells[i]) {
                pick = r;
                break;
            }
        }
        if (pick == 0) break; /* cannot happen: the field is consistent */
        h = truemaze_turn(h, pick);
        out->turns++;
    }
    return 0;
}

/* grid.c - abstract mouse for grid-mode exploration. */
#include "grid.h"
#include "explore.h"
#include "solve.h"
#include "truebelief.h"

#include <string.h>

static explore_t mouse; /* host: one grid run at a time; 2.7 KB for 32x32 */

uint8_t grid_sense(const truemaze_t *truth, truemaze_cell_t c, uint8_t h)
{
    uint8_t w = 0;
    if (!truemaze_open(truth, c, h)) w |= EXPLORE_WALL_FRONT;
    if (!truemaze_open(truth, c, truemaze_turn(h, 1))) w |= EXPLORE_WALL_RIGHT;
    if (!truemaze_open(truth, c, truemaze_turn(h, -1))) w |= EXPLORE_WALL_LEFT;
    return w;
}

int grid_explore(const truemaze_t *truth, grid_result_t *r)
{
    static uint8_t visited[(TRUEMAZE_MAX_CELLS + 7) / 8];
    static solve_path_t best;
    uint32_t limit = 16u * truemaze_cells(truth);

    memset(r, 0, sizeof *r);
    memset(visited, 0, sizeof visited);
    r->proven_at_step = -1;
    r->goal_at_step = -1;
    r->goal_reachable = solve_best(truth, &best) == 0;
    r->true_cost = best.cost;

    static maze_t blank; /* the firmware's map type: explore_init reads size, start and goal */
    if (truemaze_to_belief(truth, &blank) != 0) return 1; /* larger than the firmware's MAZE_MAX_SIZE */
    explore_init(&mouse, &blank);
    visited[mouse.cell >> 3] |= (uint8_t)(1u << (mouse.cell & 7));
    r->cells_visited = 1;
    while (r->steps < limit) {
        explore_sense(&mouse, grid_sense(truth, mouse.cell, mouse.heading));
        int d = explore_next(&mouse);
        if (d < 0) break;
        truemaze_cell_t n;
        if (!truemaze_open(truth, mouse.cell, (uint8_t)d) ||
            !truemaze_neighbour(truth, mouse.cell, (uint8_t)d, &n))
            break; /* the mouse tried to drive into a wall: a bug, stop */
        switch ((d - mouse.heading) & 3) {
        case 0: r->steps_forward++; break;
        case 1: r->steps_right++; break;
        case 2: r->steps_back++; break;
        default: r->steps_left++; break;
        }
        r->steps++;
        explore_moved(&mouse, (uint8_t)d);
        if (!((visited[n >> 3] >> (n & 7)) & 1)) {
            visited[n >> 3] |= (uint8_t)(1u << (n & 7));
            r->cells_visited++;
        }
    }
    if (mouse.proven_at_step != EXPLORE_NEVER) r->proven_at_step = mouse.proven_at_step;
    if (mouse.goal_at_step != EXPLORE_NEVER) r->goal_at_step = mouse.goal_at_step;
    r->run_cost = mouse.run_cost;
    r->ended_at_start = mouse.cell == truth->start;
    r->final_path_optimal = mouse.phase == EXPLORE_DONE && r->goal_reachable &&
                            solve_cost_from(truth, truth->start, truth->start_heading) == mouse.run_cost;
    return mouse.phase == EXPLORE_DONE ? 0 : 1;
}

/* explore.c - search the maze until the run path is proven optimal. */
#include "explore.h"
#include "hal.h"

#include <stdio.h>

void explore_init(explore_t *e, const maze_t *blank)
{
    maze_forget(&e->map, blank);
    e->cell = blank->start;
    e->heading = blank->start_heading;
    e->phase = EXPLORE_TO_GOAL;
    e->steps = 0;
    e->proven_at_step = EXPLORE_NEVER;
    e->goal_at_step = EXPLORE_NEVER;
    e->run_cost = FLOOD_UNREACHABLE;
    e->plan_us_max = 0;
    e->path_cost = FLOOD_UNREACHABLE;
}

void explore_sense(explore_t *e, uint8_t walls)
{
    /* front, right, left (computed, not tables: an AVR copies tables into its RAM) */
    for (uint8_t j = 0; j < 3; j++) {
        uint8_t bit = j == 0 ? EXPLORE_WALL_FRONT : j == 1 ? EXPLORE_WALL_RIGHT : EXPLORE_WALL_LEFT;
        maze_set_wall(&e->map, e->cell, maze_turn(e->heading, j == 2 ? -1 : (int8_t)j),
                      (walls & bit) ? MAZE_WALL_CLOSED : MAZE_WALL_OPEN);
    }
}

void explore_moved(explore_t *e, uint8_t d)
{
    maze_cell_t n;
    if (maze_neighbour(&e->map, e->cell, d, &n)) {
        /* we drove through that wall, so it is open */
        maze_set_wall(&e->map, e->cell, d, MAZE_WALL_OPEN);
        e->cell = n;
    }
    e->heading = d & 3u;
    e->steps++;
}

/* Cost from the start configuration to the goal, unknown walls open or not. */
static uint16_t start_cost(explore_t *e, uint8_t flags)
{
    flood_target_goal(&e->flood, &e->map);
    return flood_run(&e->flood, &e->map, e->map.start, e->map.start_heading, flags);
}

/* Proven when the start-to-goal cost over known-open walls equals the cost
 * with unknown walls open. *open gets the latter; the flood field is left
 * as that (optimistic) flood made it, which mark_unknown_on_path walks. */
/* The proof's log line; a function of its own so that an MCU's build
 * (without inlining) keeps the line's buffer off the stack during the floods. */
static void log_proven(const explore_t *e)
{
    char line[HAL_LOG_MAX + 1];
    hal_snprintf(line, sizeof line, HAL_STR("explore: run path proven at step %u, cost %u"),
             (unsigned)e->proven_at_step, (unsigned)e->run_cost);
    hal_log(line);
}

static int check_proven(explore_t *e, uint16_t *open)
{
    uint16_t known = start_cost(e, 0);
    *open = start_cost(e, FLOOD_UNKNOWN_OPEN);
    if (known == FLOOD_UNREACHABLE || known != *open) return 0;
    e->proven_at_step = e->steps;
    e->run_cost = known;
    log_proven(e);
    return 1;
}

/* Target = the two cells beside the LAST unknown wall (nearest the goal)
 * that the best optimistic path from the start crosses. Measured on the 481
 * classic mazes: every unknown wall of that path as targets (nearest first)
 * needs 392 steps on japan2018 and 267.8 on average; the last one alone
 * needs 256 and 271.7, because the mouse, starting at the goal, then sweeps
 * back towards the start instead of ending far from it. Ties on the walk
 * go to known-open walls, so the path checked is the most known one.
 * Returns how many unknown walls the path crosses. k is the optimistic
 * start cost and the field the one check_proven's optimistic flood left (the
 * same flood again would give the same field: one flood less per cell while
 * proving, 3 instead of 4). The target set is not read by the walk, so it
 * is rebuilt on that field. */
static uint16_t mark_unknown_on_path(explore_t *e, uint16_t k)
{
    maze_cell_t c = e->map.start;
    uint8_t h = e->map.start_heading;
    uint16_t unknown = 0;

    flood_target_clear(&e->flood);
    while (k != 0 && k != FLOOD_UNREACHABLE) {
        int d = flood_next_dir(&e->flood, &e->map, c, h, k, FLOOD_UNKNOWN_OPEN | FLOOD_PREFER_KNOWN);
        maze_cell_t n;
        if (d < 0 || !maze_neighbour(&e->map, c, (uint8_t)d, &n)) break;
        if (maze_wall(&e->map, c, (uint8_t)d) == MAZE_WALL_UNKNOWN) {
            unknown++;
            flood_target_clear(&e->flood); /* keep only the last one */
            flood_target_add(&e->flood, c);
            flood_target_add(&e->flood, n);
        }
        k = (uint16_t)(k - 1u - (d == h ? 0u : ((d - h) & 3) == 2 ? 2u : 1u));
        c = n;
        h = (uint8_t)d;
    }
    return unknown;
}

/* Step towards the current target set; -1 if it cannot be reached. */
static int step_to_targets(explore_t *e)
{
    uint16_t k = flood_run(&e->flood, &e->map, e->cell, e->heading, FLOOD_UNKNOWN_OPEN);
    return flood_next_dir(&e->flood, &e->map, e->cell, e->heading, k, FLOOD_UNKNOWN_OPEN);
}

static int decide(explore_t *e)
{
    for (;;) {
        switch (e->phase) {
        case EXPLORE_TO_GOAL:
            if (maze_is_goal(&e->map, e->cell)) {
                e->goal_at_step = e->steps;
                e->phase = EXPLORE_PROVE;
                continue;
            }
            flood_target_goal(&e->flood, &e->map);
            {
                int d = step_to_targets(e);
                if (d >= 0) return d;
            }
            HAL_LOG_STR("explore: goal unreachable");
            e->phase = EXPLORE_NO_GOAL;
            return -1;
        case EXPLORE_PROVE: {
            uint16_t open;
            if (check_proven(e, &open)) {
                e->phase = EXPLORE_RETURN;
                continue;
            }
            if (mark_unknown_on_path(e, open) == 0) {
                /* Cannot happen while known != open; stop rather than loop. */
                HAL_LOG_STR("explore: no unknown wall left to explore");
                e->phase = EXPLORE_NO_GOAL;
                return -1;
            }
            {
                int d = step_to_targets(e);
                if (d >= 0) return d;
            }
            HAL_LOG_STR("explore: exploration target unreachable");
            e->phase = EXPLORE_NO_GOAL;
            return -1;
        }
        case EXPLORE_RETURN:
            if (e->cell == e->map.start) {
                e->phase = EXPLORE_DONE;
                return -1;
            }
            flood_target_clear(&e->flood);
            flood_target_add(&e->flood, e->map.start);
            {
                int d = step_to_targets(e);
                if (d >= 0) return d;
            }
            e->phase = EXPLORE_NO_GOAL;
            return -1;
        default:
            return -1;
        }
    }
}

int explore_next(explore_t *e)
{
    uint32_t t0 = hal_micros();
    int d = decide(e);
    uint32_t took = hal_micros() - t0; /* unsigned: correct across the wrap */
    if (took > e->plan_us_max) e->plan_us_max = took;
    return d;
}

int explore_run_dir(explore_t *e, maze_cell_t c, uint8_t h)
{
    flood_target_goal(&e->flood, &e->map);
    uint16_t k = e->path_cost = flood_run(&e->flood, &e->map, c, h, 0);
    return flood_next_dir(&e->flood, &e->map, c, h, k, 0);
}

int explore_home_dir(explore_t *e, maze_cell_t c, uint8_t h)
{
    flood_target_clear(&e->flood);
    flood_target_add(&e->flood, e->map.start);
    uint16_t k = e->path_cost = flood_run(&e->flood, &e->map, c, h, 0);
    return flood_next_dir(&e->flood, &e->map, c, h, k, 0);
}

int explore_dir_ahead(const explore_t *e, maze_cell_t c, uint8_t h, uint8_t cells)
{
    /* a straight move costs 1: the field holds every configuration cheaper than the first */
    if (e->path_cost == FLOOD_UNREACHABLE || e->path_cost < cells) return -1;
    return flood_next_dir(&e->flood, &e->map, c, h, (uint16_t)(e->path_cost - cells), 0);
}

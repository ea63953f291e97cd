/* avr_flood.c - AVR side of the flood benchmark. Each measured call is
 * bracketed by two writes to GPIOR0 (MARK_START(n), MARK_END(n)); the host
 * side (bench/simavr_cycles.c) records simavr's cycle counter at each and
 * prints count, mean and max per mark. Marks:
 *   1 full heading-aware flood of a blank 16x16 map (unknown walls open):
 *     every configuration costed, the worst case
 *   2 the same map from the start configuration, stopping there (the
 *     mouse's first search flood)
 *   3 full heading-aware flood of the true map (bench_maze.h, made by
 *     bench/maze_header.c: classic/japan2018 by default)
 *   4 the true map from the start configuration, stopping there (the flood
 *     at the start of a speed run)
 *   5 every flood_run of a whole grid-mode search of the true map
 *     (explore.c, as in mmmaze explore: sense, decide, move), through
 *     -Wl,--wrap=flood_run
 *   6 every decision of that search (explore_next: one flood, or several
 *     around the goal and while proving the path)
 * then sleep with interrupts off so simavr stops. */
#include <avr/interrupt.h>
#include <avr/io.h>
#include <avr/pgmspace.h>
#include <avr/sleep.h>

#include "explore.h"
#include "hal.h"
#include "bench_maze.h"

#define MARK_START(n) (GPIOR0 = (uint8_t)((n) << 1))
#define MARK_END(n) (GPIOR0 = (uint8_t)(((n) << 1) | 1u))

static maze_t truth;
static explore_t e; /* its flood_t serves the single floods too */
volatile uint16_t sink;

uint32_t hal_micros(void) { return 0; }
void hal_log(const char *line) { (void)line; }
void hal_log_P(const char *line) { (void)line; }

uint16_t __real_flood_run(flood_t *f, const maze_t *m, maze_cell_t src, uint8_t src_heading, uint8_t flags);
uint16_t __wrap_flood_run(flood_t *f, const maze_t *m, maze_cell_t src, uint8_t src_heading, uint8_t flags);
uint16_t __wrap_flood_run(flood_t *f, const maze_t *m, maze_cell_t src, uint8_t src_heading, uint8_t flags)
{
    MARK_START(5);
    uint16_t k = __real_flood_run(f, m, src, src_heading, flags);
    MARK_END(5);
    return k;
}

static void timed_flood(uint8_t mark, const maze_t *m, uint8_t flags)
{
    flood_target_goal(&e.flood, m);
    MARK_START(mark);
    sink = __real_flood_run(&e.flood, m, m->start, m->start_heading, flags);
    MARK_END(mark);
}

/* Walls seen from (c, h) in the true maze, as grid mode senses them. */
static uint8_t sense(maze_cell_t c, uint8_t h)
{
    uint8_t w = 0;
    if (!maze_passable(&truth, c, h, 0)) w |= EXPLORE_WALL_FRONT;
    if (!maze_passable(&truth, c, maze_turn(h, 1), 0)) w |= EXPLORE_WALL_RIGHT;
    if (!maze_passable(&truth, c, maze_turn(h, -1), 0)) w |= EXPLORE_WALL_LEFT;
    return w;
}

int main(void)
{
    static maze_t blank;
    maze_init(&truth, BENCH_MAZE_W, BENCH_MAZE_H);
    memcpy_P(truth.cell, bench_maze_cell, sizeof bench_maze_cell);
    memcpy_P(truth.goal, bench_maze_goal, sizeof bench_maze_goal);
    truth.start = BENCH_MAZE_START;
    truth.start_heading = BENCH_MAZE_HEADING;
    maze_forget(&blank, &truth);

    timed_flood(1, &blank, FLOOD_UNKNOWN_OPEN | FLOOD_FULL);
    timed_flood(2, &blank, FLOOD_UNKNOWN_OPEN);
    timed_flood(3, &truth, FLOOD_FULL);
    timed_flood(4, &truth, 0);

    explore_init(&e, &truth);
    for (uint16_t steps = 0; steps < 16u * maze_cells(&truth); steps++) {
        explore_sense(&e, sense(e.cell, e.heading));
        MARK_START(6);
        int d = explore_next(&e);
        MARK_END(6);
        if (d < 0 || !maze_passable(&truth, e.cell, (uint8_t)d, 0)) break;
        explore_moved(&e, (uint8_t)d);
    }
    cli();
    sleep_mode();
    return 0;
}

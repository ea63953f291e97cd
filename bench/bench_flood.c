/* bench_flood.c - host time per full heading-aware re-flood (and classic
 * flood) on maze files: the true map, and a blank map with unknown walls
 * open (the mouse's first flood). Wall clock is fine here: this is a
 * benchmark, not the simulation. */
#include <stdio.h>
#include <time.h>

#include "flood.h"
#include "maze/mazefile.h"
#include "maze/truebelief.h"

static double now_s(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + (double)ts.tv_nsec * 1e-9;
}

static flood_t f;
static truemaze_t truth;
static maze_t m, blank; /* the firmware's map of the truth, every wall known; and with none known */

static double time_flood(const maze_t *mz, int heading, uint8_t flags)
{
    volatile uint16_t sink = 0;
    int reps = 0;
    double t0 = now_s(), t;
    flood_target_goal(&f, mz);
    do {
        for (int i = 0; i < 100; i++, reps++)
            sink = heading ? flood_run(&f, mz, mz->start, mz->start_heading, flags | FLOOD_FULL)
                           : flood_cells(&f, mz, mz->start, flags | FLOOD_FULL);
        t = now_s() - t0;
    } while (t < 0.5);
    (void)sink;
    return t / reps * 1e6;
}

int main(int argc, char **argv)
{
    char err[MAZEFILE_ERR_LEN];
    if (argc < 2) {
        fprintf(stderr, "usage: bench_flood MAZE...\n");
        return 2;
    }
    for (int i = 1; i < argc; i++) {
        if (mazefile_load(&truth, argv[i], NULL, err, sizeof err) != 0) {
            fprintf(stderr, "%s\n", err);
            return 2;
        }
        if (truemaze_to_belief(&truth, &m) != 0) {
            fprintf(stderr, "bench_flood: %s: larger than the build's MAZE_MAX_SIZE\n", argv[i]);
            return 2;
        }
        maze_forget(&blank, &m);
        printf("%s (%ux%u): heading-aware full flood %.1f us (true map), %.1f us (blank map); "
               "classic flood %.1f us\n",
               argv[i], m.width, m.height, time_flood(&m, 1, 0), time_flood(&blank, 1, FLOOD_UNKNOWN_OPEN),
               time_flood(&m, 0, 0));
    }
    return 0;
}

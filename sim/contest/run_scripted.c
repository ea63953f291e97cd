/* run_scripted.c - `--driver scripted`: the stand-in of driver.h on the
 * true maze and pose, for a given number of runs to the goal and back. */
#include "run_driver.h"

#include <stdio.h>

#include "contest/driver.h"

/* One contest per process (run_one): the driver's state is static, as
 * run_one's run_t is, so what it holds stays reachable to the end. */
static driver_t scripted_state;

static int scripted_open(run_t *r, void **self)
{
    driver_init(&scripted_state, &r->maze, r->sim.model, r->o->runs);
    *self = &scripted_state;
    return 0;
}

/* The runs are over (or the goal cannot be reached: driver_init says so at
 * once) before this step: the contest ends without it. */
static const char *scripted_before(run_t *r, void *self)
{
    driver_t *d = self;
    if (d->done) return d->reachable ? "done" : "unreachable";
    driver_update(d, &r->sim);
    return NULL;
}

/* no map of its own: its path is the true maze's best */
static void scripted_report(const run_t *r, void *self, report_t *rep, const maze_t **belief, const truemaze_t **path_on)
{
    *path_on = &r->maze;
}

static void scripted_headline(const run_t *r, const void *self)
{
    printf("%s: %ux%u, seed %llu, scripted driver, %d run%s\n", r->maze_path, r->maze.width, r->maze.height,
           (unsigned long long)r->o->seed, r->o->runs, r->o->runs == 1 ? "" : "s");
}

const run_driver_t run_scripted = {
    .name = "scripted", .open = scripted_open, .before = scripted_before,
    .headline = scripted_headline, .report = scripted_report, .watch_stall = 1, .overtime = 1,
};

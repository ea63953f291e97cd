/* run_scripted.c - `--driver scripted`: the stand-in of driver.h on the
 * true maze and pose, for a given number of runs to the goal and back. */
#include "run_driver.h"

#include <stdio.h>

static int scripted_open(run_t *r)
{
    driver_init(&r->script, &r->maze, r->sim.model, r->o->runs);
    return 0;
}

/* The runs are over (or the goal cannot be reached: driver_init says so at
 * once) before this step: the contest ends without it. */
static const char *scripted_step(run_t *r)
{
    if (r->script.done) return r->script.reachable ? "done" : "unreachable";
    driver_update(&r->script, &r->sim);
    sim_step(&r->sim);
    if (r->tel_on) telem_step(&r->tel, &r->sim);
    return NULL;
}

static void scripted_headline(const run_t *r)
{
    printf("%s: %ux%u, seed %llu, scripted driver, %d run%s\n", r->maze_path, r->maze.width, r->maze.height,
           (unsigned long long)r->o->seed, r->o->runs, r->o->runs == 1 ? "" : "s");
}

const run_driver_t run_scripted = {
    .name = "scripted", .open = scripted_open, .step = scripted_step,
    .headline = scripted_headline,
};

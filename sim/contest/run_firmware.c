/* run_firmware.c - the mouse's own firmware in-process (hal/sim): its whole
 * contest (the default driver), or its command mode driven by an mms
 * algorithm (--mms, sim/mms). Both tick the firmware after every step. */
#include "run_driver.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#include "hal.h"
#include "hal_sim.h"
#include "maze/solve.h"
#include "maze/truebelief.h"
#include "mouse.h"

/* the firmware's control tick, counted in physics steps */
typedef struct {
    long steps_per_tick, tick_steps;
} fw_t;

/* --mms: the algorithm behind the firmware's command mode */
typedef struct {
    fw_t fw;
    mms_t mms;
    int stopped; /* mms_stop done */
} fw_mms_t;

/* its control tick at HAL_TICK_HZ, then its background loop */
static void fw_tick_loop(fw_t *f)
{
    if (++f->tick_steps >= f->steps_per_tick) {
        f->tick_steps = 0;
        fw_tick();
    }
    fw_loop();
}

/* The firmware on the run's world; its tick counter in f. */
static void fw_start(run_t *r, fw_t *f)
{
    hal_sim_attach(&r->sim);
    hal_sim_set_log(r->o->verbose ? stderr : NULL);
    static maze_t announced; /* the firmware's map type: hal/sim reads size, start and goal */
    hal_sim_set_maze(truemaze_to_belief(&r->maze, &announced) == 0 ? &announced : NULL); /* told through hal_maze */
    fw_set_speed_runs((uint8_t)r->o->runs);
    fw_setup();
    /* a build with -DHAL_TICK_HZ=250 ticks every 4th step, as on the AVR */
    f->steps_per_tick = lround(1.0 / (HAL_TICK_HZ * r->cfg.sim.step_s));
    if (f->steps_per_tick < 1) f->steps_per_tick = 1;
    f->tick_steps = f->steps_per_tick - 1; /* the first step ticks */
}

/* One contest per process (run_one): the driver's state is static, as
 * run_one's run_t is, so what it holds stays reachable to the end. */
static fw_t fw_state;
static fw_mms_t mms_state;

static int fw_open(run_t *r, void **self)
{
    memset(&fw_state, 0, sizeof fw_state);
    *self = &fw_state;
    fw_start(r, &fw_state);
    return 0;
}

static void fw_close(run_t *r, void *self) { hal_sim_attach(NULL); }

static const char *fw_after(run_t *r, void *self)
{
    fw_tick_loop(self);
    uint8_t mode = mouse_status()->mode;
    if (mode == MOUSE_DONE) return "done";
    if (mode == MOUSE_NO_GOAL) return "unreachable";
    if (mode == MOUSE_CRASHED) return "crash_stop";
    return NULL;
}

/* proven_at_step and final_path_optimal: did the mouse's map prove the
 * true best path (best through known-open walls = the true best)? */
static void fw_results(run_t *r, void *self, json_t *j)
{
    static solve_path_t truth, known;
    static truemaze_t map;
    truemaze_from_belief(&map, mouse_map(), 0);
    int ok_truth = solve_best(&r->maze, &truth) == 0, ok_known = solve_best(&map, &known) == 0;
    uint16_t proven = mouse_proven_at_step();
    json_object_set_new(j, "proven_at_step", proven == 0xFFFFu ? json_null() : json_integer(proven));
    json_object_set_new(j, "final_path_optimal",
                        json_boolean(ok_truth && ok_known && proven != 0xFFFFu && known.cost == truth.cost));
}

/* the map it built, and its final path on that map */
static void fw_report(const run_t *r, void *self, report_t *rep, const maze_t **belief, const truemaze_t **path_on)
{
    static truemaze_t map;
    truemaze_from_belief(&map, mouse_map(), 0);
    *belief = mouse_map();
    *path_on = &map;
}

/* the belief the firmware reports through hal_belief, as hal/sim keeps it */
static const sim_belief_t *fw_belief(const void *self) { return hal_sim_belief(); }

static void fw_headline(const run_t *r, const void *self)
{
    printf("%s: %ux%u, seed %llu, firmware\n", r->maze_path, r->maze.width, r->maze.height,
           (unsigned long long)r->o->seed);
}

const run_driver_t run_firmware = {
    .name = "firmware", .open = fw_open, .after = fw_after, .results = fw_results, .close = fw_close,
    .headline = fw_headline, .report = fw_report, .belief = fw_belief, .watch_stall = 1, .overtime = 1,
};

/* ---- an mms algorithm drives the firmware's command mode ---- */

static int mms_open(run_t *r, void **self)
{
    char err[400];
    fw_mms_t *m = &mms_state;
    memset(m, 0, sizeof *m);
    *self = m;
    fw_start(r, &m->fw);
    mouse_cmd_mode();
    if (mms_start(&m->mms, &r->o->mms, &r->maze, err, sizeof err) != 0) {
        fprintf(stderr, "mmsim: %s\n", err);
        fw_close(r, m);
        return RUN_EXTERNAL;
    }
    return 0;
}

static void mms_close(run_t *r, void *self)
{
    fw_mms_t *m = self;
    if (!m->stopped) mms_stop(&m->mms);
    fw_close(r, m);
}

/* sim time stands still while the algorithm thinks */
static const char *mms_before(run_t *r, void *self)
{
    fw_mms_t *m = self;
    return mms_service(&m->mms, &r->sim) != MMS_STEP ? m->mms.reason : NULL;
}

static const char *mms_after(run_t *r, void *self)
{
    fw_tick_loop(&((fw_mms_t *)self)->fw);
    return NULL;
}

static void mms_end(run_t *r, void *self)
{
    fw_mms_t *m = self;
    mms_stop(&m->mms);
    m->stopped = 1;
    if (m->mms.message[0]) fprintf(stderr, "%s\n", m->mms.message);
}

static void mms_results(run_t *r, void *self, json_t *j)
{
    json_t *mj = mms_json(&((fw_mms_t *)self)->mms);
    json_object_set_new(mj, "wall_contacts", json_integer(world_collisions(r->sim.world))); /* = collisions */
    json_object_set_new(j, "mms", mj);
}

/* the algorithm's cell colours and texts over the firmware's map and path */
static void mms_report(const run_t *r, void *self, report_t *rep, const maze_t **belief, const truemaze_t **path_on)
{
    const mms_t *m = &((fw_mms_t *)self)->mms;
    report_set_cells(rep, m->color, &m->text[0][0], sizeof m->text[0]);
    fw_report(r, self, rep, belief, path_on);
}

static void mms_show(run_t *r, void *self, view_t *v)
{
    mms_t *m = &((fw_mms_t *)self)->mms;
    view_set_mms(v, m->color, &m->text[0][0], sizeof m->text[0], &m->was_reset);
}

static void mms_headline(const run_t *r, const void *self)
{
    printf("%s: %ux%u, seed %llu, mms algorithm '%s' (%s walls), score %g\n", r->maze_path, r->maze.width,
           r->maze.height, (unsigned long long)r->o->seed, ((const fw_mms_t *)self)->mms.shown,
           r->o->mms.ideal_walls ? "ideal" : "sensed", (double)mms_stats_score(&((const fw_mms_t *)self)->mms.stats));
}

/* the algorithm's failure is an external one; else: was the goal reached */
static int mms_exit(const run_t *r, const void *self)
{
    if (mms_failed(&((const fw_mms_t *)self)->mms)) return RUN_EXTERNAL;
    return run_exit_laps(r, "mms_exited", "time_limit");
}

/* no stall watch: the firmware's command mode has a stall check of its own */
const run_driver_t run_mms = {
    .name = "mms", .open = mms_open, .before = mms_before, .after = mms_after, .stop = mms_end,
    .results = mms_results, .close = mms_close, .headline = mms_headline, .exit_code = mms_exit,
    .report = mms_report, .show = mms_show, .belief = fw_belief, .overtime = 1,
};

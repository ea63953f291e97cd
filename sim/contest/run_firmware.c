/* run_firmware.c - the mouse's own firmware in-process (hal/sim): its whole
 * contest (the default driver), or its command mode driven by an mms
 * algorithm (--mms, sim/mms). Both tick the firmware after every step. */
#include "run_driver.h"

#include <stdio.h>
#include <string.h>

#include "hal.h"
#include "hal_sim.h"
#include "maze/solve.h"
#include "mouse.h"

void run_firmware_tick(run_t *r)
{
    if (++r->tick_steps >= r->steps_per_tick) {
        r->tick_steps = 0;
        fw_tick();
    }
    fw_loop();
}

static int fw_open(run_t *r)
{
    hal_sim_attach(&r->sim);
    hal_sim_set_log(r->o->verbose ? stderr : NULL);
    fw_set_maze(&r->maze);
    fw_set_speed_runs((uint8_t)r->o->runs);
    fw_setup();
    return 0;
}

static void fw_undo(run_t *r) { hal_sim_attach(NULL); }

static const char *fw_step(run_t *r)
{
    sim_step(&r->sim);
    if (r->tel_on) telem_step(&r->tel, &r->sim);
    run_firmware_tick(r);
    uint8_t mode = mouse_status()->mode;
    if (mode == MOUSE_DONE) return "done";
    if (mode == MOUSE_NO_GOAL) return "unreachable";
    if (mode == MOUSE_CRASHED) return "crash_stop";
    return NULL;
}

/* proven_at_step and final_path_optimal: did the mouse's map prove the
 * true best path (best through known-open walls = the true best)? */
static void fw_results(run_t *r, json_t *j)
{
    static solve_path_t truth, known;
    int ok_truth = solve_best(&r->maze, 0, &truth) == 0, ok_known = solve_best(mouse_map(), 0, &known) == 0;
    uint16_t proven = mouse_proven_at_step();
    json_object_set_new(j, "proven_at_step", proven == 0xFFFFu ? json_null() : json_integer(proven));
    json_object_set_new(j, "final_path_optimal",
                        json_boolean(ok_truth && ok_known && proven != 0xFFFFu && known.cost == truth.cost));
    hal_sim_attach(NULL);
}

static void fw_headline(const run_t *r)
{
    printf("%s: %ux%u, seed %llu, firmware\n", r->maze_path, r->maze.width, r->maze.height,
           (unsigned long long)r->o->seed);
}

const run_driver_t run_firmware = {
    .name = "firmware", .open = fw_open, .step = fw_step, .results = fw_results,
    .undo = fw_undo, .headline = fw_headline,
};

/* ---- an mms algorithm drives the firmware's command mode ---- */

static int mms_open(run_t *r)
{
    char err[400];
    fw_open(r);
    mouse_cmd_mode();
    if (mms_start(&r->mms, &r->o->mms, &r->maze, err, sizeof err) != 0) {
        fprintf(stderr, "mmsim: %s\n", err);
        hal_sim_attach(NULL);
        return RUN_EXTERNAL;
    }
    return 0;
}

static void mms_undo(run_t *r)
{
    mms_stop(&r->mms);
    hal_sim_attach(NULL);
}

/* sim time stands still while the algorithm thinks */
static const char *mms_step(run_t *r)
{
    if (mms_service(&r->mms, &r->sim) != MMS_STEP) return r->mms.reason;
    sim_step(&r->sim);
    if (r->tel_on) telem_step(&r->tel, &r->sim);
    run_firmware_tick(r);
    return NULL;
}

static void mms_end(run_t *r)
{
    mms_stop(&r->mms);
    if (r->mms.message[0]) fprintf(stderr, "%s\n", r->mms.message);
}

static void mms_results(run_t *r, json_t *j)
{
    json_t *mj = mms_json(&r->mms);
    json_object_set_new(mj, "wall_contacts", json_integer(world_collisions(r->sim.world))); /* = collisions */
    json_object_set_new(j, "mms", mj);
    hal_sim_attach(NULL);
}

static void mms_headline(const run_t *r)
{
    printf("%s: %ux%u, seed %llu, mms algorithm '%s' (%s walls), score %g\n", r->maze_path, r->maze.width,
           r->maze.height, (unsigned long long)r->o->seed, r->o->mms.command,
           r->o->mms.ideal_walls ? "ideal" : "sensed", (double)mms_stats_score(&r->mms.stats));
}

/* the algorithm's failure is an external one; else: was the goal reached */
static int mms_exit(const run_t *r)
{
    if (mms_failed(&r->mms)) return RUN_EXTERNAL;
    return run_exit_laps(r, "mms_exited", "time_limit");
}

const run_driver_t run_mms = {
    .name = "mms", .open = mms_open, .step = mms_step, .stop = mms_end, .results = mms_results,
    .undo = mms_undo, .headline = mms_headline, .exit_code = mms_exit,
};

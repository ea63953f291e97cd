/* run.c - one contest (see run.h): set up the world and the driver, the
 * contest loop, the results. What differs per driver is in run_driver.h's
 * tables (run_firmware.c, run_scripted.c, run_link.c). */
#include "run_driver.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "hal.h"
#include "maze/mazefile.h"
#include "mouse.h"

static double wall_now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + (double)ts.tv_nsec * 1e-9;
}

static double ms3(double s) { return round(s * 1000.0) / 1000.0; }

int run_load_config(const run_opts_t *o, simcfg_t *c)
{
    char err[400];
    config_defaults(c);
    if (o->config_path && config_load(c, o->config_path, err, sizeof err) != 0) {
        fprintf(stderr, "%s\n", err);
        return -1;
    }
    if (o->robot_path && robot_load(c, o->robot_path, err, sizeof err) != 0) {
        fprintf(stderr, "%s\n", err);
        return -1;
    }
    if (robot_fits(c, err, sizeof err) != 0) {
        fprintf(stderr, "%s: %s\n", o->config_path ? o->config_path : o->robot_path ? o->robot_path : "robots/paper.ini", err);
        return -1;
    }
    if (o->time_limit_s > 0) c->time_limit_s = o->time_limit_s;
    if (o->centre_post >= 0) c->centre_post = o->centre_post;
    if (o->paper_friction) {
        /* the paper's shipped Unity values: static 0.35, dynamic 0.25 */
        c->tyre_mu = 0.35;
        c->tyre_mu_dynamic = 0.25;
    }
    return 0;
}

int run_json_line(json_t *j)
{
    char *s = json_dumps(j, JSON_COMPACT | JSON_ENSURE_ASCII | JSON_REAL_PRECISION(10));
    if (!s) return -1;
    puts(s);
    fflush(stdout);
    free(s);
    return 0;
}

int run_exit_laps(const run_t *r, const char *ok1, const char *ok2)
{
    int ok = !strcmp(r->reason, ok1) || (ok2 && !strcmp(r->reason, ok2));
    return r->sim.race.nlaps > 0 && ok ? RUN_OK : RUN_NOT_REACHED;
}

static const run_driver_t *pick_driver(const run_opts_t *o)
{
    if (o->board) return &run_board;
    if (o->avr_elf) return &run_avr;
    if (o->serial) return &run_serial;
    if (o->scripted) return &run_scripted;
    return o->mms.command ? &run_mms : &run_firmware;
}

static int fail_setup(run_t *r, int rc)
{
    if (r->drv->undo) r->drv->undo(r);
    sim_free(&r->sim);
    return rc;
}

/* Telemetry, the report and the viewer, after the driver: 0 or RUN_EXTERNAL. */
static int open_outputs(run_t *r)
{
    const run_opts_t *o = r->o;
    char err[400];
    telem_opts_t topts = o->telem;
    if (o->serial) topts.link = &r->lnk; /* MM_LINK in HIL/PIL runs */
    topts.maze_path = r->maze_path;      /* MM_MAZE names it */
    if (r->tel_on && telem_open(&r->tel, &topts, &r->sim, err, sizeof err) != 0) {
        fprintf(stderr, "mmsim: %s\n", err);
        return RUN_EXTERNAL;
    }
    r->rep = o->report ? report_new(&r->sim) : NULL;
    r->view = NULL;
    if (!o->gui && !o->shot) return 0;
    view_opts_t vo = o->view;
    if (o->serial) { /* the HUD shows the link's port and baud */
        vo.port = r->lnk.path;
        vo.baud = (long)r->lnk.o.baud;
    }
    snprintf(err, sizeof err, "out of memory");
    r->view = view_new(&vo);
    if (r->view && r->panel) view_set_board(r->view, r->panel, r);
    if (r->view && o->mms.command)
        view_set_mms(r->view, r->mms.color, &r->mms.text[0][0], sizeof r->mms.text[0], &r->mms.was_reset);
    if (!r->view || view_open(r->view, o->gui, err, sizeof err) != 0) {
        fprintf(stderr, "mmsim: %s\n", err);
        view_free(r->view);
        report_free(r->rep);
        return RUN_EXTERNAL;
    }
    return 0;
}

/* --goal X,Y: the laps go to that cell (a firmware whose goal is not the
 * maze's, e.g. mazerunner-core as shipped: (1,0)). 0, or -1 after a line. */
static int set_goal(run_t *r)
{
    const run_opts_t *o = r->o;
    if (o->goal_x < 0) return 0;
    if (o->goal_x >= r->maze.width || o->goal_y >= r->maze.height) {
        fprintf(stderr, "--goal: cell %d,%d is outside the %ux%u maze\n", o->goal_x, o->goal_y, r->maze.width, r->maze.height);
        return -1;
    }
    maze_clear_goals(&r->maze);
    maze_set_goal(&r->maze, maze_cell(&r->maze, (uint8_t)o->goal_x, (uint8_t)o->goal_y), 1);
    return 0;
}

/* The hands' actions due now: occlude and end here, the rest on the board
 * (r->hands). NULL, or why the run ends. */
static const char *hands(run_t *r)
{
    const input_action_t *a;
    input_t *in = &r->input;
    while ((a = input_due(in, sim_time_s(&r->sim))) != NULL) {
        if (a->kind == INPUT_END) return "input_end";
        if (a->kind == INPUT_OCCLUDE) sim_ir_occlude(&r->sim, a->value, INPUT_OCCLUDE_M, INPUT_OCCLUDE_S);
        else if (r->hands) r->hands(r, a);
    }
    return NULL;
}

/* The person's clicks on the HUD's board panel: the same path as --input's
 * actions (r->hands), taking effect before the next step. */
static void gui_hands(run_t *r)
{
    static const input_kind_t kinds[] = { [VIEW_HAND_SWITCHES] = INPUT_SWITCHES, [VIEW_HAND_BUTTON_DOWN] = INPUT_BUTTON_DOWN,
                                          [VIEW_HAND_BUTTON_UP] = INPUT_BUTTON_UP, [VIEW_HAND_RESET] = INPUT_RESET };
    view_hand_t h;
    while (view_hands_request(r->view, &h)) {
        input_action_t a = { sim_time_s(&r->sim), kinds[h.kind], (int)h.switches, "" };
        if (r->hands) r->hands(r, &a);
    }
}

/* The config, the maze, the world, the driver and the outputs: 0 or the exit code. */
static int setup(run_t *r)
{
    char err[MAZEFILE_ERR_LEN];
    if (run_load_config(r->o, &r->cfg) != 0) return RUN_BAD_INPUT;
    if (mazefile_load(&r->maze, r->maze_path, NULL, err, sizeof err) != 0) {
        fprintf(stderr, "%s\n", err);
        return RUN_BAD_INPUT;
    }
    config_hash(&r->cfg, r->hash);
    if (set_goal(r) != 0) return RUN_BAD_INPUT;
    if (sim_init(&r->sim, &r->cfg, &r->maze, r->o->seed) != 0) {
        fprintf(stderr, "%s: cannot set up the ODE world\n", r->maze_path);
        return RUN_EXTERNAL;
    }
    r->drv = pick_driver(r->o);
    r->tel_on = r->o->telem.url || r->o->telem.log_path;
    r->hil = r->o->serial;
    r->reason = "done";
    r->input = r->o->input;
    int orc = r->drv->open(r);
    if (orc != 0) {
        sim_free(&r->sim);
        return orc == RUN_BAD_INPUT ? RUN_BAD_INPUT : RUN_EXTERNAL;
    }
    if (input_needs_board(&r->input) && !r->hands) {
        fprintf(stderr, "--input: switches, button, reset and send act on a board (--board NAME)\n");
        if (r->drv->undo) r->drv->undo(r);
        sim_free(&r->sim);
        return RUN_BAD_INPUT;
    }
    if (open_outputs(r) != 0) return fail_setup(r, RUN_EXTERNAL);
    /* a build with -DHAL_TICK_HZ=250 ticks every 4th step, as on the AVR */
    r->steps_per_tick = lround(1.0 / (HAL_TICK_HZ * r->cfg.step_s));
    if (r->steps_per_tick < 1) r->steps_per_tick = 1;
    r->tick_steps = r->steps_per_tick - 1; /* the first step ticks */
    return 0;
}

/* After the driver's step: the report, the viewer, the contest's limits and
 * the stall check. NULL, or why the run ends now. */
typedef struct {
    double last_x, last_y, progress_s, hard_stop_s;
} watch_t;

static const char *after_step(run_t *r, watch_t *w)
{
    const run_opts_t *o = r->o;
    sim_t *s = &r->sim;
    const char *cport;
    long cbaud;
    if (s->diverged) {
        fprintf(stderr, "%s: the physics diverged at %.6g s (more than ODE integrates in steps of %g s with this config)\n",
                r->maze_path, sim_time_s(s), r->cfg.step_s);
        return "physics_diverged";
    }
    if (r->rep) report_step(r->rep, s);
    if (o->gui && view_step(r->view, s)) return "window_closed";
    if (o->gui && view_connect_request(r->view, &cport, &cbaud)) run_link_connect(r, cport, cbaud);
    if (o->gui && r->panel) gui_hands(r);
    if (o->shot && sim_time_s(s) >= o->shot_at_s) return "screenshot";
    double t = sim_time_s(s), x, y, h;
    if (s->race.over_time && !s->race.in_run) return "time_limit";
    if (t > w->hard_stop_s) return "time_limit";
    if (s->step % 100 == 0 && !r->hil && !o->mms.command && !o->board) { /* a HIL robot or a board may wait for its MCU or a person; mms: the firmware's own stall check */
        world_pose(s->world, &x, &y, &h);
        if (hypot(x - w->last_x, y - w->last_y) > 0.01) {
            w->last_x = x;
            w->last_y = y;
            w->progress_s = t;
        } else if (t - w->progress_s > RUN_STALL_S) {
            s->cmd[0] = s->cmd[1] = 0; /* stuck: motors off, reported */
            return "crash_stop";
        }
    }
    if (o->realtime) {
        double ahead = t - (wall_now() - r->t0);
        if (ahead > 0.002) {
            struct timespec ts = { 0, (long)(ahead * 1e9) };
            nanosleep(&ts, NULL);
        }
    }
    return NULL;
}

/* The contest loop: a physics step with the driver (or the link, once an
 * MCU drives), then the common checks, until one of them ends the run. */
static void contest_loop(run_t *r)
{
    watch_t w = { 0, 0, 0, r->cfg.time_limit_s + 60.0 }; /* a lap under way may finish over time, flagged */
    double h;
    r->t0 = wall_now();
    world_pose(r->sim.world, &w.last_x, &w.last_y, &h);
    for (;;) {
        const char *why = hands(r);
        if (!why) why = r->hil ? run_link_step(r) : r->drv->step(r);
        if (!why) why = after_step(r, &w);
        if (why) {
            r->reason = why;
            break;
        }
    }
}

/* Telemetry and viewer closed: 0, or RUN_EXTERNAL after an error line. */
static int close_outputs(run_t *r)
{
    char err[600];
    int rc = 0;
    if (r->tel_on) {
        telem_finish(&r->tel, &r->sim);
        if (telem_close(&r->tel, err, sizeof err) != 0) {
            fprintf(stderr, "mmsim: %s\n", err);
            rc = RUN_EXTERNAL;
        }
    }
    if (r->view) {
        if (r->o->shot && view_screenshot(r->view, &r->sim, r->o->shot, err, sizeof err) != 0) {
            fprintf(stderr, "mmsim: %s\n", err);
            rc = RUN_EXTERNAL;
        }
        if (r->o->gui) view_hold(r->view, &r->sim);
        view_free(r->view);
    }
    return rc;
}

/* The result object up to "config_hash" (keys in this order). */
static json_t *results_json(const run_t *r, double wall)
{
    const race_t *rc = &r->sim.race;
    double t = sim_time_s(&r->sim), x, y, h;
    world_pose(r->sim.world, &x, &y, &h);
    json_t *laps = json_array();
    for (int i = 0; i < rc->nlaps; i++)
        json_array_append_new(laps, json_pack("{s:i, s:f, s:f, s:f}", "lap", i + 1, "start_s", ms3(rc->laps[i].start_s),
                                              "end_s", ms3(rc->laps[i].end_s),
                                              "run_s", ms3(rc->laps[i].end_s - rc->laps[i].start_s)));
    json_t *j = json_pack("{s:s, s:I, s:f, s:f, s:f, s:o}", "maze", r->maze_path, "seed", (json_int_t)r->o->seed,
                          "sim_time_s", ms3(t), "wall_time_s", ms3(wall), "real_time_factor",
                          wall > 0 ? round(t / wall * 10) / 10 : 0.0, "laps", laps);
    json_object_set_new(j, "first_run_s",
                        rc->nlaps ? json_real(ms3(rc->laps[0].end_s - rc->laps[0].start_s)) : json_null());
    json_object_set_new(j, "best_run_s",
                        rc->best >= 0 ? json_real(ms3(rc->laps[rc->best].end_s - rc->laps[rc->best].start_s)) : json_null());
    json_object_set_new(j, "reached_goal", json_boolean(rc->nlaps > 0));
    json_object_set_new(j, "collisions", json_integer(world_collisions(r->sim.world)));
    json_object_set_new(j, "final_pose", json_pack("{s:f, s:f, s:f}", "x_m", round(x * 1e6) / 1e6, "y_m",
                                                   round(y * 1e6) / 1e6, "heading_rad", round(h * 1e6) / 1e6));
    json_object_set_new(j, "exit_reason", json_string(r->reason));
    json_object_set_new(j, "config_hash", json_string(r->hash));
    if (r->o->robot_path) {
        /* by kind: front and side contacts are errors; a rear touch below 0.1 m/s is not */
        const world_t *w = r->sim.world;
        json_object_set_new(j, "robot", json_string(r->o->robot_path));
        json_object_set_new(j, "contacts", json_pack("{s:i, s:i, s:i, s:i}", "front", world_contacts(w, WORLD_CONTACT_FRONT),
                                                     "side", world_contacts(w, WORLD_CONTACT_SIDE), "rear_soft",
                                                     world_contacts(w, WORLD_CONTACT_REAR_SOFT), "rear",
                                                     world_contacts(w, WORLD_CONTACT_REAR)));
    }
    return j;
}

/* The report's three files: 0, or RUN_EXTERNAL after an error line. */
static int write_report(run_t *r)
{
    char title[300], err[600];
    int rc = 0;
    if (!r->rep) return 0;
    snprintf(title, sizeof title, "%s  %ux%u  seed %llu  %s driver  exit: %s", r->maze_path, r->maze.width,
             r->maze.height, (unsigned long long)r->o->seed, r->drv->name, r->reason);
    if (r->drv == &run_mms) report_set_cells(r->rep, r->mms.color, &r->mms.text[0][0], sizeof r->mms.text[0]);
    /* only what the run has: an MCU over the link keeps its map to itself (no belief, no final path); the
     * scripted driver has no map and drives the true best path */
    const maze_t *belief = r->drv == &run_firmware || r->drv == &run_mms ? mouse_map() : NULL;
    const maze_t *path_on = belief ? belief : r->drv == &run_scripted ? &r->maze : NULL;
    if (report_write(r->rep, &r->sim, belief, path_on, r->o->report, title, err, sizeof err) != 0) {
        fprintf(stderr, "%s\n", err);
        rc = RUN_EXTERNAL;
    }
    report_free(r->rep);
    return rc;
}

static void print_summary(const run_t *r, double wall)
{
    double t = sim_time_s(&r->sim);
    r->drv->headline(r);
    race_print_table(&r->sim.race, stdout);
    printf("sim time %.3f s, wall time %.3f s (%.0fx real time), collisions %u, exit: %s\n", t, wall,
           wall > 0 ? t / wall : 0.0, world_collisions(r->sim.world), r->reason);
}

int run_one(const run_opts_t *o, const char *maze_path, json_t **out, int print_text)
{
    static run_t run;
    run_t *r = &run;
    memset(r, 0, sizeof *r);
    r->o = o;
    r->maze_path = maze_path;
    *out = NULL;
    int rc = setup(r);
    if (rc) return rc;
    contest_loop(r);
    if (r->drv->stop) r->drv->stop(r);
    int out_rc = close_outputs(r);
    double wall = wall_now() - r->t0;
    json_t *j = results_json(r, wall);
    json_object_set_new(j, "driver", json_string(r->drv->name));
    if (r->drv->results) r->drv->results(r, j);
    if (r->hil) run_link_results(r, j);
    if (write_report(r)) out_rc = RUN_EXTERNAL;
    if (print_text) print_summary(r, wall);
    sim_free(&r->sim);
    *out = j;
    if (out_rc) return out_rc;
    if (o->shot) return RUN_OK; /* the picture was the point */
    if (!strcmp(r->reason, "avr_stopped")) return RUN_EXTERNAL;
    if (!strcmp(r->reason, "board_unsupported")) return RUN_BAD_INPUT;
    return r->drv->exit_code ? r->drv->exit_code(r) : run_exit_laps(r, "done", "mcu_stopped");
}

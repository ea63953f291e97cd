/* run.c - one contest (see run.h): set up the world and the driver, the
 * contest loop (one step, then every observer: run_driver.h), the results.
 * What differs per driver is in run_driver.h's tables (run_firmware.c,
 * run_scripted.c, run_link.c, run_board.c). */
#include "run_driver.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "contest/contest.h"
#include "hal.h"
#include "maze/mazefile.h"

static double wall_now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + (double)ts.tv_nsec * 1e-9;
}

static double ms3(double s) { return round(s * 1000.0) / 1000.0; }

int run_load_config(const run_opts_t *o, simcfg_t *c)
{
    char err[2048]; /* INIFILE_ERR_MAX: an unknown key's line lists the section's every key */
    config_defaults(c);
    if (o->config_text ? config_load_string(c, o->config_text, "<stdin>", err, sizeof err) != 0
                       : o->config_path && config_load(c, o->config_path, err, sizeof err) != 0) {
        fprintf(stderr, "%s\n", err);
        return -1;
    }
    if (o->robot_path && robot_load(c, o->robot_path, err, sizeof err) != 0) {
        fprintf(stderr, "%s\n", err);
        return -1;
    }
    if (o->contest) contest_apply_config(o->contest, c); /* the contest's maze and time limit */
    if (robot_fits(c, err, sizeof err) != 0) {
        fprintf(stderr, "%s: %s\n", o->config_path ? o->config_path : o->robot_path ? o->robot_path : "robots/paper.ini", err);
        return -1;
    }
    if (o->time_limit_s > 0) c->sim.time_limit_s = o->time_limit_s;
    if (o->centre_post >= 0) c->world.centre_post = o->centre_post;
    if (o->paper_friction) {
        /* the paper's shipped Unity values: static 0.35, dynamic 0.25 */
        c->robot.tyre_mu = 0.35;
        c->robot.tyre_mu_dynamic = 0.25;
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

static const run_driver_t *pick_driver(const run_opts_t *o)
{
    if (o->arm_elf) return &run_armboard;
    if (o->board) return &run_board;
    if (o->avr_elf) return &run_avr;
    if (o->serial) return &run_serial;
    if (o->scripted) return &run_scripted;
    return o->mms.command ? &run_mms : &run_firmware;
}

static int fail_setup(run_t *r, int rc)
{
    if (r->drv->close) r->drv->close(r, r->self);
    sim_free(&r->sim);
    return rc;
}

/* The firmware's belief the observers are handed: the one of the driver
 * the run began with (after the HUD's Connect the firmware no longer runs
 * and its last belief stays shown), NULL if that driver has none. */
static const sim_belief_t *run_belief(const run_t *r)
{
    return r->drv->belief ? r->drv->belief(r->self) : NULL;
}

/* Telemetry, the report and the viewer, after the driver: 0 or RUN_EXTERNAL. */
static int open_outputs(run_t *r)
{
    const run_opts_t *o = r->o;
    char err[400];
    const link_t *lnk = r->drv->link ? r->drv->link(r->self) : NULL;
    telem_opts_t topts = o->telem;
    topts.link = lnk;               /* MM_LINK in HIL/PIL runs */
    topts.maze_path = r->maze_path; /* MM_MAZE names it */
    if (r->tel_on && telem_open(&r->tel, &topts, &r->sim, err, sizeof err) != 0) {
        fprintf(stderr, "mmsim: %s\n", err);
        return RUN_EXTERNAL;
    }
    r->rep = o->report ? report_new(&r->sim) : NULL;
    r->view = NULL;
    if (!o->gui && !o->shot) return 0;
    view_opts_t vo = o->view;
    if (lnk) { /* the HUD shows the link's port and baud */
        vo.port = lnk->path;
        vo.baud = (long)lnk->o.baud;
    }
    snprintf(err, sizeof err, "out of memory");
    r->view = view_new(&vo);
    if (r->view) view_set_belief(r->view, run_belief(r)); /* the overlay reads it each frame */
    /* Connect hands the run to a serial MCU: only where the mouse is the
     * simulator's own (firmware, mms, scripted), not a board's image nor a link */
    if (r->view) view_set_link_ok(r->view, lnk == NULL && !o->board);
    if (r->view && r->drv->show) r->drv->show(r, r->self, r->view);
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
    truemaze_clear_goals(&r->maze);
    truemaze_set_goal(&r->maze, truemaze_cell(&r->maze, (uint8_t)o->goal_x, (uint8_t)o->goal_y), 1);
    return 0;
}

/* The hands' actions due now: occlude, push, lift, place and end here (on
 * the world, any driver), the rest on the board
 * (the driver's hands). NULL, or why the run ends. */
static const char *hands(run_t *r)
{
    const input_action_t *a;
    input_t *in = &r->input;
    while ((a = input_due(in, sim_time_s(&r->sim))) != NULL) {
        if (a->kind == INPUT_END) return "input_end";
        if (a->kind == INPUT_OCCLUDE) sim_occlude(&r->sim, a->value, INPUT_OCCLUDE_M, INPUT_OCCLUDE_S);
        else if (a->kind == INPUT_PUSH) sim_push(&r->sim, a->push[0] / 1000.0, a->push[1] * M_PI / 180.0, a->push[2]);
        else if (a->kind == INPUT_LIFT) sim_lift(&r->sim);
        else if (a->kind == INPUT_PLACE) sim_place(&r->sim);
        else if (r->drv->hands) r->drv->hands(r, r->self, a);
    }
    return NULL;
}

/* The person's clicks on the HUD's board panel: the same path as --input's
 * actions (the driver's hands), taking effect before the next step. */
static void gui_hands(run_t *r)
{
    static const input_kind_t kinds[] = { [VIEW_HAND_SWITCHES] = INPUT_SWITCHES, [VIEW_HAND_BUTTON_DOWN] = INPUT_BUTTON_DOWN,
                                          [VIEW_HAND_BUTTON_UP] = INPUT_BUTTON_UP, [VIEW_HAND_RESET] = INPUT_RESET };
    view_hand_t h;
    while (view_hands_request(r->view, &h)) {
        input_action_t a;
        memset(&a, 0, sizeof a);
        a.t_s = sim_time_s(&r->sim);
        a.kind = kinds[h.kind];
        a.value = (int)h.switches;
        r->drv->hands(r, r->self, &a);
    }
}

/* Each occlude's sensor found in the robot (its part index into the
 * action's value): 0, or -1 after one line naming the input and the
 * sensors there are. The parser has no robot, so this waits for the model. */
static int resolve_occlusions(run_t *r)
{
    for (int i = 0; i < r->input.n; i++) {
        input_action_t *a = &r->input.a[i];
        if (a->kind != INPUT_OCCLUDE) continue;
        a->value = sim_occlude_find(&r->sim, a->text);
        if (a->value >= 0) continue;
        char names[200];
        sim_occlude_names(&r->sim, names, sizeof names);
        fprintf(stderr, "--input:%d:%d: occlude=%s: the robot has no IR or ToF sensor of that name (its sensors: %s)\n", a->spec,
                a->col, a->text, names);
        return -1;
    }
    return 0;
}

/* The config, the maze, the world, the driver and the outputs: 0 or the exit code. */
static int setup(run_t *r)
{
    char err[MAZEFILE_ERR_LEN];
    mazefile_info_t info;
    if (run_load_config(r->o, &r->cfg) != 0) return RUN_BAD_INPUT;
    /* The in-process firmware (the firmware and mms drivers) ticks at
     * HAL_TICK_HZ and at most once a step: a longer [sim] step_s is cut to
     * the tick for them; the scripted driver and the linked MCUs (their own
     * clocks) take the config's step. */
    const run_driver_t *d = pick_driver(r->o);
    if ((d == &run_firmware || d == &run_mms) && r->cfg.sim.step_s > 1.0 / HAL_TICK_HZ) r->cfg.sim.step_s = 1.0 / HAL_TICK_HZ;
    if (mazefile_load(&r->maze, r->maze_path, &info, err, sizeof err) != 0 ||
        (r->o->contest && contest_apply_maze(r->o->contest, &r->maze, &info, r->maze_path, err, sizeof err) != 0)) {
        fprintf(stderr, "%s\n", err);
        return RUN_BAD_INPUT;
    }
    config_hash(&r->cfg, r->hash);
    if (set_goal(r) != 0) return RUN_BAD_INPUT;
    sim_model_build(&r->model, &r->cfg, r->o->seed); /* once; const from here on */
    if (sim_init(&r->sim, &r->model, &r->maze, r->o->seed) != 0) {
        fprintf(stderr, "%s: cannot set up the ODE world\n", r->maze_path);
        return RUN_EXTERNAL;
    }
    r->drv = pick_driver(r->o);
    r->tel_on = r->o->telem.url || r->o->telem.log_path;
    r->reason = "done";
    r->input = r->o->input;
    if (resolve_occlusions(r) != 0) {
        sim_free(&r->sim);
        return RUN_BAD_INPUT;
    }
    int orc = r->drv->open(r, &r->self);
    if (orc != 0) {
        sim_free(&r->sim);
        return orc == RUN_BAD_INPUT ? RUN_BAD_INPUT : RUN_EXTERNAL;
    }
    r->ctl = r->drv;
    r->ctl_self = r->self;
    if (input_needs_board(&r->input) && !r->drv->hands) {
        fprintf(stderr, "--input: switches, button, reset and send act on a board (--board NAME)\n");
        return fail_setup(r, RUN_BAD_INPUT);
    }
    if (open_outputs(r) != 0) return fail_setup(r, RUN_EXTERNAL);
    return 0;
}

/* The HUD's Connect: the serial link takes the steps from now on (the
 * driver the run began with keeps its state for its results). */
static void hand_to_link(run_t *r, const char *port, long baud)
{
    char err[400];
    void *self;
    if (r->ctl->link) {
        view_set_status(r->view, "already connected: one link per run");
        return;
    }
    if (run_link_connect(r, port, baud, &self, err, sizeof err) != 0) {
        view_set_status(r->view, err);
        return;
    }
    r->ctl = &run_serial;
    r->ctl_self = self;
    r->sim.cmd[0] = r->sim.cmd[1] = 0;
    if (r->tel_on) r->tel.link = run_serial.link(self); /* MM_LINK from now on */
    view_set_link_ok(r->view, 0);
    view_set_status(r->view, "connected: the MCU drives from now on");
}

/* After the step and the driver: the report, the viewer, the contest's
 * limits and the stall check. NULL, or why the run ends now. */
typedef struct {
    double last_x, last_y, progress_s;
} watch_t;

int run_time_up(const run_t *r, double overtime_s)
{
    const race_t *race = &r->sim.race;
    double t = sim_time_s(&r->sim), limit = r->cfg.sim.time_limit_s;
    if (!race->started) return t >= limit;
    double clock = race_global_s(race, t);
    return (clock > limit && !race->in_run) || clock > limit + overtime_s;
}

static const char *after_step(run_t *r, watch_t *w)
{
    const run_opts_t *o = r->o;
    sim_state_t *s = &r->sim;
    const char *cport;
    long cbaud;
    if (s->diverged) {
        fprintf(stderr, "%s: the physics diverged at %.6g s (more than ODE integrates in steps of %g s with this config)\n",
                r->maze_path, sim_time_s(s), r->cfg.sim.step_s);
        return "physics_diverged";
    }
    if (r->rep) report_step(r->rep, s);
    if (o->gui && view_step(r->view, s)) return "window_closed";
    if (o->gui && view_connect_request(r->view, &cport, &cbaud)) hand_to_link(r, cport, cbaud);
    if (o->gui && r->drv->hands) gui_hands(r);
    /* the time limit before the screenshot: a picture never changes how a run ends */
    if (run_time_up(r, r->ctl->overtime ? RUN_OVERTIME_S : 0)) return "time_limit";
    if (o->shot && sim_time_s(s) >= o->shot_at_s) return "screenshot";
    double t = sim_time_s(s), x, y, h;
    if (s->step % 100 == 0 && r->ctl->watch_stall) {
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

/* One step: the driver's control, the physics, the telemetry between the
 * driver's hooks (run_driver.h), then the other observers and the checks.
 * NULL, or why the run ends. */
static const char *step(run_t *r, watch_t *w)
{
    const run_driver_t *d = r->ctl;
    const char *why = d->before ? d->before(r, r->ctl_self) : NULL;
    if (why) return why;
    sim_step(&r->model, &r->sim);
    if (d->exchange) d->exchange(r, r->ctl_self);
    if (r->tel_on) telem_step(&r->tel, &r->sim, run_belief(r));
    why = d->after ? d->after(r, r->ctl_self) : NULL;
    return why ? why : after_step(r, w);
}

/* The contest loop: the hands, then a step, until something ends the run. */
static void contest_loop(run_t *r)
{
    watch_t w = { 0, 0, 0 };
    double h;
    r->t0 = wall_now();
    world_pose(r->sim.world, &w.last_x, &w.last_y, &h);
    for (;;) {
        const char *why = hands(r);
        if (!why) why = step(r, &w);
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
        telem_finish(&r->tel, &r->sim, run_belief(r));
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

/* --contest: the contest's name, rule, runs and score (contest.h); the
 * touches are the hands' lifts done (--input lift). */
static json_t *run_contest_json(const run_t *r)
{
    double lifts[INPUT_MAX];
    int n = 0;
    for (int i = 0; i < r->input.next && i < r->input.n; i++)
        if (r->input.a[i].kind == INPUT_LIFT) lifts[n++] = r->input.a[i].t_s;
    return contest_json(r->o->contest, &r->sim.race, lifts, n);
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
    if (r->o->contest) json_object_set_new(j, "contest", run_contest_json(r));
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
    const maze_t *belief = NULL; /* only what the run's driver has */
    const truemaze_t *path_on = NULL;
    if (r->drv->report) r->drv->report(r, r->self, r->rep, &belief, &path_on);
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
    r->drv->headline(r, r->self);
    race_print_table(&r->sim.race, stdout);
    printf("sim time %.3f s, wall time %.3f s (%.0fx real time), collisions %u, exit: %s\n", t, wall,
           wall > 0 ? t / wall : 0.0, world_collisions(r->sim.world), r->reason);
    if (r->o->contest) {
        json_t *c = run_contest_json(r);
        json_t *score = json_object_get(c, "score_s"), *lap = json_object_get(c, "score_lap");
        if (json_is_real(score))
            printf("contest %s (%s): score %.3f s (lap %d)\n", r->o->contest->name, json_string_value(json_object_get(c, "scoring")),
                   json_real_value(score), (int)json_integer_value(lap));
        else
            printf("contest %s (%s): no score (no run counts)\n", r->o->contest->name, json_string_value(json_object_get(c, "scoring")));
        json_decref(c);
    }
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
    if (r->drv->stop) r->drv->stop(r, r->self);
    int out_rc = close_outputs(r);
    double wall = wall_now() - r->t0;
    json_t *j = results_json(r, wall);
    json_object_set_new(j, "driver", json_string(r->drv->name));
    if (r->drv->results) r->drv->results(r, r->self, j);
    if (r->ctl != r->drv) r->ctl->results(r, r->ctl_self, j); /* the link the HUD's Connect opened */
    if (write_report(r)) out_rc = RUN_EXTERNAL;
    if (print_text) print_summary(r, wall);
    int code = r->drv->exit_code ? r->drv->exit_code(r, r->self) : run_exit_laps(r, "done", "mcu_stopped");
    if (r->ctl != r->drv) r->ctl->close(r, r->ctl_self);
    if (r->drv->close) r->drv->close(r, r->self);
    sim_free(&r->sim);
    *out = j;
    if (out_rc) return out_rc;
    return o->shot ? RUN_OK : code; /* with a screenshot, the picture was the point */
}

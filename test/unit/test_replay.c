/* test_replay.c - a log written by sim/telem replayed by sim/replay
 * without a simulation: at a logged time the replay's snapshot (snap.h)
 * has the live run's pose, wheel angles (to an encoder count), ToF rays,
 * emitter groups (MM_PARTS), contest timers and belief, and the replay's
 * model the live run's; rays cast against the maze's geometry
 * (snap_maze_ray) meet the walls and posts where the ODE world's rays do;
 * the index search; the viewer's time slider, seek keys, play/pause and
 * centre post on a replay (no window); and the load errors (missing, not
 * a log, truncated, no MM_MAZE). */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <cmocka.h>

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <lcm/eventlog.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "world/config.h"
#include "contest/driver.h"
#include "hal.h"
#include "hal_sim.h"
#include "view/hud.h"
#include "maze/mazegen.h"
#include "maze/truebelief.h"
#include "view/replay.h"
#include "view/snap.h"
#include "telemetry/telem.h"
#include "view/view.h"

#define CHECK_AT 3 /* live states kept, at CHECK_S[i] */
static const double CHECK_S[CHECK_AT] = { 0.5, 1.52, 2.5 };
static struct {
    snap_t snap; /* as the live viewer draws it */
    char g[16], l[16];
    int over, has_belief;
    uint16_t cell;
    uint8_t walls[MAZE_MAX_CELLS];
} live[CHECK_AT];

static truemaze_t maze; /* the truth */
static maze_t bmap;      /* the belief the run reports */
static double live_wheel_r_m[2]; /* the live run's model's */
static char log_path[64];
static double end_s;

/* A scripted 3.2 s run on a 5x5 maze, logged; a belief reported at 1.0 s;
 * emitter group 1 lit from 1.5 s to 2.5 s. */
static int setup(void **state)
{
    (void)state;
    static sim_state_t sim;
    static driver_t drv;
    static telem_t tel;
    static simcfg_t cfg; /* the sim's model reads it */
    char err[300];
    config_defaults(&cfg);
    if (mazegen_generate(&maze, 5, 5, 7) != 0) return -1;
    static sim_model_t sim_model;
    sim_model_build(&sim_model, &cfg, 3);
    if (sim_init(&sim, &sim_model, &maze, 3) != 0) return -1;
    hal_sim_attach(&sim);
    driver_init(&drv, &maze, sim.model, 1);
    snprintf(log_path, sizeof log_path, "/tmp/test_replay_%d.lcmlog", (int)getpid());
    telem_opts_t o = { NULL, log_path, 0, NULL, "gen.txt" };
    if (telem_open(&tel, &o, &sim, err, sizeof err) != 0) return -1;
    static maze_t seen_all;
    truemaze_to_belief(&maze, &seen_all);
    maze_forget(&bmap, &seen_all); /* size, start and goal of the truth, no walls known */
    maze_set_wall(&bmap, 0, MAZE_EAST, MAZE_WALL_CLOSED);
    int k = 0;
    while (sim_time_s(&sim) < 3.2 - 1e-9) {
        driver_update(&drv, &sim);
        sim_emitter_set(&sim, 1, sim.step >= 1500 && sim.step < 2500);
        sim_step(sim.model, &sim);
        telem_step(&tel, &sim, hal_sim_belief());
        if (sim.step == 1000) hal_belief(&bmap, 1, MAZE_NORTH, 0); /* as fw_loop would */
        if (k < CHECK_AT && sim.step == (uint64_t)llround(CHECK_S[k] * 1000)) {
            snap_from_sim(&live[k].snap, &sim);
            hud_timers(&live[k].snap, live[k].g, live[k].l, &live[k].over);
            live[k].has_belief = hal_sim_belief()->seq != 0;
            live[k].cell = hal_sim_belief()->cell;
            memcpy(live[k].walls, hal_sim_belief()->map.cell, truemaze_cells(&maze));
            k++;
        }
    }
    telem_finish(&tel, &sim, hal_sim_belief());
    end_s = sim_time_s(&sim);
    for (int i = 0; i < 2; i++) live_wheel_r_m[i] = sim.model->wheel_r_m[i];
    int rc = telem_close(&tel, err, sizeof err);
    hal_sim_attach(NULL);
    sim_free(&sim);
    return rc;
}

static int teardown(void **state)
{
    (void)state;
    unlink(log_path);
    return 0;
}

static double wrap(double a) { return atan2(sin(a), cos(a)); }

/* A replayed sensor over the floor within 1 mm of the live one, looking
 * within 0.01 rad of its way: the replay draws the robot level on the
 * floor, the live body pitches a little as it drives. */
#define SENSOR_AT_M 1e-3
#define SENSOR_TURN_RAD 0.01

static void test_state_at_logged_times(void **state)
{
    (void)state;
    static replay_t r;
    static snap_t s;
    char err[600];
    assert_int_equal(replay_load(&r, log_path, err, sizeof err), 0);
    assert_true(fabs(replay_end_s(&r) - end_s) < 1e-9);
    assert_string_equal(r.path, "gen.txt");
    assert_memory_equal(r.maze.cell, maze.cell, truemaze_cells(&maze));
    for (int i = 0; i < 2; i++) assert_true(r.model.wheel_r_m[i] == live_wheel_r_m[i]); /* the same seed's model */
    double count_rad = 2 * M_PI / (r.model.cfg->robot.drive[0].encoder_ppr * r.model.cfg->robot.drive[0].gear_ratio);
    assert_true(!live[0].snap.emitter[1] && live[1].snap.emitter[1]); /* the check times see both */
    for (int k = 0; k < CHECK_AT; k++) {
        const snap_t *lv = &live[k].snap;
        replay_snap(&r, CHECK_S[k], &s);
        assert_true(fabs(s.x_m - lv->x_m) < 1e-9 && fabs(s.y_m - lv->y_m) < 1e-9 && fabs(wrap(s.heading_rad - lv->heading_rad)) < 1e-9);
        for (int i = 0; i < 2; i++) { /* an encoder count's resolution */
            assert_true(fabs(wrap(s.wheel_rad[i] - lv->wheel_rad[i])) <= count_rad * 1.01);
            assert_true(s.wheel_hub_z_m[i] == lv->wheel_hub_z_m[i]);
        }
        assert_int_equal(s.ntof, lv->ntof);
        assert_true(s.ntof == 3 && s.tof_range_m == lv->tof_range_m);
        for (int i = 0; i < s.ntof; i++) { /* where it sits over the floor and where it looks */
            const snap_ray_t *a = &s.tof[i], *b = &lv->tof[i];
            double off = hypot(a->pos_m[0] - b->pos_m[0], a->pos_m[1] - b->pos_m[1]);
            double turn = wrap(atan2(a->axis[1], a->axis[0]) - atan2(b->axis[1], b->axis[0]));
            assert_true(a->hit_m == b->hit_m);
            if (off > SENSOR_AT_M || fabs(turn) > SENSOR_TURN_RAD)
                fail_msg("ToF %d at %.2f s: replayed %.3f mm from the live sensor, turned %.4f rad", i, CHECK_S[k], off * 1e3, turn);
        }
        for (int g = 0; g < SIM_EMITTER_GROUPS; g++) assert_int_equal(s.emitter[g], lv->emitter[g]);
        assert_int_equal(s.centre_post, lv->centre_post);
        assert_true(fabs(s.time_s - CHECK_S[k]) < 1e-9);
        char g[16], l[16];
        int over;
        hud_timers(&s, g, l, &over);
        assert_string_equal(g, live[k].g);
        assert_string_equal(l, live[k].l);
        assert_int_equal(over, live[k].over);
        scene_belief_t b;
        replay_belief(&r, CHECK_S[k], &b);
        assert_int_equal(b.map != NULL, live[k].has_belief);
        if (b.map) {
            assert_int_equal(b.cell, live[k].cell);
            assert_memory_equal(b.map->cell, live[k].walls, truemaze_cells(&maze));
            assert_true(maze_is_goal(b.map, maze.start) == truemaze_is_goal(&maze, maze.start));
        }
    }
    replay_free(&r);
}

/* Rays from points spread over a 6x6 maze at several heights (one above
 * the walls), in 32 directions level and tilted up and down, with and
 * without the centre post: snap_maze_ray meets the first wall or post
 * where the ODE world's ray does, or misses as it does. */
static void test_maze_ray_as_ode(void **state)
{
    (void)state;
    static simcfg_t c;
    static truemaze_t m;
    static sim_state_t s;
    config_defaults(&c);
    assert_int_equal(mazegen_generate(&m, 6, 6, 11), 0);
    static sim_model_t s_model;
    sim_model_build(&s_model, &c, 1);
    assert_int_equal(sim_init(&s, &s_model, &m, 1), 0);
    static const double z_m[] = { 0.002, 0.02, 0.049, 0.06 }, pitch_deg[] = { 0, 8, -8, -60, 45 };
    int hits = 0, misses = 0;
    for (int post = 1; post >= 0; post--) {
        world_set_centre_post(s.world, post);
        for (int px = 0; px < 12; px++)
            for (int py = 0; py < 12; py++)
                for (size_t iz = 0; iz < sizeof z_m / sizeof *z_m; iz++)
                    for (int a = 0; a < 32; a++)
                        for (size_t ip = 0; ip < sizeof pitch_deg / sizeof *pitch_deg; ip++) {
                            double yaw = a * M_PI / 16 + 0.01, p = pitch_deg[ip] * M_PI / 180, n[3];
                            double pos[3] = { (px * 0.5 + 0.25) * c.world.cell_m, (py * 0.5 + 0.25) * c.world.cell_m, z_m[iz] };
                            double dir[3] = { cos(p) * cos(yaw), cos(p) * sin(yaw), sin(p) };
                            double ode = world_ray_normal(s.world, pos, dir, 0.5, n);
                            double geo = snap_maze_ray(&c, &m, post, pos, dir, 0.5);
                            if (!(fabs(ode - geo) < 1e-9))
                                fail_msg("ray from (%.4f, %.4f, %.4f) yaw %.3f pitch %.0f: ODE %.6f, maze %.6f", pos[0],
                                         pos[1], pos[2], yaw, pitch_deg[ip], ode, geo);
                            if (geo >= 0) hits++;
                            else misses++;
                        }
    }
    assert_true(hits > 10000 && misses > 1000); /* both kinds tried */
    sim_free(&s);
}

static void test_index(void **state)
{
    (void)state;
    int64_t t[5] = { 0, 10, 10, 20, 30 };
    assert_int_equal(replay_index(t, sizeof *t, 5, -1), -1);
    assert_int_equal(replay_index(t, sizeof *t, 5, 0), 0);
    assert_int_equal(replay_index(t, sizeof *t, 5, 10), 2);
    assert_int_equal(replay_index(t, sizeof *t, 5, 19), 2);
    assert_int_equal(replay_index(t, sizeof *t, 5, 30), 4);
    assert_int_equal(replay_index(t, sizeof *t, 5, 99), 4);
    assert_int_equal(replay_index(t, sizeof *t, 0, 5), -1);
}

static void test_slider_and_keys(void **state)
{
    (void)state;
    static replay_t r;
    static snap_t s;
    char err[600];
    assert_int_equal(replay_load(&r, log_path, err, sizeof err), 0);
    const view_opts_t o = { 800, 600, 1, 1, "", 115200 };
    view_t *v = view_new(&o);
    assert_non_null(v);
    view_set_replay(v, &r);
    assert_true(view_time(v) == 0);
    assert_false(view_paused(v));
    /* a click at a quarter of the slider seeks there; a drag follows the mouse */
    hud_button_t sl;
    hud_slider(o.width, o.height, &sl);
    assert_int_equal(view_click(v, NULL, sl.x + sl.w * 0.25, sl.y + sl.h / 2.0), VIEW_SLIDER);
    assert_true(fabs(view_time(v) - 0.25 * end_s) < 1e-6);
    replay_snap(&r, view_time(v), &s);
    assert_true(fabs(s.time_s - 0.25 * end_s) < r.model.cfg->sim.step_s);
    view_drag(v, sl.x + sl.w * 0.5, sl.y + sl.h / 2.0);
    assert_true(fabs(view_time(v) - 0.5 * end_s) < 1e-6);
    view_drag(v, sl.x - 100.0, sl.y + sl.h / 2.0); /* past the left end: the start */
    assert_true(view_time(v) == 0);
    view_release(v);
    view_drag(v, sl.x + sl.w * 0.9, sl.y + sl.h / 2.0); /* no longer dragging */
    assert_true(view_time(v) == 0);
    /* keys: a second forward and back, one logged pose (10 ms) forward and back, the ends */
    view_key(v, NULL, GLFW_KEY_RIGHT);
    assert_true(fabs(view_time(v) - 1.0) < 1e-9);
    view_key(v, NULL, GLFW_KEY_S);
    assert_true(view_paused(v));
    assert_true(fabs(view_time(v) - 1.01) < 1e-9);
    view_key(v, NULL, GLFW_KEY_COMMA);
    view_key(v, NULL, GLFW_KEY_COMMA);
    assert_true(fabs(view_time(v) - 0.99) < 1e-9);
    view_key(v, NULL, GLFW_KEY_LEFT);
    view_key(v, NULL, GLFW_KEY_LEFT);
    assert_true(view_time(v) == 0);
    view_key(v, NULL, GLFW_KEY_END);
    assert_true(fabs(view_time(v) - end_s) < 1e-9);
    replay_snap(&r, view_time(v), &s);
    assert_true(fabs(s.x_m - r.pose[r.npose - 1].x_m) < 1e-9 && fabs(s.y_m - r.pose[r.npose - 1].y_m) < 1e-9);
    /* play at the end starts again from the start */
    view_key(v, NULL, GLFW_KEY_SPACE);
    assert_false(view_paused(v));
    assert_true(view_time(v) == 0);
    /* speed x1..x64 as live */
    for (int i = 0; i < 10; i++) view_key(v, NULL, GLFW_KEY_EQUAL);
    assert_true(view_speed(v) == VIEW_SPEED_MAX);
    /* buttons elsewhere still work; a click off every control does nothing */
    assert_int_equal(view_click(v, NULL, o.width / 2.0, o.height / 3.0), -1);
    /* the centre post shows or not in the replay */
    int post = r.centre_post;
    view_key(v, NULL, GLFW_KEY_P);
    replay_snap(&r, view_time(v), &s);
    assert_int_equal(s.centre_post, !post);
    view_free(v);
    replay_free(&r);
}

static void want_error(const char *path, const char *what)
{
    static replay_t r;
    char err[600] = "";
    assert_int_equal(replay_load(&r, path, err, sizeof err), -1);
    if (!strstr(err, what)) fail_msg("'%s' does not say '%s'", err, what);
    assert_null(strchr(err, '\n'));
    replay_free(&r);
}

static void test_errors(void **state)
{
    (void)state;
    char p[80];
    want_error("/nonexistent/x.lcmlog", "cannot open: No such file or directory");
    snprintf(p, sizeof p, "/tmp/test_replay_%d.junk", (int)getpid());
    FILE *f = fopen(p, "w");
    fputs("not a log at all\n", f);
    fclose(f);
    want_error(p, "not an LCM log");
    /* the log cut short */
    FILE *in = fopen(log_path, "rb");
    fseek(in, 0, SEEK_END);
    long n = ftell(in);
    rewind(in);
    char *buf = malloc((size_t)n);
    assert_int_equal(fread(buf, 1, (size_t)n, in), (size_t)n);
    fclose(in);
    f = fopen(p, "wb");
    fwrite(buf, 1, (size_t)n - 7, f);
    fclose(f);
    free(buf);
    want_error(p, ": truncated: ");
    /* a log without MM_MAZE (as before mmview existed) */
    lcm_eventlog_t *lg = lcm_eventlog_create(p, "w");
    uint8_t data[8] = { 0 };
    lcm_eventlog_event_t ev = { 0, 0, 7, 8, (char *)"MM_TEST", data };
    assert_int_equal(lcm_eventlog_write_event(lg, &ev), 0);
    lcm_eventlog_destroy(lg);
    want_error(p, "no MM_MAZE");
    unlink(p);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_state_at_logged_times),
        cmocka_unit_test(test_maze_ray_as_ode),
        cmocka_unit_test(test_index),
        cmocka_unit_test(test_slider_and_keys),
        cmocka_unit_test(test_errors),
    };
    return cmocka_run_group_tests(tests, setup, teardown);
}

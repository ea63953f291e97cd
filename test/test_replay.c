/* test_replay.c - a log written by sim/telem replayed by sim/replay: at a
 * logged time the stand-in simulation has the live run's pose, wheel
 * angles (to an encoder count), ToF rays, emitter groups (MM_PARTS),
 * contest timers and belief; the
 * index search; the viewer's time slider, seek keys and play/pause on a
 * replay (no window); and the load errors (missing, not a log, truncated,
 * no MM_MAZE). */
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
#include "view/replay.h"
#include "telemetry/telem.h"
#include "view/view.h"

#define CHECK_AT 3 /* live states kept, at CHECK_S[i] */
static const double CHECK_S[CHECK_AT] = { 0.5, 1.52, 2.5 };
static struct {
    double x, y, h, wheel[2], tof[3];
    char g[16], l[16];
    int over, has_belief, emitter[SIM_EMITTER_GROUPS];
    uint16_t cell;
    uint8_t walls[MAZE_MAX_CELLS];
} live[CHECK_AT];

static maze_t maze, bmap;
static char log_path[64];
static double end_s;

/* A scripted 3.2 s run on a 5x5 maze, logged; a belief reported at 1.0 s;
 * emitter group 1 lit from 1.5 s to 2.5 s. */
static int setup(void **state)
{
    (void)state;
    static sim_t sim;
    static driver_t drv;
    static telem_t tel;
    static simcfg_t cfg; /* the sim's model reads it */
    char err[300];
    config_defaults(&cfg);
    if (mazegen_generate(&maze, 5, 5, 7) != 0) return -1;
    if (sim_init(&sim, &cfg, &maze, 3) != 0) return -1;
    hal_sim_attach(&sim);
    driver_init(&drv, &maze, sim.model, 1);
    snprintf(log_path, sizeof log_path, "/tmp/test_replay_%d.lcmlog", (int)getpid());
    telem_opts_t o = { NULL, log_path, 0, NULL, "gen.txt" };
    if (telem_open(&tel, &o, &sim, err, sizeof err) != 0) return -1;
    maze_forget(&bmap, &maze);
    maze_set_wall(&bmap, 0, MAZE_EAST, MAZE_WALL_CLOSED);
    int k = 0;
    while (sim_time_s(&sim) < 3.2 - 1e-9) {
        driver_update(&drv, &sim);
        sim_emitter_set(&sim, 1, sim.step >= 1500 && sim.step < 2500);
        sim_step(&sim);
        telem_step(&tel, &sim);
        if (sim.step == 1000) hal_belief(&bmap, 1, MAZE_NORTH, 0); /* as fw_loop would */
        if (k < CHECK_AT && sim.step == (uint64_t)llround(CHECK_S[k] * 1000)) {
            world_pose(sim.world, &live[k].x, &live[k].y, &live[k].h);
            for (int i = 0; i < 2; i++) live[k].wheel[i] = world_wheel_angle(sim.world, i);
            for (int i = 0; i < 3; i++) live[k].tof[i] = sim.tof_true_m[i];
            for (int g = 0; g < SIM_EMITTER_GROUPS; g++) live[k].emitter[g] = sim_emitter(&sim, (unsigned)g);
            hud_timers(&sim, live[k].g, live[k].l, &live[k].over);
            live[k].has_belief = hal_sim_belief()->seq != 0;
            live[k].cell = hal_sim_belief()->cell;
            memcpy(live[k].walls, hal_sim_belief()->map.cell, maze_cells(&maze));
            k++;
        }
    }
    telem_finish(&tel, &sim);
    end_s = sim_time_s(&sim);
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

static void test_state_at_logged_times(void **state)
{
    (void)state;
    static replay_t r;
    static sim_t s;
    char err[600];
    assert_int_equal(replay_load(&r, log_path, err, sizeof err), 0);
    assert_true(fabs(replay_end_s(&r) - end_s) < 1e-9);
    assert_string_equal(r.path, "gen.txt");
    assert_memory_equal(r.maze.cell, maze.cell, maze_cells(&maze));
    assert_int_equal(replay_sim_init(&r, &s), 0);
    double count_rad = 2 * M_PI / (s.model->cfg->drive[0].encoder_ppr * s.model->cfg->drive[0].gear_ratio);
    assert_true(!live[0].emitter[1] && live[1].emitter[1]); /* the check times see both */
    for (int k = 0; k < CHECK_AT; k++) {
        replay_apply(&r, &s, CHECK_S[k]);
        double x, y, h;
        world_pose(s.world, &x, &y, &h);
        assert_true(fabs(x - live[k].x) < 1e-9 && fabs(y - live[k].y) < 1e-9 && fabs(wrap(h - live[k].h)) < 1e-9);
        for (int i = 0; i < 2; i++) /* an encoder count's resolution */
            assert_true(fabs(wrap(world_wheel_angle(s.world, i) - live[k].wheel[i])) <= count_rad * 1.01);
        for (int i = 0; i < 3; i++) assert_true(s.tof_true_m[i] == live[k].tof[i]);
        for (int g = 0; g < SIM_EMITTER_GROUPS; g++) assert_int_equal(sim_emitter(&s, (unsigned)g), live[k].emitter[g]);
        assert_true(fabs(sim_time_s(&s) - CHECK_S[k]) < 1e-9);
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
            assert_memory_equal(b.map->cell, live[k].walls, maze_cells(&maze));
            assert_true(maze_is_goal(b.map, maze.start) == maze_is_goal(&maze, maze.start));
        }
    }
    sim_free(&s);
    replay_free(&r);
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
    static sim_t s;
    char err[600];
    assert_int_equal(replay_load(&r, log_path, err, sizeof err), 0);
    assert_int_equal(replay_sim_init(&r, &s), 0);
    const view_opts_t o = { 800, 600, 1, 1, "", 115200 };
    view_t *v = view_new(&o);
    assert_non_null(v);
    view_set_replay(v, &r, &s);
    assert_true(view_time(v) == 0);
    assert_false(view_paused(v));
    /* a click at a quarter of the slider seeks there; a drag follows the mouse */
    hud_button_t sl;
    hud_slider(o.width, o.height, &sl);
    assert_int_equal(view_click(v, &s, sl.x + sl.w * 0.25, sl.y + sl.h / 2.0), VIEW_SLIDER);
    assert_true(fabs(view_time(v) - 0.25 * end_s) < 1e-6);
    assert_true(fabs(sim_time_s(&s) - 0.25 * end_s) < s.model->cfg->step_s);
    view_drag(v, sl.x + sl.w * 0.5, sl.y + sl.h / 2.0);
    assert_true(fabs(view_time(v) - 0.5 * end_s) < 1e-6);
    view_drag(v, sl.x - 100.0, sl.y + sl.h / 2.0); /* past the left end: the start */
    assert_true(view_time(v) == 0);
    view_release(v);
    view_drag(v, sl.x + sl.w * 0.9, sl.y + sl.h / 2.0); /* no longer dragging */
    assert_true(view_time(v) == 0);
    /* keys: a second forward and back, one logged pose (10 ms) forward and back, the ends */
    view_key(v, &s, GLFW_KEY_RIGHT);
    assert_true(fabs(view_time(v) - 1.0) < 1e-9);
    view_key(v, &s, GLFW_KEY_S);
    assert_true(view_paused(v));
    assert_true(fabs(view_time(v) - 1.01) < 1e-9);
    view_key(v, &s, GLFW_KEY_COMMA);
    view_key(v, &s, GLFW_KEY_COMMA);
    assert_true(fabs(view_time(v) - 0.99) < 1e-9);
    view_key(v, &s, GLFW_KEY_LEFT);
    view_key(v, &s, GLFW_KEY_LEFT);
    assert_true(view_time(v) == 0);
    view_key(v, &s, GLFW_KEY_END);
    assert_true(fabs(view_time(v) - end_s) < 1e-9);
    double x, y, h;
    world_pose(s.world, &x, &y, &h);
    assert_true(fabs(x - r.pose[r.npose - 1].x_m) < 1e-9 && fabs(y - r.pose[r.npose - 1].y_m) < 1e-9);
    /* play at the end starts again from the start */
    view_key(v, &s, GLFW_KEY_SPACE);
    assert_false(view_paused(v));
    assert_true(view_time(v) == 0);
    /* speed x1..x64 as live */
    for (int i = 0; i < 10; i++) view_key(v, &s, GLFW_KEY_EQUAL);
    assert_true(view_speed(v) == VIEW_SPEED_MAX);
    /* buttons elsewhere still work; a click off every control does nothing */
    assert_int_equal(view_click(v, &s, o.width / 2.0, o.height / 3.0), -1);
    view_free(v);
    sim_free(&s);
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
        cmocka_unit_test(test_index),
        cmocka_unit_test(test_slider_and_keys),
        cmocka_unit_test(test_errors),
    };
    return cmocka_run_group_tests(tests, setup, teardown);
}

/* test_wheels.c - a robot whose wheels differ in diameter sits on both
 * wheels wherever it is put: built at the start, carried back to the start
 * (world_place, as the mms reset does) and replayed from its log (mmview's
 * path: replay_load, replay_snap: each wheel's axle in the snapshot the
 * viewer draws, less the live robot's own wheel radius). The wheels differ
 * through the config's [asymmetry] and through the robot file's left and
 * right diameters. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <cmocka.h>

#include <math.h>
#include <stdio.h>
#include <string.h>
#include <unistd.h>

#include "world/config.h"
#include "maze/mazegen.h"
#include "telemetry/telem.h"
#include "view/replay.h"
#include "view/snap.h"
#include "world/sim.h"

#define SEATED_M 1e-4 /* a wheel's lowest point within 0.1 mm of the floor */
#define DIFF_M 0.002  /* right wheel's diameter minus the left's, m */

/* Both wheels' lowest points at most SEATED_M from the floor. */
static void seated(const sim_state_t *s, const char *where)
{
    for (int side = 0; side < 2; side++) {
        double gap = world_wheel_floor_gap(s->world, side);
        if (!(fabs(gap) < SEATED_M))
            fail_msg("%s: %s wheel's lowest point %.3f mm from the floor", where, side == WORLD_LEFT ? "left" : "right",
                     gap * 1e3);
    }
}

/* The replayed robot's wheels: each one's lowest point (its axle's height
 * in the snapshot less the live robot's radius of that wheel) at most
 * SEATED_M from the floor. */
static void seated_snap(const snap_t *s, const double wheel_r_m[2], const char *where)
{
    for (int side = 0; side < 2; side++) {
        double gap = s->wheel_hub_z_m[side] - wheel_r_m[side];
        if (!(fabs(gap) < SEATED_M))
            fail_msg("%s: %s wheel's lowest point %.3f mm from the floor", where, side == WORLD_LEFT ? "left" : "right",
                     gap * 1e3);
    }
}

/* Drive a while (logging to log_path), carry the robot back to the start
 * cell, then replay the log at its middle: seated at each stage. */
static void place_reset_replay(const simcfg_t *c)
{
    static truemaze_t m;
    static sim_state_t s;
    static telem_t tel;
    static replay_t r;
    static snap_t snap;
    char err[600], log_path[64];
    double wheel_r_m[2];
    assert_int_equal(mazegen_generate(&m, 5, 5, 7), 0);
    static sim_model_t s_model;
    sim_model_build(&s_model, c, 1);
    assert_int_equal(sim_init(&s, &s_model, &m, 1), 0);
    assert_true(fabs(s.model->wheel_r_m[WORLD_RIGHT] - s.model->wheel_r_m[WORLD_LEFT] - DIFF_M / 2) < 1e-9);
    seated(&s, "placed at the start");
    snprintf(log_path, sizeof log_path, "/tmp/test_wheels_%d.lcmlog", (int)getpid());
    telem_opts_t o = { NULL, log_path, 0, NULL, "gen.txt" };
    assert_int_equal(telem_open(&tel, &o, &s, err, sizeof err), 0);
    s.cmd[0] = s.cmd[1] = 300;
    for (int i = 0; i < 400; i++) {
        sim_step(s.model, &s);
        telem_step(&tel, &s, NULL); /* no firmware: no belief */
    }
    telem_finish(&tel, &s, NULL);
    assert_int_equal(telem_close(&tel, err, sizeof err), 0);
    double x, y, h;
    world_pose(s.world, &x, &y, &h);
    world_place(s.world, (truemaze_x(&m, m.start) + 0.5) * c->world.cell_m, (truemaze_y(&m, m.start) + 0.5) * c->world.cell_m, M_PI / 2, NULL);
    seated(&s, "reset to the start");
    for (int side = 0; side < 2; side++) wheel_r_m[side] = s.model->wheel_r_m[side];
    sim_free(&s);

    assert_int_equal(replay_load(&r, log_path, err, sizeof err), 0);
    replay_snap(&r, replay_end_s(&r) / 2, &snap);
    seated_snap(&snap, wheel_r_m, "replayed");
    replay_free(&r);
    unlink(log_path);
}

static void test_config_asymmetry(void **state)
{
    (void)state;
    static simcfg_t c;
    char err[300];
    config_defaults(&c);
    assert_int_equal(config_load_string(&c, "[asymmetry]\nwheel_d_diff_m = 0.002\n", "asym.ini", err, sizeof err), 0);
    place_reset_replay(&c);
}

static void test_robot_file_diameters(void **state)
{
    (void)state;
    static simcfg_t c;
    config_defaults(&c);
    /* as a robot file's chassis gives them: each wheel's */
    c.robot.wheel_left_d_m -= DIFF_M / 2;
    c.robot.wheel_right_d_m += DIFF_M / 2;
    place_reset_replay(&c);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_config_asymmetry),
        cmocka_unit_test(test_robot_file_diameters),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}

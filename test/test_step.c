/* test_step.c - physics that does not depend on the time step: forward and
 * rotation KM and TM (the voltage steps of sim/validate's voltage_step, as
 * ukmars' motorlab measures them) within 2 % across 0.25, 0.5, 1 and 2 ms
 * for both shipped robots; a 3 m/s impact on a wall goes as deep at each
 * step, within 20 %. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <cmocka.h>

#include <math.h>
#include <stdio.h>

#include "world/config.h"
#include "world/motor.h"
#include "world/robot.h"
#include "world/sim.h"
#include "world/world.h"

#define BAND_PCT 2.0 /* the bar: KM and TM within 2 % across the steps */

static const double steps_s[] = { 0.00025, 0.0005, 0.001, 0.002 };
#define NSTEPS (sizeof steps_s / sizeof steps_s[0])

static maze_t maze;
static sim_model_t model;
static sim_state_t st;  /* large */
static simcfg_t cfg;

/* An open 10 x 10 field, the robot in cell (4, 0) facing north. */
static void field(void)
{
    maze_init(&maze, 10, 10);
    maze_close_unknown(&maze);
    for (uint8_t y = 0; y < 10; y++)
        for (uint8_t x = 0; x < 10; x++) {
            maze_cell_t c = maze_cell(&maze, x, y);
            if (x + 1 < 10) maze_set_wall(&maze, c, MAZE_EAST, MAZE_WALL_OPEN);
            if (y + 1 < 10) maze_set_wall(&maze, c, MAZE_NORTH, MAZE_WALL_OPEN);
        }
    maze.start = maze_cell(&maze, 4, 0);
    maze.start_heading = MAZE_NORTH;
}

static int volt_cmd(double v_volt)
{
    long c = lround(v_volt / sim_battery_v(&st) * MOTOR_CMD_MAX);
    return (int)(c > MOTOR_CMD_MAX ? MOTOR_CMD_MAX : c < -MOTOR_CMD_MAX ? -MOTOR_CMD_MAX : c);
}

/* v_volt on both motors (rot: -v left, +v right) for 1.2 s from rest: the
 * steady speed by the encoders (mean of the last 0.2 s; m/s or rad/s) and
 * the time to 63.2 % of it (s). */
static void voltage_step(double v_volt, int rot, double *steady, double *tm_s)
{
    static double trace[8000]; /* 1.2 s at 0.25 ms: 4800 */
    field();
    sim_model_build(&model, &cfg, 1);
    assert_int_equal(sim_init(&st, &model, &maze, 1), 0);
    if (rot) world_place(st.world, 4.5 * cfg.world.cell_m, 4.5 * cfg.world.cell_m, M_PI / 2, NULL);
    long n = lround(1.2 / cfg.sim.step_s), tail = lround(0.2 / cfg.sim.step_s);
    assert_true(n <= 8000);
    for (long i = 0; i < n; i++) {
        st.cmd[WORLD_LEFT] = volt_cmd(rot ? -v_volt : v_volt);
        st.cmd[WORLD_RIGHT] = volt_cmd(v_volt);
        sim_step(st.model, &st);
        double vl = world_wheel_rate(st.world, WORLD_LEFT) * cfg.robot.wheel_left_d_m / 2;
        double vr = world_wheel_rate(st.world, WORLD_RIGHT) * cfg.robot.wheel_right_d_m / 2;
        trace[i] = rot ? (vr - vl) / (2 * cfg.robot.wheel_x_m) : (vr + vl) / 2;
    }
    *steady = 0;
    for (long i = n - tail; i < n; i++) *steady += trace[i] / tail;
    *tm_s = 0;
    for (long i = 0; i < n; i++)
        if (trace[i] >= 0.632 * *steady) {
            double prev = i ? trace[i - 1] : 0;
            *tm_s = (i + (0.632 * *steady - prev) / (trace[i] - prev)) * cfg.sim.step_s;
            break;
        }
    sim_free(&st);
}

/* KM (slope at 1.5/3 V forward, 1/2 V rotation) and TM (3 V, 2 V) at each
 * step; each within BAND_PCT of the 0.25 ms figure. */
static void check_robot(const char *path)
{
    const char *names[4] = { "forward KM", "forward TM", "rotation KM", "rotation TM" };
    double fig[NSTEPS][4];
    char err[256];
    for (size_t k = 0; k < NSTEPS; k++) {
        config_defaults(&cfg);
        assert_int_equal(robot_load(&cfg, path, err, sizeof err), 0);
        cfg.sim.step_s = steps_s[k];
        double a, b, ta, tb;
        voltage_step(1.5, 0, &a, &ta);
        voltage_step(3.0, 0, &b, &tb);
        fig[k][0] = (b - a) / 1.5, fig[k][1] = tb;
        voltage_step(1.0, 1, &a, &ta);
        voltage_step(2.0, 1, &b, &tb);
        fig[k][2] = b - a, fig[k][3] = tb;
        printf("%s h=%.2f ms: forward KM %.1f mm/s/V TM %.2f ms, rotation KM %.1f deg/s/V TM %.2f ms\n", path,
               steps_s[k] * 1e3, fig[k][0] * 1e3, fig[k][1] * 1e3, fig[k][2] * 180 / M_PI, fig[k][3] * 1e3);
    }
    for (size_t k = 1; k < NSTEPS; k++)
        for (int f = 0; f < 4; f++) {
            double dev = 100 * (fig[k][f] / fig[0][f] - 1);
            if (fabs(dev) > BAND_PCT)
                fail_msg("%s: %s at %.2f ms is %+.2f %% from 0.25 ms", path, names[f], steps_s[k] * 1e3, dev);
        }
}

/* The robot rolling at 3 m/s, motors off, into the wall ahead of a closed
 * cell: the deepest the wall goes into it (m). */
static double impact_depth(const char *path, double step_s)
{
    char err[256];
    config_defaults(&cfg);
    assert_int_equal(robot_load(&cfg, path, err, sizeof err), 0);
    cfg.sim.step_s = step_s;
    sim_model_build(&model, &cfg, 1);
    maze_init(&maze, 1, 1);
    maze_close_unknown(&maze);
    double c = cfg.world.cell_m;
    world_t *w = world_create(&model, &maze, c / 2, c / 2, M_PI / 2);
    assert_non_null(w);
    /* settle on the floor first, then roll */
    const motor_drive_t off[2] = { { 0, 0, 0 }, { 0, 0, 0 } };
    for (long i = 0; i < lround(0.05 / step_s); i++) world_step(w, off);
    world_set_speed(w, 3.0);
    double deepest = 0, v, om;
    world_velocity(w, &v, &om);
    assert_true(fabs(v - 3.0) < 0.01);
    for (long i = 0; i < lround(0.05 / step_s); i++) {
        world_step(w, off);
        deepest = fmax(deepest, world_wall_depth(w));
    }
    assert_true(world_sane(w));
    world_destroy(w);
    return deepest;
}

static void check_impact(const char *path)
{
    double d[NSTEPS];
    for (size_t k = 0; k < NSTEPS; k++) {
        d[k] = impact_depth(path, steps_s[k]);
        printf("%s h=%.2f ms: 3 m/s impact %.2f mm deep\n", path, steps_s[k] * 1e3, d[k] * 1e3);
        assert_true(d[k] > 0);
    }
    for (size_t k = 1; k < NSTEPS; k++)
        if (fabs(d[k] / d[0] - 1) > 0.20)
            fail_msg("%s: impact depth %.2f mm at %.2f ms against %.2f mm at 0.25 ms", path, d[k] * 1e3, steps_s[k] * 1e3,
                     d[0] * 1e3);
}

static void test_impact(void **state)
{
    (void)state;
    check_impact("robots/paper.ini");
    check_impact("robots/ukmarsbot.ini");
}

static void test_paper(void **state)
{
    (void)state;
    check_robot("robots/paper.ini");
}

static void test_ukmarsbot(void **state)
{
    (void)state;
    check_robot("robots/ukmarsbot.ini");
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_paper),
        cmocka_unit_test(test_ukmarsbot),
        cmocka_unit_test(test_impact),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}

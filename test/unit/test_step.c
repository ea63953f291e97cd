/* test_step.c - physics that does not depend on the time step: forward and
 * rotation KM and TM (the voltage steps of sim/validate's voltage_step, as
 * ukmars' motorlab measures them) within 2 % across 0.25, 0.5, 1 and 2 ms
 * for both shipped robots; a 3 m/s impact on a wall goes as deep at each
 * step, within 20 %; each with the wheels on hinges and as spin bodies
 * ([sim] wheels). */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <cmocka.h>

#include <math.h>
#include <stdio.h>

#include "validate/bench.h"
#include "world/config.h"
#include "world/motor.h"
#include "world/robot.h"
#include "world/sim.h"
#include "world/world.h"

#define BAND_PCT 2.0 /* the bar: KM and TM within 2 % across the steps */

static const double steps_s[] = { 0.00025, 0.0005, 0.001, 0.002 };
#define NSTEPS (sizeof steps_s / sizeof steps_s[0])

static truemaze_t maze;
static sim_model_t model;
static simcfg_t cfg;
static int wheels; /* [sim] wheels of the test in progress */

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
        cfg.sim.wheels = wheels;
        /* the steps as --validate measures them (bench.h: a first-order fit to the distance) */
        bench_step_t a = bench_voltage_step(&cfg, 1.5, 0), b = bench_voltage_step(&cfg, 3.0, 0);
        fig[k][0] = (b.steady - a.steady) / 1.5, fig[k][1] = b.tm_s;
        a = bench_voltage_step(&cfg, 1.0, 1), b = bench_voltage_step(&cfg, 2.0, 1);
        fig[k][2] = b.steady - a.steady, fig[k][3] = b.tm_s;
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
    cfg.sim.wheels = wheels;
    sim_model_build(&model, &cfg, 1);
    truemaze_init(&maze, 1, 1);
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

static void test_spin(void **state)
{
    (void)state;
    wheels = SIM_WHEELS_SPIN;
    test_paper(state);
    test_ukmarsbot(state);
    test_impact(state);
    wheels = SIM_WHEELS_HINGE;
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_paper),
        cmocka_unit_test(test_ukmarsbot),
        cmocka_unit_test(test_impact),
        cmocka_unit_test(test_spin),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}

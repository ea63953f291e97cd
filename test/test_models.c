/* test_models.c - motor, encoder and ToF models against their equations. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <cmocka.h>

#include <math.h>
#include <stdlib.h>

#include "world/config.h"
#include "world/encoder.h"
#include "world/motor.h"
#include "world/sensors/tof.h"

static simcfg_t cfg;

static int setup(void **state)
{
    (void)state;
    config_defaults(&cfg);
    return 0;
}

static void assert_near(double got, double want, double rel)
{
    if (fabs(got - want) > rel * fabs(want)) fail_msg("got %.9g, want %.9g (+-%.3g %%)", got, want, rel * 100);
}

/* A free wheel (inertia only) at full command settles at V/Kt. */
static void test_motor_no_load_speed(void **state)
{
    (void)state;
    motor_t m;
    motor_init(&m, &cfg);
    double j = 0.5 * cfg.wheel_mass_kg * pow(cfg.wheel_d_m / 2, 2); /* kg*m^2, solid disc */
    double w = 0, dt = 0.001;
    for (int i = 0; i < 5000; i++) w += motor_step(&m, MOTOR_CMD_MAX, w, dt) / j * dt;
    assert_near(w, cfg.battery_v / cfg.kt_nm_per_a, 0.02);
    /* half command, reverse: half the speed, backwards */
    for (int i = 0; i < 5000; i++) w += motor_step(&m, -512, w, dt) / j * dt;
    assert_near(w, -cfg.battery_v * 512 / 1023 / cfg.kt_nm_per_a, 0.02);
}

static void test_motor_stall_torque(void **state)
{
    (void)state;
    motor_t m;
    motor_init(&m, &cfg);
    double t = 0;
    for (int i = 0; i < 100; i++) t = motor_step(&m, MOTOR_CMD_MAX, 0.0, 0.001);
    assert_near(t, cfg.kt_nm_per_a * cfg.battery_v / cfg.r_ohm, 0.01);
    /* commands beyond 11 bits are clamped */
    motor_init(&m, &cfg);
    double t1 = motor_step(&m, 5000, 0.0, 0.001);
    motor_init(&m, &cfg);
    assert_true(t1 == motor_step(&m, 1023, 0.0, 0.001));
}

/* Backward difference: exactly V/(R + L/dt) after one step from rest. */
static void test_motor_first_step_exact(void **state)
{
    (void)state;
    motor_t m;
    motor_init(&m, &cfg);
    motor_step(&m, MOTOR_CMD_MAX, 0.0, 0.001);
    assert_true(m.i_a == cfg.battery_v / (cfg.r_ohm + cfg.l_h / 0.001));
}

/* Sub-stepped at 2 us, the current reaches 63.2 % of its final value at
 * t = L/R (60 us for the default motor). */
static void test_motor_time_constant(void **state)
{
    (void)state;
    motor_t m;
    motor_init(&m, &cfg);
    double tau = cfg.l_h / cfg.r_ohm, dt = 2e-6;
    int n = (int)lround(tau / dt);
    for (int i = 0; i < n; i++) motor_step(&m, MOTOR_CMD_MAX, 0.0, dt);
    assert_near(m.i_a, 0.632 * cfg.battery_v / cfg.r_ohm, 0.02);
}

/* Battery sag lowers the applied voltage under load. */
static void test_motor_battery_sag(void **state)
{
    (void)state;
    simcfg_t c = cfg;
    c.battery_r_ohm = 2.0;
    motor_t m;
    motor_init(&m, &c);
    for (int i = 0; i < 100; i++) motor_step(&m, MOTOR_CMD_MAX, 0.0, 0.001);
    assert_true(m.v_applied < c.battery_v - 0.5);
    assert_near(m.i_a, c.battery_v / (c.r_ohm + c.battery_r_ohm), 0.01);
}

/* A battery resistance far above the motor's (100 ohm against 16.7):
 * the current settles at V/(R + R_b) without overshoot. The sag from the
 * step before overshot by R_b/(R + L/dt) = 5.7 times and grew (issue 15). */
static void test_motor_battery_sag_stable(void **state)
{
    (void)state;
    simcfg_t c = cfg;
    c.battery_r_ohm = 100.0;
    motor_t m;
    motor_init(&m, &c);
    double last = 0;
    for (int i = 0; i < 200; i++) {
        motor_step(&m, MOTOR_CMD_MAX, 0.0, 0.001);
        assert_true(m.i_a >= last && m.i_a <= c.battery_v / (c.r_ohm + c.battery_r_ohm) * 1.000001);
        last = m.i_a;
    }
    assert_near(m.i_a, c.battery_v / (c.r_ohm + c.battery_r_ohm), 1e-6);
    assert_near(m.v_applied, c.battery_v * c.r_ohm / (c.r_ohm + c.battery_r_ohm), 1e-6);
}

/* motor_damping and motor_free_speed describe motor_step's torque:
 * T(w) = damping * (free - w), at any command and state. */
static void test_motor_law(void **state)
{
    (void)state;
    simcfg_t c = cfg;
    c.battery_r_ohm = 1.5;
    motor_t m, probe;
    motor_init(&m, &c);
    const int cmds[] = { 1023, 300, -700, 0, -1023 };
    for (int k = 0; k < 5; k++) {
        double w = 40.0 - 25.0 * k, dt = 0.001;
        double d = motor_damping(&m, cmds[k], dt), f = motor_free_speed(&m, cmds[k], dt);
        probe = m;
        double t = motor_step(&probe, cmds[k], w, dt);
        assert_near(t, d * (f - w), 1e-9);
        motor_step(&m, cmds[k], w, dt); /* a state with current for the next command */
    }
}

static void test_encoder_one_revolution(void **state)
{
    (void)state;
    encoder_t e;
    double cpr = cfg.encoder_ppr * cfg.gear_ratio; /* 358.32 */
    encoder_init(&e, cpr, 0.0);
    for (int i = 1; i <= 1000; i++) encoder_update(&e, remainder(2 * M_PI * i / 1000.0, 2 * M_PI)); /* wraps at +-pi */
    assert_true(abs(e.count - 358) <= 1);
    /* backwards two turns */
    for (int i = 1; i <= 2000; i++) encoder_update(&e, remainder(-2 * M_PI * i / 1000.0, 2 * M_PI));
    assert_true(abs(e.count - (358 - 717)) <= 1);
}

/* A million tiny steps: no pulse lost or invented. */
static void test_encoder_no_drift(void **state)
{
    (void)state;
    encoder_t e;
    double cpr = cfg.encoder_ppr * cfg.gear_ratio;
    encoder_init(&e, cpr, 0.0);
    double turns = 10.0;
    for (int i = 1; i <= 1000000; i++) encoder_update(&e, remainder(2 * M_PI * turns * i / 1e6, 2 * M_PI));
    assert_true(fabs(e.count + e.frac - cpr * turns) < 1e-6);
    assert_int_equal(e.count, (int)floor(cpr * turns));
}

static void test_tof_noise_statistics(void **state)
{
    (void)state;
    tof_t t;
    tof_init(&t, &cfg, 42, 0);
    double d = 0.5, sum = 0, sum2 = 0;
    int n = 10000;
    for (int i = 0; i < n; i++) {
        tof_reading_t r = tof_measure(&t, d);
        assert_false(r.timeout);
        sum += r.dist_m;
        sum2 += r.dist_m * r.dist_m;
    }
    double mean = sum / n, sd = sqrt(sum2 / n - mean * mean);
    assert_near(mean, d, 0.01);
    assert_near(sd, cfg.tof_cv * d, 0.05);
}

static void test_tof_clamps_and_timeout(void **state)
{
    (void)state;
    simcfg_t c = cfg;
    c.tof_blind_m = 0.03;
    c.tof_cv = 0.0;
    tof_t t;
    tof_init(&t, &c, 1, 0);
    assert_true(tof_measure(&t, 0.01).dist_m == 0.03); /* blind spot */
    tof_reading_t r = tof_measure(&t, -1.0);          /* nothing hit */
    assert_true(r.timeout && r.dist_m == c.tof_range_m);
    r = tof_measure(&t, 1.3); /* beyond range */
    assert_true(r.timeout);
    c.tof_cv = 0.5;
    tof_init(&t, &c, 1, 0);
    for (int i = 0; i < 1000; i++) {
        r = tof_measure(&t, 1.15);
        assert_true(r.dist_m >= 0 && r.dist_m <= c.tof_range_m);
    }
}

static void test_tof_streams(void **state)
{
    (void)state;
    tof_t a, b, other;
    tof_init(&a, &cfg, 7, 1);
    tof_init(&b, &cfg, 7, 1);
    tof_init(&other, &cfg, 7, 2);
    int differ = 0;
    for (int i = 0; i < 100; i++) {
        double x = tof_measure(&a, 0.3).dist_m;
        assert_true(x == tof_measure(&b, 0.3).dist_m); /* same seed, same samples */
        differ += x != tof_measure(&other, 0.3).dist_m;
    }
    assert_true(differ > 90); /* each sensor its own stream */
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_motor_no_load_speed),
        cmocka_unit_test(test_motor_stall_torque),
        cmocka_unit_test(test_motor_first_step_exact),
        cmocka_unit_test(test_motor_time_constant),
        cmocka_unit_test(test_motor_battery_sag),
        cmocka_unit_test(test_motor_battery_sag_stable),
        cmocka_unit_test(test_motor_law),
        cmocka_unit_test(test_encoder_one_revolution),
        cmocka_unit_test(test_encoder_no_drift),
        cmocka_unit_test(test_tof_noise_statistics),
        cmocka_unit_test(test_tof_clamps_and_timeout),
        cmocka_unit_test(test_tof_streams),
    };
    return cmocka_run_group_tests_name("models", tests, setup, NULL);
}

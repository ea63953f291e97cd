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

static drive_spec_t cfg; /* the paper robot's left drive */
static tof_spec_t tcfg;  /* and its first ToF sensor */
#define BATTERY_V 6.0    /* its battery (robots/paper.ini) */

static int setup(void **state)
{
    (void)state;
    static simcfg_t full;
    config_defaults(&full);
    cfg = full.robot.drive[0];
    tcfg = *(const tof_spec_t *)full.robot.part[0].spec;
    return 0;
}

static void assert_near(double got, double want, double rel)
{
    if (fabs(got - want) > rel * fabs(want)) fail_msg("got %.9g, want %.9g (+-%.3g %%)", got, want, rel * 100);
}

/* One step of a free wheel of inertia j (no ODE): the drive's torque with
 * its damping implicit in the end speed, friction against the motion. */
static double free_step(motor_t *m, int cmd, double w, double j, double dt)
{
    motor_drive_t d = motor_drive(m, cmd, w, dt);
    double t0 = d.t0_nm - (w > 0 ? d.friction_nm : w < 0 ? -d.friction_nm : 0);
    double w1 = (w + dt * t0 / j) / (1 + dt * d.damping_nm_s / j);
    motor_after(m, &d, w1, dt);
    return w1;
}

static double rpm(double w) { return w * 60 / (2 * M_PI); }

/* The paper's model: a free wheel settles at V/K, K = T_stall/i_stall. */
static void test_paper_no_load_speed(void **state)
{
    (void)state;
    drive_spec_t c = cfg;
    c.motor_model = MOTOR_MODEL_PAPER;
    motor_t m;
    motor_init(&m, &c, BATTERY_V, 0, 1.0);
    double k = c.stall_torque_nm / c.stall_a, j = 1e-5, w = 0, dt = 0.001;
    for (int i = 0; i < 5000; i++) w = free_step(&m, MOTOR_CMD_MAX, w, j, dt);
    assert_near(w, BATTERY_V / k, 0.01);
    assert_near(rpm(w), 725, 0.01); /* 61 % above the datasheet's 450 rpm */
    for (int i = 0; i < 5000; i++) w = free_step(&m, -512, w, j, dt);
    assert_near(w, -BATTERY_V * 512 / 1023 / k, 0.01);
}

/* The paper's eq. 3: a backward difference, V/(R + L/dt) after one step. */
static void test_paper_first_step(void **state)
{
    (void)state;
    drive_spec_t c = cfg;
    c.motor_model = MOTOR_MODEL_PAPER;
    motor_t m;
    motor_init(&m, &c, BATTERY_V, 0, 1.0);
    motor_drive(&m, MOTOR_CMD_MAX, 0.0, 0.001);
    assert_true(m.i_a == c.rated_v / (c.rated_v / c.stall_a + c.l_h / 0.001));
}

/* The datasheet model's constants for the Pololu 30:1 LP 6V. */
static void test_datasheet_constants(void **state)
{
    (void)state;
    double r, ke, eta;
    drive_spec_t c = cfg;
    c.friction_load_a = 0; /* a constant friction */
    motor_constants(&c, &r, &ke, &eta);
    assert_near(r, 16.6667, 1e-4);
    assert_near(ke, 0.00402714, 1e-4);
    assert_near(eta, 0.695583, 1e-4);
    /* the paper robot's friction rises by 0.0273 A under load (bench/fit_motor_losses.py):
     * the same R and Ke, the gearbox's efficiency from the stall's friction */
    motor_constants(&cfg, &r, &ke, &eta);
    assert_near(ke, 0.00402714, 1e-4);
    assert_near(eta, 0.756176, 1e-4);
}

/* The load-dependent friction: the no-load current running free, its rise
 * under load, at most half as fast as the current, none when load_a is 0. */
static void test_friction_rise(void **state)
{
    (void)state;
    assert_true(motor_friction_a(0.02, 0.0273, 0.02) == 0.02);
    assert_true(motor_friction_a(0.02, 0.0273, 0.0) == 0.02);
    assert_near(motor_friction_a(0.02, 0.0273, 0.36), 0.0472461, 1e-5); /* 0.02 + 0.0273 (1 - e^(-0.34/0.0546)) */
    assert_near(motor_friction_a(0.02, 0.0273, -0.36), 0.0472461, 1e-5);
    assert_true(motor_friction_a(0.02, 0.0273, 0.021) - 0.02 < 0.5 * 0.001);
    assert_true(motor_friction_a(0.02, 0, 0.3) == 0.02);
}

/* A free wheel at full command: the datasheet's no-load speed and current. */
static void test_datasheet_no_load(void **state)
{
    (void)state;
    motor_t m;
    motor_init(&m, &cfg, BATTERY_V, 0, 1.0);
    double w = 0, j = 2e-5;
    for (int i = 0; i < 5000; i++) w = free_step(&m, MOTOR_CMD_MAX, w, j, 0.001);
    assert_near(rpm(w), cfg.no_load_rpm, 1e-4);
    assert_near(m.i_a, cfg.no_load_a, 1e-3);
}

/* Stalled: the datasheet's stall torque (the friction taken off) and
 * current; after one step the current of L di/dt = V - R i exactly. */
static void test_datasheet_stall(void **state)
{
    (void)state;
    motor_t m;
    motor_init(&m, &cfg, BATTERY_V, 0, 1.0);
    motor_drive_t d = motor_drive(&m, MOTOR_CMD_MAX, 0.0, 0.001);
    motor_after(&m, &d, 0.0, 0.001);
    double r = cfg.rated_v / cfg.stall_a;
    assert_near(m.i_a, cfg.stall_a * (1 - exp(-0.001 * r / cfg.l_h)), 1e-9);
    for (int i = 0; i < 100; i++) {
        d = motor_drive(&m, MOTOR_CMD_MAX, 0.0, 0.001);
        motor_after(&m, &d, 0.0, 0.001);
    }
    assert_near(m.torque_nm, cfg.stall_torque_nm, 1e-6);
    assert_near(m.i_a, cfg.stall_a, 1e-6);
    /* commands beyond 11 bits are clamped */
    motor_drive_t d1 = motor_drive(&m, 5000, 0.0, 0.001), d2 = motor_drive(&m, 1023, 0.0, 0.001);
    assert_true(d1.t0_nm == d2.t0_nm);
    /* a drive weaker than the friction leaves a wheel at rest at rest */
    motor_init(&m, &cfg, BATTERY_V, 0, 1.0);
    d = motor_drive(&m, 20, 0.0, 0.001);
    assert_true(d.t0_nm < d.friction_nm);
}

/* Battery sag lowers the applied voltage under load. */
static void test_motor_battery_sag(void **state)
{
    (void)state;
    drive_spec_t c = cfg;
    double battery_r_ohm = 2.0;
    motor_t m;
    motor_init(&m, &c, BATTERY_V, battery_r_ohm, 1.0);
    for (int i = 0; i < 100; i++) {
        motor_drive_t d = motor_drive(&m, MOTOR_CMD_MAX, 0.0, 0.001);
        motor_after(&m, &d, 0.0, 0.001);
    }
    assert_true(motor_terminal_v(&m) < BATTERY_V - 0.5);
    assert_near(m.i_a, BATTERY_V / (c.rated_v / c.stall_a + battery_r_ohm), 0.01);
    /* a battery of 100 ohm: the sag is in the current's own step, no oscillation */
    battery_r_ohm = 100;
    motor_init(&m, &c, BATTERY_V, battery_r_ohm, 1.0);
    double w = 0;
    for (int i = 0; i < 3000; i++) w = free_step(&m, MOTOR_CMD_MAX, w, 2e-5, 0.001);
    assert_true(w > 0 && m.i_a > 0 && m.i_a < BATTERY_V / 100);
}

/* The asymmetry's scale multiplies the motor's constant. */
static void test_motor_scale(void **state)
{
    (void)state;
    motor_t a, b;
    motor_init(&a, &cfg, BATTERY_V, 0, 1.0);
    motor_init(&b, &cfg, BATTERY_V, 0, 1.02);
    assert_near(b.ke_v_s, 1.02 * a.ke_v_s, 1e-12);
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
    tof_init(&t, &tcfg, 42, 0);
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
    assert_near(sd, tcfg.cv * d, 0.05);
}

static void test_tof_clamps_and_timeout(void **state)
{
    (void)state;
    tof_spec_t c = tcfg;
    c.blind_m = 0.03;
    c.cv = 0.0;
    tof_t t;
    tof_init(&t, &c, 1, 0);
    assert_true(tof_measure(&t, 0.01).dist_m == 0.03); /* blind spot */
    tof_reading_t r = tof_measure(&t, -1.0);          /* nothing hit */
    assert_true(r.timeout && r.dist_m == c.range_m);
    r = tof_measure(&t, c.range_m + 1e-6); /* beyond the range: no return, a timeout */
    assert_true(r.timeout && r.dist_m == c.range_m);
    r = tof_measure(&t, c.range_m); /* at the range: detected */
    assert_false(r.timeout);
    /* the target's distance decides a timeout, not the noisy reading: a
     * wall within the range reads, above the range or not */
    c.cv = 0.5;
    tof_init(&t, &c, 1, 0);
    int above = 0;
    for (int i = 0; i < 1000; i++) {
        r = tof_measure(&t, 1.15);
        assert_false(r.timeout);
        assert_true(r.dist_m >= 0);
        above += r.dist_m > c.range_m;
    }
    assert_true(above > 300 && above < 700); /* about the half above 1.2 m */
}

static void test_tof_streams(void **state)
{
    (void)state;
    tof_t a, b, other;
    tof_init(&a, &tcfg, 7, 1);
    tof_init(&b, &tcfg, 7, 1);
    tof_init(&other, &tcfg, 7, 2);
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
        cmocka_unit_test(test_paper_no_load_speed),
        cmocka_unit_test(test_paper_first_step),
        cmocka_unit_test(test_datasheet_constants),
        cmocka_unit_test(test_friction_rise),
        cmocka_unit_test(test_datasheet_no_load),
        cmocka_unit_test(test_datasheet_stall),
        cmocka_unit_test(test_motor_battery_sag),
        cmocka_unit_test(test_motor_scale),
        cmocka_unit_test(test_encoder_one_revolution),
        cmocka_unit_test(test_encoder_no_drift),
        cmocka_unit_test(test_tof_noise_statistics),
        cmocka_unit_test(test_tof_clamps_and_timeout),
        cmocka_unit_test(test_tof_streams),
    };
    return cmocka_run_group_tests_name("models", tests, setup, NULL);
}

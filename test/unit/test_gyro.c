/* test_gyro.c - the gyro model (sim/world/sensors/gyro.h) against its equations. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <cmocka.h>

#include <math.h>

#include "world/sensors/gyro.h"

#define RAD_PER_DEG (M_PI / 180.0)

static void assert_near(double got, double want, double tol)
{
    if (fabs(got - want) > tol) fail_msg("got %.9g, want %.9g (+-%.3g)", got, want, tol);
}

/* A spec with every error off: the output is the true rate. */
static gyro_spec_t ideal(void)
{
    gyro_spec_t s;
    gyro_spec_default(&s);
    s.noise_density_dps_rthz = 0;
    s.bias_dps = 0;
    s.bias_rw_dps_rts = 0;
    s.scale_error_pct = 0;
    s.lsb_dps = 0;
    return s;
}

/* The middle of sample period k, s. */
static double mid(const gyro_spec_t *s, long k) { return (k + 0.5) / s->sample_rate_hz; }

/* At rest: the mean is the bias drawn at init, the standard deviation the
 * white noise's density * sqrt(f/2) (quantised to the default LSB). */
static void test_rest_mean_and_sigma(void **state)
{
    gyro_spec_t s;
    gyro_spec_default(&s);
    s.bias_rw_dps_rts = 0;
    gyro_t g;
    gyro_init(&g, &s, 42, 0);
    assert_true(fabs(g.bias0_dps) > 0);
    const long n = 200000;
    double sum = 0, sum2 = 0;
    for (long k = 0; k < n; k++) {
        double y = gyro_read(&g, 0.0, mid(&s, k)) / RAD_PER_DEG;
        sum += y;
        sum2 += y * y;
    }
    double mean = sum / n, sd = sqrt(sum2 / n - mean * mean), sigma = gyro_sigma_dps(&s);
    assert_near(sigma, 0.007 * sqrt(833.0 / 2), 1e-12);
    assert_near(mean, g.bias0_dps, 5 * sigma / sqrt(n) + s.lsb_dps / 100);
    assert_near(sd, sigma, 0.03 * sigma);
}

/* The bias random walk: over an ensemble of gyros its variance at sample k
 * is rw^2 * k / f, linear in time (4x the time, 4x the variance); the
 * ensemble is one gyro over many seeds. */
static void test_random_walk_linear(void **state)
{
    gyro_spec_t s = ideal();
    s.bias_rw_dps_rts = 0.01;
    const int n = 1000;
    const long k1 = 1666, k2 = 4 * 1666;
    double v1 = 0, v2 = 0;
    for (int i = 0; i < n; i++) {
        gyro_t g;
        gyro_init(&g, &s, 1000 + (uint64_t)i, 0);
        double y1 = gyro_read(&g, 0.0, mid(&s, k1)) / RAD_PER_DEG;
        double y2 = gyro_read(&g, 0.0, mid(&s, k2)) / RAD_PER_DEG;
        v1 += y1 * y1;
        v2 += y2 * y2;
    }
    v1 /= n;
    v2 /= n;
    double rw2 = s.bias_rw_dps_rts * s.bias_rw_dps_rts;
    assert_near(v1, rw2 * k1 / s.sample_rate_hz, 0.15 * rw2 * k1 / s.sample_rate_hz);
    assert_near(v2, rw2 * k2 / s.sample_rate_hz, 0.15 * rw2 * k2 / s.sample_rate_hz);
    assert_near(v2 / v1, 4.0, 0.8);
}

static void test_scale_error(void **state)
{
    gyro_spec_t s = ideal();
    s.scale_error_pct = 2.0;
    gyro_t g;
    gyro_init(&g, &s, 1, 0);
    assert_near(gyro_read(&g, 1.0, mid(&s, 0)), 1.02, 1e-12);
    assert_near(gyro_read(&g, -3.0, mid(&s, 1)), -3.06, 1e-12);
    s.scale_error_pct = -1.5;
    gyro_init(&g, &s, 1, 0);
    assert_near(gyro_read(&g, 2.0, mid(&s, 0)), 2.0 * 0.985, 1e-12);
}

static void test_saturation_and_lsb(void **state)
{
    gyro_spec_t s = ideal();
    s.lsb_dps = 0.035;
    gyro_t g;
    gyro_init(&g, &s, 1, 0);
    /* clamped to +-1000 deg/s, then quantised: 28571 LSB = 999.985 deg/s */
    double fs = 0.035 * 28571 * RAD_PER_DEG;
    assert_near(gyro_read(&g, 2 * s.full_scale_dps * RAD_PER_DEG, mid(&s, 0)), fs, 1e-12);
    assert_near(gyro_read(&g, -5 * s.full_scale_dps * RAD_PER_DEG, mid(&s, 1)), -fs, 1e-12);
    /* 100.01 deg/s -> the nearest multiple of 35 mdps: 100.00 (2857 LSB = 99.995) */
    double y = gyro_read(&g, 100.01 * RAD_PER_DEG, mid(&s, 2)) / RAD_PER_DEG;
    assert_near(y, 0.035 * 2857, 1e-9);
}

/* Two reads in one sample period give the same value, whatever the true
 * rate at the second; the next period takes a new sample. */
static void test_sample_and_hold(void **state)
{
    gyro_spec_t s;
    gyro_spec_default(&s);
    gyro_t g;
    gyro_init(&g, &s, 3, 0);
    double f = s.sample_rate_hz;
    double a = gyro_read(&g, 1.0, 10.1 / f), b = gyro_read(&g, 5.0, 10.9 / f);
    assert_true(a == b);
    double c = gyro_read(&g, 5.0, 11.2 / f);
    assert_true(c != a);
    assert_near(c, 5.0 * 1.01 + g.bias0_dps * RAD_PER_DEG, 0.05);
    assert_true(gyro_read(&g, 9.0, 1.0 / f) == c); /* time going back: the held value */
}

/* Same seed and index: the same readings; another index or seed: others.
 * Reading every sample or only the last gives the same last reading. */
static void test_determinism(void **state)
{
    gyro_spec_t s;
    gyro_spec_default(&s);
    gyro_t a, b, c, d, e;
    gyro_init(&a, &s, 99, 0);
    gyro_init(&b, &s, 99, 0);
    gyro_init(&c, &s, 99, 1);
    gyro_init(&d, &s, 100, 0);
    gyro_init(&e, &s, 99, 0);
    int differ_c = 0, differ_d = 0;
    double ya = 0;
    for (long k = 0; k < 1000; k++) {
        double t = mid(&s, k);
        ya = gyro_read(&a, 0.3, t);
        assert_true(ya == gyro_read(&b, 0.3, t));
        differ_c += ya != gyro_read(&c, 0.3, t);
        differ_d += ya != gyro_read(&d, 0.3, t);
    }
    assert_true(differ_c > 900);
    assert_true(differ_d > 900);
    assert_true(gyro_read(&e, 0.3, mid(&s, 999)) == ya);
}

/* The zero-rate level over many parts (one per seed): bias_dps is ST's
 * TyOff, the population's standard deviation (gyro.h), so with the default
 * bias_typ_sigmas = 1 the spread is 10 dps and 31.73 % of the parts start
 * beyond +-10 dps (2 * (1 - Phi(1))), 4.55 % beyond +-20 dps; read as a bound
 * (bias_typ_sigmas = 3) 0.27 % do. 20000 seeds: the fractions' standard
 * errors are 0.33, 0.15 and 0.04 points; the bars are 4 of them. */
static void test_bias_over_parts(void **state)
{
    gyro_spec_t s;
    gyro_spec_default(&s);
    assert_near(s.bias_typ_sigmas, 1.0, 0);
    for (int pass = 0; pass < 2; pass++) {
        if (pass) s.bias_typ_sigmas = 3.0;
        long n = 20000, beyond = 0, beyond2 = 0;
        double sum2 = 0;
        for (long i = 0; i < n; i++) {
            gyro_t g;
            gyro_init(&g, &s, (uint64_t)i + 1, 0);
            sum2 += g.bias0_dps * g.bias0_dps;
            beyond += fabs(g.bias0_dps) > s.bias_dps;
            beyond2 += fabs(g.bias0_dps) > 2 * s.bias_dps;
        }
        double sd = sqrt(sum2 / n), want = s.bias_dps / s.bias_typ_sigmas;
        assert_near(sd, want, 0.02 * want);
        if (!pass) {
            assert_near((double)beyond / n, 0.3173, 4 * 0.0033);
            assert_near((double)beyond2 / n, 0.0455, 4 * 0.0015);
        } else {
            assert_near((double)beyond / n, 0.0027, 4 * 0.0004);
        }
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_rest_mean_and_sigma),
        cmocka_unit_test(test_random_walk_linear),
        cmocka_unit_test(test_scale_error),
        cmocka_unit_test(test_saturation_and_lsb),
        cmocka_unit_test(test_sample_and_hold),
        cmocka_unit_test(test_determinism),
        cmocka_unit_test(test_bias_over_parts),
    };
    return cmocka_run_group_tests_name("gyro", tests, NULL, NULL);
}

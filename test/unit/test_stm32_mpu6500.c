/* test_stm32_mpu6500.c - the MPU-6500 model (sim/arm/mpu6500.h) against its
 * product specification and register map: reset values, bulebule's
 * setup_mpu sequence, gyro Z = rate x LSB/(deg/s) + ZRO within the noise
 * (0.01 deg/s/sqrt(Hz) over the 250 Hz filter: 2.59 LSB at 16.4 LSB/(deg/s)),
 * the ZRO spread, the user offset as bulebule's calibration writes it,
 * burst reads, saturation, determinism by seed. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <cmocka.h>

#include <math.h>
#include <stdint.h>

#include "arm/mpu6500.h"

static const mmio_clocks_t clk = { 72000000, 72000000, 36000000, 72000000, 72000000, 72000000, 9000000 };
#define MS 72000u /* core cycles per ms */

static double rate_rad_s;
static double rate(void *ctx, uint64_t cycle) { return rate_rad_s; }

static void wreg(mpu6500_t *m, uint8_t reg, uint8_t v, uint64_t t)
{
    mpu6500_select(m, false);
    mpu6500_exchange(m, reg, t);
    mpu6500_exchange(m, v, t);
    mpu6500_select(m, true);
}
static uint8_t rreg(mpu6500_t *m, uint8_t reg, uint64_t t)
{
    mpu6500_select(m, false);
    mpu6500_exchange(m, 0x80 | reg, t);
    uint8_t v = mpu6500_exchange(m, 0, t);
    mpu6500_select(m, true);
    return v;
}
/* bulebule's mpu_read_gyro_z_raw: two single-register reads */
static int16_t gyro_z(mpu6500_t *m, uint64_t t)
{
    return (int16_t)(uint16_t)(rreg(m, 0x47, t) << 8 | rreg(m, 0x48, t));
}
/* bulebule's setup_mpu, at its 100 ms waits */
static void bulebule_setup(mpu6500_t *m)
{
    wreg(m, 107, 0x80, 0);
    wreg(m, 104, 0x07, 100 * MS);
    wreg(m, 106, 0x10, 200 * MS);
    wreg(m, 25, 0x00, 200 * MS);
    wreg(m, 26, 0x00, 200 * MS);
    wreg(m, 27, 0x18, 200 * MS);
}

static void test_reset_values(void **state)
{
    mpu6500_t m;
    mpu6500_init(&m, &clk, rate, NULL, 7, 0);
    assert_int_equal(rreg(&m, 117, 0), 0x70);
    assert_int_equal(rreg(&m, 107, 0), 0x01);
    assert_int_equal(rreg(&m, 27, 0), 0x00);
    assert_int_equal(mpu6500_exchange(&m, 0xF5, 0), 0xFF); /* not selected */
    wreg(&m, 117, 0x12, 0);
    assert_int_equal(rreg(&m, 117, 0), 0x70); /* read-only */
    wreg(&m, 27, 0x18, 0);
    wreg(&m, 107, 0x80, 0); /* DEVICE_RESET */
    assert_int_equal(rreg(&m, 27, 0), 0x00);
    assert_int_equal(rreg(&m, 107, 0), 0x01);
    assert_int_equal(m.unmodeled_count, 0);
    wreg(&m, 0x23, 0x78, 0); /* FIFO_EN: not modeled, counted */
    assert_true(mpu6500_unmodeled(&m, 0x23));
    assert_false(mpu6500_unmodeled(&m, 107));
    assert_int_equal(m.unmodeled_count, 1);
}

static void stats(mpu6500_t *m, unsigned n, uint64_t t0, double *mean, double *sd)
{
    double s = 0, s2 = 0;
    for (unsigned k = 0; k < n; k++) {
        double y = gyro_z(m, t0 + (uint64_t)k * MS);
        s += y;
        s2 += y * y;
    }
    *mean = s / n;
    *sd = sqrt(s2 / n - *mean * *mean);
}

static void test_gyro_z_rate(void **state)
{
    mpu6500_t m;
    mpu6500_init(&m, &clk, rate, NULL, 42, 0);
    bulebule_setup(&m);
    rate_rad_s = 2.0;
    assert_int_equal(rreg(&m, 27, 300 * MS), 0x18);
    assert_int_equal(rreg(&m, 106, 300 * MS), 0x10);
    assert_int_equal(rreg(&m, 104, 300 * MS), 0x00); /* its bits clear themselves */
    const unsigned n = 2000;
    double mean, sd, sigma = mpu6500_sigma_dps(&m) * 16.4;
    assert_true(fabs(sigma - 0.01 * sqrt(250.0) * 16.4) < 1e-9);
    stats(&m, n, 300 * MS, &mean, &sd);
    double want = (2.0 * 180.0 / M_PI + m.zro_dps) * 16.4;
    if (fabs(mean - want) > 4.0 * sigma / sqrt(n) + 0.1) fail_msg("mean %.3f, want %.3f", mean, want);
    double sd_want = sqrt(sigma * sigma + 1.0 / 12.0); /* the noise and the rounding */
    if (fabs(sd - sd_want) > 0.1 * sd_want) fail_msg("sd %.3f LSB, want %.3f", sd, sd_want);
    /* FS_SEL 0: 131 LSB/(deg/s) */
    rate_rad_s = 1.0;
    wreg(&m, 27, 0x00, 3000 * MS);
    stats(&m, n, 3001 * MS, &mean, &sd);
    want = (180.0 / M_PI + m.zro_dps) * 131.0;
    if (fabs(mean - want) > 4.0 * 0.01 * sqrt(250.0) * 131.0 / sqrt(n) + 0.1) fail_msg("mean %.3f, want %.3f", mean, want);
}

static void test_deterministic_and_zro_spread(void **state)
{
    mpu6500_t a, b;
    mpu6500_init(&a, &clk, rate, NULL, 9, 0);
    mpu6500_init(&b, &clk, rate, NULL, 9, 0);
    bulebule_setup(&a);
    bulebule_setup(&b);
    rate_rad_s = 0.5;
    for (unsigned k = 0; k < 200; k++) assert_int_equal(gyro_z(&a, (300 + k) * MS), gyro_z(&b, (300 + k) * MS));
    mpu6500_init(&b, &clk, rate, NULL, 10, 0);
    assert_true(a.zro_dps != b.zro_dps);
    double s = 0, s2 = 0;
    for (unsigned seed = 0; seed < 2000; seed++) {
        mpu6500_init(&b, &clk, rate, NULL, seed, 0);
        assert_true(fabs(b.zro_dps) <= 5.0);
        s += b.zro_dps;
        s2 += b.zro_dps * b.zro_dps;
    }
    double sd = sqrt(s2 / 2000 - (s / 2000) * (s / 2000));
    if (fabs(sd - 5.0 / 3.0) > 0.1 * 5.0 / 3.0) fail_msg("ZRO spread %.3f deg/s, want 5/3", sd);
}

/* bulebule's gyro_z_calibration: ZG_OFFS = -(2 x average) at +-2000 deg/s
 * (OffsetLSB = OFFS x 4 / 2^FS_SEL, added): the output centres on 0. */
static void test_user_offset(void **state)
{
    mpu6500_t m;
    mpu6500_init(&m, &clk, rate, NULL, 3, 0);
    bulebule_setup(&m);
    rate_rad_s = 0.0;
    double mean, sd;
    stats(&m, 1000, 300 * MS, &mean, &sd);
    int16_t c2 = (int16_t)-(int16_t)lround(mean * 2);
    wreg(&m, 23, (uint8_t)((uint16_t)c2 >> 8), 1400 * MS);
    wreg(&m, 24, (uint8_t)c2, 1400 * MS);
    stats(&m, 1000, 1500 * MS, &mean, &sd);
    if (fabs(mean) > 1.0) fail_msg("mean after the offset %.3f LSB", mean);
}

static void test_burst_and_saturation(void **state)
{
    mpu6500_t m;
    mpu6500_init(&m, &clk, rate, NULL, 5, 0);
    bulebule_setup(&m);
    rate_rad_s = 1.0;
    mpu6500_select(&m, false);
    mpu6500_exchange(&m, 0x80 | 0x47, 400 * MS);
    uint8_t h = mpu6500_exchange(&m, 0, 400 * MS + 100), l = mpu6500_exchange(&m, 0, 400 * MS + 200);
    mpu6500_select(&m, true);
    assert_int_equal((int16_t)(uint16_t)(h << 8 | l), gyro_z(&m, 400 * MS + 200));
    assert_int_equal(rreg(&m, 0x3F, 400 * MS) << 8 | rreg(&m, 0x40, 400 * MS), 16384); /* accel Z: +1 g at +-2 g */
    rate_rad_s = 50.0; /* 2865 deg/s beyond +-2000 */
    assert_int_equal(gyro_z(&m, 500 * MS), 32767);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_reset_values),
        cmocka_unit_test(test_gyro_z_rate),
        cmocka_unit_test(test_deterministic_and_zro_spread),
        cmocka_unit_test(test_user_offset),
        cmocka_unit_test(test_burst_and_saturation),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}

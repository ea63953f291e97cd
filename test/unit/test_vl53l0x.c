/* test_vl53l0x.c - the VL53L0X model (sim/arm/vl53l0x.h) through the I2C
 * master (sim/arm/stm32_i2c.h) at 400 kHz: the model ID the ST API and the
 * Pololu library check (0xC0 = 0xEE), the stop variable on page 1, the ST
 * API's single ranging sequence (SYSRANGE_START bit 0 clearing, the
 * new-sample status after the 33 ms budget, the range at 0x1E, the
 * interrupt clear), out of range (8190), back-to-back ranging every 33 ms. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <cmocka.h>

#include <stdint.h>

#include "arm/stm32_i2c.h"
#include "arm/vl53l0x.h"

static const mmio_clocks_t clk = { 168000000, 168000000, 42000000, 84000000, 84000000, 168000000, 42000000 };
enum { CR1 = 0x00, CR2 = 0x04, DR = 0x10, SR1 = 0x14, SR2 = 0x18, CCR = 0x1C };
#define PE 1u
#define START (1u << 8)
#define STOP (1u << 9)
#define ACK (1u << 10)

static stm32_i2c_t i2c;
static vl53l0x_t tof;
static uint64_t now;
static double target_mm;

static double range(void *ctx, uint64_t cycle) { return target_mm; }
static uint32_t rd(uint32_t off)
{
    uint32_t v;
    stm32_i2c_ops.advance(&i2c, now);
    assert_int_equal(stm32_i2c_ops.read(&i2c, off, 4, &v), MMIO_OK);
    return v;
}
static void wr(uint32_t off, uint32_t v)
{
    stm32_i2c_ops.advance(&i2c, now);
    assert_int_equal(stm32_i2c_ops.write(&i2c, off, 4, v), MMIO_OK);
}
static void wait(uint32_t flag)
{
    while (!(rd(SR1) & flag)) {
        uint64_t t = stm32_i2c_ops.next_event(&i2c);
        if (t == MMIO_NEVER) fail_msg("I2C flag %x never rose", flag);
        now = t;
    }
}
static void begin(bool read)
{
    wr(CR1, PE | ACK | START);
    wait(1u);
    wr(DR, (VL53L0X_I2C_ADDR << 1) | (read ? 1u : 0u));
    wait(2u);
    rd(SR1);
    rd(SR2);
}
static void write_reg(uint8_t reg, uint8_t v)
{
    begin(false);
    wr(DR, reg);
    wr(DR, v);
    wait(4u);
    wr(CR1, PE | STOP);
    now += 1000;
}
/* Reads n (1 or 2) bytes from reg, most significant first. */
static unsigned read_reg(uint8_t reg, unsigned n)
{
    begin(false);
    wr(DR, reg);
    wait(4u);
    wr(CR1, PE | ACK | START);
    wait(1u);
    wr(DR, (VL53L0X_I2C_ADDR << 1) | 1u);
    wait(2u);
    unsigned v = 0;
    if (n == 1) {
        wr(CR1, PE);
        rd(SR1);
        rd(SR2);
        wr(CR1, PE | STOP);
        wait(1u << 6);
        v = rd(DR);
    } else {
        wr(CR1, PE | (1u << 11)); /* POS */
        rd(SR1);
        rd(SR2);
        wait(4u);
        wr(CR1, PE | (1u << 11) | STOP);
        v = rd(DR) << 8;
        v |= rd(DR);
        wr(CR1, PE);
    }
    now += 1000;
    return v;
}

static void setup_tof(void)
{
    now = 0;
    target_mm = 150.0;
    vl53l0x_init(&tof, &clk, range, NULL);
    stm32_i2c_init(&i2c, 1, &clk, (mmio_irq_t){ NULL, NULL }, (mmio_dma_req_t){ NULL, NULL }, 0, 0);
    stm32_i2c_attach(&i2c, (stm32_i2c_slave_t){ VL53L0X_I2C_ADDR, vl53l0x_i2c_start, vl53l0x_i2c_write,
                                               vl53l0x_i2c_read, vl53l0x_i2c_stop, &tof });
    wr(CR2, 42);
    wr(CCR, (1u << 15) | 35u); /* 400 kHz */
    wr(CR1, PE);
}

/* The ST API's VL53L0X_PerformSingleRangingMeasurement as Pololu's readRangeSingleMillimeters writes it. */
static unsigned single_range(uint8_t stop_variable, uint64_t *started, uint64_t *ready)
{
    write_reg(0x80, 0x01);
    write_reg(0xFF, 0x01);
    write_reg(0x00, 0x00);
    write_reg(0x91, stop_variable);
    write_reg(0x00, 0x01);
    write_reg(0xFF, 0x00);
    write_reg(0x80, 0x00);
    write_reg(0x00, 0x01);
    *started = now;
    while (read_reg(0x00, 1) & 1u) {}
    while ((read_reg(0x13, 1) & 7u) == 0) now += 168000; /* poll each ms */
    *ready = now;
    unsigned mm = read_reg(0x14 + 10, 2);
    write_reg(0x0B, 0x01);
    assert_int_equal(read_reg(0x13, 1) & 7u, 0);
    return mm;
}

static void test_identity(void **state)
{
    setup_tof();
    assert_int_equal(read_reg(0xC0, 1), 0xEE);
    assert_int_equal(read_reg(0xC2, 1), 0x10);
    write_reg(0x80, 0x01);
    write_reg(0xFF, 0x01);
    write_reg(0x00, 0x00);
    assert_int_equal(read_reg(0x91, 1), 0x3C); /* the stop variable, page 1 */
    write_reg(0x00, 0x01);
    write_reg(0xFF, 0x00);
    write_reg(0x80, 0x00);
    assert_int_equal(read_reg(0xC0, 1), 0xEE); /* page 0 again */
    write_reg(0x44, 0x12);                     /* a tuning register: stored */
    assert_int_equal(read_reg(0x44, 1), 0x12);
}

static void test_single_ranging(void **state)
{
    setup_tof();
    uint64_t started, ready;
    assert_int_equal(single_range(0x3C, &started, &ready), 150);
    /* the 33 ms budget = 5,544,000 cycles at 168 MHz, found by 1 ms polls */
    assert_true(ready - started >= 5544000u);
    assert_true(ready - started < 5544000u + 168000u + 200000u);
    assert_int_equal(read_reg(0x14, 1) >> 3, 11); /* range valid */
    target_mm = 2500.0;
    assert_int_equal(single_range(0x3C, &started, &ready), 8190);
    assert_int_equal(read_reg(0x14, 1) >> 3, 4);
    assert_int_equal(tof.measurements, 2);
}

static void test_back_to_back(void **state)
{
    setup_tof();
    write_reg(0x00, 0x02 | 0x01);
    uint64_t t0 = now;
    now = t0 + 5544000u - 200000u;
    assert_int_equal(read_reg(0x13, 1) & 7u, 0);
    now = t0 + 5544000u;
    assert_int_equal(read_reg(0x13, 1) & 7u, 4);
    write_reg(0x0B, 0x01);
    target_mm = 321.0;
    now = t0 + 2 * 5544000u + 10000u;
    assert_int_equal(read_reg(0x13, 1) & 7u, 4);
    assert_int_equal(read_reg(0x1E, 2), 321);
    write_reg(0x00, 0x00); /* stop */
    write_reg(0x0B, 0x01);
    now += 3 * 5544000u;
    assert_int_equal(read_reg(0x13, 1) & 7u, 0);
    assert_int_equal(tof.measurements, 2);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_identity),
        cmocka_unit_test(test_single_ranging),
        cmocka_unit_test(test_back_to_back),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}

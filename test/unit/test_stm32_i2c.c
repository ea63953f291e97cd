/* test_stm32_i2c.c - the STM32 I2C master model (sim/arm/stm32_i2c.h)
 * against RM0090 section 27 (RM0008 section 26 the same) with an MPU-6050
 * (sim/arm/mpu6500.h's engine) at 0x68 on I2C1, PCLK1 42 MHz, HCLK 168 MHz:
 * HAL_I2C_Mem_Read's WHO_AM_I sequence returns 0x68 with its flags in the
 * manual's order (SB, ADDR, TxE/BTF, repeated start, NACK'd single byte and
 * STOP) and 100 kHz timing (9 SCL periods of 1680 cycles a byte); a
 * register write wakes the chip; a 2-byte read with POS (figure 242's
 * method) gets GYRO_ZOUT; a NACK'd address sets AF and the error IRQ 32;
 * fast mode at 400 kHz; the MPU-6050's own reset values. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <cmocka.h>

#include <math.h>
#include <stdint.h>

#include "arm/mpu6500.h"
#include "arm/stm32_i2c.h"

static const mmio_clocks_t clk = { 168000000, 168000000, 42000000, 84000000, 84000000, 168000000, 42000000 };

enum { CR1 = 0x00, CR2 = 0x04, DR = 0x10, SR1 = 0x14, SR2 = 0x18, CCR = 0x1C, TRISE = 0x20 };
#define PE 1u
#define START (1u << 8)
#define STOP (1u << 9)
#define ACK (1u << 10)
#define POS (1u << 11)
#define SB 1u
#define ADDR 2u
#define BTF 4u
#define RXNE (1u << 6)
#define TXE (1u << 7)
#define AF (1u << 10)
#define MSL 1u
#define BUSY 2u
#define TRA 4u

static stm32_i2c_t i2c;
static mpu6500_t mpu;
static uint64_t now;
static bool irq[96];

static void irq_set(void *ctx, unsigned n, bool level) { irq[n] = level; }
static double spin(void *ctx, uint64_t cycle) { return 1.0; } /* rad/s */

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
/* Poll SR1 as the HAL does, jumping to each event: the cycle the flag rose. */
static uint64_t wait(uint32_t flag)
{
    for (int n = 0; n < 100; n++) {
        if (rd(SR1) & flag) return now;
        uint64_t t = stm32_i2c_ops.next_event(&i2c);
        if (t == MMIO_NEVER) fail_msg("waiting for %x at %llu: no event (cr1 %x sr1 %x sr2 %x phase %d)", flag, (unsigned long long)now, i2c.cr1, i2c.sr1, i2c.sr2, i2c.phase);
        now = t;
    }
    fail_msg("flag %x never rose", flag);
    return 0;
}

static void setup_bus(uint32_t ccr)
{
    now = 0;
    for (unsigned k = 0; k < 96; k++) irq[k] = false;
    mpu6050_init(&mpu, &clk, spin, NULL, 7, 0);
    stm32_i2c_init(&i2c, 1, &clk, (mmio_irq_t){ irq_set, NULL }, (mmio_dma_req_t){ NULL, NULL }, 0, 0);
    assert_true(stm32_i2c_attach(&i2c, (stm32_i2c_slave_t){ 0x68, mpu6500_i2c_start, mpu6500_i2c_write,
                                                              mpu6500_i2c_read, mpu6500_i2c_stop, &mpu }));
    wr(CR2, 42); /* FREQ: 42 MHz */
    wr(CCR, ccr);
    wr(TRISE, 43);
    wr(CR1, PE);
}

/* HAL_I2C_Mem_Read of one register: the cycle each phase ended in t[]. */
static uint8_t mem_read1(uint8_t reg, uint64_t t[6])
{
    wr(CR1, PE | ACK | START);
    t[0] = wait(SB);
    assert_int_equal(rd(SR2) & (MSL | BUSY), MSL | BUSY);
    wr(DR, 0x68u << 1);
    t[1] = wait(ADDR);
    rd(SR1);
    assert_int_equal(rd(SR2) & TRA, TRA);
    assert_true(rd(SR1) & TXE);
    wr(DR, reg);
    t[2] = wait(BTF);
    wr(CR1, PE | ACK | START); /* repeated start */
    t[3] = wait(SB);
    wr(DR, (0x68u << 1) | 1u);
    t[4] = wait(ADDR);
    wr(CR1, PE);               /* ACK = 0: NACK the only byte */
    rd(SR1);
    assert_int_equal(rd(SR2) & TRA, 0);
    wr(CR1, PE | STOP);
    t[5] = wait(RXNE);
    uint8_t v = (uint8_t)rd(DR);
    now += 2000;
    assert_int_equal(rd(SR2) & (MSL | BUSY), 0); /* the stop condition is done */
    assert_int_equal(rd(CR1) & STOP, 0);
    return v;
}

static void mem_write1(uint8_t reg, uint8_t v)
{
    wr(CR1, PE | ACK | START);
    wait(SB);
    wr(DR, 0x68u << 1);
    wait(ADDR);
    rd(SR1);
    rd(SR2);
    wr(DR, reg);
    wr(DR, v); /* DR while the register address shifts: TxE falls */
    assert_false(rd(SR1) & TXE);
    wait(BTF);
    wr(CR1, PE | ACK | STOP);
    now += 2000;
}

static void test_who_am_i(void **state)
{
    setup_bus(210); /* standard mode 100 kHz: 2 x 210 / 42 MHz = 10 us = 1680 cycles */
    uint64_t t[6];
    assert_int_equal(mem_read1(0x75, t), 0x68);
    assert_int_equal(t[0], 1680);             /* START: one period */
    assert_int_equal(t[1] - t[0], 9 * 1680);  /* the address and its ACK */
    assert_int_equal(t[2] - t[1], 9 * 1680);
    assert_int_equal(t[3] - t[2], 1680);
    assert_int_equal(t[4] - t[3], 9 * 1680);
    assert_int_equal(t[5] - t[4], 9 * 1680);
    assert_int_equal(i2c.bytes, 2);
}

static void test_mpu6050_registers(void **state)
{
    setup_bus(210);
    uint64_t t[6];
    assert_int_equal(mem_read1(0x6B, t), 0x40); /* PWR_MGMT_1: asleep after reset (6050 RM section 3) */
    mem_write1(0x6B, 0x00);                     /* wake */
    assert_int_equal(mem_read1(0x6B, t), 0x00);
    mem_write1(0x1B, 0x18);                     /* GYRO_CONFIG FS_SEL 3: 16.4 LSB/(deg/s) */
    now += 168000;                              /* 1 ms: a new sample at 8 kHz */
    /* a 2-byte read of GYRO_ZOUT_H/L with POS (RM0090 27.3.3, figure 242 note) */
    wr(CR1, PE | ACK | START);
    wait(SB);
    wr(DR, 0x68u << 1);
    wait(ADDR);
    rd(SR1);
    rd(SR2);
    wr(DR, 0x47);
    wait(BTF);
    wr(CR1, PE | ACK | START);
    wait(SB);
    wr(DR, (0x68u << 1) | 1u);
    wait(ADDR);
    wr(CR1, PE | POS); /* ACK 0 applies to the 2nd byte */
    rd(SR1);
    rd(SR2);
    wait(BTF);         /* byte 1 in DR, byte 2 in the shift register */
    wr(CR1, PE | POS | STOP);
    int16_t z = (int16_t)(uint16_t)(rd(DR) << 8 | rd(DR));
    /* 1 rad/s = 57.3 deg/s x 16.4 = 940 LSB, + ZRO (within +-20 deg/s: +-328 LSB) + noise */
    assert_in_range(z, 940 - 340, 940 + 340);
    assert_true(fabs((double)z - (940.0 + mpu.zro_dps * 16.4)) < 10.0);
    /* TEMP_OUT at 25 degC: (25 - 36.53) x 340 = -3920 */
    uint64_t tt[6];
    int16_t temp = (int16_t)(uint16_t)(mem_read1(0x41, tt) << 8 | mem_read1(0x42, tt));
    assert_int_equal(temp, -3920);
}

static void test_nack_and_errors(void **state)
{
    setup_bus(210);
    wr(CR2, 42 | (1u << 8) | (1u << 9)); /* ITERREN, ITEVTEN */
    wr(CR1, PE | ACK | START);
    wait(SB);
    assert_true(irq[31]);                 /* SB is an event */
    rd(SR1);
    wr(DR, 0x29u << 1);                   /* nobody at 0x29 */
    wait(AF);
    assert_false(rd(SR1) & ADDR);
    assert_true(irq[32]);
    wr(SR1, ~AF);                         /* rc_w0 */
    assert_false(irq[32]);
    wr(CR1, PE | STOP);
    now += 2000;
    assert_int_equal(rd(SR2) & BUSY, 0);
    /* unmodeled: SMBus, LAST */
    assert_int_equal(stm32_i2c_ops.write(&i2c, CR1, 4, PE | 2u), MMIO_UNMODELED);
    assert_int_equal(stm32_i2c_ops.write(&i2c, CR2, 4, 42 | (1u << 12)), MMIO_UNMODELED);
    uint32_t v;
    assert_int_equal(stm32_i2c_ops.read(&i2c, 0x24, 4, &v), MMIO_UNMODELED);
}

/* DMAEN: TxE and RxNE raise the DMA requests the board numbered (27.3.7). */
static bool req[8];
static void dma_req(void *ctx, unsigned ch, bool level) { req[ch] = level; }

static void test_dma_requests(void **state)
{
    setup_bus(210);
    for (unsigned k = 0; k < 8; k++) req[k] = false;
    stm32_i2c_init(&i2c, 1, &clk, (mmio_irq_t){ irq_set, NULL }, (mmio_dma_req_t){ dma_req, NULL }, 6, 5);
    assert_true(stm32_i2c_attach(&i2c, (stm32_i2c_slave_t){ 0x68, mpu6500_i2c_start, mpu6500_i2c_write,
                                                              mpu6500_i2c_read, mpu6500_i2c_stop, &mpu }));
    wr(CR2, 42 | (1u << 11)); /* DMAEN */
    wr(CCR, 210);
    wr(CR1, PE | ACK | START);
    wait(SB);
    wr(DR, 0x68u << 1);
    wait(ADDR);
    assert_false(req[6]);
    rd(SR1);
    rd(SR2);
    assert_true(req[6]);  /* TxE: the TX request */
    wr(DR, 0x75);
    wr(DR, 0x00);         /* DR full behind the shift register */
    assert_false(req[6]);
    wait(TXE);
    assert_true(req[6]);
    wait(BTF);
    wr(CR1, PE | ACK | START);
    wait(SB);
    assert_false(req[6]);
    wr(DR, (0x68u << 1) | 1u);
    wait(ADDR);
    rd(SR1);
    rd(SR2);
    wait(RXNE);
    assert_true(req[5]);  /* RxNE: the RX request */
    rd(DR);
    assert_false(req[5]);
}

static void test_fast_mode(void **state)
{
    setup_bus((1u << 15) | 35u); /* F/S, DUTY 0: 3 x 35 / 42 MHz = 2.5 us = 420 cycles */
    uint64_t t[6];
    assert_int_equal(mem_read1(0x75, t), 0x68);
    assert_int_equal(t[0], 420);
    assert_int_equal(t[1] - t[0], 9 * 420);
    wr(CR1, PE | (1u << 15)); /* SWRST: registers to reset */
    assert_int_equal(rd(TRISE), 2);
    assert_int_equal(rd(CCR), 0);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_who_am_i),
        cmocka_unit_test(test_mpu6050_registers),
        cmocka_unit_test(test_nack_and_errors),
        cmocka_unit_test(test_dma_requests),
        cmocka_unit_test(test_fast_mode),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}

/* test_stm32_spi.c - the STM32F1 SPI master model (sim/arm/stm32f1_spi.h)
 * against RM0008 section 25, with the MPU-6500 (sim/arm/mpu6500.h) on SPI2
 * as bulebule wires it: a WHO_AM_I read returns 0x70 with the frame timing
 * of its baud rate, BSY/TXE/RXNE in their order, overrun, mode fault. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <cmocka.h>

#include <stdint.h>

#include "arm/mpu6500.h"
#include "arm/stm32f1_spi.h"

static const mmio_clocks_t clk = { 72000000, 72000000, 36000000, 72000000, 72000000, 72000000, 9000000 };

enum { CR1 = 0x00, CR2 = 0x04, SR = 0x08, DR = 0x0C, CRCPR = 0x10 };
#define MSTR (1u << 2)
#define BR(x) ((uint32_t)(x) << 3)
#define SPE (1u << 6)
#define SSI (1u << 8)
#define SSM (1u << 9)
#define CRCEN (1u << 13)
#define RXNEIE (1u << 6)
#define S_RXNE 1u
#define S_TXE 2u
#define S_MODF (1u << 5)
#define S_OVR (1u << 6)
#define S_BSY (1u << 7)

static stm32_spi_t spi;
static mpu6500_t mpu;
static bool irq_level;

static void irq_set(void *ctx, unsigned irq, bool level) { assert_int_equal(irq, 36); irq_level = level; }

static void setup_spi(void)
{
    irq_level = false;
    mpu6500_init(&mpu, &clk, NULL, NULL, 1, 0);
    mpu6500_select(&mpu, true);
    stm32_spi_init(&spi, 2, &clk, (mmio_irq_t){ irq_set, NULL }, (mmio_dma_req_t){ NULL, NULL },
                   (stm32_spi_slave_t){ mpu6500_exchange, &mpu });
}
static uint32_t rd(uint32_t off, uint64_t now)
{
    uint32_t v;
    stm32_spi_ops.advance(&spi, now);
    assert_int_equal(stm32_spi_ops.read(&spi, off, 4, &v), MMIO_OK);
    return v;
}
static void wr(uint32_t off, uint32_t v, uint64_t now)
{
    stm32_spi_ops.advance(&spi, now);
    assert_int_equal(stm32_spi_ops.write(&spi, off, 4, v), MMIO_OK);
}

static void test_reset(void **state)
{
    setup_spi();
    assert_int_equal(rd(SR, 0), 0x0002);
    assert_int_equal(rd(CRCPR, 0), 0x0007);
}

/* bulebule's setup_spi_high_speed and mpu_read_register(WHO_AM_I): fPCLK1/2 =
 * 18 MHz, 8 bits = 16 PCLK1 cycles = 32 core cycles a frame. */
static void test_who_am_i(void **state)
{
    setup_spi();
    wr(CR1, MSTR | BR(0) | SSM | SSI | SPE, 0);
    mpu6500_select(&mpu, false);
    wr(DR, 0x80 | 0x75, 100);
    uint32_t sr = rd(SR, 100);
    assert_true(sr & S_TXE); /* into the shifter at once */
    assert_true(sr & S_BSY);
    assert_false(sr & S_RXNE);
    assert_int_equal(stm32_spi_ops.next_event(&spi), 132);
    sr = rd(SR, 131);
    assert_true(sr & S_BSY);
    assert_false(sr & S_RXNE);
    sr = rd(SR, 132);
    assert_true(sr & S_RXNE);
    assert_false(sr & S_BSY);
    rd(DR, 132);
    assert_false(rd(SR, 132) & S_RXNE);
    wr(DR, 0x00, 140);
    assert_false(rd(SR, 171) & S_RXNE);
    assert_int_equal(rd(DR, 172), 0x70);
    mpu6500_select(&mpu, true);
}

/* setup_spi_low_speed: fPCLK1/64: a frame of 8 x 64 PCLK1 cycles = 1024 core cycles. */
static void test_low_speed_and_back_to_back(void **state)
{
    setup_spi();
    wr(CR1, MSTR | BR(5) | SSM | SSI | SPE, 0);
    wr(DR, 0x11, 0);
    wr(DR, 0x22, 0); /* TDR behind the shifter */
    assert_false(rd(SR, 0) & S_TXE);
    assert_true(rd(SR, 1023) & S_BSY);
    uint32_t sr = rd(SR, 1024);
    assert_true(sr & S_TXE); /* 0x22 into the shifter; BSY stays: a continuous transfer */
    assert_true(sr & S_BSY);
    assert_true(sr & S_RXNE);
    /* the second frame ends with RXNE still set: overrun, the buffer keeps the first byte */
    sr = rd(SR, 2048);
    assert_true(sr & S_OVR);
    assert_false(sr & S_BSY);
    assert_int_equal(rd(DR, 2048), 0xFF); /* nothing selected on the bus */
    assert_true(rd(SR, 2048) & S_OVR);    /* DR read then SR read clears it, after this read */
    assert_false(rd(SR, 2048) & S_OVR);
}

static void test_interrupt(void **state)
{
    setup_spi();
    wr(CR1, MSTR | SSM | SSI | SPE, 0);
    wr(CR2, RXNEIE, 0);
    wr(DR, 0, 0);
    assert_false(irq_level);
    stm32_spi_ops.advance(&spi, 32);
    assert_true(irq_level);
    rd(DR, 32);
    assert_false(irq_level);
}

/* TXDMAEN/RXDMAEN: SPI2's requests on DMA1 channels 5 (TX) and 4 (RX) (RM0008 Table 78). */
static bool req[8];
static unsigned rises[8];
static void dma_req(void *ctx, unsigned ch, bool level) { rises[ch] += level && !req[ch]; req[ch] = level; }

static void test_dma_requests(void **state)
{
    setup_spi();
    stm32_spi_init(&spi, 2, &clk, (mmio_irq_t){ irq_set, NULL }, (mmio_dma_req_t){ dma_req, NULL },
                   (stm32_spi_slave_t){ NULL, NULL });
    wr(CR1, MSTR | SSM | SSI | SPE, 0);
    wr(CR2, 3u, 0); /* RXDMAEN, TXDMAEN */
    assert_true(req[5]);
    assert_false(req[4]);
    unsigned r0 = rises[5];
    wr(DR, 0xA5, 0);
    assert_int_equal(rises[5], r0 + 1); /* TXE fell at the write and rose as the shifter took it: a new request */
    wr(DR, 0x5A, 0);
    assert_false(req[5]); /* TX buffer full */
    stm32_spi_ops.advance(&spi, 32);
    assert_true(req[5]);
    assert_true(req[4]);
    rd(DR, 32);
    assert_false(req[4]);
}

static void test_mode_fault_and_unmodeled(void **state)
{
    setup_spi();
    wr(CR1, MSTR | SSM | SPE, 0); /* NSS (SSI) low in master mode */
    uint32_t sr = rd(SR, 0);
    assert_true(sr & S_MODF);
    assert_int_equal(rd(CR1, 0) & (SPE | MSTR), 0);
    wr(CR1, MSTR | SSM | SSI, 1); /* SR read then CR1 write clears MODF */
    assert_false(rd(SR, 1) & S_MODF);
    wr(CR1, MSTR | SSM, 2); /* disabled: no mode fault (libopencm3's set-up order) */
    assert_false(rd(SR, 2) & S_MODF);
    assert_int_equal(rd(CR1, 2) & MSTR, MSTR);
    assert_int_equal(stm32_spi_ops.write(&spi, CR1, 4, MSTR | SSM | SSI | CRCEN), MMIO_UNMODELED);
    assert_int_equal(stm32_spi_ops.write(&spi, CR1, 4, SSM | SSI | SPE), MMIO_UNMODELED); /* slave */
    uint32_t v;
    assert_int_equal(stm32_spi_ops.read(&spi, 0x1C, 4, &v), MMIO_UNMODELED); /* I2SCFGR */
    assert_int_equal(stm32_spi_ops.write(&spi, CR2, 4, 1u << 4), MMIO_UNMODELED); /* FRF: the F4's TI mode */
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_reset),
        cmocka_unit_test(test_who_am_i),
        cmocka_unit_test(test_low_speed_and_back_to_back),
        cmocka_unit_test(test_interrupt),
        cmocka_unit_test(test_dma_requests),
        cmocka_unit_test(test_mode_fault_and_unmodeled),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}

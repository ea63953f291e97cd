/* test_stm32f4_soc.c - the STM32F405 SoC (sim/arm/stm32f4_soc.c) running our
 * own register-level firmware (test/firmware/armf4, build/armf4/f4test.elf) on the
 * Cortex-M4 core: one scenario per test, picked with pins PE0-PE3, each
 * checked against RM0090 rev 19 (and DS8626 rev 9 for timings) from the
 * mailbox in SRAM, the models' state and what the board sees (pins,
 * serial bytes, I2C slaves). Each fails if the behaviour it checks breaks:
 * the firmware waits on the flags the reference manual says rise. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <cmocka.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "arm/armcore.h"
#include "arm/armimage.h"
#include "arm/mpu6500.h"
#include "arm/stm32f4_soc.h"
#include "arm/vl53l0x.h"
#include "../test/firmware/armf4/f4test.h"

#define IMAGE "build/armf4/f4test.elf"
#define HSE_HZ 8000000u
#define F_CPU 168000000u
#define CHUNK 100000u
#define MAX_PIN_EVENTS 64
#define MAX_BYTES 64
#define GYRO_RATE_RAD_S 1.0 /* the rate the MPU-6050's z axis turns at */
#define RANGE_MM 150.0      /* the VL53L0X's target */

typedef struct { unsigned port, pin; int level; uint64_t cycle; } pin_ev_t;

typedef struct {
    armimage_t img;
    stm32f4_soc_t soc;
    armcore_t *core;
    mpu6500_t mpu;
    mpu6500_t gyro;      /* the MPU-6500 on SPI1, nCS on PA4 */
    vl53l0x_t tof;
    pin_ev_t pins[MAX_PIN_EVENTS];
    int npins;
    uint8_t bytes[MAX_BYTES];
    uint64_t byte_cycle[MAX_BYTES];
    int nbytes;
} rig_t;

/* ADC1's channels: 0.5, 1.0, 2.0 V on IN0-IN2 */
static double volts(void *ctx, unsigned ch, uint64_t cycle)
{
    (void)ctx, (void)cycle;
    return ch == 0 ? 0.5 : ch == 1 ? 1.0 : ch == 2 ? 2.0 : 0.0;
}

static void on_pin(void *ctx, unsigned port, unsigned pin, int level)
{
    rig_t *r = ctx;
    if (port == 0 && pin == SPI_CS_PIN) mpu6500_select(&r->gyro, level != 0);
    /* port B changes come from DMA2's transfers: the cycle the controller is at */
    if (r->npins < MAX_PIN_EVENTS) r->pins[r->npins++] = (pin_ev_t){ port, pin, level, r->soc.dma[1].now };
}

static void on_byte(void *ctx, uint8_t b, uint64_t cycle)
{
    rig_t *r = ctx;
    if (r->nbytes < MAX_BYTES) r->bytes[r->nbytes] = b, r->byte_cycle[r->nbytes++] = cycle;
}

static double gyro_rate(void *ctx, uint64_t cycle) { (void)ctx, (void)cycle; return GYRO_RATE_RAD_S; }
static double tof_range(void *ctx, uint64_t cycle) { (void)ctx, (void)cycle; return RANGE_MM; }

static rig_t *rig_new(unsigned scenario)
{
    rig_t *r = calloc(1, sizeof *r);
    char err[300];
    assert_non_null(r);
    if (armimage_read(IMAGE, armimage_mcu("stm32f405xg"), &r->img, err, sizeof err) != 0) fail_msg("%s (make %s)", err, IMAGE);
    stm32f4_soc_io_t io = { .volts = volts, .pin = on_pin, .pin_ctx = r, .usart_sink = on_byte, .usart_ctx = r };
    armcore_cfg_t cfg = { .image = &r->img };
    if (stm32f4_soc_init(&r->soc, &r->core, &cfg, HSE_HZ, &io, err, sizeof err) != 0) fail_msg("%s", err);
    for (unsigned b = 0; b < 4; b++) stm32f4_gpio_input(stm32f4_soc_gpio(&r->soc, 4), b, true, (scenario >> b) & 1u);
    const mmio_clocks_t *clk = stm32f4_soc_clocks(&r->soc);
    mpu6050_init(&r->mpu, clk, gyro_rate, r, 1, 0);
    vl53l0x_init(&r->tof, clk, tof_range, r);
    mpu6500_init(&r->gyro, clk, gyro_rate, r, 2, 1);
    stm32_spi_attach(stm32f4_soc_spi(&r->soc, 1), (stm32_spi_slave_t){ mpu6500_exchange, &r->gyro });
    stm32_i2c_t *i2c = stm32f4_soc_i2c(&r->soc, 1);
    assert_true(stm32_i2c_attach(i2c, (stm32_i2c_slave_t){ 0x68, mpu6500_i2c_start, mpu6500_i2c_write, mpu6500_i2c_read,
                                                            mpu6500_i2c_stop, &r->mpu }));
    assert_true(stm32_i2c_attach(i2c, (stm32_i2c_slave_t){ VL53L0X_I2C_ADDR, vl53l0x_i2c_start, vl53l0x_i2c_write,
                                                            vl53l0x_i2c_read, vl53l0x_i2c_stop, &r->tof }));
    r->npins = 0; /* the ports' power-on levels */
    return r;
}

static void rig_free(rig_t *r)
{
    stm32f4_soc_free(&r->soc);
    armimage_free(&r->img);
    free(r);
}

static mailbox_t mailbox(rig_t *r)
{
    mailbox_t mb;
    assert_int_equal(armcore_read(r->core, 0x20000000u, &mb, sizeof mb), 0);
    return mb;
}

static void no_crash(rig_t *r)
{
    uint32_t pc;
    const char *cause;
    if (armcore_crashed(r->core, &pc, &cause)) fail_msg("crashed at 0x%08x: %s", pc, cause);
}

/* Run until the mailbox says field (done or step) >= want, at most max cycles. */
static mailbox_t run_until(rig_t *r, size_t field, uint32_t want, uint64_t max)
{
    mailbox_t mb = mailbox(r);
    while (armcore_cycles(r->core) < max) {
        armcore_run_to(r->core, armcore_cycles(r->core) + CHUNK);
        no_crash(r);
        mb = mailbox(r);
        uint32_t v;
        memcpy(&v, (const char *)&mb + field, sizeof v);
        if (v >= want) return mb;
    }
    fail_msg("scenario %u not there after %llu cycles (step %u, done %u, log %u; v 0x%x 0x%x 0x%x 0x%x 0x%x 0x%x)",
             mb.scenario, (unsigned long long)max, mb.step, mb.done, mb.nlog, mb.v[0], mb.v[1], mb.v[2], mb.v[3],
             mb.v[4], mb.v[5]);
    return mb;
}

static mailbox_t run_done(rig_t *r, uint64_t max) { return run_until(r, offsetof(mailbox_t, done), 1, max); }

static void no_unmodeled(rig_t *r)
{
    int n;
    const armcore_unmodeled_t *u = armcore_unmodeled(r->core, &n);
    for (int i = 0; i < n; i++) fail_msg("unmodeled register 0x%08x (%s)", u[i].addr, u[i].region);
}

/* RM0090 6.3.1-6.3.3: HSE 8 MHz, PLL M 8 N 336 P 2 -> 168 MHz (PLLON through the bit-band alias, 2.3.2),
 * APB1 /4 42 MHz, APB2 /2 84 MHz, timers x2; FLASH ACR LATENCY 5 read back (3.5.1 table 10); SysTick 1 kHz
 * from HCLK (PM0214 4.5) driving HAL_Delay(10): 11 ticks, 10-11 ms */
static void test_clock_setup(void **state)
{
    (void)state;
    rig_t *r = rig_new(SC_CLOCK);
    mailbox_t mb = run_done(r, 40u * 1000u * 1000u);
    const mmio_clocks_t *c = stm32f4_soc_clocks(&r->soc);
    assert_int_equal(c->sysclk, F_CPU);
    assert_int_equal(c->hclk, F_CPU);
    assert_int_equal(c->pclk1, 42000000u);
    assert_int_equal(c->pclk2, 84000000u);
    assert_int_equal(c->tim_apb1, 84000000u);
    assert_int_equal(c->tim_apb2, F_CPU);
    assert_int_equal(mb.v[0], 0x705u);                 /* LATENCY 5, PRFTEN, ICEN, DCEN */
    assert_int_equal(mb.v[3] & 0xCu, 0x8u);            /* SWS = PLL */
    assert_int_equal((mb.v[3] >> 10) & 7u, 5u);
    assert_int_equal((mb.v[3] >> 13) & 7u, 4u);
    assert_int_equal(mb.v[5], 1u);                     /* PLLRDY through the alias */
    assert_true(mb.v[6] & (1u << 14));                 /* PWR VOSRDY with the PLL on (5.4.2) */
    assert_int_equal(mb.v[2], 11u);                    /* HAL_Delay(10): 11 ticks */
    assert_true(mb.v[1] > 10u * (F_CPU / 1000u) && mb.v[1] <= 11u * (F_CPU / 1000u) + 200u);
    /* HSE start-up 2 ms (DS8626 6.3.7 tsu(HSE) typ) at HSI 16 MHz happened before the PLL */
    assert_true(armcore_time_ps(r->core) > 2000000000ull + 11000000000ull);
    assert_int_equal(stm32f4_soc_gated_accesses(&r->soc), 0);
    no_unmodeled(r);
    rig_free(r);
}

/* TIM2 TRGO on update (MMS 010, 18.4.2) at 1 kHz triggers ADC1's regular scan IN0-IN2 (EXTSEL 0110 table 69,
 * EXTEN rising, 13.6), each result moved by DMA2 stream 0 channel 0 (table 43) into a circular buffer of two
 * scans: HT after each first scan, TC after each second (10.3.8, 10.5.5), the codes V / 3.3 V x 4095; ADC's
 * EOC interrupt once per scan (EOCS 0, 13.9) */
static void test_adc_scan_dma(void **state)
{
    (void)state;
    rig_t *r = rig_new(SC_ADC_DMA);
    mailbox_t mb = run_done(r, 60u * 1000u * 1000u);
    assert_int_equal(mb.nlog, 8);
    for (unsigned i = 0; i < 8; i++) assert_int_equal(mb.log[i] >> 8, (i % 2) ? 'T' : 'H');
    const double want[3] = { 0.5, 1.0, 2.0 };
    for (unsigned i = 0; i < ADC_BUF; i++) {
        double code = want[i % 3] / 3.3 * 4095.0;
        if (fabs(mb.v[12 + i] - code) > 1.0) fail_msg("buffer[%u] %u, want %.1f", i, mb.v[12 + i], code);
    }
    assert_int_equal(mb.v[1] & (1u << 5), 0);           /* no OVR */
    assert_int_equal(mb.v[18], 8);                     /* an EOC interrupt per scan (EOCS 0) */
    assert_true(mb.v[19] & (1u << 4));                 /* STRT seen */
    assert_int_equal(mb.v[2], ADC_BUF);                 /* NDTR reloaded (circular) */
    assert_int_equal(r->soc.tim[STM32F4_TIM2].trig_want, 1u << STM32_TIM_TRGO); /* EXTSEL 0110: TIM2's TRGO alone */
    assert_int_equal(r->soc.tim[STM32F4_TIM1].trig_want, 0);
    /* HT at v[5], v[7], v[9], v[11]: 2 ms apart (two 1 kHz triggers per half); the first 1 ms after CEN plus a scan */
    for (unsigned k = 7; k <= 11; k += 2) {
        long d = (long)(mb.v[k] - mb.v[k - 2]) - 2L * (F_CPU / 1000);
        if (labs(d) > 100) fail_msg("HT %u: %u cycles after the previous", k, mb.v[k] - mb.v[k - 2]);
    }
    uint32_t first = mb.v[5] - mb.v[0];
    /* the first update 1 ms after CEN, then the scan: 3 x (56 + 12) ADC clocks at 21 MHz (13.5) */
    assert_true(first > F_CPU / 1000u + 3u * 68u * 8u && first < F_CPU / 1000u + 3u * 68u * 8u + 200u);
    no_unmodeled(r);
    rig_free(r);
}

/* TIM1 CC1 (CCR1 50 of a 100 us period at 1 MHz) requests DMA2 stream 1 channel 6 (table 43), which writes
 * GPIOB BSRR (8.4.7) from a pattern: PB0/PB1 change at each compare, 100 us apart; TC after 6 transfers */
static void test_tim_dma_gpio(void **state)
{
    (void)state;
    rig_t *r = rig_new(SC_TIM_DMA_GPIO);
    mailbox_t mb = run_done(r, 40u * 1000u * 1000u);
    const struct { unsigned pin; int level; unsigned k; } want[8] = {
        { 0, 1, 0 }, { 0, 0, 1 }, { 1, 1, 2 }, { 1, 0, 3 }, { 0, 1, 4 }, { 1, 1, 4 }, { 0, 0, 5 }, { 1, 0, 5 } };
    int n = 0;
    pin_ev_t ev[8];
    for (int i = 0; i < r->npins; i++)
        if (r->pins[i].port == 1 && r->pins[i].pin < 2 && n < 8) ev[n++] = r->pins[i];
    assert_int_equal(n, 8);
    for (int i = 0; i < 8; i++) {
        assert_int_equal(ev[i].pin, want[i].pin);
        assert_int_equal(ev[i].level, want[i].level);
        assert_int_equal(ev[i].cycle - ev[0].cycle, (uint64_t)want[i].k * 100u * (F_CPU / 1000000u));
    }
    /* CEN to TC's interrupt (DWT CYCCNT): the first compare at CNT 50, five periods more */
    uint32_t tc = mb.v[3] - mb.v[0];
    assert_true(tc >= 550u * (F_CPU / 1000000u) && tc < 550u * (F_CPU / 1000000u) + 200u);
    assert_int_equal(mb.v[1], 0);                      /* NDTR 0: done, stream disabled */
    assert_int_equal(mb.v[2] & 3u, 0);
    assert_int_equal(mb.nlog, 1);
    assert_int_equal(mb.log[0], EV('T', 1));
    no_unmodeled(r);
    rig_free(r);
}

/* I2C1 at 100 kHz (27.6.8: CCR 210 at PCLK1 42 MHz: 10 us SCL): MPU-6050 WHO_AM_I 0x68 (RM-MPU-6000A 4.32),
 * woken through PWR_MGMT_1, gyro Z at 131 LSB/(deg/s); VL53L0X model ID 0xEE, a single range after the
 * 33 ms budget, 150 mm */
static void test_i2c_mpu6050_vl53l0x(void **state)
{
    (void)state;
    rig_t *r = rig_new(SC_I2C);
    mailbox_t mb = run_done(r, 200u * 1000u * 1000u);
    assert_int_equal(mb.v[6], 0);                      /* no NACK, no timeout */
    assert_int_equal(mb.v[0], 0x68);
    uint32_t scl = 2u * 210u * (F_CPU / 42000000u);    /* an SCL period, core cycles */
    assert_true(mb.v[1] > 30u * scl && mb.v[1] < 50u * scl); /* 39 periods: 2 STARTs, 4 bytes, a STOP */
    double want = (GYRO_RATE_RAD_S * 180.0 / M_PI + r->mpu.zro_dps) * mpu6500_lsb_per_dps(&r->mpu);
    double tol = 6.0 * mpu6500_sigma_dps(&r->mpu) * mpu6500_lsb_per_dps(&r->mpu) + 1.0;
    if (fabs((double)(int32_t)mb.v[2] - want) > tol) fail_msg("gyro z %d, want %.0f +- %.0f", (int32_t)mb.v[2], want, tol);
    assert_int_equal(mb.v[3], 0xEE);
    assert_true(mb.v[4] > 33u * (F_CPU / 1000u) - 60u * scl && mb.v[4] < 33u * (F_CPU / 1000u) + 60u * scl);
    assert_int_equal(mb.v[5], (uint32_t)RANGE_MM);
    assert_int_equal(r->tof.measurements, 1);
    no_unmodeled(r);
    rig_free(r);
}

/* USART2 (30.6) at BRR 22.8125 of 42 MHz sends the message by DMA1 stream 6 channel 4 (table 42, DMAT):
 * one frame (10 bits) every 16 x 22.8125 x 10 / 42 MHz; TC's interrupt after the last stop bit (30.3.13) */
static void test_usart_dma_tc(void **state)
{
    (void)state;
    rig_t *r = rig_new(SC_USART_DMA);
    mailbox_t mb = run_done(r, 40u * 1000u * 1000u);
    const char *msg = USART_MSG;
    assert_int_equal(r->nbytes, (int)strlen(msg));
    assert_memory_equal(r->bytes, msg, strlen(msg));
    uint64_t frame = 10u * 365u * (F_CPU / 42000000u); /* 10 bits of 16 x 22.8125 PCLK1 periods */
    for (int i = 1; i < r->nbytes; i++) assert_int_equal(r->byte_cycle[i] - r->byte_cycle[i - 1], frame);
    /* from the stream's enable to TC's interrupt: the ten frames back to back (DWT CYCCNT) */
    /* TE's idle frame first (30.3.2), then the ten */
    assert_true(mb.v[1] - mb.v[0] >= 11u * frame && mb.v[1] - mb.v[0] < 11u * frame + 300u);
    assert_true(mb.v[2] & (1u << 21));                 /* DMA1 HISR TCIF6 */
    assert_int_equal(mb.nlog, 1);
    no_unmodeled(r);
    rig_free(r);
}

/* PC13 to EXTI13 through SYSCFG EXTICR4 (9.2.6), falling edges only (FTSR, 12.3.4): EXTI15_10 (IRQ 40) on
 * each falling edge, none on the rising one */
static void test_exti_syscfg(void **state)
{
    (void)state;
    rig_t *r = rig_new(SC_EXTI);
    stm32f4_gpio_t *pc = stm32f4_soc_gpio(&r->soc, 2);
    run_until(r, offsetof(mailbox_t, step), 1, 40u * 1000u * 1000u);
    stm32f4_gpio_input(pc, 13, true, 0);
    mailbox_t mb = run_until(r, offsetof(mailbox_t, step), 2, armcore_cycles(r->core) + 1000000u);
    stm32f4_gpio_input(pc, 13, true, 1);
    armcore_run_to(r->core, armcore_cycles(r->core) + 1000000u);
    mb = mailbox(r);
    assert_int_equal(mb.step, 2);                      /* the rising edge: nothing */
    stm32f4_gpio_input(pc, 13, true, 0);
    mb = run_done(r, armcore_cycles(r->core) + 1000000u);
    assert_int_equal(mb.nlog, 2);
    assert_int_equal(mb.log[0], EV('X', 0));
    assert_int_equal(mb.log[1], EV('X', 0));
    /* PA13 (EXTICR4's reset choice) does not reach the line once port C is selected */
    no_unmodeled(r);
    rig_free(r);
}

/* Sector 3 erase (3.5.3) at x32 parallelism: BSY for tERASE16KB 250 ms typ (DS8626 table "Flash memory
 * programming") at HSI 16 MHz, the sector 0xFF after, sector 2 kept, EOP not set without EOPIE (3.8.4);
 * then the firmware's stores into flash (3.5.4): a word with PG at PSIZE x32 programmed, a byte refused
 * (PGPERR), a store without PG refused (PGSERR) */
static void test_flash_sector_erase(void **state)
{
    (void)state;
    rig_t *r = rig_new(SC_FLASH_ERASE);
    uint32_t w;
    assert_int_equal(armcore_read(r->core, SECTOR3_ADDR, &w, 4), 0);
    assert_int_equal(w, 0x5EC70003u);
    mailbox_t mb = run_done(r, 20u * 1000u * 1000u);
    assert_int_equal(mb.v[0], 0x5EC70003u);
    assert_int_equal(mb.v[1] >> 31, 0);                /* unlocked by KEY1, KEY2 */
    uint32_t want = 250u * (STM32F4_HSI_HZ / 1000u);
    assert_true(mb.v[2] >= want && mb.v[2] < want + 200u);
    assert_int_equal(mb.v[3], 0);                      /* no error, no EOP */
    assert_int_equal(mb.v[4], 0xFFFFFFFFu);
    assert_int_equal(mb.v[5], 0xFFFFFFFFu);
    assert_int_equal(mb.v[6], 0x5EC70002u);
    assert_int_equal(mb.v[7] >> 31, 1);                /* locked again */
    assert_int_equal(armcore_read(r->core, SECTOR3_ADDR + 8u, &w, 4), 0);
    assert_int_equal(w, 0xFFFFFFFFu);
    assert_int_equal(r->soc.flash.sectors_erased, 1);
    /* programmed: BSY tprog 16 us (DS8626) at 16 MHz, the word read back; refused stores leave 0xFF */
    assert_true(mb.v[8] >= 16u * 16u && mb.v[8] < 16u * 16u + 100u);
    assert_int_equal(mb.v[9], 0x12345678u);
    assert_int_equal(mb.v[10], 1u << 6);               /* PGPERR */
    assert_int_equal(mb.v[11], 1u << 7);               /* PGSERR */
    assert_int_equal(mb.v[12], 0xFFFFFFFFu);
    assert_int_equal(mb.v[13], 0xFFFFFFFFu);
    assert_int_equal(r->soc.flash.programmed, 1);
    no_unmodeled(r);
    rig_free(r);
}

/* TIM2 with its APB1ENR bit clear (6.3.13): a write ignored, reads 0; with it, ARR written and read back */
static void test_clock_gate(void **state)
{
    (void)state;
    rig_t *r = rig_new(SC_GATE);
    mailbox_t mb = run_done(r, 1000000u);
    assert_int_equal(mb.v[0], 0);
    assert_int_equal(mb.v[2], 1234u);
    assert_int_equal(stm32f4_soc_gated_accesses(&r->soc), 2);
    rig_free(r);
}

/* SPI1 (28.3) at PCLK2 84 MHz / 128, 8-bit frames: the MPU-6500's WHO_AM_I 0x70 (RM-MPU-6500A 4.40) by
 * polling, two frames of 8 x 128 PCLK2 periods; then GYRO_ZOUT_H/L as HAL_SPI_TransmitReceive_DMA: DMA2
 * stream 3 channel 3 feeds SPI1_TX, stream 2 channel 3 takes SPI1_RX (table 43), the three frames back to
 * back, the RX stream's TC interrupt after the last (28.3.9); SR then TXE alone (no BSY, RXNE, OVR) */
static void test_spi_dma_mpu6500(void **state)
{
    (void)state;
    rig_t *r = rig_new(SC_SPI_DMA);
    mailbox_t mb = run_done(r, 80u * 1000u * 1000u);
    uint32_t frame = 8u * 128u * (F_CPU / 84000000u);  /* core cycles per 8-bit frame */
    assert_int_equal(mb.v[0], 0x70);
    assert_true(mb.v[1] >= 2u * frame && mb.v[1] < 2u * frame + 200u);
    double want = (GYRO_RATE_RAD_S * 180.0 / M_PI + r->gyro.zro_dps) * mpu6500_lsb_per_dps(&r->gyro);
    double tol = 6.0 * mpu6500_sigma_dps(&r->gyro) * mpu6500_lsb_per_dps(&r->gyro) + 1.0;
    if (fabs((double)(int32_t)mb.v[2] - want) > tol) fail_msg("gyro z %d, want %.0f +- %.0f", (int32_t)mb.v[2], want, tol);
    if (mb.v[4] < 3u * frame || mb.v[4] > 3u * frame + 300u) fail_msg("DMA transfer %u cycles, want %u", mb.v[4], 3u * frame);
    assert_int_equal(mb.v[5], 0x2u);                   /* TXE; no BSY, RXNE, OVR */
    assert_int_equal(mb.v[6], 0);                      /* TX NDTR done */
    assert_int_equal(mb.v[7], 0x0C300000u);            /* at RX TC: TCIF2 HTIF2 TCIF3 HTIF3, no error (10.5.1) */
    assert_int_equal(mb.nlog, 1);
    assert_int_equal(r->gyro.unmodeled_count, 0);
    assert_int_equal(r->mpu.unmodeled_count, 0);
    no_unmodeled(r);
    rig_free(r);
}

/* USART6 (APB2: PCLK2 84 MHz, BRR 45.5625) receives four bytes by DMA2 stream 1 channel 5 (table 43,
 * DMAR 30.3.13): TC after the fourth frame, then USART6's IDLE interrupt (line 71, table 61) one idle frame
 * later (30.6.1); UART4 and UART5 (APB1, 42 MHz) send, polled: "PING" one frame apart after TE's idle
 * frame, then '5' */
static void test_uart_rx_dma(void **state)
{
    (void)state;
    rig_t *r = rig_new(SC_UART_RX_DMA);
    run_until(r, offsetof(mailbox_t, step), 1, 40u * 1000u * 1000u);
    stm32_usart_t *u6 = stm32f4_soc_usart(&r->soc, 6);
    for (const char *p = "ping"; *p; p++) assert_true(stm32_usart_push(u6, (uint8_t)*p, armcore_cycles(r->core)));
    armcore_cortexm(r->core)->attention = true;        /* the host changed a model: its next event again */
    mailbox_t mb = run_done(r, armcore_cycles(r->core) + 20u * 1000u * 1000u);
    uint32_t rx_frame = 10u * 729u * (F_CPU / 84000000u), tx_frame = 10u * 365u * (F_CPU / 42000000u);
    assert_true(mb.v[1] - mb.v[0] >= 4u * rx_frame);
    long idle = (long)(mb.v[2] - mb.v[1]) - (long)rx_frame; /* each stamped in its handler: a few cycles apart */
    if (labs(idle) > 100)
        fail_msg("IDLE %u cycles after TC, want %u", mb.v[2] - mb.v[1], rx_frame);
    assert_int_equal(mb.v[3], 0);                      /* NDTR: all four moved */
    assert_int_equal(mb.nlog, 2);
    assert_int_equal(mb.log[0], EV('D', 'p'));
    assert_int_equal(mb.log[1], EV('I', 0));
    assert_int_equal(r->nbytes, 5);
    assert_memory_equal(r->bytes, "PING5", 5);
    for (int i = 1; i < 4; i++) assert_int_equal(r->byte_cycle[i] - r->byte_cycle[i - 1], tx_frame);
    assert_int_equal(stm32f4_soc_gated_accesses(&r->soc), 0);
    no_unmodeled(r);
    rig_free(r);
}

/* Master/slave timers through the internal trigger connections (RM0090 17.4.3, 18.4.3): TIM8 gated by
 * TIM1's enable (ITR0) counts 1 MHz only while TIM1 runs; TIM2 clocked by TIM3's update TRGO (ITR2,
 * external clock mode 1, 18.3.14) overflows every 10 x 100 us; TIM4 started by TIM2's TRGO (ITR1, trigger
 * mode) counts from TIM2's first update; TIM5 reset at each TIM3 update (ITR1, reset mode) */
static void test_tim_itr(void **state)
{
    (void)state;
    rig_t *r = rig_new(SC_TIM_ITR);
    mailbox_t mb = run_done(r, 80u * 1000u * 1000u);
    assert_int_equal(mb.v[0], 0);                      /* gated, TIM1 off */
    if (mb.v[1] < 999u || mb.v[1] > 1001u) fail_msg("TIM8 gated count %u, want 1000", mb.v[1]);
    assert_int_equal(mb.v[2], mb.v[1]);                /* TIM1 off again: stopped */
    assert_true(mb.v[3] & (1u << 6));                  /* TIF */
    uint32_t ms = F_CPU / 1000u;
    assert_true(mb.v[5] - mb.v[4] >= ms && mb.v[5] - mb.v[4] < ms + 200u);
    for (unsigned k = 1; k < 3; k++) {
        long d = (long)(mb.v[5 + k] - mb.v[4 + k]) - (long)ms;
        if (labs(d) > 50) fail_msg("TIM2 update %u: %u cycles after the previous", k, mb.v[5 + k] - mb.v[4 + k]);
        if (mb.v[8 + k] < 1000u * k - 1u || mb.v[8 + k] > 1000u * k + 1u) fail_msg("TIM4 at update %u: %u", k, mb.v[8 + k]);
    }
    assert_true(mb.v[8] <= 1u);                        /* TIM4 started at TIM2's first update */
    for (unsigned k = 0; k < 3; k++)                   /* TIM5 (84 MHz) reset by the update the interrupt follows */
        if (mb.v[11 + k] > 200u) fail_msg("TIM5 at update %u: %u, reset mode not applied", k, mb.v[11 + k]);
    assert_int_equal(mb.v[14] & 1u, 1);                /* TIM4's CEN set by the trigger */
    assert_int_equal(mb.v[15], 0);
    assert_int_equal(r->soc.tim[STM32F4_TIM3].trig_want & 1u, 1u); /* TIM3's TRGO taken (TIM2, TIM5) */
    no_unmodeled(r);
    rig_free(r);
}

/* The SoC is the same at any chunking (armcore.h): the ADC/DMA scenario and the emitter scenario run to
 * the same cycle in one go and in pseudo-random chunks of 1-5,000 cycles give the same SRAM and pin edges */
static void run_chunked(rig_t *r, uint64_t end, uint32_t seed)
{
    while (armcore_cycles(r->core) < end) {
        uint64_t step = seed ? 1u + (seed = seed * 1103515245u + 12345u) % 5000u : end;
        uint64_t to = armcore_cycles(r->core) + step;
        armcore_run_to(r->core, to < end ? to : end);
        no_crash(r);
    }
}

static void test_chunking_same_state(void **state)
{
    (void)state;
    static uint8_t a[128 << 10], b[128 << 10];
    const unsigned sc[2] = { SC_ADC_DMA, SC_TIM_DMA_GPIO };
    for (unsigned k = 0; k < 2; k++) {
        rig_t *one = rig_new(sc[k]), *many = rig_new(sc[k]);
        run_chunked(one, 1500000u, 0);
        run_chunked(many, 1500000u, 7u + k);
        assert_int_equal(armcore_read(one->core, 0x20000000u, a, sizeof a), 0);
        assert_int_equal(armcore_read(many->core, 0x20000000u, b, sizeof b), 0);
        assert_memory_equal(a, b, sizeof a);
        assert_int_equal(one->npins, many->npins);
        for (int i = 0; i < one->npins; i++) assert_int_equal(one->pins[i].cycle, many->pins[i].cycle);
        assert_true(armcore_stats(many->core).splits > 10); /* stops inside translated blocks happened */
        rig_free(one);
        rig_free(many);
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_clock_setup), cmocka_unit_test(test_adc_scan_dma), cmocka_unit_test(test_tim_dma_gpio),
        cmocka_unit_test(test_i2c_mpu6050_vl53l0x), cmocka_unit_test(test_usart_dma_tc),
        cmocka_unit_test(test_exti_syscfg), cmocka_unit_test(test_flash_sector_erase), cmocka_unit_test(test_clock_gate),
        cmocka_unit_test(test_spi_dma_mpu6500), cmocka_unit_test(test_uart_rx_dma), cmocka_unit_test(test_tim_itr),
        cmocka_unit_test(test_chunking_same_state),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}

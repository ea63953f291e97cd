/* test_stm32f4_rcc.c - the STM32F4 RCC and PWR models (sim/arm/stm32f4_rcc.h,
 * stm32f4_pwr.h) against RM0090 section 6 and 5.4: reset values, a Cube
 * HAL clock setup (HSE 8 MHz, PLL M 8 N 336 P 2 Q 7 -> 168 MHz, the PLL
 * switched on through the peripheral bit-band alias 0x42470060, AHB /1,
 * APB1 /4, APB2 /2) with its ready times, the timer clocks x2, a switch to
 * a source not yet ready, the F411's 100 MHz from HSI, locked sources. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <cmocka.h>

#include <stdint.h>

#include "arm/bitband.h"
#include "arm/stm32f4_pwr.h"
#include "arm/stm32f4_rcc.h"

enum { CR = 0x00, PLLCFGR = 0x04, CFGR = 0x08, AHB1ENR = 0x30, CSR = 0x74 };
#define HSERDY (1u << 17)
#define PLLRDY (1u << 25)

static stm32f4_rcc_t rcc;
static stm32f4_pwr_t pwr;

static uint32_t rd(uint32_t off, uint64_t now)
{
    uint32_t v;
    stm32f4_rcc_ops.advance(&rcc, now);
    assert_int_equal(stm32f4_rcc_ops.read(&rcc, off, 4, &v), MMIO_OK);
    return v;
}
static void wr(uint32_t off, uint32_t v, uint64_t now)
{
    stm32f4_rcc_ops.advance(&rcc, now);
    assert_int_equal(stm32f4_rcc_ops.write(&rcc, off, 4, v), MMIO_OK);
}

/* The core's bus as the bit-band helper sees it: RCC at its base. */
static uint64_t bus_now;
static bool bus_read(void *ctx, uint32_t addr, unsigned size, uint32_t *v)
{
    if (addr - STM32F4_RCC_BASE >= STM32F4_RCC_SIZE) return false;
    stm32f4_rcc_ops.advance(&rcc, bus_now);
    return stm32f4_rcc_ops.read(&rcc, addr - STM32F4_RCC_BASE, size, v) == MMIO_OK;
}
static bool bus_write(void *ctx, uint32_t addr, unsigned size, uint32_t v)
{
    if (addr - STM32F4_RCC_BASE >= STM32F4_RCC_SIZE) return false;
    stm32f4_rcc_ops.advance(&rcc, bus_now);
    return stm32f4_rcc_ops.write(&rcc, addr - STM32F4_RCC_BASE, size, v) == MMIO_OK;
}
static const mmio_bus_t bus = { bus_read, bus_write, NULL };

static void test_reset(void **state)
{
    stm32f4_rcc_init(&rcc, STM32F4_F405, 8000000);
    assert_int_equal(rd(CR, 0), 0x00000083u);
    assert_int_equal(rd(PLLCFGR, 0), 0x24003010u);
    assert_int_equal(rd(CFGR, 0), 0);
    assert_int_equal(rd(AHB1ENR, 0), 0x00100000u);
    assert_int_equal(rd(CSR, 0), 0x0E000000u);
    const mmio_clocks_t *k = stm32f4_rcc_clocks(&rcc);
    assert_int_equal(k->sysclk, 16000000);
    assert_int_equal(k->hclk, 16000000);
    assert_int_equal(k->pclk1, 16000000);
    assert_int_equal(k->tim_apb1, 16000000);
    uint32_t v;
    assert_int_equal(stm32f4_rcc_ops.read(&rcc, 0x1C, 4, &v), MMIO_UNMODELED); /* reserved */
    stm32f4_pwr_init(&pwr, &rcc);
    assert_int_equal(stm32f4_pwr_ops.read(&pwr, 0, 4, &v), MMIO_OK);
    assert_int_equal(v, 0x00004000u); /* VOS scale 1 (RM0090 5.4.1) */
    assert_int_equal(stm32f4_pwr_ops.read(&pwr, 4, 4, &v), MMIO_OK);
    assert_int_equal(v, 0);
}

static void test_cube_168mhz(void **state)
{
    stm32f4_rcc_init(&rcc, STM32F4_F405, 8000000);
    stm32f4_pwr_init(&pwr, &rcc);
    uint64_t t = 100;
    wr(CR, rd(CR, t) | (1u << 16), t); /* HSEON */
    /* tsu(HSE) 2 ms at HSI 16 MHz: 32000 cycles */
    assert_int_equal(stm32f4_rcc_ops.next_event(&rcc), t + 32000);
    assert_false(rd(CR, t + 31999) & HSERDY);
    assert_true(rd(CR, t + 32000) & HSERDY);
    t += 32000;
    wr(PLLCFGR, (7u << 24) | (1u << 22) | (0u << 16) | (336u << 6) | 8u, t);
    /* PLLON through the bit-band alias of RCC CR bit 24 */
    uint32_t addr;
    unsigned bit;
    assert_true(bitband_addr(0x42470060u, &addr, &bit));
    assert_int_equal(addr, 0x40023800u);
    assert_int_equal(bit, 24);
    bus_now = t;
    assert_true(bitband_write(&bus, 0x42470060u, 1));
    assert_true(rd(CR, t) & (1u << 24));
    uint32_t v;
    assert_true(bitband_read(&bus, 0x42470064u, &v)); /* PLLRDY, bit 25 */
    assert_int_equal(v, 0);
    /* tLOCK 100 us at 16 MHz: 1600 cycles; VOSRDY follows */
    assert_false(rd(CR, t + 1599) & PLLRDY);
    assert_true(rd(CR, t + 1600) & PLLRDY);
    assert_int_equal(stm32f4_pwr_ops.read(&pwr, 4, 4, &v), MMIO_OK);
    assert_int_equal(v, 1u << 14);
    t += 1600;
    /* HPRE /1, PPRE1 /4 (101), PPRE2 /2 (100), SW PLL */
    wr(CFGR, (5u << 10) | (4u << 13) | 2u, t);
    assert_int_equal((rd(CFGR, t) >> 2) & 3u, 2); /* SWS: PLL */
    const mmio_clocks_t *k = stm32f4_rcc_clocks(&rcc);
    assert_int_equal(k->sysclk, 168000000);
    assert_int_equal(k->hclk, 168000000);
    assert_int_equal(k->pclk1, 42000000);
    assert_int_equal(k->pclk2, 84000000);
    assert_int_equal(k->tim_apb1, 84000000);
    assert_int_equal(k->tim_apb2, 168000000);
    assert_int_equal(rcc.pll48_hz, 48000000); /* 336 MHz / Q 7: USB's 48 MHz */
    /* the system clock's sources cannot be stopped (RM0090 6.3.1) */
    wr(CR, 0, t);
    assert_int_equal(rd(CR, t) & ((1u << 16) | (1u << 24)), (1u << 16) | (1u << 24));
    /* PLLCFGR cannot change with the PLL on: reported */
    assert_int_equal(stm32f4_rcc_ops.write(&rcc, PLLCFGR, 4, 0x24003010u), MMIO_UNMODELED);
    assert_int_equal(rd(PLLCFGR, t) & 0x3Fu, 8);
}

static void test_switch_waits_for_ready(void **state)
{
    stm32f4_rcc_init(&rcc, STM32F4_F405, 8000000);
    wr(CR, 0x83u | (1u << 16), 0);
    wr(CFGR, 1u, 10); /* SW HSE before HSERDY: SWS stays HSI */
    assert_int_equal((rd(CFGR, 10) >> 2) & 3u, 0);
    assert_int_equal(stm32f4_rcc_clocks(&rcc)->sysclk, 16000000);
    assert_int_equal((rd(CFGR, 32000) >> 2) & 3u, 1);
    assert_int_equal(stm32f4_rcc_clocks(&rcc)->sysclk, 8000000);
    /* AHB /2 (1000), APB1 /1: timer clock = PCLK1 */
    wr(CFGR, 1u | (8u << 4), 32000);
    assert_int_equal(stm32f4_rcc_clocks(&rcc)->hclk, 4000000);
    assert_int_equal(stm32f4_rcc_clocks(&rcc)->tim_apb1, 4000000);
}

static void test_no_crystal_never_ready(void **state)
{
    stm32f4_rcc_init(&rcc, STM32F4_F405, 0);
    wr(CR, 0x83u | (1u << 16), 0);
    assert_int_equal(stm32f4_rcc_ops.next_event(&rcc), MMIO_NEVER);
    assert_false(rd(CR, 100000000) & HSERDY);
}

static void test_f411_100mhz_from_hsi(void **state)
{
    stm32f4_rcc_init(&rcc, STM32F4_F411, 25000000);
    stm32f4_pwr_init(&pwr, &rcc);
    uint32_t v;
    assert_int_equal(stm32f4_pwr_ops.read(&pwr, 0, 4, &v), MMIO_OK);
    assert_int_equal(v, 0x00008000u); /* VOS scale 2 (RM0383 5.4.1) */
    assert_int_equal(stm32f4_pwr_ops.write(&pwr, 0, 4, 0x0000C000u | (1u << 8)), MMIO_OK);
    assert_int_equal(stm32f4_pwr_scale(&pwr), 1);
    /* HSI 16 MHz, M 16, N 400, P 4 (01), Q 8 (a 400 MHz VCO) -> 100 MHz */
    wr(PLLCFGR, (8u << 24) | (1u << 16) | (400u << 6) | 16u, 0);
    wr(CR, rd(CR, 0) | (1u << 24), 0);
    wr(CFGR, 2u | (4u << 10), 1600);
    assert_int_equal(stm32f4_rcc_clocks(&rcc)->sysclk, 100000000);
    assert_int_equal(stm32f4_rcc_clocks(&rcc)->pclk1, 50000000);
    assert_int_equal(stm32f4_rcc_clocks(&rcc)->tim_apb1, 100000000);
    /* the F411 has no AHB3 (FSMC) */
    assert_int_equal(stm32f4_rcc_ops.read(&rcc, 0x38, 4, &v), MMIO_UNMODELED);
}

static void test_bad_pll_reported(void **state)
{
    stm32f4_rcc_init(&rcc, STM32F4_F405, 8000000);
    wr(PLLCFGR, (7u << 24) | (500u << 6) | 8u, 0); /* N 500 > 432 */
    assert_int_equal(stm32f4_rcc_ops.write(&rcc, CR, 4, 0x83u | (1u << 24)), MMIO_UNMODELED);
    assert_int_equal(stm32f4_rcc_ops.write(&rcc, 0x0C, 4, 1u << 8), MMIO_UNMODELED); /* LSIRDYIE */
    assert_int_equal(stm32f4_pwr_ops.write(&pwr, 0, 4, 1u << 4), MMIO_UNMODELED); /* PVDE */
}

static void test_lsi_and_rmvf(void **state)
{
    stm32f4_rcc_init(&rcc, STM32F4_F405, 8000000);
    wr(CSR, 1u, 0); /* LSION: tsu(LSI) 15 us = 240 cycles at 16 MHz */
    assert_int_equal(rd(CSR, 239) & 3u, 1u);
    assert_int_equal(rd(CSR, 240) & 3u, 3u);
    wr(CSR, 1u | (1u << 24), 240);
    assert_int_equal(rd(CSR, 240), 3u);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_reset),
        cmocka_unit_test(test_cube_168mhz),
        cmocka_unit_test(test_switch_waits_for_ready),
        cmocka_unit_test(test_no_crystal_never_ready),
        cmocka_unit_test(test_f411_100mhz_from_hsi),
        cmocka_unit_test(test_bad_pll_reported),
        cmocka_unit_test(test_lsi_and_rmvf),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}

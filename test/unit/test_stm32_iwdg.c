/* test_stm32_iwdg.c - the STM32F1 independent watchdog model
 * (sim/arm/stm32f1_iwdg.c) against RM0008 19: reset values, PR and RLR
 * protected until KR 0x5555, PVU/RVU for 5 LSI periods, the reset
 * request after (RLR+1) x prescaler / 40 kHz from the start key, a reload
 * (0xAAAA) postponing it, the started hook (LSI forced on). */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <cmocka.h>

#include <stdint.h>

#include "arm/stm32f1_iwdg.h"

#define KR 0x00
#define PR 0x04
#define RLR 0x08
#define SR 0x0C

static mmio_clocks_t clk = { .sysclk = 72000000, .hclk = 72000000 };
static stm32f1_iwdg_t wd;
static int resets, starts;
static void on_reset(void *ctx) { (void)ctx; resets++; }
static void on_start(void *ctx) { (void)ctx; starts++; }

static uint32_t rd(uint32_t off)
{
    uint32_t v = 0xDEADBEEF;
    assert_int_equal(stm32f1_iwdg_ops.read(&wd, off, 4, &v), MMIO_OK);
    return v;
}
static void wr(uint32_t off, uint32_t v) { assert_int_equal(stm32f1_iwdg_ops.write(&wd, off, 4, v), MMIO_OK); }
static void at(uint64_t now) { stm32f1_iwdg_ops.advance(&wd, now); }

static int setup(void **state)
{
    resets = starts = 0;
    stm32f1_iwdg_init(&wd, &clk, (stm32f1_iwdg_hooks_t){ on_reset, on_start, NULL });
    return 0;
}

static void test_reset_values_and_protection(void **state)
{
    assert_int_equal(rd(PR), 0);
    assert_int_equal(rd(RLR), 0xFFF);
    assert_int_equal(rd(SR), 0);
    assert_int_equal(stm32f1_iwdg_ops.next_event(&wd), MMIO_NEVER);
    wr(PR, 3);
    wr(RLR, 10);
    assert_int_equal(rd(PR), 0); /* protected */
    assert_int_equal(rd(RLR), 0xFFF);
    wr(KR, 0x5555);
    wr(PR, 3);
    assert_int_equal(rd(PR), 3);
    wr(KR, 0x1234); /* any other key protects them again */
    wr(RLR, 10);
    assert_int_equal(rd(RLR), 0xFFF);
    uint32_t v;
    assert_int_equal(stm32f1_iwdg_ops.read(&wd, 0x10, 4, &v), MMIO_UNMODELED);
}

/* /32, RLR 99: (99+1) x 32 / 40 kHz = 80 ms = 5,760,000 cycles at 72 MHz */
static void test_timeout(void **state)
{
    wr(KR, 0x5555);
    wr(PR, 3);
    wr(RLR, 99);
    assert_int_equal(rd(SR), 3); /* PVU, RVU */
    assert_int_equal(stm32f1_iwdg_ops.next_event(&wd), 5 * 1800); /* 5 LSI periods */
    at(9000);
    assert_int_equal(rd(SR), 0);
    at(10000);
    wr(KR, 0xCCCC);
    assert_int_equal(starts, 1);
    assert_int_equal(stm32f1_iwdg_ops.next_event(&wd), 10000 + 5760000);
    at(10000 + 5759999);
    assert_int_equal(resets, 0);
    at(10000 + 5760000);
    assert_int_equal(resets, 1);
}

/* a reload halfway: the reset comes a full timeout after it, give or take a prescaled period */
static void test_reload_postpones(void **state)
{
    wr(KR, 0x5555);
    wr(RLR, 9); /* /4: (9+1) x 4 / 40 kHz = 1 ms = 72,000 cycles */
    at(20000);
    wr(KR, 0xCCCC);
    at(20000 + 36000);
    wr(KR, 0xAAAA);
    uint64_t t = stm32f1_iwdg_ops.next_event(&wd);
    assert_true(t > 20000 + 36000 + 72000 - 4 * 1800 && t <= 20000 + 36000 + 72000);
    at(20000 + 72000);
    assert_int_equal(resets, 0);
    at(t);
    assert_int_equal(resets, 1);
    /* the system reset stops it */
    stm32f1_iwdg_ops.reset(&wd);
    assert_int_equal(stm32f1_iwdg_ops.next_event(&wd), MMIO_NEVER);
}

/* the longest: /256 and 0xFFF: 26.2144 s */
static void test_longest(void **state)
{
    wr(KR, 0x5555);
    wr(PR, 7);
    at(1000000);
    wr(KR, 0xCCCC);
    assert_int_equal(stm32f1_iwdg_ops.next_event(&wd), 1000000 + 262144ull * 72000000ull / 10000ull);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test_setup(test_reset_values_and_protection, setup),
        cmocka_unit_test_setup(test_timeout, setup),
        cmocka_unit_test_setup(test_reload_postpones, setup),
        cmocka_unit_test_setup(test_longest, setup),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}

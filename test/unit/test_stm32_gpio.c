/* test_stm32_gpio.c - the STM32F1 GPIO, AFIO and EXTI models
 * (sim/arm/stm32f1_gpio.c, stm32f1_exti.c) against RM0008 9 and 10:
 * reset values, CRL/CRH modes and what a pin reads in each, BSRR (set wins
 * over reset), BRR, the pin-change callback, the outside's drive with
 * pulls, LCKR's key sequence, AFIO's timer remaps, and EXTI: a rising
 * edge on the port EXTICR selects pends the right NVIC line (EXTI0,
 * EXTI9_5, EXTI15_10), masked lines and other ports do not, PR is cleared
 * by writing 1, SWIER pends in software. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <cmocka.h>

#include <stdint.h>

#include "arm/stm32f1_gpio.h"

#define CRL 0x00
#define CRH 0x04
#define IDR 0x08
#define ODR 0x0C
#define BSRR 0x10
#define BRR 0x14
#define LCKR 0x18

static int irq_level[64], irq_sets;
static void irq_set(void *ctx, unsigned irq, bool level) { (void)ctx; irq_level[irq] = level, irq_sets++; }

static stm32f1_afio_t afio;
static stm32f1_exti_t exti;
static stm32f1_gpio_t gpa, gpb;
static int changes, last_port, last_pin, last_level;

static void on_change(void *ctx, unsigned port, unsigned pin, int level)
{
    changes++, last_port = (int)port, last_pin = (int)pin, last_level = level;
}

static uint32_t rd(stm32f1_gpio_t *g, uint32_t off)
{
    uint32_t v = 0xDEADBEEF;
    assert_int_equal(stm32f1_gpio_ops[g->port].read(g, off, 4, &v), MMIO_OK);
    return v;
}

static mmio_status_t wr(stm32f1_gpio_t *g, uint32_t off, uint32_t v) { return stm32f1_gpio_ops[g->port].write(g, off, 4, v); }
static uint32_t erd(uint32_t off)
{
    uint32_t v = 0;
    assert_int_equal(stm32f1_exti_ops.read(&exti, off, 4, &v), MMIO_OK);
    return v;
}
static void ewr(uint32_t off, uint32_t v) { assert_int_equal(stm32f1_exti_ops.write(&exti, off, 4, v), MMIO_OK); }

static int setup(void **state)
{
    for (unsigned i = 0; i < 64; i++) irq_level[i] = 0;
    irq_sets = changes = 0;
    stm32f1_afio_init(&afio);
    stm32f1_exti_init(&exti, &afio, (mmio_irq_t){ irq_set, NULL });
    stm32f1_gpio_init(&gpa, 0, &exti);
    stm32f1_gpio_init(&gpb, 1, &exti);
    stm32f1_gpio_on_change(&gpa, on_change, NULL);
    return 0;
}

static void test_reset_values(void **state)
{
    assert_int_equal(rd(&gpa, CRL), 0x44444444);
    assert_int_equal(rd(&gpa, CRH), 0x44444444);
    assert_int_equal(rd(&gpa, ODR), 0);
    assert_int_equal(rd(&gpa, IDR), 0);
    assert_string_equal(stm32f1_gpio_ops[2].name, "GPIOC");
    uint32_t v;
    assert_int_equal(stm32f1_gpio_ops[0].read(&gpa, 0x1C, 4, &v), MMIO_UNMODELED);
}

static void test_bsrr_set_wins_and_brr(void **state)
{
    wr(&gpa, CRL, 0x44444412); /* PA0 push-pull 2 MHz (0010), PA1 push-pull 10 MHz (0001) */
    wr(&gpa, CRL, 0x44444433); /* PA0, PA1 push-pull 50 MHz */
    wr(&gpa, BSRR, 1u << 0 | 1u << 16 | 1u << 17); /* set and reset PA0: set wins; reset PA1 */
    assert_int_equal(rd(&gpa, ODR), 1);
    assert_int_equal(rd(&gpa, IDR) & 3u, 1);
    assert_int_equal(changes, 1);
    assert_int_equal(last_pin, 0);
    assert_int_equal(last_level, 1);
    wr(&gpa, BSRR, 1u << 1);
    assert_int_equal(rd(&gpa, ODR), 3);
    wr(&gpa, BRR, 1u << 0);
    assert_int_equal(rd(&gpa, ODR), 2);
    assert_int_equal(last_pin, 0);
    assert_int_equal(last_level, 0);
    assert_int_equal(rd(&gpa, BSRR), 0);
    stm32f1_pin_t p = stm32f1_gpio_pin(&gpa, 1);
    assert_true(p.output && p.driven && p.level == 1 && !p.af && !p.open_drain);
    /* a byte write to BSRR's upper half-word resets */
    stm32f1_gpio_ops[0].write(&gpa, BSRR + 2, 2, 1u << 1);
    assert_int_equal(rd(&gpa, ODR), 0);
}

static void test_modes(void **state)
{
    /* PA2 input pull-up/down (1000), PA3 analog (0000), PA4 open-drain (0111), PA5 AF push-pull (1011) */
    wr(&gpa, CRL, 0x44B70844);
    wr(&gpa, ODR, 1u << 2);                    /* pull-up */
    assert_true(rd(&gpa, IDR) & (1u << 2));
    wr(&gpa, ODR, 0);                          /* pull-down */
    assert_false(rd(&gpa, IDR) & (1u << 2));
    stm32f1_gpio_drive(&gpa, 2, STM32F1_DRIVE_HIGH); /* driven beats the pull */
    assert_true(rd(&gpa, IDR) & (1u << 2));
    stm32f1_gpio_drive(&gpa, 3, STM32F1_DRIVE_HIGH);
    assert_false(rd(&gpa, IDR) & (1u << 3)); /* analog: reads 0 */
    assert_true(stm32f1_gpio_pin(&gpa, 3).analog);
    /* open-drain: 0 pulls low; 1 lets the outside set the level */
    stm32f1_pin_t p = stm32f1_gpio_pin(&gpa, 4);
    assert_true(p.open_drain && p.driven && p.level == 0);
    wr(&gpa, BSRR, 1u << 4);
    p = stm32f1_gpio_pin(&gpa, 4);
    assert_false(p.driven);
    assert_int_equal(p.level, 0);
    stm32f1_gpio_drive(&gpa, 4, STM32F1_DRIVE_HIGH); /* an external pull-up */
    assert_true(rd(&gpa, IDR) & (1u << 4));
    /* AF push-pull follows the peripheral, not ODR */
    wr(&gpa, BSRR, 1u << 5);
    assert_false(rd(&gpa, IDR) & (1u << 5));
    stm32f1_gpio_af_level(&gpa, 5, 1);
    assert_true(rd(&gpa, IDR) & (1u << 5));
    assert_true(stm32f1_gpio_pin(&gpa, 5).af);
    /* CNF 11 in input mode is reserved */
    assert_int_equal(wr(&gpa, CRH, 0x4444444C), MMIO_UNMODELED);
}

static void test_lckr(void **state)
{
    wr(&gpa, LCKR, 1u << 16 | 1u << 0);
    wr(&gpa, LCKR, 1u << 0);
    wr(&gpa, LCKR, 1u << 16 | 1u << 0);
    assert_int_equal(rd(&gpa, LCKR), 1u << 0);           /* read 0 */
    assert_int_equal(rd(&gpa, LCKR), 1u << 16 | 1u << 0); /* read 1: locked */
    wr(&gpa, CRL, 0x33333333);
    assert_int_equal(rd(&gpa, CRL), 0x33333334); /* PA0's configuration frozen */
    stm32f1_gpio_ops[0].reset(&gpa);
    wr(&gpa, CRL, 0x33333333);
    assert_int_equal(rd(&gpa, CRL), 0x33333333);
    /* a broken sequence locks nothing */
    wr(&gpa, LCKR, 1u << 16 | 1u << 1);
    wr(&gpa, LCKR, 1u << 16 | 1u << 1);
    rd(&gpa, LCKR);
    assert_int_equal(rd(&gpa, LCKR) & (1u << 16), 0);
}

static void test_afio_remap(void **state)
{
    uint32_t v;
    /* SWJ_CFG JTAG off (010), TIM2 full remap (11) */
    assert_int_equal(stm32f1_afio_ops.write(&afio, 0x04, 4, 2u << 24 | 3u << 8), MMIO_OK);
    assert_int_equal(stm32f1_afio_tim_remap(&afio, 2), 3);
    assert_int_equal(stm32f1_afio_tim_remap(&afio, 3), 0);
    stm32f1_afio_ops.read(&afio, 0x04, 4, &v);
    assert_int_equal(v, 3u << 8); /* SWJ_CFG reads 0 */
    assert_int_equal(stm32f1_afio_ops.read(&afio, 0x1C, 4, &v), MMIO_UNMODELED);
}

static void test_exti_rising_edge(void **state)
{
    /* line 0 follows PB0 (EXTICR1 EXTI0 = 0001), line 7 PA7, line 12 PA12 */
    stm32f1_afio_ops.write(&afio, 0x08, 4, 1u);
    ewr(0x08, 1u << 0 | 1u << 7 | 1u << 12); /* RTSR */
    ewr(0x00, 1u << 0 | 1u << 7);            /* IMR: 12 masked */
    stm32f1_gpio_drive(&gpa, 0, STM32F1_DRIVE_HIGH); /* PA0: not the selected port */
    assert_int_equal(erd(0x14), 0);
    stm32f1_gpio_drive(&gpb, 0, STM32F1_DRIVE_HIGH);
    assert_int_equal(erd(0x14), 1u << 0);
    assert_true(irq_level[6]); /* EXTI0 */
    stm32f1_gpio_drive(&gpb, 0, STM32F1_DRIVE_LOW); /* a falling edge: not selected */
    ewr(0x14, 1u << 0);                              /* PR: cleared by writing 1 */
    assert_int_equal(erd(0x14), 0);
    assert_false(irq_level[6]);
    stm32f1_gpio_drive(&gpa, 7, STM32F1_DRIVE_HIGH);
    assert_true(irq_level[23]); /* EXTI9_5 */
    stm32f1_gpio_drive(&gpa, 12, STM32F1_DRIVE_HIGH);
    assert_false(irq_level[40]); /* masked: not pending */
    assert_int_equal(erd(0x14), 1u << 7);
    ewr(0x00, 1u << 0 | 1u << 7 | 1u << 12);
    stm32f1_gpio_drive(&gpa, 12, STM32F1_DRIVE_LOW);
    stm32f1_gpio_drive(&gpa, 12, STM32F1_DRIVE_HIGH);
    assert_true(irq_level[40]); /* EXTI15_10 */
    /* an analog pin never reaches EXTI (its Schmitt trigger is off) */
    ewr(0x14, 1u << 12);
    wr(&gpa, CRH, 0x44404444); /* PA12 analog */
    stm32f1_gpio_drive(&gpa, 12, STM32F1_DRIVE_LOW);
    stm32f1_gpio_drive(&gpa, 12, STM32F1_DRIVE_HIGH);
    assert_int_equal(erd(0x14) & (1u << 12), 0);
    wr(&gpa, CRH, 0x44444444);
    assert_int_equal(erd(0x14) & (1u << 12), 1u << 12); /* back to an input: it rises */
    ewr(0x14, 1u << 12);
    /* a falling edge when FTSR selects it; writing 0 to PR changes nothing */
    ewr(0x0C, 1u << 12);
    ewr(0x14, 1u << 12);
    ewr(0x14, 0);
    stm32f1_gpio_drive(&gpa, 12, STM32F1_DRIVE_LOW);
    assert_int_equal(erd(0x14), 1u << 7 | 1u << 12);
}

static void test_exti_swier(void **state)
{
    ewr(0x00, 1u << 3);
    ewr(0x10, 1u << 3 | 1u << 4); /* line 4 masked: not pending */
    assert_int_equal(erd(0x14), 1u << 3);
    assert_true(irq_level[9]);
    assert_false(irq_level[10]);
    ewr(0x14, 1u << 3);
    assert_int_equal(erd(0x10), 1u << 4); /* SWIER3 cleared with PR3 */
    assert_false(irq_level[9]);
    /* a peripheral line: 17 (RTC alarm) -> IRQ 41 */
    ewr(0x00, 1u << 17);
    ewr(0x08, 1u << 17);
    stm32f1_exti_line(&exti, 17, 1);
    assert_true(irq_level[41]);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test_setup(test_reset_values, setup),
        cmocka_unit_test_setup(test_bsrr_set_wins_and_brr, setup),
        cmocka_unit_test_setup(test_modes, setup),
        cmocka_unit_test_setup(test_lckr, setup),
        cmocka_unit_test_setup(test_afio_remap, setup),
        cmocka_unit_test_setup(test_exti_rising_edge, setup),
        cmocka_unit_test_setup(test_exti_swier, setup),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}

/* test_stm32f4_gpio.c - the STM32F4 GPIO, SYSCFG and EXTI models
 * (sim/arm/stm32f4_gpio.h, stm32f4_syscfg.h) against RM0090 sections 8, 9
 * and 12: reset values (the debug pins), BSRR by word and by half-words as
 * old CMSIS's BSRRL/BSRRH write it, IDR of push-pull, open-drain, pulled,
 * analog pins, alternate functions, the LCKR sequence, a button on PC13
 * through SYSCFG EXTICR4 to EXTI15_10 (IRQ 40) on its falling edge, SWIER. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <cmocka.h>

#include <stdint.h>

#include "arm/stm32f4_gpio.h"
#include "arm/stm32f4_syscfg.h"

enum { MODER = 0x00, OTYPER = 0x04, OSPEEDR = 0x08, PUPDR = 0x0C, IDR = 0x10, ODR = 0x14, BSRR = 0x18,
       LCKR = 0x1C, AFRL = 0x20, AFRH = 0x24 };

static stm32f4_gpio_t ga, gc;
static stm32f4_syscfg_t sys;
static stm32f4_exti_t exti;
static bool irq[96];
static unsigned changes;

static void irq_set(void *ctx, unsigned n, bool level) { irq[n] = level; }
static void changed(void *ctx, unsigned port, unsigned pin, int level)
{
    changes++;
    stm32f4_exti_pin(&exti, port, pin, level);
}

static uint32_t rd(stm32f4_gpio_t *g, uint32_t off)
{
    uint32_t v;
    assert_int_equal(stm32f4_gpio_ops.read(g, off, 4, &v), MMIO_OK);
    return v;
}
static void wr(stm32f4_gpio_t *g, uint32_t off, uint32_t v, unsigned size)
{
    assert_int_equal(stm32f4_gpio_ops.write(g, off, size, v), MMIO_OK);
}

static int setup(void **state)
{
    for (unsigned i = 0; i < 96; i++) irq[i] = false;
    changes = 0;
    stm32f4_syscfg_init(&sys, 0);
    stm32f4_exti_init(&exti, &sys, (mmio_irq_t){ irq_set, NULL });
    stm32f4_gpio_init(&ga, 0, changed, NULL);
    stm32f4_gpio_init(&gc, 2, changed, NULL);
    return 0;
}

static void test_reset(void **state)
{
    assert_int_equal(rd(&ga, MODER), 0xA8000000u);
    assert_int_equal(rd(&ga, PUPDR), 0x64000000u);
    assert_int_equal(rd(&gc, MODER), 0);
    assert_int_equal(rd(&ga, IDR), (1u << 13) | (1u << 15)); /* PA13/PA15 pulled up, PA14 down */
    stm32f4_gpio_t gb;
    stm32f4_gpio_init(&gb, 1, NULL, NULL);
    assert_int_equal(rd(&gb, MODER), 0x00000280u);
    assert_int_equal(rd(&gb, OSPEEDR), 0x000000C0u);
    assert_int_equal(rd(&gb, PUPDR), 0x00000100u);
    uint32_t v;
    assert_int_equal(stm32f4_gpio_ops.read(&ga, 0x28, 4, &v), MMIO_UNMODELED);
    assert_int_equal(changes, 2); /* PA13 and PA15 read 1 at power-on: told once */
}

static void test_bsrr_and_idr(void **state)
{
    wr(&gc, MODER, 0x5u, 4); /* PC0, PC1 outputs */
    wr(&gc, BSRR, 0x3u, 4);
    assert_int_equal(rd(&gc, ODR), 3);
    assert_int_equal(rd(&gc, IDR) & 3u, 3);
    wr(&gc, BSRR, (1u << 16) | (1u << 17) | 1u, 4); /* BS0 wins over BR0 */
    assert_int_equal(rd(&gc, ODR), 1);
    wr(&gc, BSRR + 2, 0x1u, 2); /* BSRRH: reset PC0 */
    assert_int_equal(rd(&gc, ODR), 0);
    wr(&gc, BSRR, 0x2u, 2); /* BSRRL: set PC1 */
    assert_int_equal(rd(&gc, ODR), 2);
    /* open-drain PC1 with ODR 1: the line is the outside's */
    wr(&gc, OTYPER, 0x2u, 4);
    assert_int_equal(rd(&gc, IDR) & 2u, 0);
    stm32f4_gpio_input(&gc, 1, true, 1);
    assert_int_equal(rd(&gc, IDR) & 2u, 2);
    wr(&gc, BSRR, 1u << 17, 4);
    assert_int_equal(rd(&gc, IDR) & 2u, 0); /* drives low whatever the outside does */
    /* an input pulled down reads 0, driven high 1; analog reads 0 */
    wr(&gc, PUPDR, 2u << 4, 4);
    assert_int_equal(rd(&gc, IDR) & 4u, 0);
    wr(&gc, PUPDR, 1u << 4, 4);
    assert_int_equal(rd(&gc, IDR) & 4u, 4);
    wr(&gc, MODER, rd(&gc, MODER) | (3u << 4), 4);
    assert_int_equal(rd(&gc, IDR) & 4u, 0);
    /* byte write of MODER's top byte leaves the rest */
    wr(&gc, MODER + 3, 0x80u, 1);
    assert_int_equal(rd(&gc, MODER), 0x80000035u);
    assert_int_equal(stm32f4_gpio_mode(&gc, 15), STM32F4_PIN_AF);
}

static void test_af(void **state)
{
    wr(&ga, AFRL, 0x77000000u, 4); /* PA6, PA7: AF7 */
    wr(&ga, AFRH, 0x00000050u, 4); /* PA9: AF5 */
    assert_int_equal(stm32f4_gpio_af(&ga, 6), 7);
    assert_int_equal(stm32f4_gpio_af(&ga, 7), 7);
    assert_int_equal(stm32f4_gpio_af(&ga, 9), 5);
    assert_int_equal(stm32f4_gpio_af(&ga, 8), 0);
}

static void test_lock(void **state)
{
    wr(&gc, MODER, 0x1u, 4);
    wr(&gc, LCKR, 0x10001u, 4);
    wr(&gc, LCKR, 0x00001u, 4);
    wr(&gc, LCKR, 0x10001u, 4);
    assert_int_equal(rd(&gc, LCKR), 0x10001u); /* the sequence's read: LCKK now 1 */
    wr(&gc, MODER, 0x0000000Cu, 4);
    assert_int_equal(rd(&gc, MODER), 0x0000000Du); /* PC0 frozen, PC1 free */
    wr(&gc, LCKR, 0, 4); /* locked until reset */
    assert_int_equal(rd(&gc, LCKR), 0x10001u);
    stm32f4_gpio_ops.reset(&gc);
    assert_int_equal(rd(&gc, LCKR), 0);
    /* a wrong sequence does not lock */
    wr(&gc, LCKR, 0x10001u, 4);
    wr(&gc, LCKR, 0x00002u, 4);
    wr(&gc, LCKR, 0x10002u, 4);
    rd(&gc, LCKR);
    assert_false(rd(&gc, LCKR) & 0x10000u);
}

static void test_exti_button(void **state)
{
    /* PC13 input with pull-up, a button to ground: EXTICR4 EXTI13 = PC (0010) */
    wr(&gc, PUPDR, 1u << 26, 4);
    assert_int_equal(stm32f4_syscfg_ops.write(&sys, 0x14, 4, 2u << 4), MMIO_OK);
    assert_int_equal(stm32f4_exti_ops.write(&exti, 0x0C, 4, 1u << 13), MMIO_OK); /* FTSR */
    stm32f4_gpio_input(&gc, 13, true, 0); /* pressed, IMR still 0: no pending bit */
    uint32_t v;
    assert_int_equal(stm32f4_exti_ops.read(&exti, 0x14, 4, &v), MMIO_OK);
    assert_int_equal(v, 0);
    stm32f4_gpio_input(&gc, 13, false, 0); /* released */
    assert_int_equal(stm32f4_exti_ops.write(&exti, 0x00, 4, 1u << 13), MMIO_OK); /* IMR */
    stm32f4_gpio_input(&gc, 13, true, 0);
    assert_int_equal(stm32f4_exti_ops.read(&exti, 0x14, 4, &v), MMIO_OK);
    assert_int_equal(v, 1u << 13);
    assert_true(irq[40]);
    stm32f4_gpio_input(&gc, 13, false, 0); /* rising edge: RTSR 0, nothing more */
    assert_int_equal(stm32f4_exti_ops.write(&exti, 0x14, 4, 1u << 13), MMIO_OK);
    assert_false(irq[40]);
    /* PA13's edge does not reach line 13 (EXTICR selects PC) */
    wr(&ga, MODER, 0x54000000u, 4);
    wr(&ga, BSRR, 1u << 29, 4);
    assert_int_equal(stm32f4_exti_ops.read(&exti, 0x14, 4, &v), MMIO_OK);
    assert_int_equal(v, 0);
    /* SWIER on line 0: EXTI0 is IRQ 6 */
    assert_int_equal(stm32f4_exti_ops.write(&exti, 0x00, 4, 1u), MMIO_OK);
    assert_int_equal(stm32f4_exti_ops.write(&exti, 0x10, 4, 1u), MMIO_OK);
    assert_true(irq[6]);
    assert_int_equal(stm32f4_exti_ops.write(&exti, 0x14, 4, 1u), MMIO_OK);
    assert_false(irq[6]);
    assert_int_equal(stm32f4_exti_ops.read(&exti, 0x10, 4, &v), MMIO_OK);
    assert_int_equal(v, 0);
    /* CMPCR READY with CMP_PD; PMC's Ethernet select is reported */
    assert_int_equal(stm32f4_syscfg_ops.write(&sys, 0x20, 4, 1u), MMIO_OK);
    assert_int_equal(stm32f4_syscfg_ops.read(&sys, 0x20, 4, &v), MMIO_OK);
    assert_int_equal(v, 0x101u);
    assert_int_equal(stm32f4_syscfg_ops.write(&sys, 0x04, 4, 1u << 23), MMIO_UNMODELED);
    assert_int_equal(stm32f4_syscfg_mem_mode(&sys), 0);
    /* line 13 moved to PA13 (pulled up, reading 1 since power-on): its fall is an edge */
    wr(&ga, MODER, 0xA8000000u, 4);
    wr(&ga, BSRR, 1u << 13, 4);
    assert_int_equal(stm32f4_syscfg_ops.write(&sys, 0x14, 4, 0u), MMIO_OK);
    assert_int_equal(stm32f4_exti_ops.write(&exti, 0x00, 4, 1u << 13), MMIO_OK); /* IMR */
    stm32f4_gpio_input(&ga, 13, true, 0);
    assert_int_equal(stm32f4_exti_ops.read(&exti, 0x14, 4, &v), MMIO_OK);
    assert_int_equal(v, 1u << 13);
    assert_true(irq[40]);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test_setup(test_reset, setup),
        cmocka_unit_test_setup(test_bsrr_and_idr, setup),
        cmocka_unit_test_setup(test_af, setup),
        cmocka_unit_test_setup(test_lock, setup),
        cmocka_unit_test_setup(test_exti_button, setup),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}

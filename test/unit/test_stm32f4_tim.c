/* test_stm32f4_tim.c - the F4's timers (sim/arm/stm32f4_tim.c on the model
 * of stm32f1_tim.c) against RM0090 17-19: TIM5's 32-bit counter counting
 * past 0xFFFF and its 32-bit ARR, TIM1 CC3 as the ADC trigger source
 * (EXTSEL 2, table 69) at the exact cycle of the compare each period, the
 * TIM1 CC2/CC4 DMA requests at their compare cycles, TRGO from the update,
 * UG, CEN, CC1 and OC1REF (CR2 MMS), TIM9's two PWM channels and its
 * absent registers, TIM8's interrupt lines, one-pulse mode stopping CEN,
 * the slave modes trigger (ITR), gated (TI1FP1) and reset (TI2FP2). */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <cmocka.h>

#include <stdint.h>

#include "arm/stm32f4_tim.h"

#define CR1 0x00
#define CR2 0x04
#define SMCR 0x08
#define DIER 0x0C
#define SR 0x10
#define EGR 0x14
#define CCMR1 0x18
#define CCMR2 0x1C
#define CCER 0x20
#define CNT 0x24
#define PSC 0x28
#define ARR 0x2C
#define CCR1 0x34
#define CCR2 0x38
#define CCR3 0x3C
#define CCR4 0x40

/* 168 MHz HCLK, APB1 /4 (timers x2: 84 MHz), APB2 /2 (timers x2: 168 MHz): RM0090 6.2 */
static mmio_clocks_t clk = { .sysclk = 168000000, .hclk = 168000000, .pclk1 = 42000000, .pclk2 = 84000000,
                             .tim_apb1 = 84000000, .tim_apb2 = 168000000, .adcclk = 21000000 };
static stm32f1_tim_t tim;
static unsigned idx;

static int irq_level[96];
static void irq_set(void *ctx, unsigned irq, bool level) { (void)ctx; irq_level[irq] = level; }

#define MAXREC 32
typedef struct { unsigned what; int rising; uint64_t now; } rec_t;
static rec_t trig[MAXREC], dma[MAXREC];
static unsigned ntrig, ndma;
static void on_trigger(void *ctx, unsigned source, int rising, uint64_t now)
{
    (void)ctx;
    if (ntrig < MAXREC) trig[ntrig++] = (rec_t){ source, rising, now };
}
/* the DMA model sees a request at the cycle the timer is advanced to */
static void on_dma(void *ctx, unsigned req, bool level)
{
    (void)ctx;
    if (level && ndma < MAXREC) dma[ndma++] = (rec_t){ req, 1, tim.now };
}

static uint32_t rd(uint32_t off)
{
    uint32_t v = 0xDEADBEEF;
    assert_int_equal(stm32f4_tim_ops[idx].read(&tim, off, 4, &v), MMIO_OK);
    return v;
}
static mmio_status_t wr(uint32_t off, uint32_t v) { return stm32f4_tim_ops[idx].write(&tim, off, 4, v); }
static void at(uint64_t now) { stm32f4_tim_ops[idx].advance(&tim, now); }
static uint64_t next(void) { return stm32f4_tim_ops[idx].next_event(&tim); }

static void init(unsigned i)
{
    for (unsigned k = 0; k < 96; k++) irq_level[k] = 0;
    ntrig = ndma = 0;
    idx = i;
    stm32f4_tim_init(&tim, i, &clk, (mmio_irq_t){ irq_set, NULL }, (mmio_dma_req_t){ on_dma, NULL },
                     (stm32_tim_trigger_t){ on_trigger, NULL });
}

/* Runs event to event (as the core does, never past next_event) until cycle end. */
static void run_events(uint64_t end)
{
    for (uint64_t n = next(); n <= end; n = next()) at(n);
    at(end);
}

/* TIM5 is 32-bit (RM0090 18.1): reset ARR 0xFFFF FFFF, counts past 0xFFFF */
static void test_tim5_32bit(void **state)
{
    init(STM32F4_TIM5);
    assert_string_equal(stm32f4_tim_ops[STM32F4_TIM5].name, "TIM5");
    assert_int_equal(stm32f4_tim[STM32F4_TIM5].base, 0x40000C00u);
    assert_int_equal(rd(ARR), 0xFFFFFFFFu);
    wr(CR1, 1);
    at(2 * 70000); /* 84 MHz timer clock: one count per 2 HCLK cycles */
    assert_int_equal(rd(CNT), 70000);
    assert_int_equal(rd(SR), 0); /* no overflow at 0xFFFF */
    wr(ARR, 99999);
    assert_int_equal(rd(ARR), 99999);
    wr(DIER, 1);
    assert_int_equal(next(), 2 * 100000);
    at(2 * 100000 - 1);
    assert_false(irq_level[50]);
    at(2 * 100000);
    assert_true(irq_level[50]); /* TIM5 global interrupt, table 61 */
    assert_int_equal(rd(CNT), 0);
    wr(CNT, 0x89ABCDEFu);
    assert_int_equal(rd(CNT), 0x89ABCDEFu);
    /* downcounting from 5: the underflow reloads 0xFFFF FFFF, then counts down on */
    wr(CR1, 1u | 1u << 4);
    wr(ARR, 0xFFFFFFFFu);
    wr(CNT, 5);
    wr(SR, 0);
    at(tim.now + 2 * 6);
    assert_int_equal(rd(CNT), 0xFFFFFFFFu);
    assert_int_equal(rd(SR) & 1u, 1);
    at(tim.now + 2 * 0x10000);
    assert_int_equal(rd(CNT), 0xFFFEFFFFu);
    /* TIM3 stays 16-bit */
    init(STM32F4_TIM3);
    wr(ARR, 0x12345678u);
    assert_int_equal(rd(ARR), 0x5678u);
}

/* TIM1 CC3, the ADC's EXTSEL 2: a pulse at the cycle CNT reaches CCR3, each period */
static void test_tim1_cc3_triggers_adc(void **state)
{
    init(STM32F4_TIM1);
    unsigned src = STM32_TIM_TRIG(1, STM32_TIM_CC3);
    assert_int_equal(stm32f4_tim_extsel_code(src, 0), 2);
    assert_int_equal(stm32f4_tim_extsel_code(STM32_TIM_TRIG(8, STM32_TIM_TRGO), 0), 14);
    assert_int_equal(stm32f4_tim_extsel_code(STM32_TIM_TRIG(1, STM32_TIM_TRGO), 1), 1);
    stm32_tim_trigger_want(&tim, stm32f4_tim_adc_wants(1, 2, 15));
    assert_int_equal(tim.trig_want, 1u << STM32_TIM_CC3);
    wr(ARR, 999);
    wr(CCR3, 250);
    wr(CCR2, 100); /* CC2 not wanted: no trigger */
    wr(CCMR2, 6u << 4); /* OC3M PWM mode 1 */
    wr(CCER, 1u << 8);
    wr(CR1, 1);
    assert_int_equal(next(), 250); /* the listener's compare is an event */
    run_events(2300);
    assert_int_equal(ntrig, 6); /* a pulse: rising and falling at the same cycle */
    for (unsigned k = 0; k < 3; k++) {
        assert_int_equal(trig[2 * k].what, src);
        assert_int_equal(trig[2 * k].rising, 1);
        assert_int_equal(trig[2 * k].now, 250 + 1000 * k);
        assert_int_equal(trig[2 * k + 1].rising, 0);
        assert_int_equal(trig[2 * k + 1].now, 250 + 1000 * k);
    }
    /* one long advance gives the same cycles */
    init(STM32F4_TIM1);
    stm32_tim_trigger_want(&tim, 1u << STM32_TIM_CC3);
    wr(PSC, 2); /* 3 timer clocks a count */
    wr(EGR, 1);
    wr(ARR, 999);
    wr(CCR3, 250);
    wr(CCMR2, 6u << 4);
    wr(CR1, 1);
    at(7000);
    assert_int_equal(ntrig, 6);
    assert_int_equal(trig[0].now, 750);
    assert_int_equal(trig[2].now, 3750);
    assert_int_equal(trig[4].now, 6750);
}

/* TIM1 CC2/CC4 DMA requests (DIER CC2DE, CC4DE) at their compare cycles; CCDS moves them to the update */
static void test_tim1_cc_dma(void **state)
{
    init(STM32F4_TIM1);
    stm32_tim_trigger_want(&tim, 0);
    wr(ARR, 999);
    wr(CCR2, 100);
    wr(CCR4, 600);
    wr(CCMR1, 1u << 12); /* OC2M active on match */
    wr(CCMR2, 1u << 12); /* OC4M */
    wr(DIER, 1u << 10 | 1u << 12);
    wr(CR1, 1);
    assert_int_equal(next(), 100);
    run_events(1700);
    assert_int_equal(ndma, 4);
    uint64_t when[4] = { 100, 600, 1100, 1600 };
    unsigned what[4] = { STM32F4_DREQ_TIM1_CH2, STM32F4_DREQ_TIM1_CH4, STM32F4_DREQ_TIM1_CH2, STM32F4_DREQ_TIM1_CH4 };
    for (unsigned k = 0; k < 4; k++) {
        assert_int_equal(dma[k].what, what[k]);
        assert_int_equal(dma[k].now, when[k]);
    }
    ndma = 0;
    wr(CR2, 1u << 3); /* CCDS: the CCx requests at the update */
    run_events(2100);
    assert_int_equal(ndma, 2);
    assert_int_equal(dma[0].now, 2000);
    assert_int_equal(dma[1].now, 2000);
}

/* CR2 MMS: update (010) each period, reset (000) on UG, enable (001) on CEN, compare pulse (011) */
static void test_trgo(void **state)
{
    unsigned trgo = STM32_TIM_TRIG(2, STM32_TIM_TRGO);
    init(STM32F4_TIM2);
    stm32_tim_trigger_want(&tim, stm32f4_tim_adc_wants(2, 6, 15)); /* EXTSEL 6: TIM2_TRGO */
    assert_int_equal(tim.trig_want, 1u);
    assert_int_equal(wr(CR2, 2u << 4), MMIO_OK);
    wr(PSC, 1);
    wr(ARR, 499);
    wr(EGR, 1); /* UG: an update event, so TRGO */
    assert_int_equal(ntrig, 2);
    assert_int_equal(trig[0].now, 0);
    ntrig = 0;
    wr(CR1, 1);
    at(4500); /* 84 MHz / 2 / 500: an update each 2000 HCLK cycles */
    assert_int_equal(ntrig, 4);
    assert_int_equal(trig[0].what, trgo);
    assert_int_equal(trig[0].now, 2000);
    assert_int_equal(trig[2].now, 4000);

    init(STM32F4_TIM2);
    wr(CR2, 0); /* reset: UG is TRGO */
    at(10);
    wr(EGR, 1);
    assert_int_equal(ntrig, 2);
    assert_int_equal(trig[0].now, 10);
    ntrig = 0;
    wr(CR2, 1u << 4); /* enable: TRGO is CEN */
    at(20);
    wr(CR1, 1);
    assert_int_equal(ntrig, 1);
    assert_int_equal(trig[0].rising, 1);
    assert_int_equal(trig[0].now, 20);

    init(STM32F4_TIM3);
    stm32_tim_trigger_want(&tim, 1u); /* TRGO (EXTSEL 8) */
    wr(CR2, 3u << 4); /* compare pulse: CC1IF */
    wr(ARR, 999);
    wr(CCR1, 400);
    wr(CR1, 1);
    assert_int_equal(next(), 800);
    run_events(2000);
    assert_int_equal(ntrig, 2);
    assert_int_equal(trig[0].what, STM32_TIM_TRIG(3, STM32_TIM_TRGO));
    assert_int_equal(trig[0].now, 800);
    /* OC1REF (100): PWM mode 1 falls at the compare, rises at the update */
    init(STM32F4_TIM3);
    stm32_tim_trigger_want(&tim, 1u);
    wr(ARR, 999);
    wr(CCR1, 400);
    wr(CCMR1, 6u << 4);
    wr(CR2, 4u << 4);
    assert_int_equal(ntrig, 1); /* OC1REF high while CNT < CCR1 */
    ntrig = 0;
    wr(CR1, 1);
    run_events(2900);
    assert_int_equal(ntrig, 3);
    assert_int_equal(trig[0].rising, 0);
    assert_int_equal(trig[0].now, 800);
    assert_int_equal(trig[1].rising, 1);
    assert_int_equal(trig[1].now, 2000);
    assert_int_equal(trig[2].now, 2800);
    /* forced active (101) past the compare: OC1REF and so TRGO rise at the write */
    ntrig = 0;
    at(3000);
    wr(CCMR1, 5u << 4);
    assert_int_equal(ntrig, 1);
    assert_int_equal(trig[0].rising, 1);
    assert_int_equal(trig[0].now, 3000);
}

/* TIM9: two channels, upcounting only, no CR2, no DMA (RM0090 19.5) */
static void test_tim9_pwm(void **state)
{
    init(STM32F4_TIM9);
    assert_int_equal(stm32f4_tim[STM32F4_TIM9].base, 0x40014000u);
    wr(ARR, 999);
    wr(CCR1, 250);
    wr(CCR2, 750);
    wr(CCMR1, 6u << 4 | 1u << 3 | 7u << 12 | 1u << 11); /* OC1 PWM1, OC2 PWM2, preloads */
    wr(CCER, 1u | 1u << 4);
    wr(EGR, 1);
    wr(CR1, 1 | 1u << 4); /* DIR not there: stays upcounting */
    assert_int_equal(rd(CR1), 1);
    stm32f1_tim_out_t a = stm32f1_tim_output(&tim, 1), b = stm32f1_tim_output(&tim, 2);
    assert_true(a.enabled && a.pwm && b.enabled && b.pwm);
    assert_float_equal(a.duty, 0.25, 1e-12);
    assert_float_equal(b.duty, 0.25, 1e-12);
    assert_float_equal(a.freq_hz, 168000.0, 1e-6); /* APB2 timer clock 168 MHz / 1000 */
    assert_int_equal(stm32f1_tim_output(&tim, 3).enabled, 0);
    at(300);
    assert_int_equal(stm32f1_tim_output(&tim, 1).level, 0);
    assert_int_equal(stm32f1_tim_output(&tim, 2).level, 0);
    at(800);
    assert_int_equal(stm32f1_tim_output(&tim, 2).level, 1);
    wr(DIER, 1u | 1u << 1 | 1u << 8 | 1u << 3);
    assert_int_equal(rd(DIER), 3u); /* no UDE, no CC3IE */
    at(1000);
    assert_true(irq_level[24]); /* TIM1_BRK_TIM9 */
    uint32_t v;
    assert_int_equal(stm32f4_tim_ops[idx].read(&tim, CCMR2, 4, &v), MMIO_UNMODELED);
    assert_int_equal(wr(CCR3, 1), MMIO_UNMODELED);
    assert_int_equal(wr(CR2, 0x20), MMIO_UNMODELED);
    assert_int_equal(wr(SMCR, 3), MMIO_UNMODELED); /* no encoder modes */
    init(STM32F4_TIM11);
    assert_int_equal(wr(CCR2, 1), MMIO_UNMODELED);
    assert_int_equal(wr(SMCR, 0), MMIO_UNMODELED);
}

/* TIM8: advanced, its own four lines (TIM8_UP_TIM13 44, TIM8_CC 46) */
static void test_tim8_irqs(void **state)
{
    init(STM32F4_TIM8);
    assert_int_equal(stm32f4_tim[STM32F4_TIM8].base, 0x40010400u);
    wr(ARR, 99);
    wr(CCR1, 50);
    wr(DIER, 1u | 1u << 1);
    wr(CR1, 1);
    at(50);
    assert_true(irq_level[46]);
    assert_false(irq_level[44]);
    at(100);
    assert_true(irq_level[44]);
    wr(SR, 0);
    assert_false(irq_level[44] || irq_level[46]);
}

/* one-pulse mode (OPM): the update stops CEN */
static void test_one_pulse(void **state)
{
    init(STM32F4_TIM1);
    wr(ARR, 99);
    wr(CCR1, 40);
    wr(CCMR1, 7u << 4); /* PWM2: the pulse after CNT reaches 40 */
    wr(DIER, 1);
    wr(CR1, 1 | 1u << 3);
    at(50);
    assert_int_equal(stm32f1_tim_output(&tim, 1).ref, 1);
    at(100);
    assert_int_equal(rd(CR1) & 1u, 0);
    assert_int_equal(rd(CNT), 0);
    assert_true(irq_level[25]);
    wr(SR, 0);
    at(1000);
    assert_int_equal(rd(SR), 0);
    assert_int_equal(rd(CNT), 0);
    assert_int_equal(next(), MMIO_NEVER);
}

/* slave modes (SMCR, RM0090 18.3.14): trigger from ITR1, gated by TI1FP1, reset by TI2FP2 */
static void test_slave_modes(void **state)
{
    init(STM32F4_TIM3);
    assert_int_equal(wr(SMCR, 6u | 1u << 4), MMIO_UNMODELED); /* ITR1 while no TRGO is routed */
    stm32_tim_route_itr(&tim);
    assert_int_equal(wr(SMCR, 6u | 1u << 4), MMIO_OK); /* trigger mode, TS ITR1 */
    wr(DIER, 1u << 6);                                  /* TIE */
    stm32_tim_itr(&tim, 2, 1, 100);                      /* ITR2: not selected */
    assert_int_equal(rd(CR1) & 1u, 0);
    stm32_tim_itr(&tim, 1, 1, 500);
    assert_int_equal(rd(CR1) & 1u, 1);
    assert_int_equal(rd(SR), 1u << 6);
    assert_true(irq_level[29]);
    at(1500);
    assert_int_equal(rd(CNT), 500); /* counting from cycle 500, one count per 2 cycles */

    init(STM32F4_TIM3);
    assert_int_equal(wr(SMCR, 5u | 5u << 4), MMIO_OK); /* gated by TI1FP1 */
    wr(CR1, 1);
    at(100);
    assert_int_equal(rd(CNT), 0);
    stm32f1_tim_input(&tim, 100, 1, 1);
    at(300);
    assert_int_equal(rd(CNT), 100);
    stm32f1_tim_input(&tim, 300, 1, 0);
    at(1000);
    assert_int_equal(rd(CNT), 100);
    assert_int_equal(rd(SR), 1u << 6);
    assert_int_equal(next(), MMIO_NEVER);

    init(STM32F4_TIM3);
    assert_int_equal(wr(SMCR, 4u | 6u << 4), MMIO_OK); /* reset by TI2FP2 */
    wr(CCER, 1u << 5);                                   /* CC2P: the falling edge */
    wr(CR1, 1);
    at(400);
    stm32f1_tim_input(&tim, 400, 2, 1);
    assert_int_equal(rd(CNT), 200);
    stm32f1_tim_input(&tim, 400, 2, 0);
    assert_int_equal(rd(CNT), 0);
    assert_int_equal(rd(SR), 1u | 1u << 6); /* UIF from the update, TIF */
    assert_int_equal(wr(SMCR, 7u), MMIO_UNMODELED); /* external clock mode 1 from an unrouted ITR0 */

    /* external clock mode 1 (18.3.14) from ITR2: each rising TRGI edge a tick through PSC, time alone nothing */
    init(STM32F4_TIM3);
    stm32_tim_route_itr(&tim);
    assert_int_equal(wr(SMCR, 7u | 5u << 4), MMIO_UNMODELED); /* from TI1FP1: not modeled */
    assert_int_equal(wr(SMCR, 7u | 2u << 4), MMIO_OK);
    wr(PSC, 1);                                          /* two edges a count */
    wr(ARR, 2);
    wr(EGR, 1);
    wr(SR, 0);
    wr(DIER, 1);
    wr(CR1, 1);
    at(5000);
    assert_int_equal(rd(CNT), 0);
    for (unsigned k = 1; k <= 5; k++) {
        stm32_tim_itr(&tim, 2, 1, 5000 + 100 * k);
        stm32_tim_itr(&tim, 2, 0, 5050 + 100 * k);
    }
    assert_int_equal(rd(CNT), 2);
    assert_int_equal(rd(SR) & 1u, 0);
    stm32_tim_itr(&tim, 2, 1, 5600);                     /* the sixth edge: the third count, the overflow */
    assert_int_equal(rd(CNT), 0);
    assert_int_equal(rd(SR) & 0x41u, 0x41u);            /* UIF, TIF (CCxIF too: CCRx 0 matched at the wrap) */
    assert_true(irq_level[29]);
    assert_int_equal(next(), MMIO_NEVER);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_tim5_32bit),     cmocka_unit_test(test_tim1_cc3_triggers_adc),
        cmocka_unit_test(test_tim1_cc_dma),    cmocka_unit_test(test_trgo),
        cmocka_unit_test(test_tim9_pwm),       cmocka_unit_test(test_tim8_irqs),
        cmocka_unit_test(test_one_pulse),      cmocka_unit_test(test_slave_modes),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}

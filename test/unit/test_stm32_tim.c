/* test_stm32_tim.c - the STM32F1 timer model (sim/arm/stm32f1_tim.c)
 * against RM0008 14-15: the update interrupt after (PSC+1)(ARR+1) timer
 * clocks with the clock ratio to HCLK, UIF rc_w0, PSC preload taking
 * effect at the update, ARR preload (ARPE), PWM mode 1/2 duty =
 * CCR/(ARR+1) with polarity and TIM1's MOE, compare interrupts on TIM1's
 * CC line, the repetition counter, one-pulse mode, center-aligned
 * periods, the update's DMA request, encoder modes (4x and 2x the lines
 * per turn, wrap at ARR, DIR), input capture (polarity, ICxPSC, CCxOF,
 * the CCR read clearing the flag), a long jump in time, and the registers
 * not modeled reported. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <cmocka.h>

#include <stdint.h>

#include "arm/stm32f1_tim.h"

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
#define RCR 0x30
#define CCR1 0x34
#define BDTR 0x44

static int irq_level[64];
static void irq_set(void *ctx, unsigned irq, bool level) { (void)ctx; irq_level[irq] = level; }
static int dma_count[8];
static void dma_req(void *ctx, unsigned ch, bool level) { (void)ctx; if (level && ch < 8) dma_count[ch]++; }

static mmio_clocks_t clk = { .sysclk = 72000000, .hclk = 72000000, .pclk1 = 36000000, .pclk2 = 72000000,
                             .tim_apb1 = 72000000, .tim_apb2 = 72000000, .adcclk = 12000000 };
static stm32f1_tim_t tim;

static uint32_t rd(uint32_t off)
{
    uint32_t v = 0xDEADBEEF;
    assert_int_equal(stm32f1_tim_ops[tim.n - 1].read(&tim, off, 4, &v), MMIO_OK);
    return v;
}
static mmio_status_t wr(uint32_t off, uint32_t v) { return stm32f1_tim_ops[tim.n - 1].write(&tim, off, 4, v); }
static void at(uint64_t now) { stm32f1_tim_ops[tim.n - 1].advance(&tim, now); }
static uint64_t next(void) { return stm32f1_tim_ops[tim.n - 1].next_event(&tim); }

static void init(unsigned n)
{
    for (unsigned i = 0; i < 64; i++) irq_level[i] = 0;
    for (unsigned i = 0; i < 8; i++) dma_count[i] = 0;
    clk.hclk = 72000000, clk.tim_apb1 = 72000000, clk.tim_apb2 = 72000000;
    stm32f1_tim_init(&tim, n, &clk, (mmio_irq_t){ irq_set, NULL }, (mmio_dma_req_t){ dma_req, NULL });
}

static void test_reset_values(void **state)
{
    init(2);
    assert_int_equal(rd(CR1), 0);
    assert_int_equal(rd(SR), 0);
    assert_int_equal(rd(CNT), 0);
    assert_int_equal(rd(ARR), 0xFFFF);
    assert_string_equal(stm32f1_tim_ops[3].name, "TIM4");
    assert_int_equal(next(), MMIO_NEVER);
}

/* TIM2: PSC 71, ARR 999 at 72 MHz: an update every 72,000 timer clocks */
static void test_update_interrupt_period(void **state)
{
    init(2);
    wr(PSC, 71);
    wr(ARR, 999);
    wr(EGR, 1); /* UG: loads PSC; sets UIF */
    assert_int_equal(rd(SR), 1);
    wr(SR, 0);
    wr(DIER, 1);
    at(100);
    wr(CR1, 1);
    assert_int_equal(next(), 100 + 72000);
    at(100 + 71999);
    assert_int_equal(rd(SR) & 1, 0);
    assert_int_equal(rd(CNT), 999);
    assert_false(irq_level[28]);
    at(100 + 72000);
    assert_int_equal(rd(SR) & 1, 1);
    assert_int_equal(rd(CNT), 0);
    assert_true(irq_level[28]);
    /* rc_w0: writing 1 leaves the flag, writing 0 clears it */
    wr(SR, 0xFFFF);
    assert_int_equal(rd(SR) & 1, 1);
    wr(SR, ~1u);
    assert_int_equal(rd(SR) & 1, 0);
    assert_false(irq_level[28]);
    assert_int_equal(next(), 100 + 2 * 72000);
}

/* the timer clock at half HCLK: twice the core cycles */
static void test_clock_ratio(void **state)
{
    init(3);
    clk.tim_apb1 = 36000000;
    wr(ARR, 99);
    wr(DIER, 1);
    wr(CR1, 1);
    assert_int_equal(next(), 200);
    at(199);
    assert_int_equal(rd(CNT), 99);
    at(200);
    assert_true(irq_level[29]);
    /* 10 s of counting at once (nothing due meanwhile): the counter where it must be */
    wr(SR, 0);
    wr(DIER, 0);
    at(200 + 720000000ull + 2 * 37);
    assert_int_equal(rd(CNT), 37);
    assert_int_equal(rd(SR) & 1, 1);
}

/* bulebule's setup_emitters after a TIM1 reset: PSC 449 and ARR 9 written,
 * CEN and UIE set, no UG: the first update comes after 10 clocks at the
 * old PSC 0, then every 4,500 clocks (16 kHz at 72 MHz) */
static void test_bulebule_emitter_timer(void **state)
{
    init(1);
    at(1000);
    wr(CR1, 0);
    wr(PSC, 72000000 / 160000 - 1);
    wr(ARR, 10 - 1);
    wr(CR1, 1);
    wr(DIER, 1);
    assert_int_equal(next(), 1010);
    at(1010);
    assert_true(irq_level[25]);
    wr(SR, ~1u);
    assert_int_equal(next(), 1010 + 4500);
    at(1010 + 4500);
    assert_true(irq_level[25]);
    wr(SR, ~1u);
    assert_int_equal(next(), 1010 + 2 * 4500);
}

/* PSC is preloaded: a new value takes effect at the next update */
static void test_psc_preload(void **state)
{
    init(2);
    wr(ARR, 9);
    wr(DIER, 1);
    wr(CR1, 1);
    at(5);
    wr(PSC, 1); /* /2 from the update at 10 */
    assert_int_equal(rd(PSC), 1);
    assert_int_equal(next(), 10);
    at(10);
    assert_true(irq_level[28]);
    wr(SR, 0);
    assert_int_equal(next(), 30);
    at(29);
    assert_int_equal(rd(CNT), 9);
    at(30);
    assert_int_equal(rd(SR) & 1, 1);
}

/* ARPE: the new ARR waits for the update; without it, at once */
static void test_arr_preload(void **state)
{
    init(4);
    wr(ARR, 9);
    wr(CR1, 1 | 1u << 7);
    wr(ARR, 19);
    at(10);
    assert_int_equal(rd(CNT), 0); /* wrapped at the old 9 */
    at(29);
    assert_int_equal(rd(CNT), 19);
    at(30);
    assert_int_equal(rd(CNT), 0);
}

static void test_pwm_duty(void **state)
{
    init(3);
    wr(ARR, 2999);
    wr(CCMR1, 6u << 4 | 1u << 3 | 7u << 12); /* CH1 PWM1 with preload, CH2 PWM2 */
    wr(CCMR2, 6u << 4);
    wr(CCR1, 750);
    wr(CCR1 + 4, 750);
    wr(CCR1 + 8, 4000); /* above ARR: always active */
    wr(CCER, 1u | 1u << 4 | 1u << 5 | 1u << 8);
    stm32f1_tim_out_t o = stm32f1_tim_output(&tim, 1);
    assert_true(o.pwm && o.enabled);
    assert_true(o.duty == 0.0); /* CCR1 preloaded: not yet in effect */
    wr(EGR, 1);
    o = stm32f1_tim_output(&tim, 1);
    assert_true(o.duty == 750.0 / 3000.0);
    assert_false(o.running);
    assert_true(o.freq_hz == 24000.0); /* 72 MHz / 3000 */
    o = stm32f1_tim_output(&tim, 2); /* PWM2, active low */
    assert_true(o.duty == 1.0 - 750.0 / 3000.0);
    assert_true(o.active_low);
    assert_true(o.high == 750.0 / 3000.0);
    assert_true(stm32f1_tim_output(&tim, 3).duty == 1.0);
    o = stm32f1_tim_output(&tim, 4);
    assert_false(o.enabled);
    assert_false(o.pwm);
    /* center-aligned: active while CNT < CCR over 2 x ARR counts */
    wr(CR1, 1u << 5);
    assert_true(stm32f1_tim_output(&tim, 1).duty == 750.0 / 2999.0);
    /* TIM1's outputs need MOE */
    init(1);
    wr(CCMR1, 6u << 4);
    wr(CCER, 1);
    assert_false(stm32f1_tim_output(&tim, 1).enabled);
    assert_int_equal(wr(BDTR, 1u << 15), MMIO_OK);
    assert_true(stm32f1_tim_output(&tim, 1).enabled);
}

/* output compare modes: active on match, toggle (a square wave at half
 * the update rate), forced; the pin follows OCxREF and CCxP */
static void test_output_compare_levels(void **state)
{
    init(2);
    wr(ARR, 99);
    wr(CCR1, 50);
    wr(CCR1 + 4, 20);
    wr(CCMR1, 1u << 4 | 3u << 12); /* CH1 active on match, CH2 toggle */
    wr(CCMR2, 5u << 4 | 4u << 12); /* CH3 forced active, CH4 forced inactive */
    wr(CCER, 1u | 1u << 4 | 1u << 8 | 1u << 12 | 1u << 13); /* CH4 active low */
    assert_int_equal(stm32f1_tim_output(&tim, 1).level, 0);
    assert_int_equal(stm32f1_tim_output(&tim, 3).level, 1);
    assert_int_equal(stm32f1_tim_output(&tim, 4).level, 1);
    wr(CR1, 1);
    at(49);
    assert_int_equal(stm32f1_tim_output(&tim, 1).ref, 0);
    assert_int_equal(stm32f1_tim_output(&tim, 2).ref, 1); /* toggled at 20 */
    at(50);
    assert_int_equal(stm32f1_tim_output(&tim, 1).ref, 1);
    at(120);
    assert_int_equal(stm32f1_tim_output(&tim, 2).ref, 0); /* toggled again at 120 */
    at(120 + 100 * 1001);
    assert_int_equal(stm32f1_tim_output(&tim, 2).ref, 1); /* 1,001 more periods: odd */
    stm32f1_tim_out_t o = stm32f1_tim_output(&tim, 2);
    assert_true(o.pwm && o.duty == 0.5 && o.freq_hz == 72000000.0 / 100 / 2);
    /* PWM1: OCxREF from the counter */
    wr(CCMR1, 6u << 4);
    wr(CNT, 10);
    assert_int_equal(stm32f1_tim_output(&tim, 1).ref, 1);
    wr(CNT, 60);
    assert_int_equal(stm32f1_tim_output(&tim, 1).ref, 0);
}

/* TIM1: CC1 on its CC line (27), update on UP (25), DMA request of the update on channel 5 */
static void test_tim1_compare_and_lines(void **state)
{
    init(1);
    wr(ARR, 999);
    wr(CCR1, 500);
    wr(DIER, 1u << 1 | 1u << 8); /* CC1IE, UDE */
    wr(CR1, 1);
    assert_int_equal(next(), 500);
    at(500);
    assert_int_equal(rd(SR), 1u << 1);
    assert_true(irq_level[27]);
    assert_false(irq_level[25]);
    assert_int_equal(next(), 1000); /* the update, for its DMA request */
    at(1000);
    assert_int_equal(dma_count[5], 1);
    assert_false(irq_level[25]); /* UIE off */
    wr(DIER, 1);
    assert_true(irq_level[25]);
}

/* TIM1's repetition counter: an update every RCR+1 overflows */
static void test_repetition_counter(void **state)
{
    init(1);
    wr(ARR, 9);
    wr(RCR, 2);
    wr(EGR, 1);
    wr(SR, 0);
    wr(DIER, 1);
    wr(CR1, 1);
    at(20);
    assert_int_equal(rd(SR) & 1, 0);
    at(29);
    assert_int_equal(rd(SR) & 1, 0);
    at(30);
    assert_int_equal(rd(SR) & 1, 1);
    assert_int_equal(wr(RCR + 0, 0), MMIO_OK);
    init(3);
    assert_int_equal(wr(RCR, 0), MMIO_UNMODELED); /* reserved on TIM2-4 */
}

static void test_one_pulse(void **state)
{
    init(2);
    wr(ARR, 9);
    wr(CR1, 1 | 1u << 3);
    at(10);
    assert_int_equal(rd(CR1) & 1, 0); /* CEN cleared at the update */
    at(100);
    assert_int_equal(rd(CNT), 0);
}

/* center-aligned mode 3: up to ARR, down to 0; an update at each end */
static void test_center_aligned(void **state)
{
    init(2);
    wr(ARR, 10);
    wr(CR1, 1 | 3u << 5);
    at(10);
    assert_int_equal(rd(CNT), 10);
    assert_int_equal(rd(SR) & 1, 1);
    assert_int_equal(rd(CR1) & (1u << 4), 1u << 4); /* counting down */
    wr(SR, 0);
    at(15);
    assert_int_equal(rd(CNT), 5);
    at(20);
    assert_int_equal(rd(CNT), 0);
    assert_int_equal(rd(SR) & 1, 1);
    assert_int_equal(rd(CR1) & (1u << 4), 0);
}

/* encoder mode 3 on a 512-line encoder: 2048 counts a turn; wraps at ARR */
static void test_encoder_mode3(void **state)
{
    init(4);
    wr(SMCR, 3);
    wr(CCMR1, 1u | 1u << 8); /* CC1S = TI1, CC2S = TI2 */
    wr(CR1, 1);
    stm32f1_tim_encoder(&tim, 1000, 2048);
    assert_int_equal(rd(CNT), 2048);
    assert_int_equal(rd(CR1) & (1u << 4), 0);
    stm32f1_tim_encoder(&tim, tim.now, 2048 - 3000); /* backwards past 0: wraps to 0xFFFF */
    assert_int_equal(rd(CNT), 0x10000 - 952);
    assert_int_equal(rd(CR1) & (1u << 4), 1u << 4);
    assert_int_equal(rd(SR) & 1, 1);
    assert_int_equal(next(), MMIO_NEVER); /* the clock does not count it */
    at(100000);
    assert_int_equal(rd(CNT), 0x10000 - 952);
    /* wraps at ARR */
    init(2);
    wr(ARR, 999);
    wr(SMCR, 3);
    wr(CR1, 1);
    stm32f1_tim_encoder(&tim, tim.now, 2048);
    assert_int_equal(rd(CNT), 48);
    assert_int_equal(rd(SR) & 1, 1);
    /* CC1P reverses the direction */
    wr(CCER, 1u << 1);
    stm32f1_tim_encoder(&tim, tim.now, 2048 + 10);
    assert_int_equal(rd(CNT), 38);
}

/* encoder modes 1 and 2 count one channel's edges: 2 per line */
static void test_encoder_mode1_2(void **state)
{
    for (uint32_t mode = 1; mode <= 2; mode++) {
        init(2);
        wr(SMCR, mode);
        wr(CR1, 1);
        stm32f1_tim_encoder(&tim, tim.now, 2048);
        assert_int_equal(rd(CNT), 1024);
        stm32f1_tim_encoder(&tim, tim.now, 2047);
        stm32f1_tim_encoder(&tim, tim.now, 2046);
        assert_int_equal(rd(CNT), 1023);
        for (int64_t p = 2046; p >= 0; p--) stm32f1_tim_encoder(&tim, tim.now, p);
        assert_int_equal(rd(CNT), 0);
    }
}

static void test_unmodeled(void **state)
{
    init(2);
    assert_int_equal(wr(SMCR, 4), MMIO_UNMODELED); /* reset mode */
    assert_int_equal(wr(SMCR, 3), MMIO_OK);
    assert_int_equal(wr(CR2, 2u << 4), MMIO_UNMODELED); /* MMS: TRGO */
    assert_int_equal(wr(0x48, 0), MMIO_UNMODELED);      /* DCR */
    assert_int_equal(wr(CCMR1, 3), MMIO_OK);
    assert_int_equal(wr(CCER, 1), MMIO_UNMODELED);      /* a capture from TRC */
    uint32_t v;
    assert_int_equal(stm32f1_tim_ops[1].read(&tim, BDTR, 4, &v), MMIO_UNMODELED);
}

/* input capture: CH1 from TI1 on rising edges, CH2 from TI1 (CCxS 10) on falling, every 2nd */
static void test_input_capture(void **state)
{
    init(2);
    wr(CCMR1, 1u | 2u << 8 | 1u << 10); /* CC1S 01; CC2S 10, IC2PSC /2 */
    wr(CCER, 1u | 1u << 4 | 1u << 5);   /* CC1E; CC2E, CC2P falling */
    wr(DIER, 1u << 1);
    wr(CR1, 1);
    at(100);
    stm32f1_tim_input(&tim, tim.now, 1, 1);
    assert_int_equal(rd(SR), 1u << 1);
    assert_true(irq_level[28]);
    assert_int_equal(rd(CCR1), 100); /* the read clears CC1IF */
    assert_int_equal(rd(SR), 0);
    assert_false(irq_level[28]);
    at(150);
    stm32f1_tim_input(&tim, tim.now, 1, 0);
    assert_int_equal(rd(SR), 0); /* CH2: first falling edge of two */
    at(170);
    stm32f1_tim_input(&tim, tim.now, 1, 1);
    at(200);
    stm32f1_tim_input(&tim, tim.now, 1, 0);
    assert_int_equal(rd(SR), 1u << 1 | 1u << 2);
    assert_int_equal(rd(CCR1 + 4), 200);
    stm32f1_tim_input(&tim, 300, 1, 1); /* brings the timer to cycle 300 itself */
    assert_int_equal(rd(SR), 1u << 1 | 1u << 9); /* CC1OF: CC1IF still set from 170 */
    assert_int_equal(rd(CCR1), 300);
    assert_int_equal(stm32f1_tim_ops[1].write(&tim, CCR1, 4, 5), MMIO_OK); /* read-only in capture */
    assert_int_equal(rd(CCR1), 300);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_reset_values),
        cmocka_unit_test(test_update_interrupt_period),
        cmocka_unit_test(test_clock_ratio),
        cmocka_unit_test(test_bulebule_emitter_timer),
        cmocka_unit_test(test_psc_preload),
        cmocka_unit_test(test_arr_preload),
        cmocka_unit_test(test_pwm_duty),
        cmocka_unit_test(test_output_compare_levels),
        cmocka_unit_test(test_tim1_compare_and_lines),
        cmocka_unit_test(test_repetition_counter),
        cmocka_unit_test(test_one_pulse),
        cmocka_unit_test(test_center_aligned),
        cmocka_unit_test(test_encoder_mode3),
        cmocka_unit_test(test_encoder_mode1_2),
        cmocka_unit_test(test_unmodeled),
        cmocka_unit_test(test_input_capture),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}

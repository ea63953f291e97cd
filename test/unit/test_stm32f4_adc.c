/* test_stm32f4_adc.c - the STM32F4 ADC model (sim/arm/stm32f4_adc.h)
 * against RM0090 section 13 and DS8626's timing: a regular scan started by
 * TIM1 CC3 (EXTEN rising, EXTSEL 0010, as a Cube mouse triggers it)
 * converts at trigger + 2 ADC clocks latency + (sampling + 12) ADC clocks
 * per rank; other sources, the wrong edge and both edges; ADCPRE; EOC per
 * conversion (EOCS 1) or per sequence (EOCS 0) with the shared IRQ 18;
 * overrun; 8-bit resolution; the injected group by JSWSTART; the
 * temperature sensor and VREFINT; unmodeled bits reported. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <cmocka.h>

#include <stdint.h>

#include "arm/stm32f4_adc.h"

static const mmio_clocks_t clk = { 168000000, 168000000, 42000000, 84000000, 84000000, 168000000, 42000000 };

enum { SR = 0x00, CR1 = 0x04, CR2 = 0x08, SMPR1 = 0x0C, SMPR2 = 0x10, SQR1 = 0x2C, SQR3 = 0x34, JSQR = 0x38,
       JDR1 = 0x3C, DR = 0x4C };
#define EOC (1u << 1)
#define JEOC (1u << 2)
#define STRT (1u << 4)
#define OVR (1u << 5)
#define SCAN (1u << 8)
#define EOCIE (1u << 5)
#define OVRIE (1u << 26)
#define ADON 1u
#define EOCS (1u << 10)
#define EXTSEL(x) ((uint32_t)(x) << 24)
#define EXTEN(x) ((uint32_t)(x) << 28)
#define SWSTART (1u << 30)
#define JSWSTART (1u << 22)

static stm32f4_adc_common_t common;
static stm32f4_adc_t adc;
static bool irq18;
static unsigned nsamples;
static uint64_t sampled_at[32];
static unsigned sampled_ch[32];

static void irq_set(void *ctx, unsigned irq, bool level) { assert_int_equal(irq, 18); irq18 = level; }
static double volts(void *ctx, unsigned ch, uint64_t cycle)
{
    if (nsamples < 32) { sampled_at[nsamples] = cycle; sampled_ch[nsamples] = ch; }
    nsamples++;
    return 0.33 * (ch + 1); /* 0.33 V steps: code 410 x (ch + 1) at 12 bits */
}

static void setup_adc(void)
{
    irq18 = false;
    nsamples = 0;
    stm32f4_adc_common_init(&common, &clk, (mmio_irq_t){ irq_set, NULL });
    stm32f4_adc_init(&adc, &common, 1, (mmio_dma_req_t){ NULL, NULL }, 0, volts, NULL, 3.3);
}
static uint32_t rd(uint32_t off, uint64_t now)
{
    uint32_t v;
    stm32f4_adc_ops.advance(&adc, now);
    assert_int_equal(stm32f4_adc_ops.read(&adc, off, 4, &v), MMIO_OK);
    return v;
}
static void wr(uint32_t off, uint32_t v, uint64_t now)
{
    stm32f4_adc_ops.advance(&adc, now);
    assert_int_equal(stm32f4_adc_ops.write(&adc, off, 4, v), MMIO_OK);
}

static void test_timer_triggered_scan(void **state)
{
    setup_adc();
    wr(CR1, SCAN, 0);
    wr(SQR1, 2u << 20, 0);                          /* 3 ranks */
    wr(SQR3, 3u | (5u << 5) | (1u << 10), 0);        /* channels 3, 5, 1 */
    wr(SMPR2, 4u << 15, 0);                         /* channel 5: 84 cycles; others 3 */
    wr(CR2, ADON | EOCS | EXTSEL(2) | EXTEN(1), 0); /* TIM1_CC3, rising */
    /* the wrong source and the falling edge do nothing */
    stm32f4_adc_ext_trigger(&adc, false, STM32F4_ADC_EXT_TIM1_CC1, true, 1000);
    stm32f4_adc_ext_trigger(&adc, false, STM32F4_ADC_EXT_TIM1_CC3, false, 1000);
    assert_int_equal(stm32f4_adc_ops.next_event(&adc), MMIO_NEVER);
    stm32f4_adc_ext_trigger(&adc, false, STM32F4_ADC_EXT_TIM1_CC3, true, 1000);
    /* ADCCLK 42 MHz = 4 HCLK: start at 1000 + 8; rank 1 (3 + 12 clocks) ends at 1068 */
    assert_int_equal(rd(SR, 1007) & STRT, 0);
    assert_int_equal(rd(SR, 1008) & STRT, STRT);
    assert_false(rd(SR, 1067) & EOC);
    assert_int_equal(sampled_at[0], 1008 + 12);      /* sampling ends after 3 clocks */
    assert_true(rd(SR, 1068) & EOC);
    assert_int_equal(rd(DR, 1068), 1638);            /* channel 3: 1.32 V */
    /* rank 2, channel 5: (84 + 12) x 4 = 384 cycles */
    assert_false(rd(SR, 1068 + 383) & EOC);
    assert_int_equal(rd(DR, 1068 + 384), 2458);      /* 1.98 V */
    assert_int_equal(rd(DR, 1452 + 60), 819);        /* channel 1: 0.66 V */
    assert_int_equal(nsamples, 3);
    assert_int_equal(sampled_ch[1], 5);
    assert_int_equal(stm32f4_adc_ops.next_event(&adc), MMIO_NEVER); /* not continuous: done */
    /* both edges (EXTEN 11), ADCPRE /4: 8 HCLK a clock */
    assert_int_equal(stm32f4_adc_common_ops.write(&common, 0x04, 4, 1u << 16), MMIO_OK);
    assert_int_equal(stm32f4_adc_clock(&common), 21000000);
    wr(CR2, ADON | EOCS | EXTSEL(2) | EXTEN(3), 2000);
    stm32f4_adc_ext_trigger(&adc, false, STM32F4_ADC_EXT_TIM1_CC3, false, 3000);
    assert_false(rd(SR, 3000 + 16 + 120 - 1) & EOC);
    assert_true(rd(SR, 3000 + 16 + 120) & EOC);
}

static void test_eoc_per_sequence_and_irq(void **state)
{
    setup_adc();
    wr(CR1, SCAN | EOCIE, 0);
    wr(SQR1, 1u << 20, 0); /* 2 ranks: channels 0, 0 */
    wr(CR2, ADON, 0);      /* EOCS 0 */
    wr(CR2, ADON | SWSTART, 0);
    assert_false(rd(CR2, 8) & SWSTART); /* cleared as the conversion starts */
    assert_false(rd(SR, 68) & EOC);     /* rank 1 done: no EOC yet */
    assert_false(irq18);
    assert_true(rd(SR, 128) & EOC);     /* the sequence's end */
    assert_true(irq18);
    rd(DR, 128);
    assert_false(irq18);
    assert_int_equal(adc.seq.conversions, 2);
}

static void test_overrun(void **state)
{
    setup_adc();
    wr(CR1, OVRIE, 0);
    wr(CR2, ADON | EOCS | 2u, 0); /* CONT */
    wr(CR2, ADON | EOCS | 2u | SWSTART, 0);
    assert_true(rd(SR, 68) & EOC);
    assert_false(rd(SR, 127) & OVR);
    assert_true(rd(SR, 128) & OVR); /* the 2nd result while DR unread */
    assert_true(irq18);
    assert_int_equal(stm32f4_adc_ops.next_event(&adc), MMIO_NEVER); /* stopped */
    wr(SR, ~OVR, 200);
    assert_false(irq18);
}

static void test_resolution_and_internal(void **state)
{
    setup_adc();
    wr(CR1, 2u << 24, 0); /* RES 8 bits: 3 + 8 clocks */
    wr(SQR3, 4u, 0);      /* channel 4: 1.65 V */
    wr(CR2, ADON | EOCS | SWSTART, 0);
    assert_false(rd(SR, 8 + 43) & EOC);
    assert_true(rd(SR, 8 + 44) & EOC);
    assert_int_equal(rd(DR, 52), 128);
    wr(CR2, ADON | EOCS | (1u << 11) | SWSTART, 100); /* left-aligned 8-bit: in bits 15:8 */
    assert_int_equal(rd(DR, 200), 128u << 8);
    /* channel 16 (TS) and 17 (VREFINT) with TSVREFE, 12 bits */
    assert_int_equal(stm32f4_adc_common_ops.write(&common, 0x04, 4, 1u << 23), MMIO_OK);
    wr(CR1, 0, 300);
    wr(SQR3, 16u, 300);
    wr(CR2, ADON | SWSTART, 300);
    assert_int_equal(rd(DR, 400), 943);  /* 0.76 V at 25 degC */
    wr(SQR3, 17u, 400);
    wr(CR2, ADON | SWSTART, 400);
    assert_int_equal(rd(DR, 500), 1502); /* 1.21 V */
}

static void test_injected(void **state)
{
    setup_adc();
    wr(CR1, SCAN, 0);
    wr(JSQR, (1u << 20) | (2u << 10) | (6u << 15), 0); /* JL 1: JSQ3 = 2, JSQ4 = 6 */
    wr(CR2, ADON | JSWSTART, 0);
    assert_false(rd(CR2, 12) & JSWSTART); /* 3 clocks of latency */
    assert_true(rd(SR, 12 + 120) & JEOC);
    assert_int_equal(rd(JDR1, 132), 1229); /* channel 2: 0.99 V */
    assert_int_equal(rd(JDR1 + 4, 132), 2867); /* channel 6: 2.31 V */
    assert_false(rd(SR, 132) & EOC);
    /* left-aligned (ALIGN, bit 11): an injected result sits one bit below a
     * regular one, SEXT in bit 15 (RM0090 13.4 figure 49) */
    wr(CR2, ADON | (1u << 11) | JSWSTART, 200);
    assert_int_equal(rd(JDR1, 340), 1229u << 3);
}

static void test_unmodeled(void **state)
{
    setup_adc();
    assert_int_equal(stm32f4_adc_ops.write(&adc, CR1, 4, 1u << 23), MMIO_UNMODELED); /* AWDEN */
    assert_int_equal(stm32f4_adc_ops.write(&adc, CR1, 4, 1u << 11), MMIO_UNMODELED); /* DISCEN */
    assert_int_equal(stm32f4_adc_common_ops.write(&common, 0x04, 4, 6u), MMIO_UNMODELED); /* MULTI */
    uint32_t v;
    assert_int_equal(stm32f4_adc_common_ops.read(&common, 0x08, 4, &v), MMIO_UNMODELED); /* CDR */
    assert_int_equal(stm32f4_adc_ops.read(&adc, 0x50, 4, &v), MMIO_UNMODELED);
    assert_int_equal(rd(0x24, 0), 0xFFF); /* HTR reset */
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_timer_triggered_scan),
        cmocka_unit_test(test_eoc_per_sequence_and_irq),
        cmocka_unit_test(test_overrun),
        cmocka_unit_test(test_resolution_and_internal),
        cmocka_unit_test(test_injected),
        cmocka_unit_test(test_unmodeled),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}

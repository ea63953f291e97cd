/* test_stm32_adc.c - the STM32F1 ADC model (sim/arm/stm32f1_adc.h) against
 * RM0008 section 11 and the STM32F103 datasheet's ADC timing: calibration
 * time, an injected 4-channel scan as bulebule runs it (order, sampling
 * instants, JSWSTART, JEOC, JDRx codes), offsets and alignment, a regular
 * conversion started by a second ADON write, DMA requests, the internal
 * channels, the unmodeled bits. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <cmocka.h>

#include <stdint.h>

#include "arm/stm32f1_adc.h"

/* bulebule's clocks: HCLK 72 MHz, ADC clock PCLK2/8 = 9 MHz: 8 core cycles per ADC cycle */
static const mmio_clocks_t clk = { 72000000, 72000000, 36000000, 72000000, 72000000, 72000000, 9000000 };

enum { SR = 0x00, CR1 = 0x04, CR2 = 0x08, SMPR1 = 0x0C, SMPR2 = 0x10, JOFR1 = 0x14, SQR1 = 0x2C, SQR3 = 0x34,
       JSQR = 0x38, JDR1 = 0x3C, DR = 0x4C };
#define ADON (1u << 0)
#define CAL (1u << 2)
#define RSTCAL (1u << 3)
#define DMA (1u << 8)
#define ALIGN (1u << 11)
#define JEXTSEL_SW (7u << 12)
#define JEXTTRIG (1u << 15)
#define JSWSTART (1u << 21)
#define TSVREFE (1u << 23)
#define SCAN (1u << 8)
#define JEOCIE (1u << 7)
#define JAUTO (1u << 10)
#define S_EOC 2u
#define S_JEOC 4u
#define S_JSTRT 8u
#define S_STRT 16u

static double volts_of[18];
static unsigned calls, call_ch[16];
static uint64_t call_at[16];
static bool irq_level, dma_level;

static double volts(void *ctx, unsigned ch, uint64_t cycle)
{
    if (calls < 16) { call_ch[calls] = ch; call_at[calls] = cycle; }
    calls++;
    return volts_of[ch];
}
static void irq_set(void *ctx, unsigned irq, bool level) { assert_int_equal(irq, 18); irq_level = level; }
static void dma_req(void *ctx, unsigned ch, bool level) { assert_int_equal(ch, 1); dma_level = level; }

static stm32_adc_t adc;

static void setup_adc(void)
{
    calls = 0;
    irq_level = dma_level = false;
    for (int i = 0; i < 18; i++) volts_of[i] = 0.0;
    stm32_adc_init(&adc, 1, &clk, (mmio_irq_t){ irq_set, NULL }, (mmio_dma_req_t){ dma_req, NULL }, volts, NULL, 3.3);
}

static uint32_t rd(uint32_t off, uint64_t now)
{
    uint32_t v = 0xDEADBEEF;
    stm32_adc_ops.advance(&adc, now);
    assert_int_equal(stm32_adc_ops.read(&adc, off, 4, &v), MMIO_OK);
    return v;
}
static void wr(uint32_t off, uint32_t v, uint64_t now)
{
    stm32_adc_ops.advance(&adc, now);
    assert_int_equal(stm32_adc_ops.write(&adc, off, 4, v), MMIO_OK);
}

static void test_reset_values(void **state)
{
    setup_adc();
    assert_int_equal(rd(SR, 0), 0);
    assert_int_equal(rd(CR2, 0), 0);
    assert_int_equal(rd(0x24, 0), 0x0FFF); /* HTR */
    assert_int_equal(stm32_adc_ops.next_event(&adc), MMIO_NEVER);
}

/* RSTCAL clears after one ADC clock (ours), CAL after tCAL = 83 ADC clocks (DS5319 Table 46). */
static void test_calibration_time(void **state)
{
    setup_adc();
    wr(CR2, ADON, 100);
    wr(CR2, ADON | RSTCAL, 200);
    assert_true(rd(CR2, 207) & RSTCAL);
    assert_false(rd(CR2, 208) & RSTCAL);
    wr(CR2, ADON | CAL, 1000);
    assert_int_equal(stm32_adc_ops.next_event(&adc), 1000 + 83 * 8);
    assert_true(rd(CR2, 1000 + 83 * 8 - 1) & CAL);
    assert_false(rd(CR2, 1000 + 83 * 8) & CAL);
    assert_int_equal(calls, 0); /* no conversion was started by those writes */
    /* CAL written while the ADC is off: the calibration runs once it is on */
    setup_adc();
    wr(CR2, CAL, 0);
    assert_int_equal(stm32_adc_ops.next_event(&adc), MMIO_NEVER);
    wr(CR2, ADON | CAL, 100);
    assert_false(rd(CR2, 100 + 83 * 8) & CAL);
}

/* bulebule's setup_adc1 and sm_emitter_adc: channels 4, 3, 5, 2 injected, 13.5-cycle sampling. */
static void setup_injected(void)
{
    setup_adc();
    volts_of[4] = 1.0;
    volts_of[3] = 2.0;
    volts_of[5] = 0.5;
    volts_of[2] = 3.3;
    wr(CR1, SCAN | JEOCIE, 0);
    wr(CR2, JEXTTRIG | JEXTSEL_SW, 0);
    wr(SMPR2, 02222222222, 0); /* SMPx = 010: 13.5 cycles, channels 0..9 */
    wr(JSQR, (3u << 20) | (2u << 15) | (5u << 10) | (3u << 5) | 4u, 0);
    wr(CR2, ADON | JEXTTRIG | JEXTSEL_SW, 10);
}

static void test_injected_scan(void **state)
{
    setup_injected();
    const uint64_t t0 = 1000, start = t0 + 3 * 8; /* tlat: 3 ADC clocks */
    wr(CR2, ADON | JEXTTRIG | JEXTSEL_SW | JSWSTART, t0);
    assert_true(rd(CR2, start - 1) & JSWSTART);
    assert_false(rd(SR, start - 1) & S_JSTRT);
    assert_false(rd(CR2, start) & JSWSTART); /* cleared as the conversion starts */
    assert_true(rd(SR, start) & S_JSTRT);
    /* each conversion: 13.5 + 12.5 = 26 ADC clocks = 208 core cycles; the sample at 13.5 clocks = 108 */
    assert_false(rd(SR, start + 4 * 208 - 1) & S_JEOC);
    assert_false(irq_level);
    uint32_t sr = rd(SR, start + 4 * 208);
    assert_true(sr & S_JEOC);
    assert_true(sr & S_EOC); /* set with JEOC at an injected group's end (RM0008 11.12.1) */
    assert_true(irq_level);
    assert_int_equal(calls, 4);
    const unsigned order[4] = { 4, 3, 5, 2 };
    for (unsigned k = 0; k < 4; k++) {
        assert_int_equal(call_ch[k], order[k]);
        assert_int_equal(call_at[k], start + 208 * k + 108);
    }
    /* round(V * 4096 / 3.3): 1241, 2482, 621 (620.6), 4095 (clamped) */
    assert_int_equal(rd(JDR1, 2000), 1241);
    assert_int_equal(rd(JDR1 + 4, 2000), 2482);
    assert_int_equal(rd(JDR1 + 8, 2000), 621);
    assert_int_equal(rd(JDR1 + 12, 2000), 4095);
    assert_true(rd(SR, 2000) & S_JEOC); /* reading JDRx does not clear it */
    wr(SR, ~S_JEOC, 2000);              /* rc_w0 */
    assert_false(rd(SR, 2000) & S_JEOC);
    assert_false(irq_level);
}

/* Without JEXTTRIG, JSWSTART starts nothing and stays set. */
static void test_jswstart_needs_jexttrig(void **state)
{
    setup_injected();
    wr(CR2, ADON | JSWSTART, 1000);
    assert_true(rd(CR2, 5000) & JSWSTART);
    assert_int_equal(calls, 0);
}

static void test_offset_and_alignment(void **state)
{
    setup_injected();
    wr(JOFR1, 1300, 20);
    wr(CR2, ADON | JEXTTRIG | JEXTSEL_SW | JSWSTART, 1000);
    assert_int_equal(rd(JDR1, 3000), 0xFFC5); /* 1241 - 1300 = -59, sign-extended */
    wr(CR2, ADON | ALIGN | JEXTTRIG | JEXTSEL_SW | JSWSTART, 3000);
    assert_int_equal(rd(JDR1, 5000), 0xFE28); /* -59 << 3: SEXT in bit 15, data in 14:3 (RM0008 11.5) */
    assert_int_equal(rd(JDR1 + 4, 5000), 2482 << 3);
}

/* bulebule's voltage.c: ADC2-style single regular conversion by writing ADON again. */
static void test_regular_by_adon(void **state)
{
    setup_adc();
    volts_of[0] = 1.65;
    wr(SMPR2, 2, 0);
    wr(CR2, ADON, 10);
    assert_int_equal(calls, 0); /* the first ADON only powers on */
    wr(CR2, ADON, 1000);
    const uint64_t start = 1000 + 2 * 8; /* tlatr: 2 ADC clocks */
    assert_false(rd(SR, start - 1) & S_STRT);
    assert_true(rd(SR, start) & S_STRT);
    assert_false(rd(SR, start + 207) & S_EOC);
    assert_true(rd(SR, start + 208) & S_EOC);
    assert_int_equal(rd(DR, start + 208), 2048);
    assert_false(rd(SR, start + 208) & S_EOC); /* reading DR cleared it */
    /* ADON written with another bit changing starts nothing */
    wr(CR2, ADON | ALIGN, 3000);
    assert_int_equal(stm32_adc_ops.next_event(&adc), MMIO_NEVER);
}

static void test_dma_request_and_internal_channels(void **state)
{
    setup_adc();
    wr(SQR3, 17, 0); /* VREFINT */
    wr(CR2, ADON | DMA | TSVREFE, 0);
    wr(CR2, ADON | DMA | TSVREFE, 100);
    stm32_adc_ops.advance(&adc, 100 + 16 + 14 * 8);
    assert_true(dma_level);
    assert_int_equal(rd(DR, 1000), 1489); /* 1.20 V (DS5319 Table 12) */
    assert_false(dma_level);
    wr(SQR3, 16, 1000); /* temperature sensor at 25 degC: V25 = 1.43 V (Table 50) */
    wr(SMPR1, 7u << 18, 1000);
    wr(CR2, ADON | DMA | TSVREFE, 1001);
    assert_int_equal(rd(DR, 1001 + 16 + 252 * 8), 1775);
    wr(CR2, ADON | DMA, 5000); /* TSVREFE off: the channel reads 0 */
    wr(CR2, ADON | DMA, 5001);
    assert_int_equal(rd(DR, 5001 + 16 + 252 * 8), 0);
}

/* An injected trigger during a regular scan: the regular conversion is
 * interrupted and resumed from the same rank (RM0008 11.3.9). */
static void test_injection_interrupts_regular(void **state)
{
    setup_injected();
    volts_of[0] = 0.1;
    volts_of[1] = 0.2;
    wr(SQR1, 1u << 20, 20);            /* two regular ranks */
    wr(SQR3, (1u << 5) | 0u, 20);      /* channel 0 then 1 */
    wr(CR2, ADON | JEXTTRIG | JEXTSEL_SW, 100); /* ADON again, nothing else changes: a regular start */
    wr(CR2, ADON | JEXTTRIG | JEXTSEL_SW | JSWSTART, 200);
    stm32_adc_ops.advance(&adc, 10000);
    /* 0 sampled (at 116+108), interrupted at 224 before its end (324), injected 4,3,5,2, then 0 again, 1 */
    assert_int_equal(calls, 7);
    const unsigned order[7] = { 0, 4, 3, 5, 2, 0, 1 };
    for (unsigned k = 0; k < 7; k++) assert_int_equal(call_ch[k], order[k]);
    assert_int_equal(rd(DR, 10000), 248); /* 0.2 V: the regular group's last rank */
}

/* A timer's trigger event starts the injected group JEXTSEL selects (RM0008 11.7). */
static void test_external_trigger(void **state)
{
    setup_injected();
    wr(CR2, ADON | JEXTTRIG | (STM32_ADC_JEXT_TIM1_TRGO << 12), 20);
    stm32_adc_ext_trigger(&adc, true, STM32_ADC_JEXT_TIM2_TRGO, 1000); /* not the one selected */
    stm32_adc_ext_trigger(&adc, false, STM32_ADC_EXT_TIM1_CC1, 1000);  /* regular: EXTTRIG off */
    assert_int_equal(stm32_adc_ops.next_event(&adc), MMIO_NEVER);
    stm32_adc_ext_trigger(&adc, true, STM32_ADC_JEXT_TIM1_TRGO, 1000);
    assert_int_equal(stm32_adc_ops.next_event(&adc), 1000 + 24);
    assert_true(rd(SR, 1000 + 24 + 4 * 208) & S_JEOC);
    assert_int_equal(calls, 4);
}

/* The same conversions whatever the advance steps (arm/mmio.h): cycle by cycle or at once. */
static void test_chunking(void **state)
{
    uint64_t at[2][16];
    uint32_t jdr[2][4];
    for (int run = 0; run < 2; run++) {
        setup_injected();
        wr(CR2, ADON | JEXTTRIG | JEXTSEL_SW | JSWSTART, 1000);
        if (run == 0)
            for (uint64_t t = 1000; t <= 3000; t++) stm32_adc_ops.advance(&adc, t);
        else
            stm32_adc_ops.advance(&adc, 3000);
        for (int k = 0; k < 4; k++) { at[run][k] = call_at[k]; jdr[run][k] = rd(JDR1 + 4 * k, 3000); }
    }
    assert_memory_equal(at[0], at[1], 4 * sizeof at[0][0]);
    assert_memory_equal(jdr[0], jdr[1], sizeof jdr[0]);
}

/* The analog watchdog on one injected channel: AWD when the code leaves [LTR, HTR]. */
static void test_analog_watchdog(void **state)
{
    setup_injected();
    wr(0x24, 3000, 20); /* HTR */
    wr(0x28, 100, 20);  /* LTR */
    wr(CR1, SCAN | (1u << 22) | (1u << 9) | (1u << 6) | 3u, 20); /* JAWDEN, AWDSGL, AWDIE, channel 3 */
    wr(CR2, ADON | JEXTTRIG | JEXTSEL_SW | JSWSTART, 1000);
    assert_false(rd(SR, 3000) & 1u); /* channel 3: 2482, inside */
    volts_of[3] = 3.0;               /* 3724 > HTR */
    wr(CR2, ADON | JEXTTRIG | JEXTSEL_SW | JSWSTART, 3000);
    assert_true(rd(SR, 5000) & 1u);
    assert_true(irq_level);
}

static void test_unmodeled(void **state)
{
    setup_adc();
    uint32_t v;
    assert_int_equal(stm32_adc_ops.write(&adc, CR1, 4, JAUTO), MMIO_UNMODELED);
    assert_int_equal(stm32_adc_ops.read(&adc, 0x50, 4, &v), MMIO_UNMODELED);
    assert_int_equal(stm32_adc_ops.read(&adc, SR + 1, 2, &v), MMIO_UNMODELED); /* misaligned */
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_reset_values),
        cmocka_unit_test(test_calibration_time),
        cmocka_unit_test(test_injected_scan),
        cmocka_unit_test(test_jswstart_needs_jexttrig),
        cmocka_unit_test(test_offset_and_alignment),
        cmocka_unit_test(test_regular_by_adon),
        cmocka_unit_test(test_dma_request_and_internal_channels),
        cmocka_unit_test(test_injection_interrupts_regular),
        cmocka_unit_test(test_external_trigger),
        cmocka_unit_test(test_chunking),
        cmocka_unit_test(test_analog_watchdog),
        cmocka_unit_test(test_unmodeled),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}

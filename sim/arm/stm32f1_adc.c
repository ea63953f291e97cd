/* stm32f1_adc.c - STM32F1 ADC1/ADC2: RM0008 rev 21 section 11 (11.3 functional
 * description: power-on, calibration 11.4, channel selection, single,
 * continuous and scan modes, injected channel management 11.3.9, data
 * alignment 11.5, sample time and conversion time 11.6, external triggers
 * 11.7, DMA 11.8, temperature sensor 11.10; registers 11.12). Timing and
 * analog figures from the STM32F103x8/B datasheet (DS5319), its tables
 * "ADC characteristics" (tCAL 83 1/fADC, tlat 3 and tlatr 2 1/fADC, tCONV =
 * Ts + 12.5 1/fADC; the same figures in the STM32F102 datasheet's), "TS
 * characteristics" (V25 1.43 V, Avg_Slope 4.3 mV/degC) and "Embedded
 * internal reference voltage" (VREFINT 1.20 V), each the typical value.
 *
 * Modeled: power on/off (ADON), calibration and its reset (CAL, RSTCAL clear
 * after their time), regular group (SQR1-3: SCAN, CONT, software start by a
 * second ADON write, SWSTART or an external trigger through EXTTRIG/EXTSEL),
 * injected group (JSQR, JSWSTART or JEXTTRIG/JEXTSEL; it interrupts a regular
 * conversion, which resumes after it), sample times (SMPR1/2), right/left
 * alignment, injected offsets (JOFR1-4, signed results), the analog watchdog
 * (AWDEN, JAWDEN, AWDSGL, AWDCH, HTR, LTR, AWDIE), EOC/JEOC/AWD interrupts,
 * the regular DMA request, channels 16/17 with TSVREFE.
 * Not modeled (a write that sets them answers MMIO_UNMODELED, the bits then
 * act as 0): DUALMOD, DISCEN/JDISCEN, JAUTO. Stated limits:
 * an ideal converter (code = round(V * 4096 / VREF+), no offset, gain or
 * linearity error: DS5319's "ADC accuracy" table gives ET +-2 LSB max); no tSTAB wait
 * after power-on; the extra 1/fPCLK2 of an external trigger's latency; the
 * ADC clock's phase against HCLK (times round up to a core cycle).
 * The conversion engine is stm32_adcseq.c's; this file is the F1's register
 * map and figures for it (stm32_adcseq_family_t), its calibration, start
 * bits, triggers and analog inputs. */
#include "arm/stm32f1_adc.h"

#include "arm/stm32f1_clk.h"

/* CR1 (RM0008 11.12.2) */
#define CR1_JAUTO    (1u << 10)
#define CR1_DISCEN   (1u << 11)
#define CR1_JDISCEN  (1u << 12)
#define CR1_DUALMOD  (0xFu << 16)
#define CR1_UNMODELED (CR1_JAUTO | CR1_DISCEN | CR1_JDISCEN | CR1_DUALMOD)
#define CR1_MASK     0x00CFFFFFu
/* CR2 (RM0008 11.12.3) */
#define CR2_ADON     STM32_ADCSEQ_CR2_ADON
#define CR2_CAL      (1u << 2)
#define CR2_RSTCAL   (1u << 3)
#define CR2_DMA      STM32_ADCSEQ_CR2_DMA
#define CR2_JEXTSEL_SHIFT 12
#define CR2_JEXTTRIG (1u << 15)
#define CR2_EXTSEL_SHIFT 17
#define CR2_EXTTRIG  (1u << 20)
#define CR2_JSWSTART (1u << 21)
#define CR2_SWSTART  (1u << 22)
#define CR2_TSVREFE  (1u << 23)
#define CR2_MASK     0x00FEF90Fu
#define TRIG_SW      7u /* (J)EXTSEL 111: (J)SWSTART */
/* the engine's clear_at slots, in the order they act within a cycle */
#define CLEAR_RSTCAL 0
#define CLEAR_CAL    1

/* DS5319 "ADC characteristics" (typical, in ADC clock cycles) */
#define TCAL_ADC        83u /* tCAL, calibration time */
#define TRSTCAL_ADC     1u  /* ours: the datasheet gives no time for RSTCAL; one ADC clock */
/* DS5319 "TS characteristics" and "Embedded internal reference voltage" (typical) */
#define TS_V25_V        1.43   /* V25, sensor voltage at 25 degC */
#define TS_SLOPE_V_C    0.0043 /* Avg_Slope; the voltage falls as the die warms (RM0008 11.10) */
#define VREFINT_V       1.20   /* VREFINT */

static uint64_t f1_cycles(const stm32_adcseq_t *s, uint64_t half_ticks)
{
    const stm32_adc_t *a = (const stm32_adc_t *)s;
    return stm32_half_ticks_to_cycles(half_ticks, a->clk->hclk, a->clk->adcclk);
}

/* ADC1 and ADC2 drive one line (ADC1_2): the OR of both. */
static void f1_irq(stm32_adcseq_t *s)
{
    stm32_adc_t *a = (stm32_adc_t *)s;
    bool line = s->irq_level || (a->partner && a->partner->seq.irq_level);
    if (a->irq.set) a->irq.set(a->irq.ctx, STM32_ADC_IRQ, line);
}

/* The input voltage of a channel at cycle t: pins from the board, 16/17 the
 * temperature sensor and VREFINT (ADC1 with TSVREFE only; 0 V otherwise). */
static double f1_volts(const stm32_adcseq_t *s, unsigned ch, uint64_t t)
{
    const stm32_adc_t *a = (const stm32_adc_t *)s;
    if (ch < 16) return a->volts ? a->volts(a->volts_ctx, ch, t) : 0.0;
    if (ch > 17 || a->index != 1 || !(s->cr2 & CR2_TSVREFE)) return 0.0;
    if (ch == 16) return TS_V25_V - (a->temp_c - 25.0) * TS_SLOPE_V_C;
    return VREFINT_V;
}

/* An APB register takes a narrow write's lanes as a word (stm32_write_lanes). */
static uint32_t f1_lanes(uint32_t old, uint32_t off, unsigned size, uint32_t value)
{
    (void)old, (void)off;
    return stm32_write_lanes(value, size);
}

static void f1_write_cr2(stm32_adcseq_t *s, uint32_t v)
{
    uint32_t old = s->cr2;
    uint64_t t = s->now;
    v &= CR2_MASK;
    /* the self-clearing bits stay set until their hardware clears them */
    s->cr2 = v | (old & (CR2_CAL | CR2_RSTCAL));
    if (!(v & CR2_ADON)) { stm32_adcseq_power_off(s); return; }
    /* RM0008 11.12.3 ADON: writing 1 when it is 1 starts a regular conversion,
     * unless another bit changes in the same write */
    if ((old & CR2_ADON) && ((old ^ v) & CR2_MASK & ~CR2_ADON) == 0) stm32_adcseq_trigger(s, STM32_ADCSEQ_REG, false, t);
    /* a calibration (or its reset) runs while the ADC is on; one asked for
     * while it was off starts when it is powered */
    if ((s->cr2 & CR2_RSTCAL) && s->clear_at[CLEAR_RSTCAL] == MMIO_NEVER)
        s->clear_at[CLEAR_RSTCAL] = stm32_at(t, stm32_adcseq_cycles(s, 2 * TRSTCAL_ADC));
    if ((s->cr2 & CR2_CAL) && s->clear_at[CLEAR_CAL] == MMIO_NEVER)
        s->clear_at[CLEAR_CAL] = stm32_at(t, stm32_adcseq_cycles(s, 2 * TCAL_ADC));
    if ((v & CR2_SWSTART) && (v & CR2_EXTTRIG) && ((v >> CR2_EXTSEL_SHIFT) & 7u) == TRIG_SW)
        stm32_adcseq_trigger(s, STM32_ADCSEQ_REG, true, t);
    if ((v & CR2_JSWSTART) && (v & CR2_JEXTTRIG) && ((v >> CR2_JEXTSEL_SHIFT) & 7u) == TRIG_SW)
        stm32_adcseq_trigger(s, STM32_ADCSEQ_INJ, true, t);
    if (!(v & CR2_DMA)) stm32_adcseq_set_dma(s, false);
}

static const stm32_adcseq_family_t f1_family = {
    .cr2_swstart = CR2_SWSTART, .cr2_jswstart = CR2_JSWSTART,
    .cr2_eocs = 0, .sr_ovr = 0, /* no EOCS, no overrun flag (RM0008 11.12.1/3) */
    .sr_inj_eoc = STM32_ADCSEQ_SR_EOC, /* RM0008 11.12.1: EOC ends an injected group too (ST's F1 HAL clears both) */
    .sr_w0 = 0x1Fu,                    /* AWD, EOC, JEOC, JSTRT, STRT */
    .smpr1_mask = 0x00FFFFFFu,         /* SMP10-17 (RM0008 11.12.4) */
    .late_regular_at_inj_end = true,   /* a regular trigger during the injected group converts after it */
    .inj_left_drop = 1,                /* RM0008 11.5 figure 28: an injected result's SEXT at bit 15, data below */
    .res_shift = 0, .res_mask = 0, .res_bits = { 12 },
    .conv_half = { 25 },               /* 12.5 cycles of successive approximation (RM0008 11.6), x2 */
    /* RM0008 11.12.4/5 SMPx: 1.5, 7.5, 13.5, 28.5, 41.5, 55.5, 71.5, 239.5 cycles, x2 */
    .smp_half = { 3, 15, 27, 57, 83, 111, 143, 479 },
    .tlat_inj_half = 2 * 3,            /* DS5319 tlat, injection trigger conversion latency: 3 1/fADC */
    .tlat_reg_half = 2 * 2,            /* DS5319 tlatr, regular trigger conversion latency: 2 1/fADC */
    .cycles = f1_cycles, .volts = f1_volts, .irq = f1_irq, .write_cr2 = f1_write_cr2, .lanes = f1_lanes,
};

void stm32_adc_ext_trigger(stm32_adc_t *a, bool injected, unsigned source, uint64_t now)
{
    stm32_adcseq_advance(a, now);
    uint32_t cr2 = a->seq.cr2, en = injected ? CR2_JEXTTRIG : CR2_EXTTRIG;
    unsigned sel = (cr2 >> (injected ? CR2_JEXTSEL_SHIFT : CR2_EXTSEL_SHIFT)) & 7u;
    if ((cr2 & en) && sel == source && source != TRIG_SW)
        stm32_adcseq_trigger(&a->seq, injected ? STM32_ADCSEQ_INJ : STM32_ADCSEQ_REG, false, now);
}

const mmio_ops_t stm32_adc_ops = { "ADC", stm32_adcseq_read, stm32_adcseq_write, stm32_adcseq_advance,
                                   stm32_adcseq_next_event, stm32_adcseq_reset };

void stm32_adc_init(stm32_adc_t *a, unsigned index, const mmio_clocks_t *clk, mmio_irq_t irq,
                    mmio_dma_req_t dma, stm32_adc_volts_fn volts, void *volts_ctx, double vref_v)
{
    *a = (stm32_adc_t){ 0 };
    stm32_adcseq_init(&a->seq, &f1_family, dma, STM32_ADC1_DMA_CH, vref_v);
    /* ADC2 has no DUALMOD (RM0008 11.12.2: ADC1's only): its bits are kept 0, unreported */
    a->seq.cr1_keep = CR1_MASK & (index == 1 ? ~0u : ~CR1_DUALMOD);
    a->seq.cr1_unmodeled = index == 1 ? CR1_UNMODELED : CR1_UNMODELED & ~CR1_DUALMOD;
    a->seq.clear_bit[CLEAR_RSTCAL] = CR2_RSTCAL;
    a->seq.clear_bit[CLEAR_CAL] = CR2_CAL;
    a->clk = clk;
    a->irq = irq;
    a->volts = volts;
    a->volts_ctx = volts_ctx;
    a->index = index;
    a->temp_c = 25.0; /* ours: a die at the datasheet's reference temperature */
    stm32_adcseq_reset(a);
}

void stm32_adc_share_irq(stm32_adc_t *a, stm32_adc_t *b)
{
    a->partner = b;
    b->partner = a;
}

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
 * ADC clock's phase against HCLK (times round up to a core cycle). */
#include "arm/stm32f1_adc.h"

#include <math.h>

#include "arm/stm32f1_clk.h"

/* RM0008 11.12: register offsets */
enum { SR = 0x00, CR1 = 0x04, CR2 = 0x08, SMPR1 = 0x0C, SMPR2 = 0x10, JOFR1 = 0x14, HTR = 0x24, LTR = 0x28,
       SQR1 = 0x2C, SQR2 = 0x30, SQR3 = 0x34, JSQR = 0x38, JDR1 = 0x3C, DR = 0x4C };
/* SR */
#define SR_AWD   (1u << 0)
#define SR_EOC   (1u << 1)
#define SR_JEOC  (1u << 2)
#define SR_JSTRT (1u << 3)
#define SR_STRT  (1u << 4)
/* CR1 */
#define CR1_AWDCH    0x1Fu
#define CR1_EOCIE    (1u << 5)
#define CR1_AWDIE    (1u << 6)
#define CR1_JEOCIE   (1u << 7)
#define CR1_SCAN     (1u << 8)
#define CR1_AWDSGL   (1u << 9)
#define CR1_JAUTO    (1u << 10)
#define CR1_DISCEN   (1u << 11)
#define CR1_JDISCEN  (1u << 12)
#define CR1_DUALMOD  (0xFu << 16)
#define CR1_JAWDEN   (1u << 22)
#define CR1_AWDEN    (1u << 23)
#define CR1_UNMODELED (CR1_JAUTO | CR1_DISCEN | CR1_JDISCEN | CR1_DUALMOD)
#define CR1_MASK     0x00CFFFFFu
/* CR2 */
#define CR2_ADON     (1u << 0)
#define CR2_CONT     (1u << 1)
#define CR2_CAL      (1u << 2)
#define CR2_RSTCAL   (1u << 3)
#define CR2_DMA      (1u << 8)
#define CR2_ALIGN    (1u << 11)
#define CR2_JEXTSEL_SHIFT 12
#define CR2_JEXTTRIG (1u << 15)
#define CR2_EXTSEL_SHIFT 17
#define CR2_EXTTRIG  (1u << 20)
#define CR2_JSWSTART (1u << 21)
#define CR2_SWSTART  (1u << 22)
#define CR2_TSVREFE  (1u << 23)
#define CR2_MASK     0x00FEF90Fu
#define TRIG_SW      7u /* (J)EXTSEL 111: (J)SWSTART */

#define GROUP_IDLE 0
#define GROUP_REG  1
#define GROUP_INJ  2

/* DS5319 "ADC characteristics" (typical, in ADC clock cycles) */
#define TCAL_ADC        83u /* tCAL, calibration time */
#define TRSTCAL_ADC     1u  /* ours: the datasheet gives no time for RSTCAL; one ADC clock */
#define TLAT_INJ_ADC    3u  /* tlat, injection trigger conversion latency */
#define TLAT_REG_ADC    2u  /* tlatr, regular trigger conversion latency */
#define TCONV_HALF      25u /* 12.5 cycles of successive approximation (RM0008 11.6), x2 */
/* RM0008 11.12.4/5 SMPx: 1.5, 7.5, 13.5, 28.5, 41.5, 55.5, 71.5, 239.5 cycles, x2 */
static const uint16_t smp_half[8] = { 3, 15, 27, 57, 83, 111, 143, 479 };
/* DS5319 "TS characteristics" and "Embedded internal reference voltage" (typical) */
#define TS_V25_V        1.43   /* V25, sensor voltage at 25 degC */
#define TS_SLOPE_V_C    0.0043 /* Avg_Slope; the voltage falls as the die warms (RM0008 11.10) */
#define VREFINT_V       1.20   /* VREFINT */

static uint64_t adc_cycles(const stm32_adc_t *a, uint64_t half_ticks)
{
    return stm32_half_ticks_to_cycles(half_ticks, a->clk->hclk, a->clk->adcclk);
}

static void update_irq(stm32_adc_t *a)
{
    bool lv = ((a->sr & SR_EOC) && (a->cr1 & CR1_EOCIE)) || ((a->sr & SR_JEOC) && (a->cr1 & CR1_JEOCIE))
           || ((a->sr & SR_AWD) && (a->cr1 & CR1_AWDIE));
    a->irq_level = lv;
    bool line = lv || (a->partner && a->partner->irq_level);
    if (a->irq.set) a->irq.set(a->irq.ctx, STM32_ADC_IRQ, line);
}

static void set_dma(stm32_adc_t *a, bool level)
{
    if (a->dma_level == level) return;
    a->dma_level = level;
    if (a->dma.request) a->dma.request(a->dma.ctx, a->dma_channel, level);
}

/* The channel of rank pos (0-based) of a group. JSQR: with JL+1 ranks the
 * conversion starts at JSQ(4-JL-1) (RM0008 11.12.12 note); rank k's result
 * goes to JDR(k+1), as ST's F1 HAL reads rank k from JDRk. */
static unsigned channel_of(const stm32_adc_t *a, int group, unsigned pos)
{
    if (group == GROUP_INJ) {
        unsigned jl = (a->jsqr >> 20) & 3u, slot = 3u - jl + pos;
        return (a->jsqr >> (5 * slot)) & 0x1Fu;
    }
    if (pos < 6) return (a->sqr3 >> (5 * pos)) & 0x1Fu;
    if (pos < 12) return (a->sqr2 >> (5 * (pos - 6))) & 0x1Fu;
    return (a->sqr1 >> (5 * (pos - 12))) & 0x1Fu;
}

static unsigned group_length(const stm32_adc_t *a, int group)
{
    if (!(a->cr1 & CR1_SCAN)) return 1; /* RM0008 11.3.8: without SCAN a group is its first channel */
    return group == GROUP_INJ ? ((a->jsqr >> 20) & 3u) + 1 : ((a->sqr1 >> 20) & 0xFu) + 1;
}

static unsigned sample_half(const stm32_adc_t *a, unsigned ch)
{
    uint32_t smp = ch < 10 ? a->smpr2 >> (3 * ch) : ch < 18 ? a->smpr1 >> (3 * (ch - 10)) : 0;
    return smp_half[smp & 7u];
}

static void begin_conversion(stm32_adc_t *a, uint64_t t)
{
    a->channel = channel_of(a, a->group, a->pos);
    unsigned ts = sample_half(a, a->channel);
    a->sample_at = stm32_at(t, adc_cycles(a, ts));
    a->end_at = stm32_at(t, adc_cycles(a, ts + TCONV_HALF));
}

/* The input voltage of a channel at cycle t: pins from the board, 16/17 the
 * temperature sensor and VREFINT (ADC1 with TSVREFE only; 0 V otherwise). */
static double channel_volts(const stm32_adc_t *a, unsigned ch, uint64_t t)
{
    if (ch < 16) return a->volts ? a->volts(a->volts_ctx, ch, t) : 0.0;
    if (ch > 17 || a->index != 1 || !(a->cr2 & CR2_TSVREFE)) return 0.0;
    if (ch == 16) return TS_V25_V - (a->temp_c - 25.0) * TS_SLOPE_V_C;
    return VREFINT_V;
}

static void sample(stm32_adc_t *a, uint64_t t)
{
    double v = channel_volts(a, a->channel, t);
    double c = a->vref_v > 0.0 ? floor(v * 4096.0 / a->vref_v + 0.5) : 0.0;
    if (!(c >= 0.0)) c = 0.0; /* also NaN */
    if (c > 4095.0) c = 4095.0;
    a->code = (uint16_t)c;
    a->sample_at = MMIO_NEVER;
}

static void watchdog(stm32_adc_t *a)
{
    bool on = a->group == GROUP_INJ ? (a->cr1 & CR1_JAWDEN) : (a->cr1 & CR1_AWDEN);
    if (!on || ((a->cr1 & CR1_AWDSGL) && a->channel != (a->cr1 & CR1_AWDCH))) return;
    if (a->code > (a->htr & 0xFFFu) || a->code < (a->ltr & 0xFFFu)) a->sr |= SR_AWD;
}

/* The result of a conversion into DR or JDRx, aligned (RM0008 11.5). */
static void store(stm32_adc_t *a)
{
    bool left = a->cr2 & CR2_ALIGN;
    if (a->group == GROUP_INJ) {
        int v = (int)a->code - (int)(a->jofr[a->pos] & 0xFFFu);
        a->jdr[a->pos] = (uint16_t)(left ? v * 8 : v); /* SEXT above the data */
    } else {
        a->dr = left ? (uint32_t)a->code << 4 : a->code;
        if ((a->cr2 & CR2_DMA) && a->dma.request) set_dma(a, true);
    }
    watchdog(a);
}

static void end_group(stm32_adc_t *a, uint64_t t)
{
    if (a->group == GROUP_INJ) {
        a->sr |= SR_JEOC | SR_EOC; /* RM0008 11.12.1: EOC ends an injected group too (ST's F1 HAL clears both) */
        a->group = GROUP_IDLE;
        if (a->reg_resume && a->reg_start == MMIO_NEVER) { a->reg_start = t; a->reg_sw = false; } /* resume */
        else if (a->reg_start != MMIO_NEVER && a->reg_start < t) a->reg_start = t;
    } else {
        a->sr |= SR_EOC;
        a->reg_pos = 0;
        a->reg_resume = false;
        a->group = GROUP_IDLE;
        if (a->cr2 & CR2_CONT) { a->group = GROUP_REG; a->pos = 0; begin_conversion(a, t); }
    }
}

static void end_conversion(stm32_adc_t *a, uint64_t t)
{
    a->end_at = MMIO_NEVER;
    store(a);
    a->pos++;
    if (a->pos < group_length(a, a->group)) { begin_conversion(a, t); return; }
    end_group(a, t);
}

static void start_group(stm32_adc_t *a, int group, uint64_t t)
{
    if (group == GROUP_INJ) {
        if (a->group == GROUP_REG) { a->reg_pos = a->pos; a->reg_resume = true; } /* aborted, resumed later */
        a->inj_start = MMIO_NEVER;
        a->sr |= SR_JSTRT;
        if (a->inj_sw) a->cr2 &= ~CR2_JSWSTART; /* cleared as the conversion starts (RM0008 11.12.3) */
        a->pos = 0;
    } else {
        a->reg_start = MMIO_NEVER;
        a->sr |= SR_STRT;
        if (a->reg_sw) a->cr2 &= ~CR2_SWSTART;
        a->pos = a->reg_pos;
        a->reg_resume = false;
    }
    a->group = group;
    begin_conversion(a, t);
}

static uint64_t adc_next_event(void *self)
{
    const stm32_adc_t *a = self;
    uint64_t t = a->rstcal_end;
    if (a->cal_end < t) t = a->cal_end;
    if (a->group != GROUP_INJ && a->inj_start < t) t = a->inj_start;
    if (a->group == GROUP_IDLE && a->reg_start < t) t = a->reg_start;
    if (a->sample_at < t) t = a->sample_at;
    if (a->end_at < t) t = a->end_at;
    return t;
}

/* One event due at cycle t, in the order they happen within a cycle. */
static void step(stm32_adc_t *a, uint64_t t)
{
    if (a->rstcal_end == t) { a->cr2 &= ~CR2_RSTCAL; a->rstcal_end = MMIO_NEVER; return; }
    if (a->cal_end == t) { a->cr2 &= ~CR2_CAL; a->cal_end = MMIO_NEVER; return; }
    if (a->sample_at == t) { sample(a, t); return; }
    if (a->end_at == t) { end_conversion(a, t); update_irq(a); return; }
    if (a->group != GROUP_INJ && a->inj_start == t) { start_group(a, GROUP_INJ, t); return; }
    if (a->group == GROUP_IDLE && a->reg_start == t) { start_group(a, GROUP_REG, t); return; }
}

static void adc_advance(void *self, uint64_t now)
{
    stm32_adc_t *a = self;
    for (;;) {
        uint64_t t = adc_next_event(a);
        if (t > now) break;
        step(a, t);
    }
    if (now > a->now) a->now = now;
}

/* A trigger for a group at cycle t: the start after the trigger latency.
 * A trigger while the same group converts is ignored (RM0008 11.3.9). */
static void trigger(stm32_adc_t *a, int group, bool sw, uint64_t t)
{
    if (!(a->cr2 & CR2_ADON)) return;
    if (group == GROUP_INJ) {
        if (a->group == GROUP_INJ || a->inj_start != MMIO_NEVER) return;
        a->inj_sw = sw;
        a->inj_start = stm32_at(t, adc_cycles(a, 2 * TLAT_INJ_ADC));
    } else {
        if (a->group == GROUP_REG || a->reg_start != MMIO_NEVER) return;
        a->reg_sw = sw;
        a->reg_start = stm32_at(t, adc_cycles(a, 2 * TLAT_REG_ADC));
    }
}

void stm32_adc_ext_trigger(stm32_adc_t *a, bool injected, unsigned source, uint64_t now)
{
    adc_advance(a, now);
    uint32_t en = injected ? CR2_JEXTTRIG : CR2_EXTTRIG;
    unsigned sel = (a->cr2 >> (injected ? CR2_JEXTSEL_SHIFT : CR2_EXTSEL_SHIFT)) & 7u;
    if ((a->cr2 & en) && sel == source && source != TRIG_SW)
        trigger(a, injected ? GROUP_INJ : GROUP_REG, false, now);
}

static void power_off(stm32_adc_t *a)
{
    a->group = GROUP_IDLE;
    a->reg_start = a->inj_start = a->sample_at = a->end_at = MMIO_NEVER;
    a->reg_pos = 0;
    a->reg_resume = false;
}

static void write_cr2(stm32_adc_t *a, uint32_t v)
{
    uint32_t old = a->cr2;
    uint64_t t = a->now;
    v &= CR2_MASK;
    /* the self-clearing bits stay set until their hardware clears them */
    a->cr2 = v | (old & (CR2_CAL | CR2_RSTCAL));
    if (!(v & CR2_ADON)) { power_off(a); return; }
    /* RM0008 11.12.3 ADON: writing 1 when it is 1 starts a regular conversion,
     * unless another bit changes in the same write */
    if ((old & CR2_ADON) && ((old ^ v) & CR2_MASK & ~CR2_ADON) == 0) trigger(a, GROUP_REG, false, t);
    /* a calibration (or its reset) runs while the ADC is on; one asked for
     * while it was off starts when it is powered */
    if ((a->cr2 & CR2_RSTCAL) && a->rstcal_end == MMIO_NEVER)
        a->rstcal_end = stm32_at(t, adc_cycles(a, 2 * TRSTCAL_ADC));
    if ((a->cr2 & CR2_CAL) && a->cal_end == MMIO_NEVER)
        a->cal_end = stm32_at(t, adc_cycles(a, 2 * TCAL_ADC));
    if ((v & CR2_SWSTART) && (v & CR2_EXTTRIG) && ((v >> CR2_EXTSEL_SHIFT) & 7u) == TRIG_SW)
        trigger(a, GROUP_REG, true, t);
    if ((v & CR2_JSWSTART) && (v & CR2_JEXTTRIG) && ((v >> CR2_JEXTSEL_SHIFT) & 7u) == TRIG_SW)
        trigger(a, GROUP_INJ, true, t);
    if (!(v & CR2_DMA)) set_dma(a, false);
}

/* The stored word at a register offset, no side effect; false: none there. */
static bool peek(const stm32_adc_t *a, uint32_t off, uint32_t *v)
{
    switch (off) {
    case SR: *v = a->sr; return true;
    case CR1: *v = a->cr1; return true;
    case CR2: *v = a->cr2; return true;
    case SMPR1: *v = a->smpr1; return true;
    case SMPR2: *v = a->smpr2; return true;
    case HTR: *v = a->htr; return true;
    case LTR: *v = a->ltr; return true;
    case SQR1: *v = a->sqr1; return true;
    case SQR2: *v = a->sqr2; return true;
    case SQR3: *v = a->sqr3; return true;
    case JSQR: *v = a->jsqr; return true;
    case DR: *v = a->dr; return true;
    default: break;
    }
    if (off >= JOFR1 && off < HTR) { *v = a->jofr[(off - JOFR1) / 4]; return true; }
    if (off >= JDR1 && off < DR) { *v = a->jdr[(off - JDR1) / 4]; return true; }
    return false;
}

static mmio_status_t adc_read(void *self, uint32_t off, unsigned size, uint32_t *value)
{
    stm32_adc_t *a = self;
    uint32_t v;
    if (!stm32_access_ok(off, size) || !peek(a, off & ~3u, &v)) return MMIO_UNMODELED;
    if ((off & ~3u) == DR) { /* reading DR clears EOC (RM0008 11.12.1) */
        a->sr &= ~SR_EOC;
        set_dma(a, false);
        update_irq(a);
    }
    *value = stm32_read_lanes(v, off, size);
    return MMIO_OK;
}

static mmio_status_t write_word(stm32_adc_t *a, uint32_t off, uint32_t v)
{
    mmio_status_t st = MMIO_OK;
    switch (off) {
    case SR: a->sr &= (v & 0x1Fu) | ~0x1Fu; break; /* rc_w0 */
    case CR1:
        if (v & (a->index == 1 ? CR1_UNMODELED : CR1_UNMODELED & ~CR1_DUALMOD)) st = MMIO_UNMODELED;
        a->cr1 = v & CR1_MASK & (a->index == 1 ? ~0u : ~CR1_DUALMOD);
        break;
    case CR2: write_cr2(a, v); break;
    case SMPR1: a->smpr1 = v & 0x00FFFFFFu; break;
    case SMPR2: a->smpr2 = v & 0x3FFFFFFFu; break;
    case HTR: a->htr = v & 0xFFFu; break;
    case LTR: a->ltr = v & 0xFFFu; break;
    case SQR1: a->sqr1 = v & 0x00FFFFFFu; break;
    case SQR2: a->sqr2 = v & 0x3FFFFFFFu; break;
    case SQR3: a->sqr3 = v & 0x3FFFFFFFu; break;
    case JSQR: a->jsqr = v & 0x003FFFFFu; break;
    case DR: break; /* read-only */
    default:
        if (off >= JOFR1 && off < HTR) a->jofr[(off - JOFR1) / 4] = v & 0xFFFu;
        else if (!(off >= JDR1 && off < DR)) st = MMIO_UNMODELED;
        break;
    }
    update_irq(a);
    return st;
}

static mmio_status_t adc_write(void *self, uint32_t off, unsigned size, uint32_t value)
{
    stm32_adc_t *a = self;
    uint32_t old;
    if (!stm32_access_ok(off, size) || !peek(a, off & ~3u, &old)) return MMIO_UNMODELED;
    return write_word(a, off & ~3u, stm32_write_lanes(value, size));
}

static void adc_reset(void *self)
{
    stm32_adc_t *a = self;
    a->sr = a->cr1 = a->cr2 = a->smpr1 = a->smpr2 = 0;
    for (int i = 0; i < 4; i++) a->jofr[i] = a->jdr[i] = 0;
    a->htr = 0x0FFFu; /* RM0008 11.12.7: reset 0x0000 0FFF */
    a->ltr = a->sqr1 = a->sqr2 = a->sqr3 = a->jsqr = a->dr = 0;
    a->rstcal_end = a->cal_end = MMIO_NEVER;
    a->reg_sw = a->inj_sw = false;
    a->code = 0;
    a->channel = 0;
    power_off(a);
    set_dma(a, false);
    update_irq(a);
}

const mmio_ops_t stm32_adc_ops = { "ADC", adc_read, adc_write, adc_advance, adc_next_event, adc_reset };

void stm32_adc_init(stm32_adc_t *a, unsigned index, const mmio_clocks_t *clk, mmio_irq_t irq,
                    mmio_dma_req_t dma, stm32_adc_volts_fn volts, void *volts_ctx, double vref_v)
{
    *a = (stm32_adc_t){ 0 };
    a->clk = clk;
    a->irq = irq;
    a->dma = dma;
    a->dma_channel = STM32_ADC1_DMA_CH;
    a->volts = volts;
    a->volts_ctx = volts_ctx;
    a->index = index;
    a->vref_v = vref_v;
    a->temp_c = 25.0; /* ours: a die at the datasheet's reference temperature */
    adc_reset(a);
}

void stm32_adc_share_irq(stm32_adc_t *a, stm32_adc_t *b)
{
    a->partner = b;
    b->partner = a;
}

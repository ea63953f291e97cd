/* stm32f4_adc.c - STM32F4 ADC1-3: RM0090 rev 19 section 13 (13.3.1 ADON,
 * 13.3.5-13.3.8 single, continuous, scan modes, 13.3.4 channel selection,
 * 13.3.11 injected channels, 13.4 data alignment (left alignment of a
 * reduced resolution, 13.4 figure 48), 13.5 channel-wise programmable
 * sampling time: tCONV = sampling + 12/10/8/6 ADCCLK cycles at RES
 * 12/10/8/6 bits, 13.6 conversion on external trigger (EXTEN edge, EXTSEL
 * table 69, JEXTEN/JEXTSEL table 70), 13.8 DMA with DDS and overrun
 * (13.8.1), 13.9 EOC/EOCS, 13.10 temperature sensor, 13.12 interrupts, 13.13
 * registers) and RM0383 rev 3 section 11. Timing and analog figures from
 * DS8626 rev 9: 6.3.20 table "ADC characteristics" (tlat injection trigger
 * latency 3 1/fADC max, tlatr regular trigger latency 2 1/fADC max),
 * 6.3.21 "temperature sensor" (V25 0.76 V, Avg_Slope 2.5 mV/degC, typical),
 * 6.3.22 "VBAT" (a /2 bridge), 6.3.23 "internal reference voltage"
 * (VREFINT 1.21 V typical).
 *
 * Modeled: ADON, RES, SCAN, CONT, SQR1-3 (up to 16 ranks), SWSTART and
 * external triggers (EXTEN/EXTSEL), the injected group (JSQR, JSWSTART,
 * JEXTEN/JEXTSEL; it interrupts a regular conversion, which restarts its
 * rank after it), SMPR1/2, ALIGN, JOFR1-4, EOCS (EOC per conversion or
 * per sequence), the DMA request per regular conversion (DMA), overrun
 * (OVR: a regular result overwritten while unread, with DMA or EOCS; the
 * ADC stops until ADON or SWSTART again), EOC/JEOC/OVR interrupts on the
 * shared line, the common CCR's ADCPRE, TSVREFE and VBATE, CSR (the three
 * ADCs' flags).
 * Not modeled (a write that sets them answers MMIO_UNMODELED; the bits
 * then act as 0): the analog watchdog (AWDEN, JAWDEN: AWD never set),
 * DISCEN/JDISCEN, JAUTO, CCR's multi-ADC modes (MULTI, DELAY, DMA, DDS),
 * CDR. Stated limits: an ideal converter (code = round(V x 2^RES / VREF+));
 * no tSTAB after ADON; DDS = 0's end of requests after the DMA
 * controller's last transfer is not seen (requests continue as with DDS =
 * 1); the ADC clock's phase against HCLK (times round up to a core cycle);
 * channel 16 is the temperature sensor (F40x; the F411's sensor on channel
 * 18 is read as VBAT there). */
#include "arm/stm32f4_adc.h"

#include <math.h>
#include <stddef.h>

#include "arm/stm32f1_clk.h"
#include "arm/stm32f4_reg.h"

enum { SR = 0x00, CR1 = 0x04, CR2 = 0x08, SMPR1 = 0x0C, SMPR2 = 0x10, JOFR1 = 0x14, HTR = 0x24, LTR = 0x28,
       SQR1 = 0x2C, SQR2 = 0x30, SQR3 = 0x34, JSQR = 0x38, JDR1 = 0x3C, DR = 0x4C };
enum { CSR = 0x00, CCR = 0x04, CDR = 0x08 };
#define SR_EOC   (1u << 1)
#define SR_JEOC  (1u << 2)
#define SR_JSTRT (1u << 3)
#define SR_STRT  (1u << 4)
#define SR_OVR   (1u << 5)
#define CR1_EOCIE  (1u << 5)
#define CR1_JEOCIE (1u << 7)
#define CR1_SCAN   (1u << 8)
#define CR1_UNMODELED ((1u << 6) | (1u << 10) | (1u << 11) | (1u << 12) | (1u << 22) | (1u << 23))
#define CR1_RES_SHIFT 24
#define CR1_OVRIE  (1u << 26)
#define CR1_MASK   0x07C0FFFFu
#define CR2_ADON   (1u << 0)
#define CR2_CONT   (1u << 1)
#define CR2_DMA    (1u << 8)
#define CR2_EOCS   (1u << 10)
#define CR2_ALIGN  (1u << 11)
#define CR2_JEXTSEL_SHIFT 16
#define CR2_JEXTEN_SHIFT 20
#define CR2_JSWSTART (1u << 22)
#define CR2_EXTSEL_SHIFT 24
#define CR2_EXTEN_SHIFT 28
#define CR2_SWSTART (1u << 30)
#define CR2_MASK   0x7F7F0F03u
#define CCR_ADCPRE_SHIFT 16
#define CCR_VBATE  (1u << 22)
#define CCR_TSVREFE (1u << 23)
#define CCR_UNMODELED 0x0000EF1Fu /* MULTI, DELAY, DDS, DMA */

#define GROUP_IDLE 0
#define GROUP_REG  1
#define GROUP_INJ  2
#define TLAT_INJ_ADC 3u  /* DS8626 tlat */
#define TLAT_REG_ADC 2u  /* DS8626 tlatr */
static const uint16_t smp_cycles[8] = { 3, 15, 28, 56, 84, 112, 144, 480 }; /* RM0090 13.13.4/5 */
static const uint8_t res_bits[4] = { 12, 10, 8, 6 };                        /* CR1 RES */
#define TS_V25_V     0.76   /* DS8626 6.3.21 */
#define TS_SLOPE_V_C 0.0025
#define VREFINT_V    1.21   /* DS8626 6.3.23 */

uint32_t stm32f4_adc_clock(const stm32f4_adc_common_t *c)
{
    return c->clk->pclk2 / (2u * (((c->ccr >> CCR_ADCPRE_SHIFT) & 3u) + 1u));
}

static uint64_t adc_cycles(const stm32f4_adc_t *a, uint64_t ticks)
{
    return stm32_ticks_to_cycles(ticks, a->common->clk->hclk, stm32f4_adc_clock(a->common));
}

static void common_irq(stm32f4_adc_common_t *c)
{
    bool lv = false;
    for (int i = 0; i < 3; i++) lv = lv || (c->adc[i] && c->adc[i]->irq_level);
    if (lv == c->irq_level) return;
    c->irq_level = lv;
    if (c->irq.set) c->irq.set(c->irq.ctx, STM32F4_ADC_IRQ, lv);
}

static void update_irq(stm32f4_adc_t *a)
{
    a->irq_level = ((a->sr & SR_EOC) && (a->cr1 & CR1_EOCIE)) || ((a->sr & SR_JEOC) && (a->cr1 & CR1_JEOCIE))
                || ((a->sr & SR_OVR) && (a->cr1 & CR1_OVRIE));
    common_irq(a->common);
}

static void set_dma(stm32f4_adc_t *a, bool level)
{
    if (a->dma_level == level) return;
    a->dma_level = level;
    if (a->dma.request) a->dma.request(a->dma.ctx, a->dma_request, level);
}

/* The channel of rank pos of a group (JSQR: JL+1 ranks from JSQ(4-JL-1), 13.13.12). */
static unsigned channel_of(const stm32f4_adc_t *a, int group, unsigned pos)
{
    if (group == GROUP_INJ) {
        unsigned jl = (a->jsqr >> 20) & 3u;
        return (a->jsqr >> (5 * (3u - jl + pos))) & 0x1Fu;
    }
    if (pos < 6) return (a->sqr3 >> (5 * pos)) & 0x1Fu;
    if (pos < 12) return (a->sqr2 >> (5 * (pos - 6))) & 0x1Fu;
    return (a->sqr1 >> (5 * (pos - 12))) & 0x1Fu;
}

static unsigned group_length(const stm32f4_adc_t *a, int group)
{
    if (!(a->cr1 & CR1_SCAN)) return 1; /* 13.3.7: without SCAN a group is its first rank */
    return group == GROUP_INJ ? ((a->jsqr >> 20) & 3u) + 1 : ((a->sqr1 >> 20) & 0xFu) + 1;
}

static unsigned resolution(const stm32f4_adc_t *a) { return res_bits[(a->cr1 >> CR1_RES_SHIFT) & 3u]; }

static void begin_conversion(stm32f4_adc_t *a, uint64_t t)
{
    a->channel = channel_of(a, a->group, a->pos);
    unsigned ch = a->channel;
    uint32_t smp = ch < 10 ? a->smpr2 >> (3 * ch) : ch < 19 ? a->smpr1 >> (3 * (ch - 10)) : 0;
    unsigned ts = smp_cycles[smp & 7u];
    a->sample_at = stm32_at(t, adc_cycles(a, ts));
    a->end_at = stm32_at(t, adc_cycles(a, ts + resolution(a))); /* 13.5 */
}

static double channel_volts(const stm32f4_adc_t *a, unsigned ch, uint64_t t)
{
    uint32_t ccr = a->common->ccr;
    if (ch < 16) return a->volts ? a->volts(a->volts_ctx, ch, t) : 0.0;
    if (a->index != 1 || ch > 18) return 0.0;
    if (ch == 16) return (ccr & CCR_TSVREFE) ? TS_V25_V + (a->temp_c - 25.0) * TS_SLOPE_V_C : 0.0;
    if (ch == 17) return (ccr & CCR_TSVREFE) ? VREFINT_V : 0.0;
    return (ccr & CCR_VBATE) && a->volts ? a->volts(a->volts_ctx, 18, t) / 2.0 : 0.0;
}

static void sample(stm32f4_adc_t *a, uint64_t t)
{
    double full = (double)(1u << resolution(a));
    double v = channel_volts(a, a->channel, t);
    double c = a->vref_v > 0.0 ? floor(v * full / a->vref_v + 0.5) : 0.0;
    if (!(c >= 0.0)) c = 0.0; /* also NaN */
    if (c > full - 1.0) c = full - 1.0;
    a->code = (uint16_t)c;
    a->sample_at = MMIO_NEVER;
}

/* A result aligned (13.4): right, or left within 16 bits (6-bit: within a byte). */
static uint32_t aligned(const stm32f4_adc_t *a, int v)
{
    if (!(a->cr2 & CR2_ALIGN)) return (uint16_t)v;
    unsigned res = resolution(a);
    return (uint16_t)(v * (1 << ((res == 6 ? 8u : 16u) - res)));
}

static void power_off(stm32f4_adc_t *a)
{
    a->group = GROUP_IDLE;
    a->reg_start = a->inj_start = a->sample_at = a->end_at = MMIO_NEVER;
    a->reg_pos = 0;
    a->reg_resume = false;
}

/* A regular result into DR; false: an overrun stopped the ADC (13.8.1). */
static bool store_regular(stm32f4_adc_t *a)
{
    bool detect = (a->cr2 & CR2_DMA) || (a->cr2 & CR2_EOCS);
    if (a->dr_unread && detect) {
        a->sr |= SR_OVR;
        set_dma(a, false);
        power_off(a);
        return false;
    }
    a->dr = aligned(a, a->code);
    a->dr_unread = true;
    if (a->cr2 & CR2_DMA) set_dma(a, true);
    return true;
}

static void end_group(stm32f4_adc_t *a, uint64_t t)
{
    if (a->group == GROUP_INJ) {
        a->sr |= SR_JEOC;
        a->group = GROUP_IDLE;
        if (a->reg_resume && a->reg_start == MMIO_NEVER) { a->reg_start = t; a->reg_sw = false; }
        return;
    }
    a->sr |= SR_EOC; /* EOCS 0: at the sequence's end */
    a->reg_pos = 0;
    a->reg_resume = false;
    a->group = GROUP_IDLE;
    if (a->cr2 & CR2_CONT) { a->group = GROUP_REG; a->pos = 0; begin_conversion(a, t); }
}

static void end_conversion(stm32f4_adc_t *a, uint64_t t)
{
    a->end_at = MMIO_NEVER;
    a->conversions++;
    if (a->group == GROUP_INJ) {
        a->jdr[a->pos] = aligned(a, (int)a->code - (int)(a->jofr[a->pos] & 0xFFFu));
    } else {
        if (!store_regular(a)) return;
        if (a->cr2 & CR2_EOCS) a->sr |= SR_EOC; /* EOCS 1: after each conversion (13.9) */
    }
    a->pos++;
    if (a->pos < group_length(a, a->group)) { begin_conversion(a, t); return; }
    end_group(a, t);
}

static void start_group(stm32f4_adc_t *a, int group, uint64_t t)
{
    if (group == GROUP_INJ) {
        if (a->group == GROUP_REG) { a->reg_pos = a->pos; a->reg_resume = true; }
        a->inj_start = MMIO_NEVER;
        a->sr |= SR_JSTRT;
        if (a->inj_sw) a->cr2 &= ~CR2_JSWSTART; /* cleared as the conversion starts (13.13.3) */
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
    const stm32f4_adc_t *a = self;
    uint64_t t = a->sample_at < a->end_at ? a->sample_at : a->end_at;
    if (a->group != GROUP_INJ && a->inj_start < t) t = a->inj_start;
    if (a->group == GROUP_IDLE && a->reg_start < t) t = a->reg_start;
    return t;
}

static void step(stm32f4_adc_t *a, uint64_t t)
{
    if (a->sample_at == t) { sample(a, t); return; }
    if (a->end_at == t) { end_conversion(a, t); update_irq(a); return; }
    if (a->group != GROUP_INJ && a->inj_start == t) { start_group(a, GROUP_INJ, t); return; }
    if (a->group == GROUP_IDLE && a->reg_start == t) start_group(a, GROUP_REG, t);
}

static void adc_advance(void *self, uint64_t now)
{
    stm32f4_adc_t *a = self;
    for (;;) {
        uint64_t t = adc_next_event(a);
        if (t > now) break;
        step(a, t);
    }
    if (now > a->now) a->now = now;
}

/* A trigger for a group at cycle t: the start after the trigger latency;
 * ignored while the same group converts or is about to. */
static void trigger(stm32f4_adc_t *a, int group, bool sw, uint64_t t)
{
    if (!(a->cr2 & CR2_ADON)) return;
    if (group == GROUP_INJ) {
        if (a->group == GROUP_INJ || a->inj_start != MMIO_NEVER) return;
        a->inj_sw = sw;
        a->inj_start = stm32_at(t, adc_cycles(a, TLAT_INJ_ADC));
    } else {
        if (a->group == GROUP_REG || a->reg_start != MMIO_NEVER) return;
        a->reg_sw = sw;
        a->reg_start = stm32_at(t, adc_cycles(a, TLAT_REG_ADC));
    }
}

void stm32f4_adc_ext_trigger(stm32f4_adc_t *a, bool injected, unsigned source, bool rising, uint64_t now)
{
    adc_advance(a, now);
    unsigned en = (a->cr2 >> (injected ? CR2_JEXTEN_SHIFT : CR2_EXTEN_SHIFT)) & 3u;
    unsigned sel = (a->cr2 >> (injected ? CR2_JEXTSEL_SHIFT : CR2_EXTSEL_SHIFT)) & 0xFu;
    bool edge_ok = rising ? (en & 1u) : (en & 2u); /* EXTEN 01 rising, 10 falling, 11 both */
    if (edge_ok && sel == source) trigger(a, injected ? GROUP_INJ : GROUP_REG, false, now);
}

static void write_cr2(stm32f4_adc_t *a, uint32_t v)
{
    v &= CR2_MASK;
    a->cr2 = v;
    if (!(v & CR2_ADON)) { power_off(a); a->cr2 &= ~(CR2_SWSTART | CR2_JSWSTART); return; }
    if (v & CR2_SWSTART) trigger(a, GROUP_REG, true, a->now);
    if (v & CR2_JSWSTART) trigger(a, GROUP_INJ, true, a->now);
    if (!(v & CR2_DMA)) set_dma(a, false);
}

static bool peek(const stm32f4_adc_t *a, uint32_t off, uint32_t *v)
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
    stm32f4_adc_t *a = self;
    uint32_t v;
    if (!stm32_access_ok(off, size) || !peek(a, off & ~3u, &v)) return MMIO_UNMODELED;
    if ((off & ~3u) == DR) { /* reading DR clears EOC (13.13.1) and serves the DMA request */
        a->sr &= ~SR_EOC;
        a->dr_unread = false;
        set_dma(a, false);
        update_irq(a);
    }
    *value = stm32_read_lanes(v, off, size);
    return MMIO_OK;
}

static mmio_status_t write_word(stm32f4_adc_t *a, uint32_t off, uint32_t v)
{
    mmio_status_t st = MMIO_OK;
    switch (off) {
    case SR: a->sr &= (v & 0x3Fu) | ~0x3Fu; break; /* rc_w0 */
    case CR1:
        if (v & CR1_UNMODELED) st = MMIO_UNMODELED;
        a->cr1 = v & CR1_MASK & ~CR1_UNMODELED;
        break;
    case CR2: write_cr2(a, v); break;
    case SMPR1: a->smpr1 = v & 0x07FFFFFFu; break;
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
        break; /* JDRx: read-only */
    }
    update_irq(a);
    return st;
}

static mmio_status_t adc_write(void *self, uint32_t off, unsigned size, uint32_t value)
{
    stm32f4_adc_t *a = self;
    uint32_t w = off & ~3u, old;
    if (!stm32_access_ok(off, size) || !peek(a, w, &old)) return MMIO_UNMODELED;
    return write_word(a, w, stm32f4_merge(old, off, size, value));
}

static void adc_reset(void *self)
{
    stm32f4_adc_t *a = self;
    a->sr = a->cr1 = a->cr2 = a->smpr1 = a->smpr2 = 0;
    for (int i = 0; i < 4; i++) a->jofr[i] = a->jdr[i] = 0;
    a->htr = 0x0FFFu; /* 13.13.7 */
    a->ltr = a->sqr1 = a->sqr2 = a->sqr3 = a->jsqr = a->dr = 0;
    a->reg_sw = a->inj_sw = a->dr_unread = false;
    a->code = 0;
    a->channel = 0;
    power_off(a);
    set_dma(a, false);
    update_irq(a);
}

const mmio_ops_t stm32f4_adc_ops = { "ADC", adc_read, adc_write, adc_advance, adc_next_event, adc_reset };

void stm32f4_adc_init(stm32f4_adc_t *a, stm32f4_adc_common_t *common, unsigned index, mmio_dma_req_t dma,
                      unsigned dma_request, stm32f4_adc_volts_fn volts, void *volts_ctx, double vref_v)
{
    *a = (stm32f4_adc_t){ 0 };
    a->common = common;
    a->dma = dma;
    a->dma_request = dma_request;
    a->volts = volts;
    a->volts_ctx = volts_ctx;
    a->index = index;
    a->vref_v = vref_v;
    a->temp_c = 25.0; /* ours: the datasheet's reference temperature */
    if (index >= 1 && index <= 3) common->adc[index - 1] = a;
    adc_reset(a);
}

/* The common registers (13.13.16-13.13.18): CSR mirrors the ADCs' SR bits 0-5 at 0, 8, 16. */
static mmio_status_t common_read(void *self, uint32_t off, unsigned size, uint32_t *value)
{
    stm32f4_adc_common_t *c = self;
    uint32_t w = off & ~3u, v = 0;
    if (!stm32_access_ok(off, size) || w > CCR) return MMIO_UNMODELED; /* CDR: multi-mode data */
    if (w == CCR) v = c->ccr;
    else for (int i = 0; i < 3; i++) if (c->adc[i]) v |= (c->adc[i]->sr & 0x3Fu) << (8 * i);
    *value = stm32_read_lanes(v, off, size);
    return MMIO_OK;
}

static mmio_status_t common_write(void *self, uint32_t off, unsigned size, uint32_t value)
{
    stm32f4_adc_common_t *c = self;
    uint32_t w = off & ~3u;
    if (!stm32_access_ok(off, size) || w > CCR) return MMIO_UNMODELED;
    if (w == CSR) return MMIO_OK; /* read-only */
    uint32_t v = stm32f4_merge(c->ccr, off, size, value);
    c->ccr = v & (0x00C3EF1Fu & ~CCR_UNMODELED);
    return (v & CCR_UNMODELED) ? MMIO_UNMODELED : MMIO_OK;
}

static void common_reset(void *self)
{
    stm32f4_adc_common_t *c = self;
    c->ccr = 0;
}

const mmio_ops_t stm32f4_adc_common_ops = { "ADC_COMMON", common_read, common_write, NULL, NULL, common_reset };

void stm32f4_adc_common_init(stm32f4_adc_common_t *c, const mmio_clocks_t *clk, mmio_irq_t irq)
{
    *c = (stm32f4_adc_common_t){ 0 };
    c->clk = clk;
    c->irq = irq;
}

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
 * 18 is read as VBAT there).
 * The conversion engine is stm32_adcseq.c's; this file is the F4's register
 * map and figures for it (stm32_adcseq_family_t), its start bits, triggers,
 * analog inputs and the common registers. */
#include "arm/stm32f4_adc.h"

#include <stddef.h>

#include "arm/stm32f1_clk.h"
#include "arm/stm32f4_reg.h"

enum { CSR = 0x00, CCR = 0x04, CDR = 0x08 };
/* CR1 (RM0090 13.13.2): AWDIE, JAUTO, DISCEN, JDISCEN, JAWDEN, AWDEN unmodeled */
#define CR1_UNMODELED ((1u << 6) | (1u << 10) | (1u << 11) | (1u << 12) | (1u << 22) | (1u << 23))
#define CR1_RES_SHIFT 24
#define CR1_MASK   0x07C0FFFFu
/* CR2 (RM0090 13.13.3) */
#define CR2_ADON   STM32_ADCSEQ_CR2_ADON
#define CR2_DMA    STM32_ADCSEQ_CR2_DMA
#define CR2_EOCS   (1u << 10)
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

#define TS_V25_V     0.76   /* DS8626 6.3.21 */
#define TS_SLOPE_V_C 0.0025
#define VREFINT_V    1.21   /* DS8626 6.3.23 */

uint32_t stm32f4_adc_clock(const stm32f4_adc_common_t *c)
{
    return c->clk->pclk2 / (2u * (((c->ccr >> CCR_ADCPRE_SHIFT) & 3u) + 1u));
}

static uint64_t f4_cycles(const stm32_adcseq_t *s, uint64_t half_ticks)
{
    const stm32f4_adc_common_t *c = ((const stm32f4_adc_t *)s)->common;
    return stm32_half_ticks_to_cycles(half_ticks, c->clk->hclk, stm32f4_adc_clock(c));
}

/* The three ADCs drive one line (ADC, 18): the OR of their levels. */
static void common_irq(stm32f4_adc_common_t *c)
{
    bool lv = false;
    for (int i = 0; i < 3; i++) lv = lv || (c->adc[i] && c->adc[i]->seq.irq_level);
    if (lv == c->irq_level) return;
    c->irq_level = lv;
    if (c->irq.set) c->irq.set(c->irq.ctx, STM32F4_ADC_IRQ, lv);
}

static void f4_irq(stm32_adcseq_t *s) { common_irq(((stm32f4_adc_t *)s)->common); }

static double f4_volts(const stm32_adcseq_t *s, unsigned ch, uint64_t t)
{
    const stm32f4_adc_t *a = (const stm32f4_adc_t *)s;
    uint32_t ccr = a->common->ccr;
    if (ch < 16) return a->volts ? a->volts(a->volts_ctx, ch, t) : 0.0;
    if (a->index != 1 || ch > 18) return 0.0;
    if (ch == 16) return (ccr & CCR_TSVREFE) ? TS_V25_V + (a->temp_c - 25.0) * TS_SLOPE_V_C : 0.0;
    if (ch == 17) return (ccr & CCR_TSVREFE) ? VREFINT_V : 0.0;
    return (ccr & CCR_VBATE) && a->volts ? a->volts(a->volts_ctx, 18, t) / 2.0 : 0.0;
}

static void f4_write_cr2(stm32_adcseq_t *s, uint32_t v)
{
    v &= CR2_MASK;
    s->cr2 = v;
    if (!(v & CR2_ADON)) { stm32_adcseq_power_off(s); s->cr2 &= ~(CR2_SWSTART | CR2_JSWSTART); return; }
    if (v & CR2_SWSTART) stm32_adcseq_trigger(s, STM32_ADCSEQ_REG, true, s->now);
    if (v & CR2_JSWSTART) stm32_adcseq_trigger(s, STM32_ADCSEQ_INJ, true, s->now);
    if (!(v & CR2_DMA)) stm32_adcseq_set_dma(s, false);
}

static const stm32_adcseq_family_t f4_family = {
    .cr2_swstart = CR2_SWSTART, .cr2_jswstart = CR2_JSWSTART,
    .cr2_eocs = CR2_EOCS,              /* 13.9: EOC per conversion; with DMA, overrun detection (13.8.1) */
    .sr_ovr = STM32_ADCSEQ_SR_OVR,     /* 13.8.1 */
    .sr_inj_eoc = 0,                   /* 13.13.1: an injected group's end sets JEOC only */
    .sr_w0 = 0x3Fu,                    /* AWD, EOC, JEOC, JSTRT, STRT, OVR */
    .smpr1_mask = 0x07FFFFFFu,         /* SMP10-18 (13.13.4) */
    .late_regular_at_inj_end = false,  /* a regular start due during the injected group keeps its instant */
    .inj_left_drop = 1,                /* RM0090 13.4 figures 49/50: an injected result's SEXT at bit 15, data one bit lower */
    .res_shift = CR1_RES_SHIFT, .res_mask = 3u,
    .res_bits = { 12, 10, 8, 6 },      /* CR1 RES */
    .conv_half = { 24, 20, 16, 12 },   /* 13.5: tCONV = sampling + 12/10/8/6 ADCCLK cycles, x2 */
    /* RM0090 13.13.4/5 SMPx: 3, 15, 28, 56, 84, 112, 144, 480 cycles, x2 */
    .smp_half = { 6, 30, 56, 112, 168, 224, 288, 960 },
    .tlat_inj_half = 2 * 3,            /* DS8626 tlat: 3 1/fADC max */
    .tlat_reg_half = 2 * 2,            /* DS8626 tlatr: 2 1/fADC max */
    .cycles = f4_cycles, .volts = f4_volts, .irq = f4_irq, .write_cr2 = f4_write_cr2, .lanes = stm32f4_merge,
};

void stm32f4_adc_ext_trigger(stm32f4_adc_t *a, bool injected, unsigned source, bool rising, uint64_t now)
{
    stm32_adcseq_advance(a, now);
    uint32_t cr2 = a->seq.cr2;
    unsigned en = (cr2 >> (injected ? CR2_JEXTEN_SHIFT : CR2_EXTEN_SHIFT)) & 3u;
    unsigned sel = (cr2 >> (injected ? CR2_JEXTSEL_SHIFT : CR2_EXTSEL_SHIFT)) & 0xFu;
    bool edge_ok = rising ? (en & 1u) : (en & 2u); /* EXTEN 01 rising, 10 falling, 11 both */
    if (edge_ok && sel == source) stm32_adcseq_trigger(&a->seq, injected ? STM32_ADCSEQ_INJ : STM32_ADCSEQ_REG, false, now);
}

const mmio_ops_t stm32f4_adc_ops = { "ADC", stm32_adcseq_read, stm32_adcseq_write, stm32_adcseq_advance,
                                     stm32_adcseq_next_event, stm32_adcseq_reset };

void stm32f4_adc_init(stm32f4_adc_t *a, stm32f4_adc_common_t *common, unsigned index, mmio_dma_req_t dma,
                      unsigned dma_request, stm32f4_adc_volts_fn volts, void *volts_ctx, double vref_v)
{
    *a = (stm32f4_adc_t){ 0 };
    stm32_adcseq_init(&a->seq, &f4_family, dma, dma_request, vref_v);
    a->seq.cr1_keep = CR1_MASK & ~CR1_UNMODELED;
    a->seq.cr1_unmodeled = CR1_UNMODELED;
    a->common = common;
    a->volts = volts;
    a->volts_ctx = volts_ctx;
    a->index = index;
    a->temp_c = 25.0; /* ours: the datasheet's reference temperature */
    if (index >= 1 && index <= 3) common->adc[index - 1] = a;
    stm32_adcseq_reset(a);
}

/* The common registers (13.13.16-13.13.18): CSR mirrors the ADCs' SR bits 0-5 at 0, 8, 16. */
static mmio_status_t common_read(void *self, uint32_t off, unsigned size, uint32_t *value)
{
    stm32f4_adc_common_t *c = self;
    uint32_t w = off & ~3u, v = 0;
    if (!stm32_access_ok(off, size) || w > CCR) return MMIO_UNMODELED; /* CDR: multi-mode data */
    if (w == CCR) v = c->ccr;
    else for (int i = 0; i < 3; i++) if (c->adc[i]) v |= (c->adc[i]->seq.sr & 0x3Fu) << (8 * i);
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

/* stm32_adcseq.c - the STM32 ADC conversion engine (stm32_adcseq.h): RM0008
 * rev 21 11.3.5-11.3.9 and RM0090 rev 19 13.3.5-13.3.11 (single,
 * continuous and scan modes; the injected group, which interrupts a regular
 * conversion; the regular group resumes at the rank it was converting), 11.5
 * and 13.4 (data alignment, injected offsets), 11.6 and 13.5 (a conversion:
 * the sampling time of SMPx, then the successive approximation), 11.3.7 and
 * 13.3.7 (the analog watchdog), 11.8 and 13.8 (a DMA request per regular
 * result; the F4's overrun, 13.8.1), 11.12.1 and 13.13.1 (EOC cleared by
 * reading DR).
 * Stated limits: an ideal converter (code = round(V x 2^bits / VREF+),
 * clamped); the ADC clock's phase against HCLK (times round up to a core
 * cycle). */
#include "arm/stm32_adcseq.h"

#include <math.h>
#include <stddef.h>

#include "arm/stm32f1_clk.h"

#define SR_AWD   STM32_ADCSEQ_SR_AWD
#define SR_EOC   STM32_ADCSEQ_SR_EOC
#define SR_JEOC  STM32_ADCSEQ_SR_JEOC
#define SR_JSTRT STM32_ADCSEQ_SR_JSTRT
#define SR_STRT  STM32_ADCSEQ_SR_STRT
#define SR_OVR   STM32_ADCSEQ_SR_OVR
#define CR2_ADON  STM32_ADCSEQ_CR2_ADON
#define CR2_CONT  STM32_ADCSEQ_CR2_CONT
#define CR2_DMA   STM32_ADCSEQ_CR2_DMA
#define CR2_ALIGN STM32_ADCSEQ_CR2_ALIGN
#define GROUP_IDLE STM32_ADCSEQ_IDLE
#define GROUP_REG  STM32_ADCSEQ_REG
#define GROUP_INJ  STM32_ADCSEQ_INJ

uint64_t stm32_adcseq_cycles(const stm32_adcseq_t *s, uint64_t half_ticks) { return s->fam->cycles(s, half_ticks); }

static void update_irq(stm32_adcseq_t *s)
{
    uint32_t sr = s->sr, cr1 = s->cr1;
    s->irq_level = ((sr & SR_EOC) && (cr1 & STM32_ADCSEQ_CR1_EOCIE)) || ((sr & SR_JEOC) && (cr1 & STM32_ADCSEQ_CR1_JEOCIE))
                || ((sr & SR_AWD) && (cr1 & STM32_ADCSEQ_CR1_AWDIE)) || ((sr & SR_OVR) && (cr1 & STM32_ADCSEQ_CR1_OVRIE));
    s->fam->irq(s);
}

void stm32_adcseq_set_dma(stm32_adcseq_t *s, bool level)
{
    if (s->dma_level == level) return;
    s->dma_level = level;
    if (s->dma.request) s->dma.request(s->dma.ctx, s->dma_line, level);
}

/* The channel of rank pos (0-based) of a group. JSQR: with JL+1 ranks the
 * conversion starts at JSQ(4-JL-1) (RM0008 11.12.12 note, RM0090 13.13.12);
 * rank k's result goes to JDR(k+1), as ST's HALs read rank k from JDRk. */
static unsigned channel_of(const stm32_adcseq_t *s, int group, unsigned pos)
{
    if (group == GROUP_INJ) {
        unsigned jl = (s->jsqr >> 20) & 3u, slot = 3u - jl + pos;
        return (s->jsqr >> (5 * slot)) & 0x1Fu;
    }
    if (pos < 6) return (s->sqr3 >> (5 * pos)) & 0x1Fu;
    if (pos < 12) return (s->sqr2 >> (5 * (pos - 6))) & 0x1Fu;
    return (s->sqr1 >> (5 * (pos - 12))) & 0x1Fu;
}

/* RM0008 11.3.8, RM0090 13.3.7: without SCAN a group is its first rank. */
static unsigned group_length(const stm32_adcseq_t *s, int group)
{
    if (!(s->cr1 & STM32_ADCSEQ_CR1_SCAN)) return 1;
    return group == GROUP_INJ ? ((s->jsqr >> 20) & 3u) + 1 : ((s->sqr1 >> 20) & 0xFu) + 1;
}

static unsigned res_code(const stm32_adcseq_t *s) { return (s->cr1 >> s->fam->res_shift) & s->fam->res_mask; }

/* SMP0-9 in SMPR2, SMP10-18 in SMPR1 (a family's SMPR1 mask keeps the ones it has). */
static unsigned sample_half(const stm32_adcseq_t *s, unsigned ch)
{
    uint32_t smp = ch < 10 ? s->smpr2 >> (3 * ch) : ch < 19 ? s->smpr1 >> (3 * (ch - 10)) : 0;
    return s->fam->smp_half[smp & 7u];
}

static void begin_conversion(stm32_adcseq_t *s, uint64_t t)
{
    s->channel = channel_of(s, s->group, s->pos);
    unsigned ts = sample_half(s, s->channel);
    s->sample_at = stm32_at(t, stm32_adcseq_cycles(s, ts));
    s->end_at = stm32_at(t, stm32_adcseq_cycles(s, ts + s->fam->conv_half[res_code(s)]));
}

static void sample(stm32_adcseq_t *s, uint64_t t)
{
    double full = (double)(1u << s->fam->res_bits[res_code(s)]);
    double v = s->fam->volts(s, s->channel, t);
    double c = s->vref_v > 0.0 ? floor(v * full / s->vref_v + 0.5) : 0.0;
    if (!(c >= 0.0)) c = 0.0; /* also NaN */
    if (c > full - 1.0) c = full - 1.0;
    s->code = (uint16_t)c;
    s->sample_at = MMIO_NEVER;
}

/* RM0008 11.3.7: the watchdog on the regular (AWDEN) or injected (JAWDEN) results, one channel with AWDSGL
 * (the F4 keeps neither bit: its watchdog is not modeled). */
static void watchdog(stm32_adcseq_t *s)
{
    uint32_t cr1 = s->cr1;
    bool on = s->group == GROUP_INJ ? (cr1 & STM32_ADCSEQ_CR1_JAWDEN) : (cr1 & STM32_ADCSEQ_CR1_AWDEN);
    if (!on || ((cr1 & STM32_ADCSEQ_CR1_AWDSGL) && s->channel != (cr1 & STM32_ADCSEQ_CR1_AWDCH))) return;
    if (s->code > (s->htr & 0xFFFu) || s->code < (s->ltr & 0xFFFu)) s->sr |= SR_AWD;
}

/* A result aligned (RM0008 11.5, RM0090 13.4): right, or left within 16 bits (6 bits: within a byte),
 * an injected one inj_left_drop bits lower (its SEXT above the data). */
static uint32_t aligned(const stm32_adcseq_t *s, int v, bool injected)
{
    if (!(s->cr2 & CR2_ALIGN)) return (uint16_t)v;
    unsigned res = s->fam->res_bits[res_code(s)];
    unsigned shift = (res == 6 ? 8u : 16u) - res - (injected ? s->fam->inj_left_drop : 0u);
    return (uint16_t)(v * (1 << shift));
}

/* The result into DR or JDRx; false: an overrun (a regular result over an unread one with DMA or EOCS,
 * RM0090 13.8.1) stopped the ADC. */
static bool store(stm32_adcseq_t *s)
{
    const stm32_adcseq_family_t *f = s->fam;
    if (s->group == GROUP_INJ) {
        s->jdr[s->pos] = aligned(s, (int)s->code - (int)(s->jofr[s->pos] & 0xFFFu), true);
    } else {
        if (f->sr_ovr && s->dr_unread && (s->cr2 & (CR2_DMA | f->cr2_eocs))) {
            s->sr |= f->sr_ovr;
            stm32_adcseq_set_dma(s, false);
            stm32_adcseq_power_off(s);
            return false;
        }
        s->dr = aligned(s, s->code, false);
        s->dr_unread = true;
        if (s->cr2 & CR2_DMA) stm32_adcseq_set_dma(s, true);
        if (s->cr2 & f->cr2_eocs) s->sr |= SR_EOC; /* EOCS 1: after each conversion (RM0090 13.9) */
    }
    watchdog(s);
    return true;
}

static void end_group(stm32_adcseq_t *s, uint64_t t)
{
    if (s->group == GROUP_INJ) {
        s->sr |= SR_JEOC | s->fam->sr_inj_eoc;
        s->group = GROUP_IDLE;
        if (s->reg_resume && s->reg_start == MMIO_NEVER) { s->reg_start = t; s->reg_sw = false; } /* resume */
        else if (s->fam->late_regular_at_inj_end && s->reg_start != MMIO_NEVER && s->reg_start < t) s->reg_start = t;
        return;
    }
    s->sr |= SR_EOC; /* at the sequence's end (the F4's EOCS 0) */
    s->reg_pos = 0;
    s->reg_resume = false;
    s->group = GROUP_IDLE;
    if (s->cr2 & CR2_CONT) { s->group = GROUP_REG; s->pos = 0; begin_conversion(s, t); }
}

static void end_conversion(stm32_adcseq_t *s, uint64_t t)
{
    s->end_at = MMIO_NEVER;
    s->conversions++;
    if (!store(s)) return;
    s->pos++;
    if (s->pos < group_length(s, s->group)) { begin_conversion(s, t); return; }
    end_group(s, t);
}

static void start_group(stm32_adcseq_t *s, int group, uint64_t t)
{
    if (group == GROUP_INJ) {
        if (s->group == GROUP_REG) { s->reg_pos = s->pos; s->reg_resume = true; } /* aborted, resumed later */
        s->inj_start = MMIO_NEVER;
        s->sr |= SR_JSTRT;
        if (s->inj_sw) s->cr2 &= ~s->fam->cr2_jswstart; /* cleared as the conversion starts (RM0008 11.12.3, RM0090 13.13.3) */
        s->pos = 0;
    } else {
        s->reg_start = MMIO_NEVER;
        s->sr |= SR_STRT;
        if (s->reg_sw) s->cr2 &= ~s->fam->cr2_swstart;
        s->pos = s->reg_pos;
        s->reg_resume = false;
    }
    s->group = group;
    begin_conversion(s, t);
}

uint64_t stm32_adcseq_next_event(void *self)
{
    const stm32_adcseq_t *s = self;
    uint64_t t = s->clear_at[0];
    if (s->clear_at[1] < t) t = s->clear_at[1];
    if (s->group != GROUP_INJ && s->inj_start < t) t = s->inj_start;
    if (s->group == GROUP_IDLE && s->reg_start < t) t = s->reg_start;
    if (s->sample_at < t) t = s->sample_at;
    if (s->end_at < t) t = s->end_at;
    return t;
}

/* One event due at cycle t, in the order they happen within a cycle. */
static void step(stm32_adcseq_t *s, uint64_t t)
{
    for (int k = 0; k < 2; k++)
        if (s->clear_at[k] == t) { s->cr2 &= ~s->clear_bit[k]; s->clear_at[k] = MMIO_NEVER; return; }
    if (s->sample_at == t) { sample(s, t); return; }
    if (s->end_at == t) { end_conversion(s, t); update_irq(s); return; }
    if (s->group != GROUP_INJ && s->inj_start == t) { start_group(s, GROUP_INJ, t); return; }
    if (s->group == GROUP_IDLE && s->reg_start == t) start_group(s, GROUP_REG, t);
}

void stm32_adcseq_advance(void *self, uint64_t now)
{
    stm32_adcseq_t *s = self;
    for (;;) {
        uint64_t t = stm32_adcseq_next_event(s);
        if (t > now) break;
        step(s, t);
    }
    if (now > s->now) s->now = now;
}

void stm32_adcseq_trigger(stm32_adcseq_t *s, int group, bool sw, uint64_t t)
{
    if (!(s->cr2 & CR2_ADON)) return;
    if (group == GROUP_INJ) {
        if (s->group == GROUP_INJ || s->inj_start != MMIO_NEVER) return;
        s->inj_sw = sw;
        s->inj_start = stm32_at(t, stm32_adcseq_cycles(s, s->fam->tlat_inj_half));
    } else {
        if (s->group == GROUP_REG || s->reg_start != MMIO_NEVER) return;
        s->reg_sw = sw;
        s->reg_start = stm32_at(t, stm32_adcseq_cycles(s, s->fam->tlat_reg_half));
    }
}

void stm32_adcseq_power_off(stm32_adcseq_t *s)
{
    s->group = GROUP_IDLE;
    s->reg_start = s->inj_start = s->sample_at = s->end_at = MMIO_NEVER;
    s->reg_pos = 0;
    s->reg_resume = false;
}

/* The registers in address order: every word from SR (0x00) to DR (0x4C) is one. */
#define REG(field) (uint16_t)offsetof(stm32_adcseq_t, field)
static const uint16_t reg_field[] = { REG(sr), REG(cr1), REG(cr2), REG(smpr1), REG(smpr2), REG(jofr[0]), REG(jofr[1]),
                                      REG(jofr[2]), REG(jofr[3]), REG(htr), REG(ltr), REG(sqr1), REG(sqr2), REG(sqr3),
                                      REG(jsqr), REG(jdr[0]), REG(jdr[1]), REG(jdr[2]), REG(jdr[3]), REG(dr) };
#undef REG

/* The stored word at a register offset, no side effect; false: none there. */
static bool peek(const stm32_adcseq_t *s, uint32_t off, uint32_t *v)
{
    if (off / 4 >= sizeof reg_field / sizeof reg_field[0]) return false;
    *v = *(const uint32_t *)(const void *)((const char *)s + reg_field[off / 4]);
    return true;
}

mmio_status_t stm32_adcseq_read(void *self, uint32_t off, unsigned size, uint32_t *value)
{
    stm32_adcseq_t *s = self;
    uint32_t v;
    if (!stm32_access_ok(off, size) || !peek(s, off & ~3u, &v)) return MMIO_UNMODELED;
    if ((off & ~3u) == STM32_ADCSEQ_DR) { /* reading DR clears EOC (RM0008 11.12.1, RM0090 13.13.1), serves the DMA request */
        s->sr &= ~SR_EOC;
        s->dr_unread = false;
        stm32_adcseq_set_dma(s, false);
        update_irq(s);
    }
    *value = stm32_read_lanes(v, off, size);
    return MMIO_OK;
}

static mmio_status_t write_word(stm32_adcseq_t *s, uint32_t off, uint32_t v)
{
    mmio_status_t st = MMIO_OK;
    switch (off) {
    case STM32_ADCSEQ_SR: s->sr &= (v & s->fam->sr_w0) | ~s->fam->sr_w0; break; /* rc_w0 */
    case STM32_ADCSEQ_CR1:
        if (v & s->cr1_unmodeled) st = MMIO_UNMODELED;
        s->cr1 = v & s->cr1_keep;
        break;
    case STM32_ADCSEQ_CR2: s->fam->write_cr2(s, v); break;
    case STM32_ADCSEQ_SMPR1: s->smpr1 = v & s->fam->smpr1_mask; break;
    case STM32_ADCSEQ_SMPR2: s->smpr2 = v & 0x3FFFFFFFu; break;
    case STM32_ADCSEQ_HTR: s->htr = v & 0xFFFu; break;
    case STM32_ADCSEQ_LTR: s->ltr = v & 0xFFFu; break;
    case STM32_ADCSEQ_SQR1: s->sqr1 = v & 0x00FFFFFFu; break;
    case STM32_ADCSEQ_SQR2: s->sqr2 = v & 0x3FFFFFFFu; break;
    case STM32_ADCSEQ_SQR3: s->sqr3 = v & 0x3FFFFFFFu; break;
    case STM32_ADCSEQ_JSQR: s->jsqr = v & 0x003FFFFFu; break;
    case STM32_ADCSEQ_DR: break; /* read-only */
    default: /* JOFRx; JDRx are read-only */
        if (off >= STM32_ADCSEQ_JOFR1 && off < STM32_ADCSEQ_HTR) s->jofr[(off - STM32_ADCSEQ_JOFR1) / 4] = v & 0xFFFu;
        break;
    }
    update_irq(s);
    return st;
}

mmio_status_t stm32_adcseq_write(void *self, uint32_t off, unsigned size, uint32_t value)
{
    stm32_adcseq_t *s = self;
    uint32_t w = off & ~3u, old;
    if (!stm32_access_ok(off, size) || !peek(s, w, &old)) return MMIO_UNMODELED;
    return write_word(s, w, s->fam->lanes(old, off, size, value));
}

void stm32_adcseq_reset(void *self)
{
    stm32_adcseq_t *s = self;
    s->sr = s->cr1 = s->cr2 = s->smpr1 = s->smpr2 = 0;
    for (int i = 0; i < 4; i++) s->jofr[i] = s->jdr[i] = 0;
    s->htr = 0x0FFFu; /* RM0008 11.12.7, RM0090 13.13.7: reset 0x0000 0FFF */
    s->ltr = s->sqr1 = s->sqr2 = s->sqr3 = s->jsqr = s->dr = 0;
    s->clear_at[0] = s->clear_at[1] = MMIO_NEVER;
    s->reg_sw = s->inj_sw = s->dr_unread = false;
    s->code = 0;
    s->channel = 0;
    stm32_adcseq_power_off(s);
    stm32_adcseq_set_dma(s, false);
    update_irq(s);
}

void stm32_adcseq_init(stm32_adcseq_t *s, const stm32_adcseq_family_t *fam, mmio_dma_req_t dma, unsigned dma_line,
                       double vref_v)
{
    s->fam = fam;
    s->dma = dma;
    s->dma_line = dma_line;
    s->vref_v = vref_v;
}

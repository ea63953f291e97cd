/* stm32f1_tim.c - TIM1-TIM4 (stm32f1_tim.h): RM0008 14 (TIM1) and 15
 * (TIM2-5): time base 15.3.2, counter modes 15.3.2, update event, PWM
 * 15.3.9, encoder interface 15.3.12, registers 15.4 / 14.4. */
#include "arm/stm32f1_tim.h"

#include <string.h>

#include "arm/stm32f1_reg.h"

/* CR1 */
#define CEN (1u << 0)
#define UDIS (1u << 1)
#define URS (1u << 2)
#define OPM (1u << 3)
#define DIR (1u << 4)
#define CMS_SHIFT 5
#define ARPE (1u << 7)
#define CR1_WMASK 0x3FFu
/* SR / DIER / EGR */
#define UIF (1u << 0)
#define CCIF(i) (1u << (1 + (i)))   /* i: channel 0-3 */
#define COMIF (1u << 5)
#define TIF (1u << 6)
#define BIF (1u << 7)
#define UDE (1u << 8)
#define CCDE(i) (1u << (9 + (i)))
#define CCDS (1u << 3)              /* CR2 */
#define SR_FLAGS 0x1EFFu
#define NONE 0                      /* no DMA channel */

/* The F1's TIM1-4 (RM0008): 16-bit, four channels; IRQs TIM1_BRK 24,
 * TIM1_UP 25, TIM1_TRG_COM 26, TIM1_CC 27, TIM2 28, TIM3 29, TIM4 30
 * (table 63); DMA1 channels of the update and CC1-4 requests (table 78). */
static const stm32_tim_desc_t f1_desc[4] = {
    { "TIM1", 1, 16, 4, 1, 2, 1, 1, { 24, 25, 26, 27 }, 5, { 2, 3, 6, 4 }, 0 },
    { "TIM2", 2, 16, 4, 0, 1, 1, 1, { 28, 28, 28, 28 }, 2, { 5, 7, 1, 7 }, 0 },
    { "TIM3", 3, 16, 4, 0, 1, 1, 1, { 29, 29, 29, 29 }, 3, { 6, NONE, 2, 3 }, 0 },
    { "TIM4", 4, 16, 4, 0, 1, 1, 1, { 30, 30, 30, 30 }, 7, { 1, 4, 5, NONE }, 0 },
};

static int adv(const stm32f1_tim_t *t) { return t->d->advanced; }
static unsigned nch(const stm32f1_tim_t *t) { return t->d->channels; }
static uint32_t cmax(const stm32f1_tim_t *t) { return t->d->bits == 32 ? 0xFFFFFFFFu : 0xFFFFu; }
static unsigned mms(const stm32f1_tim_t *t) { return (t->cr2 >> 4) & 7u; }
static unsigned cms(const stm32f1_tim_t *t) { return (t->cr1 >> CMS_SHIFT) & 3u; }
static unsigned sms(const stm32f1_tim_t *t) { return t->smcr & 7u; }
static int encoder(const stm32f1_tim_t *t) { return sms(t) >= 1 && sms(t) <= 3; }
static unsigned ts(const stm32f1_tim_t *t) { return (t->smcr >> 4) & 7u; }
/* Does the counter stand still: stopped, an encoder (moved by the wheel),
 * clocked by TRGI's edges (external clock mode 1), or gated with TRGI low? */
static int held(const stm32f1_tim_t *t)
{
    return !(t->cr1 & CEN) || encoder(t) || sms(t) == 7 || (sms(t) == 5 && !t->trgi);
}
static unsigned ccs(const stm32f1_tim_t *t, unsigned i) { return (t->ccmr[i / 2] >> (8 * (i % 2))) & 3u; }
static unsigned ocm(const stm32f1_tim_t *t, unsigned i) { return (t->ccmr[i / 2] >> (8 * (i % 2) + 4)) & 7u; }
static int ocpe(const stm32f1_tim_t *t, unsigned i) { return (t->ccmr[i / 2] >> (8 * (i % 2) + 3)) & 1u; }
static uint32_t tim_hz(const stm32f1_tim_t *t) { return t->d->apb == 2 ? t->clk->tim_apb2 : t->clk->tim_apb1; }

/* ---- trigger outputs ---- */

/* The core cycle of the k-th count (k >= 1) of the batch being counted:
 * the first count after (PSC+1 - pc) timer clocks, then one each PSC+1;
 * outside an advance's counting, the cycle the state is at. */
static uint64_t count_cycle(const stm32f1_tim_t *t, uint64_t k)
{
    if (!t->ev_run) return t->now;
    uint64_t p = t->psc_sh + 1ull, ticks = t->ev_done + (p - t->ev_pc) + (k - 1) * p;
    uint32_t hz = tim_hz(t), hclk = t->clk->hclk;
    unsigned __int128 need = (unsigned __int128)ticks * hclk;
    if (need <= t->ev_acc0) return t->ev_now0;
    return t->ev_now0 + (uint64_t)((need - t->ev_acc0 + hz - 1) / hz);
}

static void emit(stm32f1_tim_t *t, unsigned kind, int rising, uint64_t now)
{
    if (t->trig.trigger && (t->trig_want >> kind & 1u)) t->trig.trigger(t->trig.ctx, STM32_TIM_TRIG(t->n, kind), rising, now);
}

static void pulse(stm32f1_tim_t *t, unsigned kind, uint64_t now)
{
    emit(t, kind, 1, now);
    emit(t, kind, 0, now);
}

/* TRGO's level (MMS enable and OCxREF modes) is now v: an edge if it moved. */
static void trgo_level(stm32f1_tim_t *t, int v, uint64_t now)
{
    if (v == t->trgo) return;
    t->trgo = v;
    emit(t, STM32_TIM_TRGO, v, now);
}

/* ---- interrupts and DMA ---- */

static void update_irq(stm32f1_tim_t *t)
{
    uint32_t req = t->sr & t->dier & 0xFFu;
    /* TIM1: BRK 24, UP 25, TRG_COM 26, CC 27; TIM2-4: one line each, 28-30 */
    uint32_t on[4] = { req & BIF, req & UIF, req & (TIF | COMIF), req & 0x1Eu };
    unsigned lines = adv(t) ? 4 : 1;
    if (!adv(t)) on[0] = req;
    for (unsigned l = 0; l < lines; l++) {
        uint32_t v = on[l] != 0, was = (t->irq_out >> l) & 1u;
        if (v == was) continue;
        t->irq_out ^= 1u << l;
        if (t->irq.set) t->irq.set(t->irq.ctx, t->d->irq[l], v);
    }
}

static void dma_pulse(stm32f1_tim_t *t, unsigned ch)
{
    if (ch == NONE || !t->dma.request) return;
    t->dma.request(t->dma.ctx, ch, true);
    t->dma.request(t->dma.ctx, ch, false);
}

/* OCxREF of a PWM mode just after the counter reaches ccr (edge-aligned):
 * PWM1 is active while CNT < CCR upcounting, CNT <= CCR downcounting. */
static int pwm_at_match(const stm32f1_tim_t *t, unsigned i)
{
    int on = t->down ? 1 : 0;
    return ocm(t, i) == 7 ? !on : on;
}

/* Channel i matched (a compare, or a capture when the channel is an input)
 * at core cycle now: CCxIF, its DMA request (unless CCDS moves it to the
 * update), its CCx event and TRGO in the compare pulse and OCxREF modes. */
static void cc_match_at(stm32f1_tim_t *t, unsigned i, uint64_t now)
{
    unsigned mode = ocm(t, i);
    if (ccs(t, i) == 0) {
        if (mode == 1) t->ref |= 1u << i;            /* active on match */
        else if (mode == 2) t->ref &= ~(1u << i);    /* inactive on match */
        else if (mode == 3) t->ref ^= 1u << i;       /* toggle */
    }
    t->sr |= CCIF(i);
    if ((t->dier & CCDE(i)) && !(t->cr2 & CCDS)) dma_pulse(t, t->d->dma_cc[i]);
    pulse(t, STM32_TIM_CC1 + i, now);
    if (i == 0 && mms(t) == 3) pulse(t, STM32_TIM_TRGO, now);
    if (mms(t) == 4 + i && ccs(t, i) == 0) {
        if (mode >= 1 && mode <= 3) trgo_level(t, (t->ref >> i) & 1u, now);
        else if (mode >= 6) trgo_level(t, pwm_at_match(t, i), now);
    }
}

static void cc_match(stm32f1_tim_t *t, unsigned i) { cc_match_at(t, i, t->now); }

/* The OCxREF TRGO of a PWM channel after an overflow (CNT at 0 or ARR). */
static void trgo_after_overflow(stm32f1_tim_t *t, uint64_t now)
{
    unsigned i = mms(t) - 4;
    if (mms(t) < 4 || i >= nch(t) || ccs(t, i) != 0 || ocm(t, i) < 6 || cms(t)) return;
    uint32_t ccr = t->ccr_sh[i], c = t->cnt;
    int on = t->down ? c <= ccr : c < ccr;
    trgo_level(t, ocm(t, i) == 7 ? !on : on, now);
}

/* The update event (RM0008 15.3.2): shadows loaded; UIF and the update's
 * DMA request unless only a UG with URS; OPM stops the counter. */
static void update_event(stm32f1_tim_t *t, int from_counter, uint64_t now)
{
    if (t->cr1 & UDIS) return;
    t->psc_sh = t->psc, t->arr_sh = t->arr, t->rcr_sh = t->rcr;
    for (unsigned i = 0; i < 4; i++) t->ccr_sh[i] = t->ccr[i];
    if (from_counter || !(t->cr1 & URS)) {
        t->sr |= UIF;
        if (t->dier & UDE) dma_pulse(t, t->d->dma_up);
        for (unsigned i = 0; i < nch(t); i++)
            if ((t->dier & CCDE(i)) && (t->cr2 & CCDS)) dma_pulse(t, t->d->dma_cc[i]);
    }
    if (mms(t) == 2) pulse(t, STM32_TIM_TRGO, now); /* the update event, URS or not (RM0090 17.4.2) */
    if (from_counter && (t->cr1 & OPM)) {
        t->cr1 &= ~CEN;
        if (mms(t) == 1) trgo_level(t, 0, now);
    }
}

/* An overflow or underflow: TIM1's repetition counter decides whether it
 * is an update event (RM0008 14.3.3). */
static void overflow(stm32f1_tim_t *t, uint64_t now)
{
    trgo_after_overflow(t, now);
    if (adv(t) && t->rep > 0) {
        t->rep--;
        return;
    }
    update_event(t, 1, now);
    t->rep = t->rcr_sh;
}

/* ---- the counter ---- */

/* Counts from now to the next overflow or underflow (>= 1). */
static uint64_t to_update(stm32f1_tim_t *t)
{
    uint64_t arr = t->arr_sh;
    if (cms(t)) {
        if (!t->down && t->cnt >= arr) t->down = 1; /* written at or above ARR: turns */
        if (t->down && t->cnt == 0) t->down = 0;
        return t->down ? t->cnt : arr - t->cnt;
    }
    if (t->down) return t->cnt + 1ull;
    return t->cnt <= arr ? arr - t->cnt + 1 : cmax(t) + 1ull - t->cnt; /* above ARR: on to the top first */
}

/* Is counter value v among the next c counts (c <= to_update, the c-th
 * the overflow when c == d)? */
static int visits(const stm32f1_tim_t *t, uint64_t v, uint64_t c, uint64_t d)
{
    uint64_t cnt = t->cnt, arr = t->arr_sh;
    if (v > arr) return 0;
    if (cms(t)) {
        unsigned mode = cms(t); /* 1: flags counting down, 2: up, 3: both */
        if (t->down) return (mode & 1u) && v < cnt && v + c >= cnt;
        return (mode & 2u) && v > cnt && v <= cnt + c;
    }
    if (t->down) return (v < cnt && v + c >= cnt) || (c == d && v == arr);
    return (v > cnt && v <= cnt + c) || (c == d && v == 0);
}

/* c counts (c <= d = to_update()): compare matches, then the counter
 * moved, with the overflow or underflow if c == d. */
static void count(stm32f1_tim_t *t, uint64_t c, uint64_t d)
{
    for (unsigned i = 0; i < nch(t); i++) {
        uint32_t v = t->ccr_sh[i];
        if (ccs(t, i) != 0 || !visits(t, v, c, d)) continue;
        uint64_t k = t->down ? (v < t->cnt ? t->cnt - v : d) : (v > t->cnt ? (uint64_t)v - t->cnt : d);
        cc_match_at(t, i, count_cycle(t, k));
    }
    if (c < d) {
        t->cnt = (uint32_t)(t->down ? t->cnt - c : t->cnt + c);
        return;
    }
    if (cms(t)) t->cnt = t->down ? 0 : t->arr_sh, t->down = !t->down;
    else t->cnt = t->down ? t->arr_sh : 0;
    overflow(t, count_cycle(t, d));
}

/* Timer clocks in one whole repeat of the counter's cycle. */
static uint64_t cycle_ticks(const stm32f1_tim_t *t)
{
    uint64_t per = cms(t) ? 2ull * t->arr_sh : t->arr_sh + 1ull;
    return per * (t->psc_sh + 1ull) * (adv(t) ? t->rcr_sh + 1ull : 1ull) * 2ull;
}

/* n timer clock ticks of counting: an overflow at a time; once a whole
 * cycle has been run after an update, whole cycles more change nothing
 * (the flags they set are set) and are skipped. */
static void run_ticks(stm32f1_tim_t *t, uint64_t n)
{
    uint64_t since = 0; /* timer clocks run since the first overflow of this call */
    int overflowed = 0;
    while (n > 0 && (t->cr1 & CEN) && t->arr_sh != 0) {
        uint64_t p = t->psc_sh + 1ull;
        uint64_t d = to_update(t);
        uint64_t need = (p - t->pc) + (d - 1) * p;
        t->ev_pc = t->pc;
        if (n < need) {
            uint64_t c = (t->pc + n) / p;
            t->pc = (uint32_t)((t->pc + n) % p);
            count(t, c, d);
            return;
        }
        n -= need, t->pc = 0;
        count(t, d, d);
        t->ev_done += need;
        if (overflowed) since += need;
        overflowed = 1;
        uint64_t cyc = cycle_ticks(t);
        int listened = t->trig.trigger && t->trig_want; /* each trigger edge counts: no skipping */
        if (since >= cyc && n >= cyc && !listened) t->ev_done += n - n % cyc, n %= cyc;
    }
}

void stm32_tim_advance(void *self, uint64_t now)
{
    stm32f1_tim_t *t = self;
    if (now <= t->now) return;
    uint64_t dc = now - t->now;
    t->ev_now0 = t->now, t->ev_acc0 = t->acc, t->ev_done = 0;
    t->now = now;
    if (held(t)) return;
    uint32_t hz = tim_hz(t), hclk = t->clk->hclk;
    if (hz == 0 || hclk == 0) return;
    unsigned __int128 x = (unsigned __int128)dc * hz + t->acc;
    t->acc = (uint64_t)(x % hclk);
    t->ev_run = 1;
    run_ticks(t, (uint64_t)(x / hclk));
    t->ev_run = 0;
    update_irq(t);
}

/* Counts until counter value v before the next overflow or underflow;
 * else UINT64_MAX (the caller stops at the update anyway). */
static uint64_t to_value(const stm32f1_tim_t *t, uint32_t v)
{
    if (v > t->arr_sh) return UINT64_MAX;
    if (!t->down && v > t->cnt) return v - t->cnt;
    if (t->down && v < t->cnt) return t->cnt - v;
    return UINT64_MAX;
}

/* The next core cycle at which an interrupt line or a DMA request may
 * change: an update or a compare match that is enabled and not yet
 * flagged, never beyond the next update (PSC may change there). */
/* Does the trigger listener take TRGO from the update (MMS update, or
 * a PWM OCxREF that moves there) or channel i's compare? */
static int want_update(const stm32f1_tim_t *t)
{
    if (!t->trig.trigger || !(t->trig_want & 1u)) return 0;
    return mms(t) == 2 || (mms(t) >= 4 && ocm(t, mms(t) - 4) >= 6);
}
static int want_cc(const stm32f1_tim_t *t, unsigned i)
{
    if (!t->trig.trigger) return 0;
    if (t->trig_want >> (STM32_TIM_CC1 + i) & 1u) return 1;
    return (t->trig_want & 1u) && ((i == 0 && mms(t) == 3) || mms(t) == 4 + i);
}

uint64_t stm32_tim_next_event(void *self)
{
    stm32f1_tim_t *t = self;
    if (held(t) || t->arr_sh == 0) return MMIO_NEVER;
    uint64_t d = to_update(t), k = UINT64_MAX;
    int any = 0;
    if (((t->dier & UIF) && !(t->sr & UIF)) || (t->dier & UDE) || want_update(t)) k = d, any = 1;
    for (unsigned i = 0; i < nch(t); i++) {
        if (ccs(t, i) != 0) continue;
        if (!(((t->dier & CCIF(i)) && !(t->sr & CCIF(i))) || (t->dier & CCDE(i)) || want_cc(t, i))) continue;
        uint64_t kv = to_value(t, t->ccr_sh[i]);
        if (kv < k) k = kv;
        any = 1;
    }
    if (!any) return MMIO_NEVER;
    if (k > d) k = d;
    uint64_t p = t->psc_sh + 1ull, ticks = (p - t->pc) + (k - 1) * p;
    uint32_t hz = tim_hz(t), hclk = t->clk->hclk;
    if (hz == 0 || hclk == 0) return MMIO_NEVER;
    unsigned __int128 need = (unsigned __int128)ticks * hclk;
    if (need <= t->acc) return t->now + 1;
    unsigned __int128 cyc = (need - t->acc + hz - 1) / hz;
    return cyc > MMIO_NEVER - t->now ? MMIO_NEVER : t->now + (uint64_t)cyc;
}

/* ---- the encoder interface ---- */

static int64_t floor_div2(int64_t a) { return a >= 0 ? a / 2 : -((-a + 1) / 2); }

/* Edges of one channel between positions a and b: channel 1 changes
 * between p and p+1 for even p, channel 2 for odd p. */
static int64_t channel_edges(int64_t a, int64_t b, int odd)
{
    int64_t lo = a < b ? a : b, hi = a < b ? b : a; /* transitions p in [lo, hi-1] */
    int64_t n = odd ? floor_div2(hi) - floor_div2(lo) : floor_div2(hi + 1) - floor_div2(lo + 1);
    return a < b ? n : -n;
}

/* n counts (signed) of the encoder: wraps at ARR with an update event. */
static void encoder_counts(stm32f1_tim_t *t, int64_t n)
{
    if (n == 0) return;
    t->down = n < 0;
    uint64_t left = (uint64_t)(n < 0 ? -n : n), full = t->arr_sh + 1ull;
    if (left > 2 * full) left = full + left % full; /* whole turns of the counter: flags already set by one */
    while (left > 0) {
        uint64_t d = t->down ? t->cnt + 1ull : (t->cnt <= t->arr_sh ? (uint64_t)t->arr_sh - t->cnt + 1 : cmax(t) + 1ull - t->cnt);
        uint64_t c = left < d ? left : d;
        uint32_t cms_saved = t->cr1 & (3u << CMS_SHIFT);
        t->cr1 &= ~(3u << CMS_SHIFT); /* the encoder counts as an edge-aligned counter */
        count(t, c, d);
        t->cr1 |= cms_saved;
        left -= c;
    }
}

void stm32f1_tim_encoder(stm32f1_tim_t *t, uint64_t now, int64_t edges)
{
    stm32_tim_advance(t, now);
    int64_t a = t->enc;
    t->enc = edges;
    if (!(t->cr1 & CEN) || !encoder(t) || t->arr_sh == 0) return;
    int64_t n = sms(t) == 3 ? edges - a : channel_edges(a, edges, sms(t) == 1 ? 0 : 1);
    int inverted = ((t->ccer >> 1) ^ (t->ccer >> 5)) & 1u; /* CC1P xor CC2P */
    encoder_counts(t, inverted ? -n : n);
    update_irq(t);
}

/* ---- slave mode (RM0090 18.3.14) ---- */

/* TRGI is now level at core cycle now (brought there): TIF on a rising
 * edge (gated mode: on both), and the slave mode's action: reset (100)
 * reinitializes the counter with an update event as UG does, gated (101)
 * counts while TRGI is high, trigger (110) sets CEN, external clock mode 1
 * (111, RM0090 18.3.14 "External clock source mode 1") counts each rising
 * edge as a clock tick instead of the internal clock. */
static void trgi_level(stm32f1_tim_t *t, int level)
{
    if (level == t->trgi) return;
    t->trgi = level;
    unsigned m = sms(t);
    if (m < 4) return;
    if (m == 5 || level) t->sr |= TIF;
    if (!level) return;
    if (m == 7) { /* external clock mode 1: a rising edge is a timer clock tick (through PSC), at its cycle */
        if (t->cr1 & CEN) run_ticks(t, 1);
    } else if (m == 4) {
        t->cnt = (t->down && !cms(t)) ? t->arr : 0;
        t->pc = 0;
        update_event(t, 0, t->now);
        t->rep = t->rcr_sh;
    } else if (m == 6 && !(t->cr1 & CEN)) {
        t->cr1 |= CEN;
        if (mms(t) == 1) trgo_level(t, 1, t->now);
    }
}

void stm32_tim_itr(stm32f1_tim_t *t, unsigned itr, int rising, uint64_t now)
{
    stm32_tim_advance(t, now);
    if (sms(t) < 4 || ts(t) != itr) return;
    trgi_level(t, rising != 0);
    update_irq(t);
}

void stm32_tim_route_itr(stm32f1_tim_t *t) { t->itr_routed = 0xF; }
void stm32_tim_route_itr_mask(stm32f1_tim_t *t, unsigned mask) { t->itr_routed = (int)(mask & 0xFu); }

/* ---- timers linked through ITRx (stm32_tim_links_t) ---- */

void stm32_tim_links_init(const stm32_tim_links_t *l)
{
    for (unsigned i = 0; i < l->count; i++) {
        unsigned m = 0;
        for (unsigned x = 0; x < 4; x++) m |= (l->itr[i][x] != 0) << x;
        stm32_tim_route_itr_mask(&l->tim[i], m);
    }
}

void stm32_tim_links_trgo(const stm32_tim_links_t *l, unsigned source, int rising, uint64_t now)
{
    if (source % 8u != STM32_TIM_TRGO) return;
    for (unsigned i = 0; i < l->count; i++)
        for (unsigned x = 0; x < 4; x++)
            if (l->itr[i][x] == source / 8u) stm32_tim_itr(&l->tim[i], x, rising, now);
}

/* The timer n whose TRGO TIM(i+1)'s slave mode takes now (SMS 100-111 on a linked ITRx), 0: none. */
static unsigned link_master(const stm32_tim_links_t *l, unsigned i)
{
    const stm32f1_tim_t *t = &l->tim[i];
    return sms(t) >= 4 && ts(t) <= 3 ? l->itr[i][ts(t)] : 0u;
}

void stm32_tim_links_wants(const stm32_tim_links_t *l, uint32_t *want)
{
    for (unsigned i = 0; i < l->count; i++) {
        unsigned m = link_master(l, i);
        if (m >= 1 && m <= l->count) want[m - 1u] |= 1u << STM32_TIM_TRGO;
    }
}

void stm32_tim_links_written(const stm32_tim_links_t *l, stm32f1_tim_t *t)
{
    unsigned i = t->n - 1u, m = i < l->count ? link_master(l, i) : 0u;
    if (m >= 1 && m <= l->count && sms(t) == 5) stm32_tim_itr(t, ts(t), l->tim[m - 1u].trgo, t->now);
}

/* An edge of TIti as TRGI: TI1F_ED (TS 100) every edge as a pulse,
 * TI1FP1 (101) and TI2FP2 (110) the level after the CCxP polarity. */
static void trgi_input(stm32f1_tim_t *t, unsigned ti, int rising)
{
    if (sms(t) < 4) return;
    if (ts(t) == 4 && ti == 1) {
        trgi_level(t, 1);
        trgi_level(t, 0);
    } else if ((ts(t) == 5 && ti == 1) || (ts(t) == 6 && ti == 2)) {
        int inverted = (t->ccer >> (4 * (ti - 1) + 1)) & 1u;
        trgi_level(t, (rising != 0) ^ inverted);
    }
}

/* ---- input capture ---- */

/* RM0008 15.3.5: an edge of the selected polarity on the channel's input
 * (CCxS 01: its own TIx; 10: the pair's other) copies CNT into CCRx at
 * every ICxPSC-th edge: CCxIF, or CCxOF if CCxIF was still set. */
void stm32f1_tim_input(stm32f1_tim_t *t, uint64_t now, unsigned ti, int rising)
{
    stm32_tim_advance(t, now);
    if (ti < 1 || ti > 4) return;
    for (unsigned i = 0; i < nch(t); i++) {
        unsigned sel = ccs(t, i), src = sel == 1 ? i : sel == 2 ? (i ^ 1u) : 99u;
        int falling_wanted = (t->ccer >> (4 * i + 1)) & 1u;
        if (src != ti - 1 || !((t->ccer >> (4 * i)) & 1u) || (!rising) != falling_wanted) continue;
        unsigned every = 1u << ((t->ccmr[i / 2] >> (8 * (i % 2) + 2)) & 3u); /* ICxPSC: 1, 2, 4, 8 */
        if (++t->ic_edges[i] < every) continue;
        t->ic_edges[i] = 0;
        t->ccr[i] = t->ccr_sh[i] = t->cnt;
        if (t->sr & CCIF(i)) t->sr |= 1u << (9 + i); /* CCxOF */
        cc_match(t, i);
    }
    trgi_input(t, ti, rising);
    update_irq(t);
}

/* ---- registers ---- */

void stm32_tim_reset(void *self)
{
    stm32f1_tim_t *t = self;
    t->cr1 = t->cr2 = t->smcr = t->dier = t->sr = t->ccmr[0] = t->ccmr[1] = t->ccer = 0;
    t->psc = t->rcr = t->bdtr = t->cnt = 0;
    t->psc_sh = t->rcr_sh = t->pc = t->rep = 0;
    /* ARR: RM0008 15.4.12 says 0x0000, with which the counter is blocked;
     * ST's later manuals of the same timer design give 0xFFFF (RM0367
     * 22.4.11), and a firmware that sets ARPE, writes ARR and starts the
     * counter without a UG (bulebule's TIM3) runs on the chip, which it
     * could not with a null shadow: 0xFFFF, preload and shadow. */
    t->arr = t->arr_sh = cmax(t); /* RM0090 18.4.12: 0xFFFF FFFF on the 32-bit TIM2/TIM5 */
    t->down = 0, t->acc = 0;
    memset(t->ccr, 0, sizeof t->ccr);
    memset(t->ccr_sh, 0, sizeof t->ccr_sh);
    memset(t->ic_edges, 0, sizeof t->ic_edges);
    t->ref = 0, t->trgo = 0, t->trgi = 0;
    update_irq(t);
}

void stm32_tim_init(stm32f1_tim_t *t, const stm32_tim_desc_t *desc, const mmio_clocks_t *clk, mmio_irq_t irq,
                    mmio_dma_req_t dma, stm32_tim_trigger_t trig)
{
    memset(t, 0, sizeof *t);
    t->d = desc, t->n = desc->n;
    t->clk = clk, t->irq = irq, t->dma = dma, t->trig = trig;
    t->trig_want = 0x1Fu;
    stm32_tim_reset(t);
}

void stm32f1_tim_init(stm32f1_tim_t *t, unsigned n, const mmio_clocks_t *clk, mmio_irq_t irq, mmio_dma_req_t dma)
{
    stm32f1_tim_init_trig(t, n, clk, irq, dma, (stm32_tim_trigger_t){ NULL, NULL });
}

void stm32f1_tim_init_trig(stm32f1_tim_t *t, unsigned n, const mmio_clocks_t *clk, mmio_irq_t irq, mmio_dma_req_t dma,
                           stm32_tim_trigger_t trig)
{
    stm32_tim_init(t, &f1_desc[(n >= 1 && n <= 4 ? n : 2) - 1], clk, irq, dma, trig);
}

/* RM0008 rev 21 14.4.3 (TIM1: TIM5, TIM2, TIM3, TIM4) and 15.4.3 (TIM2: TIM1, TIM8, TIM3, TIM4; TIM3:
 * TIM1, TIM2, TIM5, TIM4; TIM4: TIM1, TIM2, TIM3, TIM8) "TIMx internal trigger connection"; TIM5 and TIM8
 * do not exist on the medium-density STM32F103 */
const uint8_t stm32f1_tim_itr[4][4] = { { 0, 2, 3, 4 }, { 1, 0, 3, 4 }, { 1, 2, 0, 4 }, { 1, 2, 3, 0 } };

#define T1(n, k) STM32_TIM_TRIG(n, STM32_TIM_##k)
const uint16_t stm32f1_adc_extsel[2][8] = {
    /* ADC1/2 regular EXTSEL, RM0008 11.12.3 (110: EXTI line 11, 111: SWSTART) */
    { T1(1, CC1), T1(1, CC2), T1(1, CC3), T1(2, CC2), T1(3, TRGO), T1(4, CC4), STM32F1_ADC_NOT_TIM, STM32F1_ADC_NOT_TIM },
    /* injected JEXTSEL (110: EXTI line 15, 111: JSWSTART) */
    { T1(1, TRGO), T1(1, CC4), T1(2, TRGO), T1(2, CC1), T1(3, CC4), T1(4, TRGO), STM32F1_ADC_NOT_TIM, STM32F1_ADC_NOT_TIM },
};

void stm32_tim_trigger_want(stm32f1_tim_t *t, uint32_t kinds) { t->trig_want = kinds & 0x1Fu; }

/* t->ref with channel i's OCxREF as it is now: PWM modes from the
 * counter (RM0008 15.3.9), forced modes their level, the others as the
 * last match left it. */
static uint32_t ref_now(const stm32f1_tim_t *t, unsigned i)
{
    unsigned mode = ocm(t, i);
    uint32_t ccr = t->ccr_sh[i], cnt = t->cnt;
    int on;
    if (i >= nch(t)) return t->ref;
    if (mode == 4 || mode == 5) on = mode == 5;
    else if (mode >= 6) {
        on = (!cms(t) && t->down) ? cnt <= ccr : cnt < ccr;
        if (mode == 7) on = !on;
    } else return t->ref;
    return on ? t->ref | 1u << i : t->ref & ~(1u << i);
}

/* EGR (RM0008 15.4.6): UG reinitializes the counter and the prescaler
 * and makes an update event; the others set their flags. */
static void write_egr(stm32f1_tim_t *t, uint32_t v)
{
    if (v & 1u) {
        t->cnt = (t->down && !cms(t) && !encoder(t)) ? t->arr : 0;
        t->pc = 0;
        update_event(t, 0, t->now);
        t->rep = t->rcr_sh;
        if (mms(t) == 0) pulse(t, STM32_TIM_TRGO, t->now); /* reset: UG is TRGO */
    }
    uint32_t ccg = ((1u << nch(t)) - 1u) << 1; /* CCxG */
    t->sr |= v & (ccg | (adv(t) ? 0xE0u : t->d->has_smcr ? TIF : 0u));
}

static mmio_status_t write_cr1(stm32f1_tim_t *t, uint32_t v, uint32_t m)
{
    uint32_t wmask = CR1_WMASK;
    if (cms(t) || encoder(t)) wmask &= ~DIR; /* DIR is read-only then */
    if (t->d->up_only) wmask &= ~(DIR | 3u << CMS_SHIFT);
    t->cr1 = stm32f1_reg_merge(t->cr1, v, m, wmask);
    if (!cms(t) && !encoder(t)) t->down = (t->cr1 & DIR) != 0;
    if (!(t->cr1 & ARPE)) t->arr_sh = t->arr;
    if (mms(t) == 1) trgo_level(t, (t->cr1 & CEN) != 0, t->now); /* enable: TRGO is CNT_EN */
    return MMIO_OK;
}

/* CR2 (RM0090 17.4.2): CCDS, MMS; TRGO takes the new mode's level. */
static mmio_status_t write_cr2(stm32f1_tim_t *t, uint32_t v, uint32_t m)
{
    t->cr2 = stm32f1_reg_merge(t->cr2, v, m, adv(t) ? 0x7FFDu : 0xF8u);
    unsigned i = mms(t) - 4;
    if (mms(t) == 1) trgo_level(t, (t->cr1 & CEN) != 0, t->now);
    else if (mms(t) >= 4 && i < nch(t)) trgo_level(t, (ref_now(t, i) >> i) & 1u, t->now);
    else t->trgo = 0;
    if (t->cr2 & 0x80u) return MMIO_UNMODELED; /* TI1S */
    if (mms(t) != 0 && !t->trig.trigger) return MMIO_UNMODELED; /* a TRGO no model takes (a timer alone) */
    if (mms(t) >= 4 && (i >= nch(t) || (cms(t) && ocm(t, i) >= 6))) return MMIO_UNMODELED;
    return MMIO_OK;
}

/* Is register w there on this instance (RM0090 17.4, 18.4, 19.4 maps)? */
static int present(const stm32f1_tim_t *t, uint32_t w)
{
    switch (w) {
    case 0x04: return t->d->has_cr2;
    case 0x08: return t->d->has_smcr;
    case 0x18: case 0x20: return nch(t) >= 1;
    case 0x1C: return nch(t) >= 3;
    case 0x30: case 0x44: return adv(t);
    case 0x34: case 0x38: case 0x3C: case 0x40: return (w - 0x34) / 4 < nch(t);
    }
    return 1;
}

static uint32_t dier_mask(const stm32f1_tim_t *t)
{
    uint32_t m = 1u | ((1u << nch(t)) - 1u) << 1 | (t->d->has_smcr ? TIF : 0u) | (adv(t) ? 0xE0u : 0u);
    return t->d->dma_up ? m | (m & 0x7Fu) << 8 : m; /* UDE, CCxDE, COMDE, TDE beside their IEs */
}

/* Does a channel use what is not modeled: a capture from TRC, OCxCE? */
static mmio_status_t channels_status(const stm32f1_tim_t *t)
{
    for (unsigned i = 0; i < nch(t); i++) {
        if (ccs(t, i) == 3 && ((t->ccer >> (4 * i)) & 1u)) return MMIO_UNMODELED;
        if (ccs(t, i) == 0 && ((t->ccmr[i / 2] >> (8 * (i % 2) + 7)) & 1u)) return MMIO_UNMODELED;
    }
    return MMIO_OK;
}

static void write_ccr(stm32f1_tim_t *t, unsigned i, uint32_t v, uint32_t m)
{
    if (ccs(t, i) != 0) return; /* input capture: read-only */
    t->ccr[i] = stm32f1_reg_merge(t->ccr[i], v, m, cmax(t));
    if (!ocpe(t, i)) t->ccr_sh[i] = t->ccr[i];
}

static mmio_status_t write_ctl(stm32f1_tim_t *t, uint32_t w, uint32_t v, uint32_t m)
{
    switch (w) {
    case 0x00: return write_cr1(t, v, m);
    case 0x04: return write_cr2(t, v, m);
    case 0x08:
        t->smcr = stm32f1_reg_merge(t->smcr, v, m, 0xFFF7u);
        if (encoder(t) && nch(t) < 4) return MMIO_UNMODELED; /* TIM9/12: no encoder modes (RM0090 19.5.2) */
        /* external clock mode 2 (ECE), ETRF, an ITRx no other timer's TRGO reaches, external clock
         * mode 1 (SMS 111) from the TIx inputs (from an ITRx it is modeled) */
        if ((t->smcr & (1u << 14)) || (sms(t) >= 4 && (ts(t) == 7 || (ts(t) <= 3 && !(t->itr_routed >> ts(t) & 1))))
            || (sms(t) == 7 && ts(t) > 3))
            return MMIO_UNMODELED;
        return MMIO_OK;
    case 0x0C: t->dier = stm32f1_reg_merge(t->dier, v, m, dier_mask(t)); return MMIO_OK;
    case 0x10: t->sr &= ~(~v & m & SR_FLAGS); return MMIO_OK; /* rc_w0 */
    case 0x14: write_egr(t, v & m); return MMIO_OK;
    case 0x18: case 0x1C: {
        unsigned k = (w - 0x18) / 4;
        uint32_t keep = 0; /* CCxS only while the channel is off */
        for (unsigned j = 0; j < 2; j++)
            if ((t->ccer >> (4 * (2 * k + j))) & 1u) keep |= 3u << (8 * j);
        for (unsigned j = 0; j < 2; j++) t->ref = ref_now(t, 2 * k + j); /* the level it leaves */
        t->ccmr[k] = stm32f1_reg_merge(t->ccmr[k], v, m, 0xFFFFu & ~keep);
        for (unsigned j = 0; j < 2; j++) t->ref = ref_now(t, 2 * k + j); /* a forced level at once */
        if (mms(t) >= 4 && (mms(t) - 4) / 2 == k) trgo_level(t, (t->ref >> (mms(t) - 4)) & 1u, t->now);
        return channels_status(t);
    }
    case 0x20:
        t->ccer = stm32f1_reg_merge(t->ccer, v, m, (adv(t) ? 0x3FFFu : 0x3333u) & ((1u << (4 * nch(t))) - 1u));
        return channels_status(t);
    }
    return MMIO_UNMODELED;
}

static mmio_status_t write_time(stm32f1_tim_t *t, uint32_t w, uint32_t v, uint32_t m)
{
    switch (w) {
    case 0x24: t->cnt = stm32f1_reg_merge(t->cnt, v, m, cmax(t)); return MMIO_OK;
    case 0x28: t->psc = stm32f1_reg_merge(t->psc, v, m, 0xFFFFu); return MMIO_OK; /* at the next update */
    case 0x2C:
        t->arr = stm32f1_reg_merge(t->arr, v, m, cmax(t));
        if (!(t->cr1 & ARPE)) t->arr_sh = t->arr;
        return MMIO_OK;
    case 0x30:
        if (!adv(t)) return MMIO_UNMODELED; /* reserved on TIM2-4 */
        t->rcr = stm32f1_reg_merge(t->rcr, v, m, 0xFFu);
        return MMIO_OK;
    case 0x34: case 0x38: case 0x3C: case 0x40: write_ccr(t, (w - 0x34) / 4, v, m); return MMIO_OK;
    case 0x44:
        if (!adv(t)) return MMIO_UNMODELED;
        t->bdtr = stm32f1_reg_merge(t->bdtr, v, m, 0xFFFFu);
        return (t->bdtr & (0xFFu | 1u << 12)) ? MMIO_UNMODELED : MMIO_OK; /* dead time, break input */
    }
    return MMIO_UNMODELED; /* DCR, DMAR: DMA burst */
}

mmio_status_t stm32_tim_write(void *self, uint32_t off, unsigned size, uint32_t value)
{
    stm32f1_tim_t *t = self;
    uint32_t v = stm32f1_reg_wvalue(off, size, value), m = stm32f1_reg_mask(off, size), w = stm32f1_reg_word(off);
    if (!present(t, w)) return MMIO_UNMODELED; /* reserved on this instance */
    mmio_status_t st = w <= 0x20 ? write_ctl(t, w, v, m) : write_time(t, w, v, m);
    update_irq(t);
    return st;
}

mmio_status_t stm32_tim_read(void *self, uint32_t off, unsigned size, uint32_t *value)
{
    stm32f1_tim_t *t = self;
    uint32_t w = stm32f1_reg_word(off), reg;
    if (!present(t, w)) return MMIO_UNMODELED;
    switch (w) {
    case 0x00: reg = (cms(t) || encoder(t)) ? (t->cr1 & ~DIR) | (t->down ? DIR : 0) : t->cr1; break;
    case 0x04: reg = t->cr2; break;
    case 0x08: reg = t->smcr; break;
    case 0x0C: reg = t->dier; break;
    case 0x10: reg = t->sr; break;
    case 0x14: reg = 0; break; /* EGR: write-only */
    case 0x18: case 0x1C: reg = t->ccmr[(w - 0x18) / 4]; break;
    case 0x20: reg = t->ccer; break;
    case 0x24: reg = t->cnt; break;
    case 0x28: reg = t->psc; break;
    case 0x2C: reg = t->arr; break;
    case 0x30: if (!adv(t)) return MMIO_UNMODELED; reg = t->rcr; break;
    case 0x34: case 0x38: case 0x3C: case 0x40:
        reg = t->ccr[(w - 0x34) / 4];
        if (ccs(t, (w - 0x34) / 4) != 0) t->sr &= ~CCIF((w - 0x34) / 4), update_irq(t); /* a capture read */
        break;
    case 0x44: if (!adv(t)) return MMIO_UNMODELED; reg = t->bdtr; break;
    default: return MMIO_UNMODELED;
    }
    *value = stm32f1_reg_rvalue(off, size, reg);
    return MMIO_OK;
}

#define TIM_OPS(nm) \
    { .name = nm, .read = stm32_tim_read, .write = stm32_tim_write, .advance = stm32_tim_advance, \
      .next_event = stm32_tim_next_event, .reset = stm32_tim_reset }
const mmio_ops_t stm32f1_tim_ops[4] = { TIM_OPS("TIM1"), TIM_OPS("TIM2"), TIM_OPS("TIM3"), TIM_OPS("TIM4") };

/* ---- the outputs ---- */

/* OCxREF's active fraction in PWM mode 1 (RM0008 15.3.9): upcounting
 * active while CNT < CCR, downcounting while CNT <= CCR, center-aligned
 * while CNT < CCR; CCR above ARR holds it active. */
static double pwm1_duty(const stm32f1_tim_t *t, uint32_t ccr)
{
    double arr = t->arr_sh;
    if (ccr > t->arr_sh) return 1.0;
    if (cms(t)) return arr > 0 ? ccr / arr : 0.0;
    if (t->down) return (ccr + 1.0) / (arr + 1.0);
    return ccr / (arr + 1.0);
}

stm32f1_tim_out_t stm32f1_tim_output(const stm32f1_tim_t *t, unsigned ch)
{
    stm32f1_tim_out_t o = { 0 };
    if (ch < 1 || ch > nch(t)) return o;
    unsigned i = ch - 1, mode = ocm(t, i);
    o.enabled = ((t->ccer >> (4 * i)) & 1u) && ccs(t, i) == 0 && (!adv(t) || (t->bdtr & (1u << 15)));
    o.running = (t->cr1 & CEN) != 0;
    o.active_low = (t->ccer >> (4 * i + 1)) & 1u;
    o.pwm = mode >= 4;
    if (mode == 4) o.duty = 0.0;                 /* force inactive */
    else if (mode == 5) o.duty = 1.0;            /* force active */
    else if (mode == 6) o.duty = pwm1_duty(t, t->ccr_sh[i]);
    else if (mode == 7) o.duty = 1.0 - pwm1_duty(t, t->ccr_sh[i]);
    else if (mode == 3 && t->ccr_sh[i] <= t->arr_sh) o.pwm = 1, o.duty = 0.5; /* toggle: a square wave */
    else o.duty = -1.0;
    o.high = o.pwm ? (o.active_low ? 1.0 - o.duty : o.duty) : -1.0;
    double counts = cms(t) ? 2.0 * t->arr_sh : t->arr_sh + 1.0;
    o.freq_hz = counts > 0 ? tim_hz(t) / ((t->psc_sh + 1.0) * counts) : 0.0;
    if (mode == 3) o.freq_hz /= 2.0; /* one toggle a period: half the update rate */
    o.ref = (ref_now(t, i) >> i) & 1u;
    o.level = o.enabled ? o.ref ^ o.active_low : -1;
    return o;
}

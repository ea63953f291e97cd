/* stm32f1_dma.c - STM32F1 DMA1: RM0008 rev 21 section 13 (13.3.1 DMA
 * transactions, 13.3.2 arbiter, 13.3.3 channels: programmable data sizes,
 * pointer incrementation, circular mode, memory-to-memory mode, 13.3.4
 * programmable data width (Table 79: a narrower source is zero-extended, a
 * wider one truncated to its low part), 13.3.5 error management, 13.3.6
 * interrupts, 13.4 registers).
 *
 * A channel with EN set, CNDTR > 0 and its request high (or MEM2MEM) is
 * served; the arbiter picks the highest PL, then the lowest channel number
 * (13.3.2). Each transfer reads its source and writes its destination
 * through the bus, then decrements CNDTR: HTIF when half the programmed
 * count is done, TCIF at 0; circular mode reloads CNDTR and the addresses
 * (13.3.3). A bus error sets TEIF and clears EN (13.3.5).
 * Stated limit: a transfer takes no time (the bus cycles of RM0008 13.3.1
 * are not counted); requests are served at the cycle the controller is next
 * advanced to, which the board does right after the peripheral that raised
 * them (next_event() returns that cycle while a request waits). */
#include "arm/stm32f1_dma.h"

#include "arm/stm32f1_clk.h"

enum { ISR = 0x00, IFCR = 0x04, CH0 = 0x08, CH_STRIDE = 20, CH_END = 0x08 + 7 * 20 };
#define CCR_EN      (1u << 0)
#define CCR_TCIE    (1u << 1)
#define CCR_HTIE    (1u << 2)
#define CCR_TEIE    (1u << 3)
#define CCR_DIR     (1u << 4)
#define CCR_CIRC    (1u << 5)
#define CCR_PINC    (1u << 6)
#define CCR_MINC    (1u << 7)
#define CCR_PSIZE_SHIFT 8
#define CCR_MSIZE_SHIFT 10
#define CCR_PL_SHIFT 12
#define CCR_MEM2MEM (1u << 14)
#define CCR_MASK    0x7FFFu
/* ISR/IFCR: 4 bits per channel */
#define F_GIF  1u
#define F_TCIF 2u
#define F_HTIF 4u
#define F_TEIF 8u
/* Transfers one advance may run: a guard against a request that never
 * falls in circular mode (a peripheral model's bug), 7 full buffers. */
#define MAX_TRANSFERS_PER_ADVANCE (7u * 65536u)

static unsigned flags(const stm32_dma_t *d, unsigned i) { return (d->isr >> (4 * i)) & 0xFu; }

static void update_irq(stm32_dma_t *d, unsigned i)
{
    unsigned f = flags(d, i);
    uint32_t ccr = d->ch[i].ccr;
    bool lv = ((f & F_TCIF) && (ccr & CCR_TCIE)) || ((f & F_HTIF) && (ccr & CCR_HTIE))
           || ((f & F_TEIF) && (ccr & CCR_TEIE));
    if (lv == d->irq_level[i]) return;
    d->irq_level[i] = lv;
    if (d->irq.set) d->irq.set(d->irq.ctx, STM32_DMA1_IRQ(i + 1), lv);
}

static void set_flags(stm32_dma_t *d, unsigned i, unsigned f)
{
    d->isr |= (uint32_t)(f | F_GIF) << (4 * i);
    update_irq(d, i);
}

/* Ready: EN, CNDTR > 0 and the request high, or MEM2MEM (13.3.3); PL, CCR's priority level (13.3.2). */
static unsigned ready_pl(const void *ctl, unsigned i)
{
    const stm32_dma_chan_t *c = &((const stm32_dma_t *)ctl)->ch[i];
    bool ready = (c->ccr & CCR_EN) && c->cndtr > 0 && (c->req || (c->ccr & CCR_MEM2MEM));
    return ready ? ((c->ccr >> CCR_PL_SHIFT) & 3u) + 1u : 0u;
}

static unsigned size_bytes(uint32_t ccr, unsigned shift)
{
    unsigned s = (ccr >> shift) & 3u;
    return s == 0 ? 1 : s == 1 ? 2 : 4; /* 11 is reserved: taken as 32 bits */
}

static uint32_t width_mask(unsigned size) { return size == 4 ? 0xFFFFFFFFu : (1u << (8 * size)) - 1; }

bool stm32_dma_move(mmio_bus_t bus, const stm32_dma_item_t *it, uint32_t done)
{
    uint32_t pa = it->par + (it->pinc ? done * it->psize : 0);
    uint32_t ma = it->mar + (it->minc ? done * it->msize : 0);
    uint32_t src = it->from_mem ? ma : pa, dst = it->from_mem ? pa : ma;
    unsigned ss = it->from_mem ? it->msize : it->psize, ds = it->from_mem ? it->psize : it->msize;
    uint32_t v = 0;
    if (!bus.read || !bus.read(bus.ctx, src, ss, &v)) return false;
    v &= width_mask(ss) & width_mask(ds); /* Table 79: zero-extend or keep the low part */
    return bus.write && bus.write(bus.ctx, dst, ds, v);
}

unsigned stm32_dma_count(uint32_t *ndtr, uint32_t *done, uint32_t reload, bool circular)
{
    unsigned f = 0;
    ++*done;
    --*ndtr;
    if (2 * *done >= reload && 2 * (*done - 1) < reload) f |= STM32_DMA_HT;
    if (*ndtr == 0) {
        f |= STM32_DMA_TC;
        if (circular) { *ndtr = reload; *done = 0; }
    }
    return f;
}

unsigned stm32_dma_step(mmio_bus_t bus, const stm32_dma_item_t *it, uint32_t *ndtr, uint32_t *done, uint32_t reload,
                        bool circular)
{
    if (!stm32_dma_move(bus, it, *done)) return STM32_DMA_TE;
    return stm32_dma_count(ndtr, done, reload, circular);
}

/* One transfer of channel i; a bus error clears EN (13.3.5). */
static void serve(void *ctl, unsigned i)
{
    stm32_dma_t *d = ctl;
    stm32_dma_chan_t *c = &d->ch[i];
    uint32_t ccr = c->ccr;
    stm32_dma_item_t it = { c->cpar, c->cmar, size_bytes(ccr, CCR_PSIZE_SHIFT), size_bytes(ccr, CCR_MSIZE_SHIFT),
                            (ccr & CCR_PINC) != 0, (ccr & CCR_MINC) != 0, (ccr & CCR_DIR) != 0 };
    unsigned k = stm32_dma_step(d->bus, &it, &c->cndtr, &c->done, c->reload, (ccr & CCR_CIRC) != 0);
    if (k & STM32_DMA_TE) c->ccr &= ~CCR_EN;
    unsigned f = stm32_dma_flags(k, F_TEIF, F_HTIF, F_TCIF);
    if (f) set_flags(d, i, f);
}

static const stm32_dma_arbiter_t arbiter = { STM32_DMA_CHANNELS, MAX_TRANSFERS_PER_ADVANCE, ready_pl, serve };

static void dma_advance(void *self, uint64_t now) { stm32_dma_run(&arbiter, self, &((stm32_dma_t *)self)->now, now); }

static uint64_t dma_next_event(void *self) { return stm32_dma_next(&arbiter, self, ((const stm32_dma_t *)self)->now); }

void stm32_dma_request(void *dma, unsigned channel, bool level)
{
    stm32_dma_t *d = dma;
    if (channel >= 1 && channel <= STM32_DMA_CHANNELS) d->ch[channel - 1].req = level;
}

static bool peek(const stm32_dma_t *d, uint32_t off, uint32_t *v)
{
    if (off == ISR) { *v = d->isr; return true; }
    if (off == IFCR) { *v = 0; return true; } /* write-only */
    if (off < CH0 || off >= CH_END) return false;
    unsigned i = (off - CH0) / CH_STRIDE, r = (off - CH0) % CH_STRIDE;
    const stm32_dma_chan_t *c = &d->ch[i];
    switch (r) {
    case 0: *v = c->ccr; return true;
    case 4: *v = c->cndtr; return true;
    case 8: *v = c->cpar; return true;
    case 12: *v = c->cmar; return true;
    default: return false; /* the reserved word after each channel */
    }
}

static mmio_status_t dma_read(void *self, uint32_t off, unsigned size, uint32_t *value)
{
    uint32_t v;
    if (!stm32_access_ok(off, size) || !peek(self, off & ~3u, &v)) return MMIO_UNMODELED;
    *value = stm32_read_lanes(v, off, size);
    return MMIO_OK;
}

static void write_ccr(stm32_dma_t *d, unsigned i, uint32_t v)
{
    stm32_dma_chan_t *c = &d->ch[i];
    if ((v & CCR_EN) && !(c->ccr & CCR_EN)) { c->done = 0; c->reload = c->cndtr; }
    c->ccr = v & CCR_MASK;
    update_irq(d, i);
}

static void write_word(stm32_dma_t *d, uint32_t off, uint32_t v)
{
    if (off == ISR) return; /* read-only */
    if (off == IFCR) {
        for (unsigned i = 0; i < STM32_DMA_CHANNELS; i++) {
            uint32_t clr = (v >> (4 * i)) & 0xFu;
            if (clr & F_GIF) clr = 0xFu; /* CGIFx clears all of the channel's flags */
            d->isr &= ~(clr << (4 * i));
            update_irq(d, i);
        }
        return;
    }
    unsigned i = (off - CH0) / CH_STRIDE, r = (off - CH0) % CH_STRIDE;
    stm32_dma_chan_t *c = &d->ch[i];
    if (r == 0) { write_ccr(d, i, v); return; }
    if (c->ccr & CCR_EN) return; /* CNDTR, CPAR, CMAR: written only while disabled (13.4.4-13.4.6) */
    if (r == 4) c->cndtr = c->reload = v & 0xFFFFu;
    else if (r == 8) c->cpar = v;
    else c->cmar = v;
}

static mmio_status_t dma_write(void *self, uint32_t off, unsigned size, uint32_t value)
{
    stm32_dma_t *d = self;
    uint32_t old;
    if (!stm32_access_ok(off, size) || !peek(d, off & ~3u, &old)) return MMIO_UNMODELED;
    write_word(d, off & ~3u, stm32_write_lanes(value, size));
    return MMIO_OK;
}

static void dma_reset(void *self)
{
    stm32_dma_t *d = self;
    d->isr = 0;
    for (unsigned i = 0; i < STM32_DMA_CHANNELS; i++) {
        stm32_dma_chan_t *c = &d->ch[i];
        bool req = c->req; /* the peripherals' lines are theirs */
        *c = (stm32_dma_chan_t){ 0 };
        c->req = req;
        update_irq(d, i);
    }
}

const mmio_ops_t stm32_dma_ops = { "DMA1", dma_read, dma_write, dma_advance, dma_next_event, dma_reset };

void stm32_dma_init(stm32_dma_t *d, mmio_bus_t bus, mmio_irq_t irq)
{
    *d = (stm32_dma_t){ 0 };
    d->bus = bus;
    d->irq = irq;
    dma_reset(d);
}

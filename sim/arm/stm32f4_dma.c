/* stm32f4_dma.c - STM32F4 DMA1/DMA2: RM0090 rev 19 section 10 (10.3.3
 * channel selection and tables 42/43, 10.3.4 arbiter, 10.3.5 streams,
 * 10.3.6 source, destination and transfer modes: peripheral-to-memory,
 * memory-to-peripheral, memory-to-memory on DMA2 only, 10.3.7 pointer
 * incrementation, 10.3.8 circular mode, 10.3.10 programmable data width
 * (direct mode: MSIZE is taken as PSIZE, 10.5.5), 10.3.11 FIFO / direct
 * mode, 10.3.15 error management, 10.3.17 stream disable, 10.4
 * interrupts, 10.5 registers and reset values).
 *
 * A stream with EN set, NDTR > 0 and the request of its CHSEL high (or in
 * memory-to-memory mode) is served; the arbiter picks the highest PL, then
 * the lowest stream number (10.3.4). Each transfer reads its source and
 * writes its destination through the bus, then decrements NDTR: HTIF when
 * half the programmed count is done, TCIF at 0; circular mode reloads NDTR
 * and the addresses, otherwise EN is cleared (10.3.8, 10.5.5). A bus error
 * sets TEIF and clears EN (10.3.15). EN cleared by software during a
 * transfer sets TCIF (10.3.17). SxCR (but EN), NDTR, PAR and M0AR are
 * written only while EN is 0.
 * Not modeled (MMIO_UNMODELED on a write that sets them): double buffer
 * mode (DBM, CT), the peripheral flow controller (PFCTRL), PINCOS, bursts
 * (PBURST, MBURST), FIFO mode's thresholds and packing in peripheral
 * transfers (DMDIS set with DIR not memory-to-memory; memory-to-memory
 * runs item by item, its FIFO not modeled, PSIZE = MSIZE required), the
 * FIFO and direct-mode errors (FEIF, DMEIF read 0; FEIE, DMEIE stored).
 * Stated limit: a transfer takes no time (the AHB cycles of 10.3.5 are
 * not counted); requests are served at the cycle the controller is next
 * advanced to (next_event() returns that cycle while one waits). */
#include "arm/stm32f4_dma.h"

#include "arm/stm32f1_clk.h"
#include "arm/stm32f1_dma.h"
#include "arm/stm32f4_reg.h"

enum { LISR = 0x00, HISR = 0x04, LIFCR = 0x08, HIFCR = 0x0C, S0 = 0x10, S_STRIDE = 0x18, S_END = 0x10 + 8 * 0x18 };
#define CR_EN     (1u << 0)
#define CR_DMEIE  (1u << 1)
#define CR_TEIE   (1u << 2)
#define CR_HTIE   (1u << 3)
#define CR_TCIE   (1u << 4)
#define CR_PFCTRL (1u << 5)
#define CR_DIR_SHIFT 6
#define CR_CIRC   (1u << 8)
#define CR_PINC   (1u << 9)
#define CR_MINC   (1u << 10)
#define CR_PSIZE_SHIFT 11
#define CR_MSIZE_SHIFT 13
#define CR_PINCOS (1u << 15)
#define CR_PL_SHIFT 16
#define CR_DBM    (1u << 18)
#define CR_CT     (1u << 19)
#define CR_BURSTS (0xFu << 21)
#define CR_CHSEL_SHIFT 25
#define CR_MASK   0x0FEFFFFFu
#define CR_UNMODELED (CR_PFCTRL | CR_PINCOS | CR_DBM | CR_CT | CR_BURSTS)
#define DIR_P2M 0u
#define DIR_M2P 1u
#define DIR_M2M 2u
#define FCR_DMDIS (1u << 2)
#define FCR_RESET 0x00000021u /* FTH 1/2, FS empty (10.5.10) */
/* flags within a stream's 6-bit group */
#define F_FEIF  (1u << 0)
#define F_DMEIF (1u << 2)
#define F_TEIF  (1u << 3)
#define F_HTIF  (1u << 4)
#define F_TCIF  (1u << 5)
#define F_ALL   0x3Du
#define MAX_TRANSFERS_PER_ADVANCE (8u * 65536u)

#define D(x) STM32F4_DREQ_##x
#define N 0
/* RM0090 table 42 (DMA1) and table 43 (DMA2): [stream][channel] */
const uint8_t stm32f4_dma_map[2][STM32F4_DMA_STREAMS][8][STM32F4_DREQ_PER_CELL] = {
    { { { D(SPI3_RX) }, { D(I2C1_RX) }, { D(TIM4_CH1) }, { D(I2S3_EXT_RX) }, { D(UART5_RX) }, { D(UART8_TX) },
        { D(TIM5_CH3), D(TIM5_UP) }, { N } },
      { { N }, { N }, { N }, { D(TIM2_UP), D(TIM2_CH3) }, { D(USART3_RX) }, { D(UART7_TX) },
        { D(TIM5_CH4), D(TIM5_TRIG) }, { D(TIM6_UP) } },
      { { D(SPI3_RX) }, { D(TIM7_UP) }, { D(I2S3_EXT_RX) }, { D(I2C3_RX) }, { D(UART4_RX) },
        { D(TIM3_CH4), D(TIM3_UP) }, { D(TIM5_CH1) }, { D(I2C2_RX) } },
      { { D(SPI2_RX) }, { N }, { D(TIM4_CH2) }, { D(I2S2_EXT_RX) }, { D(USART3_TX) }, { D(UART7_RX) },
        { D(TIM5_CH4), D(TIM5_TRIG) }, { D(I2C2_RX) } },
      { { D(SPI2_TX) }, { D(TIM7_UP) }, { D(I2S2_EXT_TX) }, { D(I2C3_TX) }, { D(UART4_TX) },
        { D(TIM3_CH1), D(TIM3_TRIG) }, { D(TIM5_CH2) }, { D(USART3_TX) } },
      { { D(SPI3_TX) }, { D(I2C1_RX) }, { D(I2S3_EXT_TX) }, { D(TIM2_CH1) }, { D(USART2_RX) }, { D(TIM3_CH2) },
        { N }, { D(DAC1) } },
      { { N }, { D(I2C1_TX) }, { D(TIM4_UP) }, { D(TIM2_CH2), D(TIM2_CH4) }, { D(USART2_TX) }, { D(UART8_RX) },
        { D(TIM5_UP) }, { D(DAC2) } },
      { { D(SPI3_TX) }, { D(I2C1_TX) }, { D(TIM4_CH3) }, { D(TIM2_UP), D(TIM2_CH4) }, { D(UART5_TX) },
        { D(TIM3_CH3) }, { N }, { D(I2C2_TX) } } },
    { { { D(ADC1) }, { N }, { D(ADC3) }, { D(SPI1_RX) }, { D(SPI4_RX) }, { N }, { D(TIM1_TRIG) }, { N } },
      { { N }, { D(DCMI) }, { D(ADC3) }, { N }, { D(SPI4_TX) }, { D(USART6_RX) }, { D(TIM1_CH1) },
        { D(TIM8_UP) } },
      { { D(TIM8_CH1), D(TIM8_CH2), D(TIM8_CH3) }, { D(ADC2) }, { N }, { D(SPI1_RX) }, { D(USART1_RX) },
        { D(USART6_RX) }, { D(TIM1_CH2) }, { D(TIM8_CH1) } },
      { { N }, { D(ADC2) }, { D(SPI5_RX) }, { D(SPI1_TX) }, { D(SDIO) }, { D(SPI4_RX) }, { D(TIM1_CH1) },
        { D(TIM8_CH2) } },
      { { D(ADC1) }, { N }, { D(SPI5_TX) }, { N }, { N }, { D(SPI4_TX) }, { D(TIM1_CH4), D(TIM1_TRIG), D(TIM1_COM) },
        { D(TIM8_CH3) } },
      { { N }, { D(SPI6_TX) }, { D(CRYP_OUT) }, { D(SPI1_TX) }, { D(USART1_RX) }, { N }, { D(TIM1_UP) },
        { D(SPI5_RX) } },
      { { D(TIM1_CH1), D(TIM1_CH2), D(TIM1_CH3) }, { D(SPI6_RX) }, { D(CRYP_IN) }, { N }, { D(SDIO) },
        { D(USART6_TX) }, { D(TIM1_CH3) }, { D(SPI5_TX) } },
      { { N }, { D(DCMI) }, { D(HASH_IN) }, { N }, { D(USART1_TX) }, { D(USART6_TX) }, { N },
        { D(TIM8_CH4), D(TIM8_TRIG), D(TIM8_COM) } } },
};
#undef N
#undef D

const char *stm32f4_dreq_name(stm32f4_dreq_t r)
{
#define STM32F4_DREQ_NAME(name) #name,
    static const char *const names[] = { "none", STM32F4_DREQ_LIST(STM32F4_DREQ_NAME) };
#undef STM32F4_DREQ_NAME
    return (unsigned)r < STM32F4_DREQ_COUNT ? names[r] : "?";
}

unsigned stm32f4_dma_irq(unsigned index, unsigned stream)
{
    if (index == 1) return stream < 7 ? 11u + stream : 47u;
    return stream < 5 ? 56u + stream : 68u + (stream - 5u);
}

static const unsigned flag_shift[4] = { 0, 6, 16, 22 }; /* LISR/HISR: streams x and x+4 (10.5.1) */

static unsigned flags(const stm32f4_dma_t *d, unsigned i) { return (d->isr[i / 4] >> flag_shift[i % 4]) & 0x3Fu; }

static void update_irq(stm32f4_dma_t *d, unsigned i)
{
    unsigned f = flags(d, i);
    uint32_t cr = d->s[i].cr;
    bool lv = ((f & F_TCIF) && (cr & CR_TCIE)) || ((f & F_HTIF) && (cr & CR_HTIE)) || ((f & F_TEIF) && (cr & CR_TEIE));
    if (lv == d->irq_level[i]) return;
    d->irq_level[i] = lv;
    if (d->irq.set) d->irq.set(d->irq.ctx, stm32f4_dma_irq(d->index, i), lv);
}

static void set_flags(stm32f4_dma_t *d, unsigned i, unsigned f)
{
    d->isr[i / 4] |= (uint32_t)f << flag_shift[i % 4];
    update_irq(d, i);
}

static unsigned dir(const stm32f4_dma_stream_t *s) { return (s->cr >> CR_DIR_SHIFT) & 3u; }

static bool requested(const stm32f4_dma_t *d, unsigned i)
{
    const stm32f4_dma_stream_t *s = &d->s[i];
    if (dir(s) == DIR_M2M) return d->index == 2;
    const uint8_t *cell = stm32f4_dma_map[d->index - 1][i][(s->cr >> CR_CHSEL_SHIFT) & 7u];
    for (unsigned k = 0; k < STM32F4_DREQ_PER_CELL && cell[k]; k++)
        if (d->pending[cell[k]]) return true;
    return false;
}

/* The transfer of stream i acknowledges its request (10.3.2). */
static void acknowledge(stm32f4_dma_t *d, unsigned i)
{
    const stm32f4_dma_stream_t *s = &d->s[i];
    if (dir(s) == DIR_M2M) return;
    const uint8_t *cell = stm32f4_dma_map[d->index - 1][i][(s->cr >> CR_CHSEL_SHIFT) & 7u];
    for (unsigned k = 0; k < STM32F4_DREQ_PER_CELL && cell[k]; k++) d->pending[cell[k]] = false;
}

/* Ready: EN, NDTR > 0 and its request (10.3.3), a valid DIR; PL, CR's priority level (10.3.4). */
static unsigned ready_pl(const void *ctl, unsigned i)
{
    const stm32f4_dma_t *d = ctl;
    const stm32f4_dma_stream_t *s = &d->s[i];
    bool ready = (s->cr & CR_EN) && s->ndtr > 0 && dir(s) != 3u && requested(d, i);
    return ready ? ((s->cr >> CR_PL_SHIFT) & 3u) + 1u : 0u;
}

static unsigned size_bytes(uint32_t cr, unsigned shift)
{
    unsigned s = (cr >> shift) & 3u;
    return s == 0 ? 1 : s == 1 ? 2 : 4; /* 11 reserved: taken as 32 bits */
}

/* One transfer of stream i (stm32_dma_step, the F1's); the peripheral port is PAR (the source in
 * memory-to-memory mode), the memory port M0AR; direct mode: MSIZE is taken as PSIZE (10.5.5). A bus
 * error clears EN (10.3.15); so does the end of a stream not circular (10.3.8). */
static void serve(void *ctl, unsigned i)
{
    stm32f4_dma_t *d = ctl;
    stm32f4_dma_stream_t *s = &d->s[i];
    acknowledge(d, i);
    unsigned sz = size_bytes(s->cr, CR_PSIZE_SHIFT);
    stm32_dma_item_t it = { s->par, s->m0ar, sz, sz, (s->cr & CR_PINC) != 0, (s->cr & CR_MINC) != 0, dir(s) == DIR_M2P };
    unsigned k = stm32_dma_step(d->bus, &it, &s->ndtr, &s->done, s->reload, (s->cr & CR_CIRC) != 0);
    if ((k & STM32_DMA_TE) || ((k & STM32_DMA_TC) && !(s->cr & CR_CIRC))) s->cr &= ~CR_EN;
    unsigned f = stm32_dma_flags(k, F_TEIF, F_HTIF, F_TCIF);
    if (f) set_flags(d, i, f);
}

static const stm32_dma_arbiter_t arbiter = { STM32F4_DMA_STREAMS, MAX_TRANSFERS_PER_ADVANCE, ready_pl, serve };

static void dma_advance(void *self, uint64_t now) { stm32_dma_run(&arbiter, self, &((stm32f4_dma_t *)self)->now, now); }

static uint64_t dma_next_event(void *self) { return stm32_dma_next(&arbiter, self, ((const stm32f4_dma_t *)self)->now); }

void stm32f4_dma_request(void *dma, unsigned channel, bool level)
{
    stm32f4_dma_t *d = dma;
    if (channel == 0 || channel >= STM32F4_DREQ_COUNT) return;
    /* a rise stays pending through the line's fall until a transfer acknowledges it: a timer's
     * compare or update request is a pulse (stm32f1_tim.c), raised and lowered in one event */
    if (level && !d->req[channel]) d->pending[channel] = true;
    d->req[channel] = level;
}

static bool peek(const stm32f4_dma_t *d, uint32_t off, uint32_t *v)
{
    if (off == LISR || off == HISR) { *v = d->isr[off / 4]; return true; }
    if (off == LIFCR || off == HIFCR) { *v = 0; return true; } /* write-only */
    if (off < S0 || off >= S_END) return false;
    const stm32f4_dma_stream_t *s = &d->s[(off - S0) / S_STRIDE];
    switch ((off - S0) % S_STRIDE) {
    case 0x00: *v = s->cr; break;
    case 0x04: *v = s->ndtr; break;
    case 0x08: *v = s->par; break;
    case 0x0C: *v = s->m0ar; break;
    case 0x10: *v = s->m1ar; break;
    default: *v = s->fcr; break;
    }
    return true;
}

static mmio_status_t dma_read(void *self, uint32_t off, unsigned size, uint32_t *value)
{
    uint32_t v;
    if (!stm32_access_ok(off, size) || !peek(self, off & ~3u, &v)) return MMIO_UNMODELED;
    *value = stm32_read_lanes(v, off, size);
    return MMIO_OK;
}

static mmio_status_t write_cr(stm32f4_dma_t *d, unsigned i, uint32_t v)
{
    stm32f4_dma_stream_t *s = &d->s[i];
    mmio_status_t st = MMIO_OK;
    if (s->cr & CR_EN) { /* only EN can change while enabled (10.5.5) */
        if (!(v & CR_EN)) {
            s->cr &= ~CR_EN;
            if (s->ndtr > 0) set_flags(d, i, F_TCIF); /* disabled during a transfer (10.3.17) */
        }
        return MMIO_OK;
    }
    s->cr = v & CR_MASK;
    unsigned dr = dir(s);
    bool m2m = dr == DIR_M2M;
    if ((v & CR_UNMODELED) || dr == 3u || (m2m && d->index == 1)) st = MMIO_UNMODELED; /* DMA1 has no M2M */
    if (m2m && ((s->cr >> CR_PSIZE_SHIFT) & 3u) != ((s->cr >> CR_MSIZE_SHIFT) & 3u)) st = MMIO_UNMODELED;
    if (!m2m && (s->fcr & FCR_DMDIS) && (v & CR_EN)) st = MMIO_UNMODELED;
    if (m2m && (s->cr & CR_CIRC)) st = MMIO_UNMODELED; /* not allowed in memory-to-memory (10.3.8) */
    if (v & CR_EN) { s->done = 0; s->reload = s->ndtr; }
    update_irq(d, i);
    return st;
}

static mmio_status_t write_stream(stm32f4_dma_t *d, uint32_t off, uint32_t v)
{
    unsigned i = (off - S0) / S_STRIDE, r = (off - S0) % S_STRIDE;
    stm32f4_dma_stream_t *s = &d->s[i];
    if (r == 0x00) return write_cr(d, i, v);
    if (r == 0x10) { s->m1ar = v; return MMIO_OK; }
    if (r == 0x14) { /* FCR: FTH, DMDIS, FEIE; FS read-only */
        s->fcr = (v & 0x87u) | (s->fcr & 0x38u);
        return MMIO_OK;
    }
    if (s->cr & CR_EN) return MMIO_OK; /* NDTR, PAR, M0AR: written only while disabled (10.5.6-10.5.8) */
    if (r == 0x04) s->ndtr = s->reload = v & 0xFFFFu;
    else if (r == 0x08) s->par = v;
    else s->m0ar = v;
    return MMIO_OK;
}

static mmio_status_t dma_write(void *self, uint32_t off, unsigned size, uint32_t value)
{
    stm32f4_dma_t *d = self;
    uint32_t w = off & ~3u, old;
    if (!stm32_access_ok(off, size) || !peek(d, w, &old)) return MMIO_UNMODELED;
    if (w == LISR || w == HISR) return MMIO_OK; /* read-only */
    if (w == LIFCR || w == HIFCR) {
        uint32_t c = stm32f4_lane_value(off, size, value);
        for (unsigned k = 0; k < 4; k++) {
            unsigned i = (w == HIFCR ? 4 : 0) + k;
            d->isr[i / 4] &= ~(((c >> flag_shift[k]) & F_ALL) << flag_shift[k]);
            update_irq(d, i);
        }
        return MMIO_OK;
    }
    return write_stream(d, w, stm32f4_merge(old, off, size, value));
}

static void dma_reset(void *self)
{
    stm32f4_dma_t *d = self;
    d->isr[0] = d->isr[1] = 0;
    for (unsigned i = 0; i < STM32F4_DMA_STREAMS; i++) {
        d->s[i] = (stm32f4_dma_stream_t){ 0 };
        d->s[i].fcr = FCR_RESET;
        update_irq(d, i);
    }
}

const mmio_ops_t stm32f4_dma_ops = { "DMA", dma_read, dma_write, dma_advance, dma_next_event, dma_reset };

void stm32f4_dma_init(stm32f4_dma_t *d, unsigned index, mmio_bus_t bus, mmio_irq_t irq)
{
    *d = (stm32f4_dma_t){ 0 };
    d->index = index == 1 ? 1 : 2;
    d->bus = bus;
    d->irq = irq;
    dma_reset(d);
}

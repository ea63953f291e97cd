/* stm32f1_usart.c - STM32F1 USART1-3, asynchronous mode: RM0008 rev 21
 * section 27 (27.3.2 transmitter: TXE, TC, the idle frame sent when TE is
 * set; 27.3.3 receiver: RXNE, overrun, idle line; 27.3.4 fractional baud
 * rate: baud = fPCLK / (16 x USARTDIV), BRR holding 16 x USARTDIV; 27.3.13
 * DMA (Table 78 channels); 27.4 interrupts; 27.6 registers).
 *
 * A frame is 1 start bit, 8 or 9 data bits (M) and 0.5/1/1.5/2 stop bits
 * (STOP), each bit BRR cycles of the USART's APB clock (PCLK2 for USART1,
 * PCLK1 for the others), counted in core cycles. Writing DR fills TDR;
 * the shifter takes it at once when empty (TXE rises again) and the byte
 * reaches the sink when its frame ends; TC rises when a frame ends with TDR
 * empty. A received byte lands in RDR at its frame's end: RXNE, or ORE if
 * RXNE was still set (RDR keeps the old byte); one frame time of idle line
 * after it sets IDLE. SR read then DR read clears IDLE and ORE; SR read then
 * DR write clears TC (27.6.1); RXNE and TC also clear by writing 0.
 * Not modeled (a write that sets them answers MMIO_UNMODELED): parity (PCE),
 * wake-up (RWU, WAKE), break (SBK), LIN, synchronous clock (CLKEN),
 * IrDA, smartcard, half-duplex, hardware flow control. */
#include "arm/stm32f1_usart.h"

#include "arm/stm32f1_clk.h"

enum { SR = 0x00, DR = 0x04, BRR = 0x08, CR1 = 0x0C, CR2 = 0x10, CR3 = 0x14, GTPR = 0x18 };
#define SR_PE    (1u << 0)
#define SR_FE    (1u << 1)
#define SR_NE    (1u << 2)
#define SR_ORE   (1u << 3)
#define SR_IDLE  (1u << 4)
#define SR_RXNE  (1u << 5)
#define SR_TC    (1u << 6)
#define SR_TXE   (1u << 7)
#define SR_RESET (SR_TXE | SR_TC) /* 0x00C0 */
#define CR1_SBK    (1u << 0)
#define CR1_RWU    (1u << 1)
#define CR1_RE     (1u << 2)
#define CR1_TE     (1u << 3)
#define CR1_IDLEIE (1u << 4)
#define CR1_RXNEIE (1u << 5)
#define CR1_TCIE   (1u << 6)
#define CR1_TXEIE  (1u << 7)
#define CR1_PEIE   (1u << 8)
#define CR1_PCE    (1u << 10)
#define CR1_WAKE   (1u << 11)
#define CR1_M      (1u << 12)
#define CR1_UE     (1u << 13)
#define CR1_OVER8  (1u << 15) /* RM0090 30.6.4: oversampling by 8 (reserved on the F1) */
#define CR1_UNMODELED (CR1_SBK | CR1_RWU | CR1_PCE | CR1_WAKE | CR1_OVER8)
#define CR2_STOP_SHIFT 12
#define CR2_UNMODELED 0x4F60u /* LBDL, LBDIE, LBCL, CPHA, CPOL, CLKEN, LINEN */
#define CR3_EIE  (1u << 0)
#define CR3_DMAR (1u << 6)
#define CR3_DMAT (1u << 7)
#define CR3_UNMODELED 0x0F3Eu /* IREN, IRLP, HDSEL, NACK, SCEN, RTSE, CTSE, CTSIE; the F4's ONEBIT (RM0090 30.6.6) */

/* RM0008 Table 78: DMA1 channels of the USARTs' TX and RX requests */
static const unsigned dma_tx_ch[4] = { 0, 4, 7, 2 }, dma_rx_ch[4] = { 0, 5, 6, 3 };

/* One frame, core cycles: half-bits x BRR APB cycles / 2. */
static uint64_t frame_cycles(const stm32_usart_t *u)
{
    static const unsigned stop_half[4] = { 2, 1, 4, 3 }; /* STOP 00: 1, 01: 0.5, 10: 2, 11: 1.5 bits */
    unsigned half_bits = 2 * (1 + ((u->cr1 & CR1_M) ? 9 : 8)) + stop_half[(u->cr2 >> CR2_STOP_SHIFT) & 3u];
    uint32_t pclk = u->apb == 2 ? u->clk->pclk2 : u->clk->pclk1;
    uint32_t brr = u->brr & 0xFFFFu;
    if (brr == 0) return MMIO_NEVER;
    return stm32_half_ticks_to_cycles((uint64_t)half_bits * brr, u->clk->hclk, pclk);
}

static void update_lines(stm32_usart_t *u)
{
    uint32_t sr = u->sr, c1 = u->cr1;
    bool lv = ((sr & SR_TXE) && (c1 & CR1_TXEIE)) || ((sr & SR_TC) && (c1 & CR1_TCIE))
           || ((sr & (SR_RXNE | SR_ORE)) && (c1 & CR1_RXNEIE)) || ((sr & SR_IDLE) && (c1 & CR1_IDLEIE))
           || ((sr & SR_PE) && (c1 & CR1_PEIE)) || ((sr & SR_ORE) && (u->cr3 & CR3_EIE) && (u->cr3 & CR3_DMAR));
    if (lv != u->irq_level) {
        u->irq_level = lv;
        if (u->irq.set) u->irq.set(u->irq.ctx, u->irq_n, lv);
    }
    bool tx = (sr & SR_TXE) && (u->cr3 & CR3_DMAT), rx = (sr & SR_RXNE) && (u->cr3 & CR3_DMAR);
    if (tx != u->tx_req) {
        u->tx_req = tx;
        if (u->dma.request) u->dma.request(u->dma.ctx, u->dma_tx, tx);
    }
    if (rx != u->rx_req) {
        u->rx_req = rx;
        if (u->dma.request) u->dma.request(u->dma.ctx, u->dma_rx, rx);
    }
}

static bool enabled(const stm32_usart_t *u, uint32_t bit) { return (u->cr1 & CR1_UE) && (u->cr1 & bit); }

/* The shifter takes TDR if it is empty and TDR holds a byte. */
static void load_shifter(stm32_usart_t *u, uint64_t t)
{
    if (u->tx_end != MMIO_NEVER || (u->sr & SR_TXE) || !enabled(u, CR1_TE)) return;
    u->tx_shift = (uint16_t)u->tdr;
    u->tx_idle_frame = false;
    u->sr |= SR_TXE;
    u->tx_end = stm32_at(t, frame_cycles(u));
}

static void tx_done(stm32_usart_t *u, uint64_t t)
{
    u->tx_end = MMIO_NEVER;
    if (!u->tx_idle_frame && u->sink) u->sink(u->sink_ctx, (uint8_t)u->tx_shift, t);
    u->tx_idle_frame = false;
    load_shifter(u, t);
    if (u->tx_end == MMIO_NEVER) u->sr |= SR_TC;
}

static void rx_start(stm32_usart_t *u, uint64_t t)
{
    if (u->rx_end != MMIO_NEVER || u->rxq_count == 0) return;
    u->rx_end = stm32_at(t, frame_cycles(u));
    u->idle_at = MMIO_NEVER; /* a start bit: the line is not idle */
}

static void rx_done(stm32_usart_t *u, uint64_t t)
{
    uint8_t b = u->rxq[u->rxq_head];
    u->rxq_head = (u->rxq_head + 1) % STM32_USART_RXQ;
    u->rxq_count--;
    u->rx_end = MMIO_NEVER;
    if (enabled(u, CR1_RE)) {
        if (u->sr & SR_RXNE) u->sr |= SR_ORE; /* RDR keeps its byte (27.3.3 overrun) */
        else { u->rdr = b; u->sr |= SR_RXNE; }
        u->idle_armed = true;
    }
    rx_start(u, t);
    if (u->rx_end == MMIO_NEVER) u->idle_at = stm32_at(t, frame_cycles(u));
}

static uint64_t usart_next_event(void *self)
{
    const stm32_usart_t *u = self;
    uint64_t t = u->tx_end;
    if (u->rx_end < t) t = u->rx_end;
    if (u->idle_at < t) t = u->idle_at;
    return t;
}

static void usart_advance(void *self, uint64_t now)
{
    stm32_usart_t *u = self;
    for (;;) {
        uint64_t t = usart_next_event(u);
        if (t > now) break;
        if (u->tx_end == t) tx_done(u, t);
        else if (u->rx_end == t) rx_done(u, t);
        else {
            u->idle_at = MMIO_NEVER;
            if (u->idle_armed && enabled(u, CR1_RE)) { u->sr |= SR_IDLE; u->idle_armed = false; }
        }
        update_lines(u);
    }
    if (now > u->now) u->now = now;
}

bool stm32_usart_push(stm32_usart_t *u, uint8_t byte, uint64_t now)
{
    usart_advance(u, now);
    if (u->rxq_count == STM32_USART_RXQ) { u->rx_dropped++; return false; }
    u->rxq[(u->rxq_head + u->rxq_count) % STM32_USART_RXQ] = byte;
    u->rxq_count++;
    rx_start(u, u->now);
    return true;
}

static mmio_status_t usart_read(void *self, uint32_t off, unsigned size, uint32_t *value)
{
    stm32_usart_t *u = self;
    uint32_t v;
    if (!stm32_access_ok(off, size)) return MMIO_UNMODELED;
    switch (off & ~3u) {
    case SR: v = u->sr; u->sr_seen = u->sr; break;
    case DR:
        v = u->rdr;
        u->sr &= ~(SR_RXNE | (u->sr_seen & (SR_IDLE | SR_ORE | SR_NE | SR_FE | SR_PE)));
        u->sr_seen = 0;
        update_lines(u);
        break;
    case BRR: v = u->brr; break;
    case CR1: v = u->cr1; break;
    case CR2: v = u->cr2; break;
    case CR3: v = u->cr3; break;
    case GTPR: v = u->gtpr; break;
    default: return MMIO_UNMODELED;
    }
    *value = stm32_read_lanes(v, off, size);
    return MMIO_OK;
}

static void write_dr(stm32_usart_t *u, uint32_t v)
{
    if (u->sr_seen & SR_TC) u->sr &= ~SR_TC; /* SR read, then DR write */
    u->sr_seen = 0;
    if (!enabled(u, CR1_TE)) return;
    u->tdr = v & 0x1FFu;
    u->sr &= ~SR_TXE;
    load_shifter(u, u->now);
}

static void write_cr1(stm32_usart_t *u, uint32_t v)
{
    uint32_t old = u->cr1;
    u->cr1 = v & 0x3FFFu;
    if (!(v & CR1_UE)) { /* the USART stops: frames in progress are dropped */
        u->tx_end = u->rx_end = u->idle_at = MMIO_NEVER;
        return;
    }
    bool te_on = (v & CR1_TE) && !((old & CR1_TE) && (old & CR1_UE));
    if (te_on && u->tx_end == MMIO_NEVER) { /* 27.3.2: an idle frame before the first data frame */
        u->tx_idle_frame = true;
        u->tx_end = stm32_at(u->now, frame_cycles(u));
    }
    rx_start(u, u->now);
}

static mmio_status_t write_word(stm32_usart_t *u, uint32_t off, uint32_t v)
{
    mmio_status_t st = MMIO_OK;
    switch (off) {
    case SR: /* rc_w0 on RXNE and TC; the other bits are read-only */
        u->sr &= (v & (SR_RXNE | SR_TC)) | ~(SR_RXNE | SR_TC);
        break;
    case DR: write_dr(u, v); break;
    case BRR: u->brr = v & 0xFFFFu; break;
    case CR1:
        if (v & CR1_UNMODELED) st = MMIO_UNMODELED;
        write_cr1(u, v);
        break;
    case CR2:
        if (v & CR2_UNMODELED) st = MMIO_UNMODELED;
        u->cr2 = v & 0x7F7Fu;
        break;
    case CR3:
        if (v & CR3_UNMODELED) st = MMIO_UNMODELED;
        u->cr3 = v & 0x07FFu;
        break;
    case GTPR: u->gtpr = v & 0xFFFFu; break;
    default: return MMIO_UNMODELED;
    }
    update_lines(u);
    return st;
}

static mmio_status_t usart_write(void *self, uint32_t off, unsigned size, uint32_t value)
{
    stm32_usart_t *u = self;
    if (!stm32_access_ok(off, size) || (off & ~3u) > GTPR) return MMIO_UNMODELED;
    return write_word(u, off & ~3u, stm32_write_lanes(value, size) & 0xFFFFu); /* upper halves reserved */
}

static void usart_reset(void *self)
{
    stm32_usart_t *u = self;
    u->sr = SR_RESET;
    u->rdr = u->tdr = u->brr = u->cr1 = u->cr2 = u->cr3 = u->gtpr = 0;
    u->tx_end = u->rx_end = u->idle_at = MMIO_NEVER;
    u->tx_idle_frame = u->idle_armed = false;
    u->rxq_head = u->rxq_count = 0;
    u->sr_seen = 0;
    update_lines(u);
}

const mmio_ops_t stm32_usart_ops = { "USART", usart_read, usart_write, usart_advance, usart_next_event, usart_reset };

void stm32_usart_init(stm32_usart_t *u, unsigned index, const mmio_clocks_t *clk, mmio_irq_t irq,
                      mmio_dma_req_t dma, stm32_usart_sink_fn sink, void *sink_ctx)
{
    *u = (stm32_usart_t){ 0 };
    u->clk = clk;
    u->irq = irq;
    u->dma = dma;
    u->index = index >= 1 && index <= 6 ? index : 1;
    unsigned f1 = u->index <= 3 ? u->index : 1; /* the F1's USART1-3; the F4 sets UART4/5, USART6's after */
    u->irq_n = STM32_USART_IRQ(f1);
    u->apb = u->index == 1 || u->index == 6 ? 2 : 1;
    u->dma_tx = dma_tx_ch[f1];
    u->dma_rx = dma_rx_ch[f1];
    u->sink = sink;
    u->sink_ctx = sink_ctx;
    usart_reset(u);
}

/* stm32f1_spi.c - STM32F1 SPI1/SPI2 and STM32F4 SPI1-3, full-duplex
 * master: RM0008 rev 21 section 25 (25.3.3 master mode, 25.3.5 data
 * transmission and reception: TXE, RXNE, BSY, 25.3.7 status flags, 25.3.10
 * error flags: MODF, OVR, 25.3.9 DMA, 25.3.11 interrupts, 25.5 registers);
 * RM0090 rev 19 section 28 the same in SPI mode (28.3.3, 28.3.5, 28.3.7,
 * 28.3.9-28.3.11, 28.5), SPI1 on APB2, SPI2/3 on APB1 as on the F1.
 *
 * Writing DR fills the TX buffer; the shifter takes it at once when empty
 * (TXE rises, BSY is set) and shifts 8 or 16 bits (DFF) at fSCK = fPCLK /
 * 2^(BR+1), PCLK2 for SPI1 and PCLK1 for SPI2. At the frame's end the
 * slave's answer lands in the RX buffer: RXNE, or OVR if RXNE was still set
 * (the buffer keeps the old data); the next frame follows at once if TXE is
 * 0, else BSY clears. OVR clears by a DR read then an SR read; MODF (NSS
 * low in master mode: SSM with SSI 0) clears SPE and MSTR and clears by an
 * SR read then a CR1 write. Not modeled (a write that sets them answers
 * MMIO_UNMODELED): slave mode (SPE without MSTR), bidirectional and
 * receive-only modes, CRC, the F4's TI frame format (CR2 FRF, SR FRE),
 * I2S (I2SCFGR, I2SPR), the NSS pin as an input
 * (SSM 0 with SSOE 0 reads it as high). CPOL/CPHA select
 * the clock's edges only, which the byte exchange does not see. */
#include "arm/stm32f1_spi.h"

#include "arm/stm32f1_clk.h"

enum { CR1 = 0x00, CR2 = 0x04, SR = 0x08, DR = 0x0C, CRCPR = 0x10, RXCRCR = 0x14, TXCRCR = 0x18 };
#define CR1_MSTR     (1u << 2)
#define CR1_BR_SHIFT 3
#define CR1_SPE      (1u << 6)
#define CR1_LSBFIRST (1u << 7)
#define CR1_SSI      (1u << 8)
#define CR1_SSM      (1u << 9)
#define CR1_RXONLY   (1u << 10)
#define CR1_DFF      (1u << 11)
#define CR1_CRCNEXT  (1u << 12)
#define CR1_CRCEN    (1u << 13)
#define CR1_BIDIMODE (1u << 15)
#define CR1_UNMODELED (CR1_RXONLY | CR1_CRCNEXT | CR1_CRCEN | CR1_BIDIMODE)
#define CR2_RXDMAEN  (1u << 0)
#define CR2_TXDMAEN  (1u << 1)
#define CR2_FRF      (1u << 4) /* RM0090 28.5.2: TI mode (reserved on the F1) */
#define CR2_ERRIE    (1u << 5)
#define CR2_RXNEIE   (1u << 6)
#define CR2_TXEIE    (1u << 7)
#define SR_RXNE (1u << 0)
#define SR_TXE  (1u << 1)
#define SR_MODF (1u << 5)
#define SR_OVR  (1u << 6)
#define SR_BSY  (1u << 7)

static void update_lines(stm32_spi_t *s)
{
    uint32_t sr = s->sr, c2 = s->cr2;
    bool lv = ((sr & SR_TXE) && (c2 & CR2_TXEIE)) || ((sr & SR_RXNE) && (c2 & CR2_RXNEIE))
           || ((sr & (SR_OVR | SR_MODF)) && (c2 & CR2_ERRIE));
    if (lv != s->irq_level) {
        s->irq_level = lv;
        if (s->irq.set) s->irq.set(s->irq.ctx, s->irq_n, lv);
    }
    bool tx = (sr & SR_TXE) && (c2 & CR2_TXDMAEN), rx = (sr & SR_RXNE) && (c2 & CR2_RXDMAEN);
    if (tx != s->tx_req) {
        s->tx_req = tx;
        if (s->dma.request) s->dma.request(s->dma.ctx, s->dma_tx, tx);
    }
    if (rx != s->rx_req) {
        s->rx_req = rx;
        if (s->dma.request) s->dma.request(s->dma.ctx, s->dma_rx, rx);
    }
}

static uint8_t reverse8(uint8_t b)
{
    b = (uint8_t)((b & 0xF0u) >> 4 | (b & 0x0Fu) << 4);
    b = (uint8_t)((b & 0xCCu) >> 2 | (b & 0x33u) << 2);
    return (uint8_t)((b & 0xAAu) >> 1 | (b & 0x55u) << 1);
}

static uint8_t exchange_byte(stm32_spi_t *s, uint8_t out, uint64_t t)
{
    bool lsb = s->cr1 & CR1_LSBFIRST;
    uint8_t wire = lsb ? reverse8(out) : out;
    uint8_t in = s->slave.exchange ? s->slave.exchange(s->slave.dev, wire, t) : 0xFFu;
    return lsb ? reverse8(in) : in;
}

/* The frame's data from the slave: 16-bit frames as two bytes, the first
 * on the wire first (the high byte MSB-first, the low byte LSB-first). */
static uint16_t exchange_frame(stm32_spi_t *s, uint64_t t)
{
    if (!(s->cr1 & CR1_DFF)) return exchange_byte(s, (uint8_t)s->shift, t);
    bool lsb = s->cr1 & CR1_LSBFIRST;
    uint8_t first = lsb ? (uint8_t)s->shift : (uint8_t)(s->shift >> 8);
    uint8_t second = lsb ? (uint8_t)(s->shift >> 8) : (uint8_t)s->shift;
    uint8_t a = exchange_byte(s, first, t), b = exchange_byte(s, second, t);
    return lsb ? (uint16_t)(b << 8 | a) : (uint16_t)(a << 8 | b);
}

static bool master_on(const stm32_spi_t *s) { return (s->cr1 & CR1_SPE) && (s->cr1 & CR1_MSTR); }

static void start_frame(stm32_spi_t *s, uint64_t t)
{
    if (s->end != MMIO_NEVER || (s->sr & SR_TXE) || !master_on(s)) return;
    s->shift = (uint16_t)s->txdr;
    s->sr |= SR_TXE | SR_BSY;
    uint32_t pclk = s->index == 1 ? s->clk->pclk2 : s->clk->pclk1;
    uint64_t bits = (s->cr1 & CR1_DFF) ? 16 : 8, div = 2u << ((s->cr1 >> CR1_BR_SHIFT) & 7u);
    s->end = stm32_at(t, stm32_ticks_to_cycles(bits * div, s->clk->hclk, pclk));
}

static void end_frame(stm32_spi_t *s, uint64_t t)
{
    s->end = MMIO_NEVER;
    uint16_t in = exchange_frame(s, t);
    if (s->sr & SR_RXNE) s->sr |= SR_OVR; /* 25.3.10: the RX buffer keeps its data */
    else { s->rxdr = in; s->sr |= SR_RXNE; }
    start_frame(s, t);
    if (s->end == MMIO_NEVER) s->sr &= ~SR_BSY;
}

static uint64_t spi_next_event(void *self) { return ((const stm32_spi_t *)self)->end; }

static void spi_advance(void *self, uint64_t now)
{
    stm32_spi_t *s = self;
    while (s->end <= now) {
        end_frame(s, s->end);
        update_lines(s);
    }
    if (now > s->now) s->now = now;
}

static mmio_status_t spi_read(void *self, uint32_t off, unsigned size, uint32_t *value)
{
    stm32_spi_t *s = self;
    uint32_t v;
    if (!stm32_access_ok(off, size)) return MMIO_UNMODELED;
    switch (off & ~3u) {
    case CR1: v = s->cr1; break;
    case CR2: v = s->cr2; break;
    case SR:
        v = s->sr;
        if (s->dr_read && (s->sr & SR_OVR)) s->sr &= ~SR_OVR; /* DR read, then SR read */
        s->dr_read = false;
        s->modf_seen = (v & SR_MODF) != 0;
        update_lines(s);
        break;
    case DR:
        v = s->rxdr;
        s->sr &= ~SR_RXNE;
        s->dr_read = true;
        update_lines(s);
        break;
    case CRCPR: v = s->crcpr; break;
    default: return MMIO_UNMODELED; /* RXCRCR, TXCRCR, I2SCFGR, I2SPR */
    }
    *value = stm32_read_lanes(v, off, size);
    return MMIO_OK;
}

static mmio_status_t write_cr1(stm32_spi_t *s, uint32_t v)
{
    mmio_status_t st = (v & CR1_UNMODELED) || ((v & CR1_SPE) && !(v & CR1_MSTR)) ? MMIO_UNMODELED : MMIO_OK;
    if (s->modf_seen) s->sr &= ~SR_MODF; /* SR read, then CR1 write */
    s->modf_seen = false;
    s->cr1 = v & 0xFFFFu;
    /* NSS low in an enabled master: a mode fault (RM0008 25.3.10). Not while SPE is 0: libopencm3's
     * spi_init_master, then SSM, then SSI (every libopencm3 F1 firmware, bulebule's setup_spi) passes
     * through MSTR with SSM and SSI 0 before SPE and runs on the chip */
    if ((s->cr1 & CR1_SPE) && (s->cr1 & CR1_MSTR) && (s->cr1 & CR1_SSM) && !(s->cr1 & CR1_SSI)) {
        s->sr |= SR_MODF;
        s->cr1 &= ~(CR1_SPE | CR1_MSTR);
    }
    start_frame(s, s->now);
    return st;
}

static mmio_status_t spi_write(void *self, uint32_t off, unsigned size, uint32_t value)
{
    stm32_spi_t *s = self;
    mmio_status_t st = MMIO_OK;
    if (!stm32_access_ok(off, size)) return MMIO_UNMODELED;
    value = stm32_write_lanes(value, size) & 0xFFFFu; /* upper halves reserved */
    switch (off & ~3u) {
    case CR1: st = write_cr1(s, value); break;
    case CR2:
        if (value & CR2_FRF) st = MMIO_UNMODELED;
        s->cr2 = value & 0xE7u;
        break;
    case SR: /* rc_w0 applies to CRCERR only (not modeled); the rest is read-only */ break;
    case DR:
        s->txdr = (s->cr1 & CR1_DFF) ? value : (value & 0xFFu);
        s->sr &= ~SR_TXE;
        update_lines(s); /* TXE low, if only until the shifter takes the data: the TX DMA request falls and rises
                          * again for the next transfer (a DMA request is an edge, RM0090 10.3.2) */
        start_frame(s, s->now);
        break;
    case CRCPR: s->crcpr = value; break;
    case RXCRCR: case TXCRCR: break; /* read-only */
    default: return MMIO_UNMODELED;
    }
    update_lines(s);
    return st;
}

static void spi_reset(void *self)
{
    stm32_spi_t *s = self;
    s->cr1 = s->cr2 = s->rxdr = s->txdr = 0;
    s->sr = SR_TXE;   /* RM0008 25.5.3: reset 0x0002 */
    s->crcpr = 0x7u;  /* 25.5.5: reset 0x0007 */
    s->end = MMIO_NEVER;
    s->dr_read = s->modf_seen = false;
    update_lines(s);
}

const mmio_ops_t stm32_spi_ops = { "SPI", spi_read, spi_write, spi_advance, spi_next_event, spi_reset };

void stm32_spi_init(stm32_spi_t *s, unsigned index, const mmio_clocks_t *clk, mmio_irq_t irq,
                    mmio_dma_req_t dma, stm32_spi_slave_t slave)
{
    *s = (stm32_spi_t){ 0 };
    s->clk = clk;
    s->irq = irq;
    s->dma = dma;
    s->index = index >= 1 && index <= 3 ? index : 1;
    s->irq_n = STM32_SPI_IRQ(s->index);
    s->dma_rx = s->index == 1 ? 2 : 4; /* RM0008 Table 78 */
    s->dma_tx = s->index == 1 ? 3 : 5;
    s->slave = slave;
    spi_reset(s);
}

void stm32_spi_attach(stm32_spi_t *s, stm32_spi_slave_t slave) { s->slave = slave; }

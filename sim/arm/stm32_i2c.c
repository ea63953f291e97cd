/* stm32_i2c.c - STM32F1/F4 I2C master: RM0090 rev 19 section 27 (27.3.3
 * master mode: start condition and SB, slave address transmission and
 * ADDR, master transmitter (TxE, BTF), master receiver (RxNE, BTF, ACK and
 * POS for the (N)ACK, figure 242's 1- and 2-byte sequences, STOP after the
 * current byte), closing the communication; 27.3.4 errors (AF on a NACK);
 * 27.3.7 DMA requests; 27.4 interrupts (event and error lines); 27.6
 * registers: SB cleared by reading SR1 then writing DR, ADDR by reading SR1
 * then SR2, BTF by reading SR1 then reading or writing DR, the error flags
 * rc_w0) and RM0008 rev 21 section 26 (the same on the F1).
 * SCL period from CCR (27.6.8): standard mode 2 x CCR x TPCLK1, fast mode
 * 3 x CCR (DUTY 0) or 25 x CCR (DUTY 1) TPCLK1; a byte and its acknowledge
 * take 9 periods, a START or STOP condition one (ours: the manual gives the
 * setup and hold times, 27.6.8, which TRISE and CCR make about one period).
 * Not modeled (MMIO_UNMODELED on a write that sets them): slave mode (OAR1/2
 * stored; the peripheral never answers as a slave), SMBus (SMBUS, SMBTYPE,
 * ENARP, ENPEC, PEC, ALERT), general call (ENGC), NOSTRETCH, DMA's LAST;
 * arbitration loss and bus errors never happen (one master). Stated limit:
 * the slaves answer at once (no clock stretching by a slave). */
#include "arm/stm32_i2c.h"

#include <stddef.h>

#include "arm/stm32f1_clk.h"

enum { CR1 = 0x00, CR2 = 0x04, OAR1 = 0x08, OAR2 = 0x0C, DR = 0x10, SR1 = 0x14, SR2 = 0x18, CCR = 0x1C,
       TRISE = 0x20 };
#define CR1_PE    (1u << 0)
#define CR1_START (1u << 8)
#define CR1_STOP  (1u << 9)
#define CR1_ACK   (1u << 10)
#define CR1_POS   (1u << 11)
#define CR1_SWRST (1u << 15)
#define CR1_UNMODELED 0x30FAu /* SMBUS, SMBTYPE, ENARP, ENPEC, ENGC, NOSTRETCH, PEC, ALERT */
#define CR2_ITERREN (1u << 8)
#define CR2_ITEVTEN (1u << 9)
#define CR2_ITBUFEN (1u << 10)
#define CR2_DMAEN   (1u << 11)
#define CR2_LAST    (1u << 12)
#define SR1_SB    (1u << 0)
#define SR1_ADDR  (1u << 1)
#define SR1_BTF   (1u << 2)
#define SR1_RXNE  (1u << 6)
#define SR1_TXE   (1u << 7)
#define SR1_AF    (1u << 10)
#define SR1_ERRORS 0xDF00u /* BERR, ARLO, AF, OVR, PECERR, TIMEOUT, SMBALERT: rc_w0 */
#define SR1_EVENTS (SR1_SB | SR1_ADDR | SR1_BTF | (1u << 3) | (1u << 4))
#define SR2_MSL   (1u << 0)
#define SR2_BUSY  (1u << 1)
#define SR2_TRA   (1u << 2)
#define CCR_FS    (1u << 15)
#define CCR_DUTY  (1u << 14)

enum { PH_NONE, PH_START, PH_ADDR, PH_TX, PH_RX, PH_STOP };

/* Core cycles of n SCL periods (27.6.8). */
static uint64_t scl_cycles(const stm32_i2c_t *i, unsigned n)
{
    uint32_t c = i->ccr & 0xFFFu, k = !(i->ccr & CCR_FS) ? 2u : (i->ccr & CCR_DUTY) ? 25u : 3u;
    if (c == 0) c = 1; /* CCR 0 is not allowed (min 4 or 1); taken as 1 */
    return stm32_ticks_to_cycles((uint64_t)n * k * c, i->clk->hclk, i->clk->pclk1);
}

static void update_lines(stm32_i2c_t *i)
{
    uint32_t s = i->sr1, c = i->cr2;
    bool ev = (c & CR2_ITEVTEN) && ((s & SR1_EVENTS) || ((c & CR2_ITBUFEN) && (s & (SR1_TXE | SR1_RXNE))));
    bool er = (c & CR2_ITERREN) && (s & SR1_ERRORS);
    if (ev != i->ev_level && i->irq.set) i->irq.set(i->irq.ctx, STM32_I2C_EV_IRQ(i->index), ev);
    if (er != i->er_level && i->irq.set) i->irq.set(i->irq.ctx, STM32_I2C_ER_IRQ(i->index), er);
    i->ev_level = ev;
    i->er_level = er;
    bool dma = (c & CR2_DMAEN) && i->dma.request;
    bool tx = dma && (s & SR1_TXE), rx = dma && (s & SR1_RXNE);
    if (tx != i->tx_level) i->dma.request(i->dma.ctx, i->dma_tx, tx);
    if (rx != i->rx_level) i->dma.request(i->dma.ctx, i->dma_rx, rx);
    i->tx_level = tx;
    i->rx_level = rx;
}

static void begin(stm32_i2c_t *i, int phase, unsigned periods)
{
    i->phase = phase;
    i->phase_end = stm32_at(i->now, scl_cycles(i, periods));
}

static stm32_i2c_slave_t *cur(stm32_i2c_t *i) { return i->cur >= 0 ? &i->slave[i->cur] : 0; }

/* After a byte: a STOP or repeated START asked for, else the next byte (receiver, acknowledged). */
static void after_byte(stm32_i2c_t *i, bool more)
{
    if (i->cr1 & CR1_STOP) begin(i, PH_STOP, 1);
    else if (i->cr1 & CR1_START) begin(i, PH_START, 1);
    else if (more) begin(i, PH_RX, 9);
    else i->phase = PH_NONE;
}

static void end_address(stm32_i2c_t *i)
{
    bool read = i->shift & 1u;
    i->cur = -1;
    for (unsigned k = 0; k < i->nslaves; k++)
        if (i->slave[k].addr == (i->shift >> 1)) i->cur = (int)k;
    bool ack = i->cur >= 0 && i->slave[i->cur].start(i->slave[i->cur].dev, read, i->phase_end);
    i->phase = PH_NONE;
    i->ack_latched = i->cr1 & CR1_ACK;
    if (!ack) { i->sr1 |= SR1_AF; i->cur = -1; return; } /* 27.3.4: acknowledge failure */
    i->sr1 |= SR1_ADDR;
    i->sr2 = read ? i->sr2 & ~SR2_TRA : i->sr2 | SR2_TRA;
}

static void end_tx(stm32_i2c_t *i)
{
    stm32_i2c_slave_t *s = cur(i);
    bool ack = s && s->write(s->dev, i->shift, i->phase_end);
    i->bytes++;
    if (!ack) { i->sr1 |= SR1_AF; i->phase = PH_NONE; return; }
    if (i->dr_full) {
        i->shift = i->dr;
        i->dr_full = false;
        i->sr1 |= SR1_TXE;
        begin(i, PH_TX, 9);
        return;
    }
    i->sr1 |= SR1_BTF; /* DR empty and the byte sent: the clock is stretched */
    after_byte(i, false);
}

static void end_rx(stm32_i2c_t *i)
{
    stm32_i2c_slave_t *s = cur(i);
    uint8_t b = s ? s->read(s->dev, i->phase_end) : 0xFFu;
    bool ack = (i->cr1 & CR1_POS) ? i->ack_latched : (i->cr1 & CR1_ACK) != 0;
    i->ack_latched = i->cr1 & CR1_ACK;
    i->bytes++;
    if (i->sr1 & SR1_RXNE) { /* DR full: the byte waits in the shift register (BTF) */
        i->shift = b;
        i->rx_held = true;
        i->rx_ack = ack;
        i->sr1 |= SR1_BTF;
        i->phase = PH_NONE;
        return;
    }
    i->dr = b;
    i->sr1 |= SR1_RXNE;
    after_byte(i, ack);
}

static void end_stop(stm32_i2c_t *i)
{
    stm32_i2c_slave_t *s = cur(i);
    if (s && s->stop) s->stop(s->dev, i->phase_end);
    i->cur = -1;
    i->sr2 &= ~(SR2_MSL | SR2_BUSY | SR2_TRA);
    i->cr1 &= ~CR1_STOP; /* cleared when the stop condition is detected (27.6.1) */
    i->sr1 &= ~(SR1_TXE | SR1_BTF);
    i->phase = PH_NONE;
    if (i->cr1 & CR1_START) begin(i, PH_START, 1); /* a START asked for meanwhile: once the bus is free */
}

static void step(stm32_i2c_t *i)
{
    switch (i->phase) {
    case PH_START:
        i->sr1 |= SR1_SB;
        i->sr1 &= ~(SR1_TXE | SR1_BTF);
        i->sr2 |= SR2_MSL | SR2_BUSY;
        i->cr1 &= ~CR1_START; /* cleared when the start condition is sent */
        i->phase = PH_NONE;
        break;
    case PH_ADDR: end_address(i); break;
    case PH_TX: end_tx(i); break;
    case PH_RX: end_rx(i); break;
    case PH_STOP: end_stop(i); break;
    default: break;
    }
    update_lines(i);
}

static uint64_t i2c_next_event(void *self)
{
    const stm32_i2c_t *i = self;
    return i->phase == PH_NONE ? MMIO_NEVER : i->phase_end;
}

static void i2c_advance(void *self, uint64_t now)
{
    stm32_i2c_t *i = self;
    while (i->phase != PH_NONE && i->phase_end <= now) {
        i->now = i->phase_end;
        step(i);
    }
    if (now > i->now) i->now = now;
}

/* Reading DR (27.6.5): RxNE cleared; a byte held by BTF moves in. */
static uint8_t read_dr(stm32_i2c_t *i)
{
    uint8_t v = i->dr;
    i->sr1 &= ~SR1_RXNE;
    if (i->rx_held) {
        i->dr = i->shift;
        i->rx_held = false;
        i->sr1 = (i->sr1 & ~SR1_BTF) | SR1_RXNE;
        if ((i->sr2 & SR2_MSL) && i->phase == PH_NONE) after_byte(i, i->rx_ack);
    }
    return v;
}

/* Writing DR: the address after SB, or a data byte (transmitter). */
static void write_dr(stm32_i2c_t *i, uint8_t v)
{
    if ((i->sr1 & SR1_SB) && i->sr1_read) {
        i->sr1 &= ~SR1_SB;
        i->sr1_read = false;
        i->shift = v;
        begin(i, PH_ADDR, 9);
        return;
    }
    if (!(i->sr2 & SR2_MSL) || !(i->sr2 & SR2_TRA) || (i->sr1 & SR1_ADDR)) { i->dr = v; return; }
    i->sr1 &= ~SR1_BTF;
    if (i->phase == PH_NONE) { i->shift = v; i->sr1 |= SR1_TXE; begin(i, PH_TX, 9); return; }
    i->dr = v;
    i->dr_full = true;
    i->sr1 &= ~SR1_TXE;
}

/* Reading SR2 after SR1 clears ADDR: a transmitter's DR is empty, a receiver starts its first byte. */
static void clear_addr(stm32_i2c_t *i)
{
    i->sr1 &= ~SR1_ADDR;
    i->sr1_read = false;
    if (i->sr2 & SR2_TRA) { i->sr1 |= SR1_TXE; return; }
    begin(i, PH_RX, 9);
}

static mmio_status_t i2c_read(void *self, uint32_t off, unsigned size, uint32_t *value)
{
    stm32_i2c_t *i = self;
    uint32_t w = off & ~3u, v;
    if (!stm32_access_ok(off, size) || w > TRISE) return MMIO_UNMODELED;
    switch (w) {
    case CR1: v = i->cr1; break;
    case CR2: v = i->cr2; break;
    case OAR1: v = i->oar1; break;
    case OAR2: v = i->oar2; break;
    case DR: v = read_dr(i); break;
    case SR1: v = i->sr1; i->sr1_read = true; break;
    case SR2:
        v = i->sr2;
        if ((i->sr1 & SR1_ADDR) && i->sr1_read) clear_addr(i);
        break;
    case CCR: v = i->ccr; break;
    default: v = i->trise; break;
    }
    update_lines(i);
    *value = stm32_read_lanes(v, off, size);
    return MMIO_OK;
}

static void i2c_reset_regs(stm32_i2c_t *i)
{
    i->cr1 = i->cr2 = i->oar1 = i->oar2 = i->sr1 = i->sr2 = i->ccr = 0;
    i->trise = 0x0002u; /* 27.6.9 */
    i->dr = i->shift = 0;
    i->phase = PH_NONE;
    i->dr_full = i->rx_held = i->sr1_read = false;
    i->cur = -1;
}

static mmio_status_t write_cr1(stm32_i2c_t *i, uint32_t v)
{
    if (v & CR1_SWRST) { i2c_reset_regs(i); i->cr1 = CR1_SWRST; return MMIO_OK; }
    mmio_status_t st = (v & CR1_UNMODELED) ? MMIO_UNMODELED : MMIO_OK;
    uint32_t old = i->cr1;
    i->cr1 = v & 0xFFFFu & ~CR1_UNMODELED;
    if (!(v & CR1_PE)) { /* disabled: the bus released, the flags cleared */
        i->sr1 = i->sr2 = 0;
        i->phase = PH_NONE;
        i->cr1 &= ~(CR1_START | CR1_STOP);
        return st;
    }
    if ((v & CR1_START) && !(old & CR1_START) && i->phase == PH_NONE && !(i->sr1 & SR1_SB))
        if (!(i->sr2 & SR2_BUSY) || (i->sr2 & SR2_MSL)) begin(i, PH_START, 1); /* (repeated) start */
    if ((v & CR1_STOP) && i->phase == PH_NONE && (i->sr2 & SR2_MSL) && !(i->sr1 & SR1_ADDR))
        begin(i, PH_STOP, 1);
    return st;
}

static mmio_status_t i2c_write(void *self, uint32_t off, unsigned size, uint32_t value)
{
    stm32_i2c_t *i = self;
    uint32_t w = off & ~3u, v = stm32_write_lanes(value, size);
    mmio_status_t st = MMIO_OK;
    if (!stm32_access_ok(off, size) || w > TRISE) return MMIO_UNMODELED;
    switch (w) {
    case CR1: st = write_cr1(i, v); break;
    case CR2:
        i->cr2 = v & 0x1F3Fu;
        if (v & CR2_LAST) st = MMIO_UNMODELED;
        break;
    case OAR1: i->oar1 = v & 0xC3FFu; break;
    case OAR2: i->oar2 = v & 0xFFu; break;
    case DR: write_dr(i, (uint8_t)v); break;
    case SR1: i->sr1 &= (v & SR1_ERRORS) | ~SR1_ERRORS; break;
    case SR2: break; /* read-only */
    case CCR: i->ccr = v & 0xCFFFu; break;
    default: i->trise = v & 0x3Fu; break;
    }
    update_lines(i);
    return st;
}

static void i2c_reset(void *self)
{
    stm32_i2c_t *i = self;
    i2c_reset_regs(i);
    update_lines(i);
}

const mmio_ops_t stm32_i2c_ops = { "I2C", i2c_read, i2c_write, i2c_advance, i2c_next_event, i2c_reset };

void stm32_i2c_init(stm32_i2c_t *i, unsigned index, const mmio_clocks_t *clk, mmio_irq_t irq, mmio_dma_req_t dma,
                    unsigned dma_tx, unsigned dma_rx)
{
    *i = (stm32_i2c_t){ 0 };
    i->index = index;
    i->clk = clk;
    i->irq = irq;
    i->dma = dma;
    i->dma_tx = dma_tx;
    i->dma_rx = dma_rx;
    i2c_reset(i);
}

bool stm32_i2c_attach(stm32_i2c_t *i, stm32_i2c_slave_t s)
{
    if (i->nslaves >= STM32_I2C_SLAVES) return false;
    i->slave[i->nslaves++] = s;
    return true;
}

/* stm32f1_rcc.c - the STM32F1's RCC (stm32f1_rcc.h): RM0008 section 7,
 * registers 7.3.1-7.3.10, clock tree 7.2; start-up times from DS5319. */
#include "arm/stm32f1_rcc.h"

#include <string.h>

#include "arm/stm32f1_reg.h"

/* RCC_CR bits (RM0008 7.3.1) */
#define CR_HSION (1u << 0)
#define CR_HSIRDY (1u << 1)
#define CR_HSITRIM (0x1Fu << 3)
#define CR_HSEON (1u << 16)
#define CR_HSERDY (1u << 17)
#define CR_HSEBYP (1u << 18)
#define CR_CSSON (1u << 19)
#define CR_PLLON (1u << 24)
#define CR_PLLRDY (1u << 25)
#define CR_RESET 0x00000083u /* HSION, HSIRDY, HSITRIM 16; HSICAL (factory, per chip) read as 0 */
/* RCC_CFGR fields (RM0008 7.3.2) */
#define CFGR_SW 0x3u
#define CFGR_SWS_SHIFT 2
#define CFGR_PLL_CFG (0xFu << 18 | 1u << 17 | 1u << 16) /* PLLMUL, PLLXTPRE, PLLSRC */
#define CFGR_MCO (0x7u << 24)
#define CFGR_WMASK 0x07FFFFF3u
/* RCC_CIR (RM0008 7.3.3): flags 0-4 (LSI, LSE, HSI, HSE, PLL ready), 7 CSS;
 * enables 8-12; clear bits 16-20, 23 */
#define CIR_FLAGS 0x9Fu
#define CIR_IE (0x1Fu << 8)
#define RDY_LSI 0
#define RDY_LSE 1
#define RDY_HSI 2
#define RDY_HSE 3
#define RDY_PLL 4
/* enable/reset bits that exist on the F10x family (RM0008 7.3.4-7.3.8) */
#define APB2_BITS 0x0038FFFDu
#define APB1_BITS 0x7AFEC9FFu
#define AHB_BITS 0x00000557u
#define AHBENR_RESET 0x00000014u /* SRAMEN, FLITFEN */
/* RCC_BDCR (7.3.9) and RCC_CSR (7.3.10) */
#define BDCR_LSEON (1u << 0)
#define BDCR_LSERDY (1u << 1)
#define BDCR_LSEBYP (1u << 2)
#define BDCR_WMASK 0x00018305u
#define CSR_LSION (1u << 0)
#define CSR_LSIRDY (1u << 1)
#define CSR_RMVF (1u << 24)
#define CSR_FLAGS 0xFC000000u

/* Start-up times, ns (DS5319, the STM32F103x8/B datasheet, section 5.3:
 * the HSE, LSE, HSI and LSI oscillator and the PLL characteristics): tsu(HSI) 2 us
 * max, tSU(HSE) 2 ms typical for a crystal (an external clock on HSEBYP is
 * ready at once), tLOCK 200 us max, tsu(LSI) 85 us max, tSU(LSE) 3 s
 * typical. */
#define HSI_STARTUP_NS 2000u
#define HSE_STARTUP_NS 2000000u
#define PLL_LOCK_NS 200000u
#define LSI_STARTUP_NS 85000u
#define LSE_STARTUP_NS 3000000000u

static uint64_t after_ns(const stm32f1_rcc_t *r, uint64_t ns)
{
    return r->now + stm32f1_cycles_for(ns, 1000000000u, r->clocks.hclk);
}

static uint32_t pll_hz(const stm32f1_rcc_t *r)
{
    uint32_t mul = ((r->cfgr >> 18) & 0xFu) + 2u; /* 0000: x2 ... 1110: x16 */
    if (mul > 16) mul = 16;                        /* 1111: x16 */
    uint32_t in = STM32F1_HSI_HZ / 2;               /* PLLSRC 0: HSI/2 */
    if (r->cfgr & (1u << 16)) in = (r->cfgr & (1u << 17)) ? r->hse_hz / 2 : r->hse_hz;
    return in * mul;
}

/* RM0008 7.2, figure 8: SYSCLK from SWS; AHB, APB1, APB2 and ADC
 * prescalers; a timer's clock is its APB clock x2 unless the APB
 * prescaler is 1. */
static void update_clocks(stm32f1_rcc_t *r)
{
    static const uint16_t hpre[8] = { 2, 4, 8, 16, 64, 128, 256, 512 };
    static const uint8_t ppre[4] = { 2, 4, 8, 16 };
    uint32_t sws = (r->cfgr >> CFGR_SWS_SHIFT) & 3u, sys = STM32F1_HSI_HZ;
    if (sws == 1) sys = r->hse_hz;
    else if (sws == 2) sys = pll_hz(r);
    uint32_t hp = (r->cfgr >> 4) & 0xFu, p1 = (r->cfgr >> 8) & 7u, p2 = (r->cfgr >> 11) & 7u;
    mmio_clocks_t *c = &r->clocks;
    c->sysclk = sys;
    c->hclk = hp & 8u ? sys / hpre[hp & 7u] : sys;
    c->pclk1 = p1 & 4u ? c->hclk / ppre[p1 & 3u] : c->hclk;
    c->pclk2 = p2 & 4u ? c->hclk / ppre[p2 & 3u] : c->hclk;
    c->tim_apb1 = p1 & 4u ? 2 * c->pclk1 : c->pclk1;
    c->tim_apb2 = p2 & 4u ? 2 * c->pclk2 : c->pclk2;
    c->adcclk = c->pclk2 / (2u * (((r->cfgr >> 14) & 3u) + 1u)); /* ADCPRE: /2 /4 /6 /8 */
}

static int source_ready(const stm32f1_rcc_t *r, uint32_t sw)
{
    if (sw == 0) return (r->cr & CR_HSIRDY) != 0;
    if (sw == 1) return (r->cr & CR_HSERDY) != 0;
    if (sw == 2) return (r->cr & CR_PLLRDY) != 0;
    return 0; /* 11: not allowed */
}

/* RM0008 7.2.6: the switch to SW's source happens when it is ready. */
static void try_switch(stm32f1_rcc_t *r)
{
    uint32_t sw = r->cfgr & CFGR_SW;
    if (((r->cfgr >> CFGR_SWS_SHIFT) & 3u) == sw || !source_ready(r, sw)) return;
    r->cfgr = (r->cfgr & ~(3u << CFGR_SWS_SHIFT)) | sw << CFGR_SWS_SHIFT;
    update_clocks(r);
}

static void update_irq(stm32f1_rcc_t *r)
{
    if (r->irq.set) r->irq.set(r->irq.ctx, STM32F1_RCC_IRQ, (r->cir & (r->cir >> 8) & 0x1Fu) != 0);
}

/* An oscillator became ready: its flag in CIR if its interrupt is enabled (7.3.3). */
static void ready(stm32f1_rcc_t *r, unsigned which)
{
    if (r->cir & (1u << (8 + which))) r->cir |= 1u << which;
}

/* The PLL's input (HSI/2 or HSE) runs (RM0008 7.2.3). */
static int pll_input_ready(const stm32f1_rcc_t *r)
{
    return (r->cfgr & (1u << 16)) ? (r->cr & CR_HSERDY) != 0 : (r->cr & CR_HSIRDY) != 0;
}

static void rcc_advance(void *self, uint64_t now)
{
    stm32f1_rcc_t *r = self;
    if (now < r->now) return;
    r->now = now;
    if (r->hsi_at <= now) r->cr |= CR_HSIRDY, r->hsi_at = MMIO_NEVER, ready(r, RDY_HSI);
    if (r->hse_at <= now) r->cr |= CR_HSERDY, r->hse_at = MMIO_NEVER, ready(r, RDY_HSE);
    if (r->pll_at <= now) {
        r->pll_at = MMIO_NEVER;
        if (pll_input_ready(r)) r->cr |= CR_PLLRDY, ready(r, RDY_PLL);
        else r->pll_waits = 1; /* no input clock: it locks once its source is ready */
    }
    if (r->pll_waits && (r->cr & CR_PLLON) && pll_input_ready(r)) r->pll_waits = 0, r->pll_at = after_ns(r, PLL_LOCK_NS);
    if (r->lsi_at <= now) r->csr |= CSR_LSIRDY, r->lsi_at = MMIO_NEVER, ready(r, RDY_LSI);
    if (r->lse_at <= now) r->bdcr |= BDCR_LSERDY, r->lse_at = MMIO_NEVER, ready(r, RDY_LSE);
    try_switch(r);
    update_irq(r);
}

static uint64_t rcc_next_event(void *self)
{
    const stm32f1_rcc_t *r = self;
    uint64_t t = r->hsi_at;
    if (r->hse_at < t) t = r->hse_at;
    if (r->pll_at < t) t = r->pll_at;
    if (r->lsi_at < t) t = r->lsi_at;
    if (r->lse_at < t) t = r->lse_at;
    return t;
}

/* The system reset (RM0008 7.1.2): every register to its reset value but
 * CSR's reset flags and the backup domain (BDCR). */
static void rcc_reset(void *self)
{
    stm32f1_rcc_t *r = self;
    r->cr = CR_RESET;
    r->cfgr = r->cir = r->apb2rstr = r->apb1rstr = r->apb2enr = r->apb1enr = 0;
    r->ahbenr = AHBENR_RESET;
    r->csr &= CSR_FLAGS;
    r->hsi_at = r->hse_at = r->pll_at = r->lsi_at = MMIO_NEVER;
    r->pll_waits = 0;
    update_clocks(r);
    update_irq(r);
}

void stm32f1_rcc_init(stm32f1_rcc_t *r, uint32_t hse_hz, mmio_irq_t irq)
{
    memset(r, 0, sizeof *r);
    r->hse_hz = hse_hz;
    r->irq = irq;
    r->lse_at = MMIO_NEVER;
    r->csr = 1u << STM32F1_RST_POR | 1u << STM32F1_RST_PIN; /* reset value 0x0C000000 */
    rcc_reset(r);
}

const mmio_clocks_t *stm32f1_rcc_clocks(const stm32f1_rcc_t *r) { return &r->clocks; }

void stm32f1_rcc_reset_cause(stm32f1_rcc_t *r, stm32f1_reset_cause_t cause) { r->csr |= 1u << cause; }

void stm32f1_rcc_lsi_force(stm32f1_rcc_t *r)
{
    if (r->csr & CSR_LSION) return;
    r->csr |= CSR_LSION;
    r->lsi_at = after_ns(r, LSI_STARTUP_NS);
}

/* An oscillator's enable bit written: start-up from now, or off at once
 * (RM0008: the ready bit falls within a few of its cycles). */
static void osc(stm32f1_rcc_t *r, uint32_t *reg, uint32_t on, uint32_t rdy, int was, uint64_t *at, uint64_t ns)
{
    int is = (*reg & on) != 0;
    if (is && !was) *at = after_ns(r, ns);
    if (!is) *reg &= ~rdy, *at = MMIO_NEVER;
}

/* RM0008 7.3.1: HSI, HSE and the PLL cannot be stopped while they clock
 * the system (HSI and HSE also while they feed the PLL that does); HSEBYP
 * only changes while HSE is off. */
static mmio_status_t write_cr(stm32f1_rcc_t *r, uint32_t v, uint32_t mask)
{
    uint32_t old = r->cr, sws = (r->cfgr >> CFGR_SWS_SHIFT) & 3u;
    uint32_t keep = 0, pllsrc_hse = (r->cfgr >> 16) & 1u;
    int pll_sys = sws == 2;
    if (sws == 0 || (pll_sys && !pllsrc_hse)) keep |= CR_HSION;
    if (sws == 1 || (pll_sys && pllsrc_hse)) keep |= CR_HSEON;
    if (pll_sys) keep |= CR_PLLON;
    uint32_t wmask = CR_HSION | CR_HSITRIM | CR_HSEON | CR_CSSON | CR_PLLON;
    if (!(old & CR_HSEON)) wmask |= CR_HSEBYP;
    r->cr = stm32f1_reg_merge(r->cr, v, mask, wmask) | (old & keep);
    osc(r, &r->cr, CR_HSION, CR_HSIRDY, (old & CR_HSION) != 0, &r->hsi_at, HSI_STARTUP_NS);
    osc(r, &r->cr, CR_HSEON, CR_HSERDY, (old & CR_HSEON) != 0, &r->hse_at, (r->cr & CR_HSEBYP) ? 0 : HSE_STARTUP_NS);
    if (!r->hse_hz) r->hse_at = MMIO_NEVER; /* no crystal on the board: HSE never starts */
    osc(r, &r->cr, CR_PLLON, CR_PLLRDY, (old & CR_PLLON) != 0, &r->pll_at, PLL_LOCK_NS);
    if (!(r->cr & CR_PLLON)) r->pll_waits = 0;
    rcc_advance(r, r->now); /* a start-up of 0 ns is ready now */
    return (r->cr & CR_CSSON) ? MMIO_UNMODELED : MMIO_OK; /* the clock security system */
}

/* RM0008 7.3.2: PLLSRC, PLLXTPRE and PLLMUL only change with the PLL off. */
static mmio_status_t write_cfgr(stm32f1_rcc_t *r, uint32_t v, uint32_t mask)
{
    uint32_t wmask = CFGR_WMASK & ~(0x3u << CFGR_SWS_SHIFT);
    if (r->cr & CR_PLLON) wmask &= ~CFGR_PLL_CFG;
    if ((v & mask & CFGR_SW) == 3u) wmask &= ~CFGR_SW; /* SW 11: not allowed, kept */
    r->cfgr = stm32f1_reg_merge(r->cfgr, v, mask, wmask);
    update_clocks(r);
    try_switch(r);
    return (r->cfgr & CFGR_MCO) ? MMIO_UNMODELED : MMIO_OK; /* the MCO pin's output */
}

static void write_cir(stm32f1_rcc_t *r, uint32_t v, uint32_t mask)
{
    r->cir = stm32f1_reg_merge(r->cir, v, mask, CIR_IE);
    r->cir &= ~((v & mask) >> 16 & CIR_FLAGS); /* LSIRDYC..PLLRDYC, CSSC */
    update_irq(r);
}

/* A reset bit newly set resets the peripherals it holds (RM0008 7.3.4). */
static void write_rstr(stm32f1_rcc_t *r, uint32_t *reg, stm32f1_bus_t bus, uint32_t v, uint32_t mask, uint32_t bits)
{
    uint32_t rising = ~*reg & (v & mask & bits);
    *reg = stm32f1_reg_merge(*reg, v, mask, bits);
    for (unsigned i = 0; i < r->ngates; i++) {
        stm32f1_gate_t *g = r->gates[i];
        if (g->bus == bus && (rising & g->bit) && g->ops->reset) g->ops->reset(g->self);
    }
}

static void write_bdcr(stm32f1_rcc_t *r, uint32_t v, uint32_t mask)
{
    uint32_t old = r->bdcr, wmask = BDCR_WMASK;
    if (old & BDCR_LSEON) wmask &= ~BDCR_LSEBYP;
    r->bdcr = stm32f1_reg_merge(r->bdcr, v, mask, wmask);
    if (r->bdcr & (1u << 16)) r->bdcr = 1u << 16; /* BDRST: the backup domain reset */
    osc(r, &r->bdcr, BDCR_LSEON, BDCR_LSERDY, (old & BDCR_LSEON) != 0, &r->lse_at,
        (r->bdcr & BDCR_LSEBYP) ? 0 : LSE_STARTUP_NS);
}

static void write_csr(stm32f1_rcc_t *r, uint32_t v, uint32_t mask)
{
    uint32_t old = r->csr;
    r->csr = stm32f1_reg_merge(r->csr, v, mask, CSR_LSION);
    if (v & mask & CSR_RMVF) r->csr &= ~CSR_FLAGS;
    osc(r, &r->csr, CSR_LSION, CSR_LSIRDY, (old & CSR_LSION) != 0, &r->lsi_at, LSI_STARTUP_NS);
}

static mmio_status_t rcc_write(void *self, uint32_t off, unsigned size, uint32_t value)
{
    stm32f1_rcc_t *r = self;
    uint32_t v = stm32f1_reg_wvalue(off, size, value), m = stm32f1_reg_mask(off, size);
    mmio_status_t st = MMIO_OK;
    switch (stm32f1_reg_word(off)) {
    case 0x00: st = write_cr(r, v, m); break;
    case 0x04: st = write_cfgr(r, v, m); break;
    case 0x08: write_cir(r, v, m); break;
    case 0x0C: write_rstr(r, &r->apb2rstr, STM32F1_APB2, v, m, APB2_BITS); break;
    case 0x10: write_rstr(r, &r->apb1rstr, STM32F1_APB1, v, m, APB1_BITS); break;
    case 0x14: r->ahbenr = stm32f1_reg_merge(r->ahbenr, v, m, AHB_BITS); break;
    case 0x18: r->apb2enr = stm32f1_reg_merge(r->apb2enr, v, m, APB2_BITS); break;
    case 0x1C: r->apb1enr = stm32f1_reg_merge(r->apb1enr, v, m, APB1_BITS); break;
    case 0x20: write_bdcr(r, v, m); break;
    case 0x24: write_csr(r, v, m); break;
    default: return MMIO_UNMODELED; /* AHBRSTR, CFGR2: connectivity line only */
    }
    rcc_advance(r, r->now);
    return st;
}

static mmio_status_t rcc_read(void *self, uint32_t off, unsigned size, uint32_t *value)
{
    const stm32f1_rcc_t *r = self;
    uint32_t reg;
    switch (stm32f1_reg_word(off)) {
    case 0x00: reg = r->cr; break;
    case 0x04: reg = r->cfgr; break;
    case 0x08: reg = r->cir; break;
    case 0x0C: reg = r->apb2rstr; break;
    case 0x10: reg = r->apb1rstr; break;
    case 0x14: reg = r->ahbenr; break;
    case 0x18: reg = r->apb2enr; break;
    case 0x1C: reg = r->apb1enr; break;
    case 0x20: reg = r->bdcr; break;
    case 0x24: reg = r->csr; break;
    default: return MMIO_UNMODELED;
    }
    *value = stm32f1_reg_rvalue(off, size, reg);
    return MMIO_OK;
}

const mmio_ops_t stm32f1_rcc_ops = {
    .name = "RCC", .read = rcc_read, .write = rcc_write,
    .advance = rcc_advance, .next_event = rcc_next_event, .reset = rcc_reset,
};

int stm32f1_rcc_enabled(const stm32f1_rcc_t *r, stm32f1_bus_t bus, uint32_t bit)
{
    uint32_t en = bus == STM32F1_AHB ? r->ahbenr : bus == STM32F1_APB1 ? r->apb1enr : r->apb2enr;
    return (en & bit) != 0;
}

/* ---- the clock gate ---- */

int stm32f1_gate_init(stm32f1_gate_t *g, stm32f1_rcc_t *r, stm32f1_bus_t bus, uint32_t bit,
                      const mmio_ops_t *ops, void *self)
{
    if (r->ngates >= STM32F1_RCC_GATES) return -1;
    *g = (stm32f1_gate_t){ .rcc = r, .bus = bus, .bit = bit, .ops = ops, .self = self };
    g->bus_ops = stm32f1_gate_ops;
    g->bus_ops.name = ops->name;
    if (!ops->advance) g->bus_ops.advance = NULL;       /* the core then skips it when it looks for events (armcore.c advance_due) */
    if (!ops->next_event) g->bus_ops.next_event = NULL;
    r->gates[r->ngates++] = g;
    return 0;
}

static mmio_status_t gate_read(void *self, uint32_t off, unsigned size, uint32_t *value)
{
    stm32f1_gate_t *g = self;
    if (stm32f1_rcc_enabled(g->rcc, g->bus, g->bit)) return g->ops->read(g->self, off, size, value);
    g->off_reads++, g->rcc->gated++;
    *value = 0; /* a peripheral without its clock reads 0 */
    return MMIO_OK;
}

static mmio_status_t gate_write(void *self, uint32_t off, unsigned size, uint32_t value)
{
    stm32f1_gate_t *g = self;
    if (stm32f1_rcc_enabled(g->rcc, g->bus, g->bit)) return g->ops->write(g->self, off, size, value);
    g->off_writes++, g->rcc->gated++; /* and drops the write */
    return MMIO_OK;
}

static void gate_advance(void *self, uint64_t now)
{
    stm32f1_gate_t *g = self;
    if (g->ops->advance) g->ops->advance(g->self, now);
}

static uint64_t gate_next_event(void *self)
{
    stm32f1_gate_t *g = self;
    return g->ops->next_event ? g->ops->next_event(g->self) : MMIO_NEVER;
}

static void gate_reset(void *self)
{
    stm32f1_gate_t *g = self;
    if (g->ops->reset) g->ops->reset(g->self);
}

const mmio_ops_t stm32f1_gate_ops = {
    .name = "gate", .read = gate_read, .write = gate_write,
    .advance = gate_advance, .next_event = gate_next_event, .reset = gate_reset,
};

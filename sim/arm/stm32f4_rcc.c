/* stm32f4_rcc.c - STM32F4 RCC: RM0090 rev 19 section 6 (6.2 clock tree,
 * figure 21; 6.2.3 PLL configuration: f(VCO) = f(PLL in) x N / M, PLLCLK =
 * VCO / P, PLL48CK = VCO / Q, with 2 <= M <= 63, 50 <= N <= 432, Q >= 2, VCO
 * input 1-2 MHz, VCO output 100-432 MHz; 6.2.6 system clock switch; 6.3
 * registers and reset values) and RM0383 rev 3 section 6 for the F411.
 *
 * Modeled: CR (HSION/HSIRDY, HSEON/HSERDY/HSEBYP, PLLON/PLLRDY,
 * PLLI2SON/PLLI2SRDY; HSITRIM stored), PLLCFGR, CFGR (SW/SWS, HPRE, PPRE1,
 * PPRE2; RTCPRE, MCO1/2 and their prescalers, I2SSRC stored), the RSTR, ENR
 * and LPENR registers (stored and read back; a peripheral's clock gate is
 * the board's), BDCR (LSEON/LSERDY; the rest stored), CSR (LSION/LSIRDY,
 * the reset flags, RMVF). A source in use as the system clock (directly or
 * through the PLL) cannot be switched off (6.3.1).
 * Not modeled (a write that sets them answers MMIO_UNMODELED): CIR's ready
 * interrupts (RCC IRQ 5) and CSSON (clock security), SSCGR (spread
 * spectrum), PLLI2S's output (its ready bit rises, no I2S clock is
 * derived), F411 DCKCFGR. Stated limits: PLLCFGR written while PLLON is
 * set is ignored and reported (RM0090 6.3.2: "to be written only when the
 * PLL is disabled"); a configuration outside the manual's ranges still
 * locks, at the frequency the formula gives, and the PLLON write that
 * starts it answers MMIO_UNMODELED; the reserved bits of the enable
 * registers read back as written. */
#include "arm/stm32f4_rcc.h"

#include "arm/stm32f1_clk.h"
#include "arm/stm32f4_reg.h"

enum { CR = 0x00, PLLCFGR = 0x04, CFGR = 0x08, CIR = 0x0C, AHB1RSTR = 0x10, AHB2RSTR = 0x14, AHB3RSTR = 0x18,
       APB1RSTR = 0x20, APB2RSTR = 0x24, AHB1ENR = 0x30, AHB2ENR = 0x34, AHB3ENR = 0x38, APB1ENR = 0x40,
       APB2ENR = 0x44, AHB1LPENR = 0x50, AHB2LPENR = 0x54, AHB3LPENR = 0x58, APB1LPENR = 0x60,
       APB2LPENR = 0x64, BDCR = 0x70, CSR = 0x74, SSCGR = 0x80, PLLI2SCFGR = 0x84, DCKCFGR = 0x8C };
#define R(off) (r->reg[(off) / 4])

/* CR */
#define CR_HSION    (1u << 0)
#define CR_HSITRIM  (0x1Fu << 3)
#define CR_HSEON    (1u << 16)
#define CR_HSEBYP   (1u << 18)
#define CR_CSSON    (1u << 19)
#define CR_PLLON    (1u << 24)
#define CR_PLLI2SON (1u << 26)
/* CFGR */
#define CFGR_SW     3u
#define CFGR_SWS_SHIFT 2
#define SW_HSI 0u
#define SW_HSE 1u
#define SW_PLL 2u
/* PLLCFGR */
#define PLL_SRC_HSE (1u << 22)
#define PLLCFGR_MASK 0x0F437FFFu /* PLLQ, PLLSRC, PLLP, PLLN, PLLM (RM0090 6.3.2) */
/* CSR */
#define CSR_RMVF    (1u << 24)
#define CSR_FLAGS   0xFE000000u /* BORRSTF .. LPWRRSTF */

/* Each oscillator's enable and ready bits and its start-up time in 0.1 us
 * (DS8626 rev 9 6.3.7-6.3.10: HSE tsu(HSE) 2 ms, HSI tsu(HSI) 2.2 us, LSI
 * tsu(LSI) 15 us, LSE tsu(LSE) 2 s, typical; PLL and PLLI2S tLOCK 100 us). */
static const struct { uint32_t off, on, rdy, tenth_us; } osc[STM32F4_OSCS] = {
    [STM32F4_OSC_HSI] = { CR, 1u << 0, 1u << 1, 22u },
    [STM32F4_OSC_HSE] = { CR, 1u << 16, 1u << 17, 20000u },
    [STM32F4_OSC_PLL] = { CR, 1u << 24, 1u << 25, 1000u },
    [STM32F4_OSC_PLLI2S] = { CR, 1u << 26, 1u << 27, 1000u },
    [STM32F4_OSC_LSI] = { CSR, 1u << 0, 1u << 1, 150u },
    [STM32F4_OSC_LSE] = { BDCR, 1u << 0, 1u << 1, 20000000u },
};

static bool osc_ready(const stm32f4_rcc_t *r, int i) { return r->reg[osc[i].off / 4] & osc[i].rdy; }

bool stm32f4_rcc_pll_ready(const stm32f4_rcc_t *r) { return osc_ready(r, STM32F4_OSC_PLL); }

const mmio_clocks_t *stm32f4_rcc_clocks(const stm32f4_rcc_t *r) { return &r->clocks; }

/* The main PLL's outputs from PLLCFGR (RM0090 6.3.2). */
static void pll_config(stm32f4_rcc_t *r)
{
    uint32_t c = R(PLLCFGR);
    unsigned m = c & 0x3Fu, n = (c >> 6) & 0x1FFu, p = 2u * (((c >> 16) & 3u) + 1u), q = (c >> 24) & 0xFu;
    uint64_t in = (c & PLL_SRC_HSE) ? r->hse_hz : STM32F4_HSI_HZ;
    r->pll_bad = m < 2 || n < 50 || n > 432 || q < 2;
    if (!r->pll_bad) {
        uint64_t vin = in / m, vco = in * n / m;
        r->pll_bad = vin < 1000000u || vin > 2000000u || vco < 100000000u || vco > 432000000u;
    }
    r->pll_hz = m ? (uint32_t)(in * n / m / p) : 0;
    r->pll48_hz = (m && q) ? (uint32_t)(in * n / m / q) : 0;
}

static uint32_t ahb_div(uint32_t hpre) { return hpre < 8 ? 1u : hpre < 12 ? 2u << (hpre - 8) : 64u << (hpre - 12); }
static uint32_t apb_div(uint32_t ppre) { return ppre < 4 ? 1u : 2u << (ppre - 4); }

/* The clocks from SWS and the prescalers (RM0090 figure 21). */
static void recompute(stm32f4_rcc_t *r)
{
    uint32_t cfgr = R(CFGR), sws = (cfgr >> CFGR_SWS_SHIFT) & 3u;
    mmio_clocks_t *k = &r->clocks;
    k->sysclk = sws == SW_HSE ? r->hse_hz : sws == SW_PLL ? r->pll_hz : STM32F4_HSI_HZ;
    k->hclk = k->sysclk / ahb_div((cfgr >> 4) & 0xFu);
    uint32_t d1 = apb_div((cfgr >> 10) & 7u), d2 = apb_div((cfgr >> 13) & 7u);
    k->pclk1 = k->hclk / d1;
    k->pclk2 = k->hclk / d2;
    k->tim_apb1 = d1 == 1 ? k->pclk1 : 2 * k->pclk1;
    k->tim_apb2 = d2 == 1 ? k->pclk2 : 2 * k->pclk2;
    k->adcclk = k->pclk2 / 2;
}

/* SWS follows SW once the selected source is ready (RM0090 6.2.6). */
static void switch_sysclk(stm32f4_rcc_t *r)
{
    uint32_t sw = R(CFGR) & CFGR_SW, sws = (R(CFGR) >> CFGR_SWS_SHIFT) & 3u;
    if (sw == 3u || sw == sws) return; /* 11: not allowed, SWS stays */
    int src = sw == SW_HSE ? STM32F4_OSC_HSE : sw == SW_PLL ? STM32F4_OSC_PLL : STM32F4_OSC_HSI;
    if (!osc_ready(r, src)) return;
    R(CFGR) = (R(CFGR) & ~(3u << CFGR_SWS_SHIFT)) | (sw << CFGR_SWS_SHIFT);
    recompute(r);
}

/* An oscillator's enable bit changed: start it (ready after its start-up
 * time) or stop it (ready cleared at once). */
static void osc_enable(stm32f4_rcc_t *r, int i)
{
    uint32_t *reg = &r->reg[osc[i].off / 4];
    bool on = *reg & osc[i].on;
    if (!on) { *reg &= ~osc[i].rdy; r->ready_at[i] = MMIO_NEVER; return; }
    if ((*reg & osc[i].rdy) || r->ready_at[i] != MMIO_NEVER) return;
    if (i == STM32F4_OSC_HSE && r->hse_hz == 0) return; /* no crystal: never ready */
    r->ready_at[i] = stm32_at(r->now, stm32_ticks_to_cycles(osc[i].tenth_us, r->clocks.hclk, 10000000u));
}

static bool pll_input_ready(const stm32f4_rcc_t *r)
{
    return osc_ready(r, (R(PLLCFGR) & PLL_SRC_HSE) ? STM32F4_OSC_HSE : STM32F4_OSC_HSI);
}

static void rcc_advance(void *self, uint64_t now)
{
    stm32f4_rcc_t *r = self;
    if (now > r->now) r->now = now;
    for (int i = 0; i < STM32F4_OSCS; i++) {
        if (r->ready_at[i] > r->now) continue;
        if (i == STM32F4_OSC_PLL && !pll_input_ready(r)) continue; /* locks once its input runs */
        r->reg[osc[i].off / 4] |= osc[i].rdy;
        r->ready_at[i] = MMIO_NEVER;
    }
    switch_sysclk(r);
}

static uint64_t rcc_next_event(void *self)
{
    const stm32f4_rcc_t *r = self;
    uint64_t t = MMIO_NEVER;
    for (int i = 0; i < STM32F4_OSCS; i++)
        if (r->ready_at[i] < t && (i != STM32F4_OSC_PLL || pll_input_ready(r))) t = r->ready_at[i];
    return t < r->now ? r->now : t;
}

static bool valid(const stm32f4_rcc_t *r, uint32_t off)
{
    switch (off) {
    case CR: case PLLCFGR: case CFGR: case CIR: case AHB1RSTR: case AHB2RSTR: case APB1RSTR: case APB2RSTR:
    case AHB1ENR: case AHB2ENR: case APB1ENR: case APB2ENR: case AHB1LPENR: case AHB2LPENR: case APB1LPENR:
    case APB2LPENR: case BDCR: case CSR: case SSCGR: case PLLI2SCFGR: return true;
    case AHB3RSTR: case AHB3ENR: case AHB3LPENR: return r->part == STM32F4_F405; /* FSMC */
    case DCKCFGR: return r->part == STM32F4_F411;
    default: return false;
    }
}

static mmio_status_t rcc_read(void *self, uint32_t off, unsigned size, uint32_t *value)
{
    stm32f4_rcc_t *r = self;
    if (!stm32_access_ok(off, size) || !valid(r, off & ~3u)) return MMIO_UNMODELED;
    *value = stm32_read_lanes(r->reg[off / 4], off, size);
    return MMIO_OK;
}

/* The system clock's source oscillators, which cannot be stopped (RM0090 6.3.1). */
static uint32_t cr_locked(const stm32f4_rcc_t *r)
{
    uint32_t sws = (R(CFGR) >> CFGR_SWS_SHIFT) & 3u, keep = 0;
    bool pll = sws == SW_PLL;
    if (sws == SW_HSI || (pll && !(R(PLLCFGR) & PLL_SRC_HSE))) keep |= CR_HSION;
    if (sws == SW_HSE || (pll && (R(PLLCFGR) & PLL_SRC_HSE))) keep |= CR_HSEON;
    if (pll) keep |= CR_PLLON;
    return keep;
}

static mmio_status_t write_cr(stm32f4_rcc_t *r, uint32_t v)
{
    mmio_status_t st = MMIO_OK;
    uint32_t old = R(CR), keep = cr_locked(r);
    uint32_t wr = CR_HSION | CR_HSITRIM | CR_HSEON | CR_PLLON | CR_PLLI2SON | CR_CSSON;
    if (old & (1u << 17)) wr &= ~CR_HSEBYP; /* HSEBYP: written only with HSE off (6.3.1) */
    else wr |= CR_HSEBYP;
    uint32_t nv = (old & ~wr) | (v & wr) | (old & keep);
    if (v & CR_CSSON) st = MMIO_UNMODELED;
    if ((nv & CR_PLLON) && !(old & CR_PLLON)) {
        pll_config(r);
        if (r->pll_bad) st = MMIO_UNMODELED;
    }
    R(CR) = nv & ~CR_CSSON;
    for (int i = STM32F4_OSC_HSI; i <= STM32F4_OSC_PLLI2S; i++)
        if ((old ^ nv) & osc[i].on) osc_enable(r, i);
    return st;
}

static mmio_status_t write_reg(stm32f4_rcc_t *r, uint32_t off, uint32_t v)
{
    switch (off) {
    case CR: return write_cr(r, v);
    case PLLCFGR:
        if (R(CR) & CR_PLLON) return MMIO_UNMODELED;
        R(PLLCFGR) = v & PLLCFGR_MASK;
        pll_config(r);
        return MMIO_OK;
    case CFGR:
        R(CFGR) = (v & ~(3u << CFGR_SWS_SHIFT)) | (R(CFGR) & (3u << CFGR_SWS_SHIFT));
        recompute(r);
        switch_sysclk(r);
        return MMIO_OK;
    case CIR: /* ready interrupt enables (bits 8-14) not modeled; the clear bits are write-only */
        R(CIR) = v & 0x00007F00u;
        return (v & 0x00007F00u) ? MMIO_UNMODELED : MMIO_OK;
    case BDCR: {
        uint32_t old = R(BDCR);
        R(BDCR) = (v & ~2u) | (old & 2u);
        if ((old ^ v) & 1u) osc_enable(r, STM32F4_OSC_LSE);
        return MMIO_OK;
    }
    case CSR: {
        uint32_t old = R(CSR);
        R(CSR) = (v & 1u) | (old & (2u | CSR_FLAGS));
        if (v & CSR_RMVF) R(CSR) &= ~CSR_FLAGS; /* RMVF clears the reset flags (6.3.21) */
        if ((old ^ v) & 1u) osc_enable(r, STM32F4_OSC_LSI);
        return MMIO_OK;
    }
    case SSCGR: case DCKCFGR:
        R(off) = v;
        return v ? MMIO_UNMODELED : MMIO_OK;
    default: R(off) = v; return MMIO_OK;
    }
}

static mmio_status_t rcc_write(void *self, uint32_t off, unsigned size, uint32_t value)
{
    stm32f4_rcc_t *r = self;
    if (!stm32_access_ok(off, size) || !valid(r, off & ~3u)) return MMIO_UNMODELED;
    uint32_t w = off & ~3u;
    return write_reg(r, w, stm32f4_merge(r->reg[w / 4], off, size, value));
}

static void rcc_reset(void *self)
{
    stm32f4_rcc_t *r = self;
    bool f405 = r->part == STM32F4_F405;
    for (unsigned i = 0; i < STM32F4_RCC_WORDS; i++) r->reg[i] = 0;
    R(CR) = 0x00000083u;       /* HSION, HSIRDY, HSITRIM 16; HSICAL (factory) reads 0 here */
    R(PLLCFGR) = 0x24003010u;  /* Q 4, P /2, N 192, M 16 (RM0090 6.3.2, RM0383 6.3.2) */
    R(AHB1ENR) = f405 ? 0x00100000u : 0u; /* CCMDATARAMEN on the F405 (6.3.10) */
    /* low-power enables: RM0090 6.3.15-6.3.18, RM0383 6.3.13-6.3.16 */
    R(AHB1LPENR) = f405 ? 0x7E6791FFu : 0x0061900Fu;
    R(AHB2LPENR) = f405 ? 0x000000F1u : 0x00000080u;
    R(AHB3LPENR) = f405 ? 0x00000001u : 0u;
    R(APB1LPENR) = f405 ? 0x36FEC9FFu : 0x10E2C80Fu;
    R(APB2LPENR) = f405 ? 0x00075F33u : 0x00077930u;
    R(CSR) = 0x0E000000u;      /* PINRSTF, PORRSTF, BORRSTF after power-on (6.3.21) */
    R(PLLI2SCFGR) = 0x20003000u;
    for (int i = 0; i < STM32F4_OSCS; i++) r->ready_at[i] = MMIO_NEVER;
    pll_config(r);
    recompute(r);
}

const mmio_ops_t stm32f4_rcc_ops = { "RCC", rcc_read, rcc_write, rcc_advance, rcc_next_event, rcc_reset };

void stm32f4_rcc_init(stm32f4_rcc_t *r, stm32f4_part_t part, uint32_t hse_hz)
{
    *r = (stm32f4_rcc_t){ 0 };
    r->part = part;
    r->hse_hz = hse_hz;
    rcc_reset(r);
}

/* stm32f1_gpio.c - a GPIO port (stm32f1_gpio.h): RM0008 9.1, 9.2.1-9.2.7. */
#include "arm/stm32f1_gpio.h"

#include <string.h>

#include "arm/stm32f1_reg.h"

#define CR_RESET 0x44444444u /* every pin: input floating (RM0008 9.2.1, 9.2.2) */
#define LCKK (1u << 16)

/* A pin's 4-bit configuration: MODE 1:0, CNF 3:2. */
static unsigned cfg(const stm32f1_gpio_t *g, unsigned pin)
{
    return ((pin < 8 ? g->crl : g->crh) >> (4 * (pin % 8))) & 0xFu;
}

stm32f1_pin_t stm32f1_gpio_pin(const stm32f1_gpio_t *g, unsigned pin)
{
    stm32f1_pin_t p = { 0 };
    if (pin >= 16) return p;
    unsigned c = cfg(g, pin), mode = c & 3u, cnf = c >> 2;
    int out = (g->odr >> pin) & 1u, ext = g->ext[pin];
    p.output = mode != 0;
    if (p.output) {
        p.af = (cnf & 2u) != 0, p.open_drain = (cnf & 1u) != 0;
        int drive = p.af ? g->af_level[pin] : out;
        p.driven = !p.open_drain || drive == 0;
        p.level = p.driven ? drive : ext > 0;
    } else {
        p.analog = cnf == 0;
        if (ext >= 0) p.level = ext;
        else p.level = cnf == 2 ? out : 0; /* the pull (ODR selects up or down), else a float read low */
    }
    return p;
}

static uint32_t idr(const stm32f1_gpio_t *g)
{
    uint32_t v = g->level;
    for (unsigned pin = 0; pin < 16; pin++)
        if (cfg(g, pin) == 0) v &= ~(1u << pin); /* analog input: the Schmitt trigger is off, reads 0 */
    return v;
}

/* Recompute the levels; tell the board about each pin's change and EXTI
 * about each input data bit's (what EXTI sees: RM0008 figure 13). */
static void update(stm32f1_gpio_t *g)
{
    uint16_t now = 0;
    for (unsigned pin = 0; pin < 16; pin++)
        if (stm32f1_gpio_pin(g, pin).level) now |= (uint16_t)(1u << pin);
    uint16_t changed = now ^ g->level;
    g->level = now;
    uint16_t idr_now = (uint16_t)idr(g), idr_changed = idr_now ^ g->idr_seen;
    g->idr_seen = idr_now;
    for (unsigned pin = 0; (changed | idr_changed) && pin < 16; pin++) {
        if (((idr_changed >> pin) & 1u) && g->exti) stm32f1_exti_pin(g->exti, g->port, pin, (idr_now >> pin) & 1u);
        if (((changed >> pin) & 1u) && g->on_change) g->on_change(g->ctx, g->port, pin, (now >> pin) & 1u);
    }
}

static void gpio_reset(void *self)
{
    stm32f1_gpio_t *g = self;
    g->crl = g->crh = CR_RESET;
    g->odr = g->lckr = 0;
    g->lck_step = 0;
    memset(g->af_level, 0, sizeof g->af_level);
    update(g);
}

void stm32f1_gpio_init(stm32f1_gpio_t *g, unsigned port, stm32f1_exti_t *exti)
{
    memset(g, 0, sizeof *g);
    g->port = port, g->exti = exti;
    memset(g->ext, STM32F1_DRIVE_FLOAT, sizeof g->ext);
    gpio_reset(g);
    for (unsigned pin = 0; exti && pin < 16; pin++) stm32f1_exti_pin(exti, port, pin, (g->idr_seen >> pin) & 1u);
}

void stm32f1_gpio_on_change(stm32f1_gpio_t *g, stm32f1_pin_cb cb, void *ctx) { g->on_change = cb, g->ctx = ctx; }

void stm32f1_gpio_drive(stm32f1_gpio_t *g, unsigned pin, stm32f1_drive_t d)
{
    if (pin >= 16) return;
    g->ext[pin] = (int8_t)d;
    update(g);
}

void stm32f1_gpio_af_level(stm32f1_gpio_t *g, unsigned pin, int level)
{
    if (pin >= 16) return;
    g->af_level[pin] = level != 0;
    update(g);
}

/* The 4-bit fields of the locked pins (LCKR) within CRL (half 0) or CRH (1). */
static uint32_t locked_fields(const stm32f1_gpio_t *g, unsigned half)
{
    uint32_t m = 0;
    if (!(g->lckr & LCKK)) return 0;
    for (unsigned i = 0; i < 8; i++)
        if ((g->lckr >> (8 * half + i)) & 1u) m |= 0xFu << (4 * i);
    return m;
}

/* RM0008 9.2.7: write LCKK=1, 0, 1 with the same LCK[15:0], then read 0:
 * the configuration of the LCK pins is frozen until reset (LCKK reads 1). */
static void write_lckr(stm32f1_gpio_t *g, uint32_t v)
{
    static const int want_lckk[3] = { 1, 0, 1 };
    if (g->lckr & LCKK) return;
    int k = (v & LCKK) != 0, same = g->lck_step == 0 || (v & 0xFFFFu) == (g->lckr & 0xFFFFu);
    if (g->lck_step < 3 && k == want_lckk[g->lck_step] && same) g->lck_step++;
    else g->lck_step = k ? 1 : 0;
    g->lckr = v & 0xFFFFu; /* LCKK itself rises only at the sequence's read */
}

static mmio_status_t gpio_write(void *self, uint32_t off, unsigned size, uint32_t value)
{
    stm32f1_gpio_t *g = self;
    uint32_t v = stm32f1_reg_wvalue(off, size, value), m = stm32f1_reg_mask(off, size);
    mmio_status_t st = MMIO_OK;
    switch (stm32f1_reg_word(off)) {
    case 0x00: g->crl = stm32f1_reg_merge(g->crl, v, m, ~locked_fields(g, 0)); break;
    case 0x04: g->crh = stm32f1_reg_merge(g->crh, v, m, ~locked_fields(g, 1)); break;
    case 0x08: return MMIO_OK; /* IDR: read-only */
    case 0x0C: g->odr = stm32f1_reg_merge(g->odr, v, m, 0xFFFFu); break;
    case 0x10: { /* BSRR: BSx wins over BRx (RM0008 9.2.5) */
        uint32_t w = v & m;
        g->odr = (g->odr & ~(w >> 16)) | (w & 0xFFFFu);
        break;
    }
    case 0x14: g->odr &= ~(v & m & 0xFFFFu); break;
    case 0x18:
        if (m != 0xFFFFFFFFu) return MMIO_UNMODELED; /* the lock sequence takes word writes */
        write_lckr(g, v);
        break;
    default: return MMIO_UNMODELED;
    }
    for (unsigned pin = 0; pin < 16; pin++)
        if ((cfg(g, pin) & 3u) == 0 && cfg(g, pin) >> 2 == 3u) st = MMIO_UNMODELED; /* CNF 11 input: reserved */
    update(g);
    return st;
}

static mmio_status_t gpio_read(void *self, uint32_t off, unsigned size, uint32_t *value)
{
    stm32f1_gpio_t *g = self;
    uint32_t reg;
    switch (stm32f1_reg_word(off)) {
    case 0x00: reg = g->crl; break;
    case 0x04: reg = g->crh; break;
    case 0x08: reg = idr(g); break;
    case 0x0C: reg = g->odr; break;
    case 0x10: case 0x14: reg = 0; break; /* BSRR, BRR: write-only, read 0 */
    case 0x18:
        reg = g->lckr;
        if (g->lck_step == 3) g->lckr |= LCKK; /* the sequence's read (LCKK 0): locked from now on */
        g->lck_step = 0;
        break;
    default: return MMIO_UNMODELED;
    }
    *value = stm32f1_reg_rvalue(off, size, reg);
    return MMIO_OK;
}

#define PORT_OPS(n) { .name = n, .read = gpio_read, .write = gpio_write, .reset = gpio_reset }
const mmio_ops_t stm32f1_gpio_ops[STM32F1_GPIO_PORTS] = {
    PORT_OPS("GPIOA"), PORT_OPS("GPIOB"), PORT_OPS("GPIOC"), PORT_OPS("GPIOD"), PORT_OPS("GPIOE"),
};

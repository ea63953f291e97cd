/* stm32f4_gpio.c - STM32F4 GPIO port: RM0090 rev 19 section 8 (8.3.1-8.3.12
 * I/O configurations, figure 26 "basic structure of a five-volt tolerant
 * I/O port bit"; 8.4 registers and reset values) and RM0383 rev 3 section 8.
 *
 * IDR samples the pin through the Schmitt trigger: a push-pull output
 * reads its ODR bit; an open-drain output reads 0 when ODR is 0 and
 * otherwise what the outside or the pull resistor makes of the line; an
 * input (or an alternate function pin, whose output the peripheral drives:
 * the board's) reads the outside's level, or its pull-up/down when nothing
 * drives it; an analog pin reads 0 (the trigger is off, 8.3.12).
 * BSRR sets and resets ODR bits, BSy winning over BRy for the same pin
 * (8.4.7). LCKR's sequence (write 1+key, 0+key, 1+key, read, read)
 * freezes the locked pins' MODER, OTYPER, OSPEEDR, PUPDR, AFRL/AFRH until
 * reset; a wrong sequence aborts it.
 * Stated limits: a floating input with no pull reads 0; output speed and
 * the pins' electrical levels are not modeled (OSPEEDR stored). */
#include "arm/stm32f4_gpio.h"

#include <stddef.h>

#include "arm/stm32f1_clk.h"
#include "arm/stm32f4_reg.h"

enum { MODER = 0x00, OTYPER = 0x04, OSPEEDR = 0x08, PUPDR = 0x0C, IDR = 0x10, ODR = 0x14, BSRR = 0x18,
       LCKR = 0x1C, AFRL = 0x20, AFRH = 0x24 };
#define LCKK (1u << 16)

stm32f4_pin_mode_t stm32f4_gpio_mode(const stm32f4_gpio_t *g, unsigned pin)
{
    return (stm32f4_pin_mode_t)((g->moder >> (2 * pin)) & 3u);
}

unsigned stm32f4_gpio_af(const stm32f4_gpio_t *g, unsigned pin) { return (g->afr[pin / 8] >> (4 * (pin % 8))) & 0xFu; }

int stm32f4_gpio_level(const stm32f4_gpio_t *g, unsigned pin) { return (g->idr >> pin) & 1; }

/* One pin's input level (the rules in the file's comment). */
static int pin_input(const stm32f4_gpio_t *g, unsigned pin)
{
    stm32f4_pin_mode_t m = stm32f4_gpio_mode(g, pin);
    int odr = (g->odr >> pin) & 1;
    if (m == STM32F4_PIN_ANALOG) return 0;
    if (m == STM32F4_PIN_OUTPUT) {
        if (!((g->otyper >> pin) & 1u) || odr == 0) return odr;
    }
    if ((g->ext_driven >> pin) & 1u) return (g->ext_level >> pin) & 1;
    return ((g->pupdr >> (2 * pin)) & 3u) == 1u; /* 01 pull-up; 10 pull-down and 00 floating read 0 */
}

static void update(stm32f4_gpio_t *g)
{
    uint16_t idr = 0;
    for (unsigned p = 0; p < 16; p++) idr |= (uint16_t)(pin_input(g, p) << p);
    uint16_t diff = idr ^ g->idr;
    g->idr = idr;
    for (unsigned p = 0; diff && p < 16; p++)
        if (((diff >> p) & 1u) && g->changed) g->changed(g->ctx, g->port, p, (idr >> p) & 1);
}

void stm32f4_gpio_input(stm32f4_gpio_t *g, unsigned pin, bool driven, int level)
{
    if (pin >= 16) return;
    uint16_t b = (uint16_t)(1u << pin);
    g->ext_driven = driven ? g->ext_driven | b : g->ext_driven & (uint16_t)~b;
    g->ext_level = level ? g->ext_level | b : g->ext_level & (uint16_t)~b;
    update(g);
}

static uint32_t peek(stm32f4_gpio_t *g, uint32_t off)
{
    switch (off) {
    case MODER: return g->moder;
    case OTYPER: return g->otyper;
    case OSPEEDR: return g->ospeedr;
    case PUPDR: return g->pupdr;
    case IDR: return g->idr;
    case ODR: return g->odr;
    case LCKR: return g->lckr;
    case AFRL: return g->afr[0];
    case AFRH: return g->afr[1];
    default: return 0; /* BSRR: write-only, reads 0 */
    }
}

static mmio_status_t gpio_read(void *self, uint32_t off, unsigned size, uint32_t *value)
{
    stm32f4_gpio_t *g = self;
    uint32_t w = off & ~3u;
    if (!stm32_access_ok(off, size) || w > AFRH) return MMIO_UNMODELED;
    if (w == LCKR && g->lock_step == 3) { g->lckr |= LCKK; g->lock_step = 0; } /* the sequence's read */
    *value = stm32_read_lanes(peek(g, w), off, size);
    return MMIO_OK;
}

/* The bits of a 2-bit-per-pin or 4-bit-per-pin register the lock freezes. */
static uint32_t locked_mask(const stm32f4_gpio_t *g, unsigned bits, unsigned first_pin)
{
    uint32_t m = 0, lk = (g->lckr & LCKK) ? g->lckr & 0xFFFFu : 0;
    for (unsigned i = 0; i < 32 / bits; i++)
        if ((lk >> (first_pin + i)) & 1u) m |= ((1u << bits) - 1u) << (bits * i);
    return m;
}

static void set_locked(uint32_t *reg, uint32_t v, uint32_t frozen) { *reg = (*reg & frozen) | (v & ~frozen); }

/* LCKR's write sequence (RM0090 8.4.8): 1+key, 0+key, 1+key, then a read. */
static void write_lckr(stm32f4_gpio_t *g, uint32_t v)
{
    if (g->lckr & LCKK) return; /* locked until reset */
    uint32_t key = v & 0xFFFFu;
    bool k = v & LCKK;
    if (g->lock_step == 0 && k) { g->lckr = key; g->lock_step = 1; return; }
    if (g->lock_step == 1 && !k && key == g->lckr) { g->lock_step = 2; return; }
    if (g->lock_step == 2 && k && key == g->lckr) { g->lock_step = 3; return; }
    g->lock_step = k ? 1 : 0; /* a wrong step aborts; a 1+key starts again */
    g->lckr = key;
}

static mmio_status_t gpio_write(void *self, uint32_t off, unsigned size, uint32_t value)
{
    stm32f4_gpio_t *g = self;
    uint32_t w = off & ~3u;
    if (!stm32_access_ok(off, size) || w > AFRH) return MMIO_UNMODELED;
    uint32_t v = stm32f4_merge(peek(g, w), off, size, value);
    switch (w) {
    case MODER: set_locked(&g->moder, v, locked_mask(g, 2, 0)); break;
    case OTYPER: set_locked(&g->otyper, v & 0xFFFFu, locked_mask(g, 1, 0)); break;
    case OSPEEDR: set_locked(&g->ospeedr, v, locked_mask(g, 2, 0)); break;
    case PUPDR: set_locked(&g->pupdr, v, locked_mask(g, 2, 0)); break;
    case ODR: g->odr = v & 0xFFFFu; break;
    case BSRR: {
        uint32_t b = stm32f4_lane_value(off, size, value); /* only the written half-words act */
        g->odr = (g->odr & ~(b >> 16)) | (b & 0xFFFFu); /* BSy has priority over BRy (8.4.7) */
        break;
    }
    case LCKR: write_lckr(g, v); break;
    case AFRL: set_locked(&g->afr[0], v, locked_mask(g, 4, 0)); break;
    case AFRH: set_locked(&g->afr[1], v, locked_mask(g, 4, 8)); break;
    default: break; /* IDR: read-only */
    }
    update(g);
    return MMIO_OK;
}

static void gpio_reset(void *self)
{
    stm32f4_gpio_t *g = self;
    /* RM0090 8.4.1-8.4.4 (RM0383 the same): the debug pins PA13-15, PB3-4 in AF */
    g->moder = g->port == 0 ? 0xA8000000u : g->port == 1 ? 0x00000280u : 0u;
    g->ospeedr = g->port == 1 ? 0x000000C0u : 0u;
    g->pupdr = g->port == 0 ? 0x64000000u : g->port == 1 ? 0x00000100u : 0u;
    g->otyper = g->odr = g->afr[0] = g->afr[1] = g->lckr = 0;
    g->lock_step = 0;
    update(g);
}

const mmio_ops_t stm32f4_gpio_ops = { "GPIO", gpio_read, gpio_write, NULL, NULL, gpio_reset };

void stm32f4_gpio_init(stm32f4_gpio_t *g, unsigned port, stm32f4_gpio_pin_fn changed, void *ctx)
{
    *g = (stm32f4_gpio_t){ 0 };
    g->port = port;
    g->changed = changed;
    g->ctx = ctx;
    gpio_reset(g); /* the pins that read 1 at power-on (the pulled-up debug pins) are told once */
}

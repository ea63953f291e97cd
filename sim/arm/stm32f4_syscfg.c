/* stm32f4_syscfg.c - STM32F4 SYSCFG (RM0090 rev 19 9.2: MEMRMP reset to the
 * BOOT pins' mode, PMC, EXTICR1-4 four bits per line, CMPCR with READY set
 * while CMP_PD is on) and EXTI (RM0090 12.2 figure 42 and 12.3: an enabled
 * rising or falling edge of a line, or a 1 written to SWIER, sets the line's
 * pending bit when IMR unmasks it; the line's NVIC interrupt stays high
 * until PR is cleared by writing 1, which also clears SWIER; EMR is stored:
 * the event to the core's WFE is the core's).
 * Not modeled (MMIO_UNMODELED on a write that sets them): PMC's
 * MII_RMII_SEL (F407 Ethernet) and ADC1DC2 (F411); MEMRMP's mapping itself
 * is the core's (stm32f4_syscfg_mem_mode). Stated limit: the compensation
 * cell is ready at once. */
#include "arm/stm32f4_syscfg.h"

#include <stddef.h>

#include "arm/stm32f1_clk.h"
#include "arm/stm32f4_reg.h"

enum { MEMRMP = 0x00, PMC = 0x04, EXTICR1 = 0x08, CMPCR = 0x20 };
enum { IMR = 0x00, EMR = 0x04, RTSR = 0x08, FTSR = 0x0C, SWIER = 0x10, PR = 0x14 };
#define LINES_MASK ((1u << STM32F4_EXTI_LINES) - 1u)
#define CMP_PD    1u
#define CMP_READY (1u << 8)

unsigned stm32f4_syscfg_mem_mode(const stm32f4_syscfg_t *s) { return s->memrmp & 3u; }

static bool syscfg_peek(const stm32f4_syscfg_t *s, uint32_t off, uint32_t *v)
{
    if (off == MEMRMP) *v = s->memrmp;
    else if (off == PMC) *v = s->pmc;
    else if (off >= EXTICR1 && off < EXTICR1 + 16) *v = s->exticr[(off - EXTICR1) / 4];
    else if (off == CMPCR) *v = s->cmpcr;
    else return false;
    return true;
}

static mmio_status_t syscfg_read(void *self, uint32_t off, unsigned size, uint32_t *value)
{
    uint32_t v;
    if (!stm32_access_ok(off, size) || !syscfg_peek(self, off & ~3u, &v)) return MMIO_UNMODELED;
    *value = stm32_read_lanes(v, off, size);
    return MMIO_OK;
}

static mmio_status_t syscfg_write(void *self, uint32_t off, unsigned size, uint32_t value)
{
    stm32f4_syscfg_t *s = self;
    uint32_t w = off & ~3u, old;
    if (!stm32_access_ok(off, size) || !syscfg_peek(s, w, &old)) return MMIO_UNMODELED;
    uint32_t v = stm32f4_merge(old, off, size, value);
    if (w == MEMRMP) s->memrmp = v & 3u;
    else if (w == PMC) { s->pmc = v & ((1u << 23) | (1u << 16)); return s->pmc ? MMIO_UNMODELED : MMIO_OK; }
    else if (w == CMPCR) s->cmpcr = (v & CMP_PD) ? CMP_PD | CMP_READY : 0u;
    else s->exticr[(w - EXTICR1) / 4] = v & 0xFFFFu;
    return MMIO_OK;
}

static void syscfg_reset(void *self)
{
    stm32f4_syscfg_t *s = self;
    s->memrmp = s->boot_mode & 3u; /* RM0090 9.2.1: MEM_MODE reset to the BOOT pins' choice */
    s->pmc = s->cmpcr = 0;
    for (int i = 0; i < 4; i++) s->exticr[i] = 0;
}

const mmio_ops_t stm32f4_syscfg_ops = { "SYSCFG", syscfg_read, syscfg_write, NULL, NULL, syscfg_reset };

void stm32f4_syscfg_init(stm32f4_syscfg_t *s, uint32_t boot_mode)
{
    *s = (stm32f4_syscfg_t){ 0 };
    s->boot_mode = boot_mode;
    syscfg_reset(s);
}

/* The NVIC line of each EXTI line (RM0090 table 61) and its group (lines
 * sharing one IRQ). */
static unsigned line_irq(unsigned line)
{
    static const uint8_t hi[7] = { 1, 41, 42, 62, 76, 2, 3 };
    if (line < 5) return 6 + line;
    if (line < 10) return 23;
    if (line < 16) return 40;
    return hi[line - 16];
}

static void update_irq(stm32f4_exti_t *e)
{
    for (unsigned l = 0; l < STM32F4_EXTI_LINES; l++) {
        unsigned irq = line_irq(l);
        bool lv = false;
        for (unsigned k = 0; k < STM32F4_EXTI_LINES; k++)
            if (line_irq(k) == irq && ((e->pr & e->imr) >> k & 1u)) lv = true;
        bool was = (e->irq_out >> l) & 1u;
        if (lv == was) continue;
        for (unsigned k = 0; k < STM32F4_EXTI_LINES; k++) /* every line of the group shares the state */
            if (line_irq(k) == irq) e->irq_out = lv ? e->irq_out | (1u << k) : e->irq_out & ~(1u << k);
        if (e->irq.set) e->irq.set(e->irq.ctx, irq, lv);
    }
}

/* Line `line` now at level: an enabled edge on an unmasked line sets its pending bit. */
static void edge(stm32f4_exti_t *e, unsigned line, int level)
{
    uint32_t b = 1u << line;
    e->lines = level ? e->lines | b : e->lines & ~b;
    bool hit = level ? (e->rtsr & b) : (e->ftsr & b);
    if (hit && (e->imr & b)) e->pr |= b;
    update_irq(e);
}

/* A pin's edge reaches line `pin` when EXTICR selects its port; the edge is
 * the pin's own, so a port selected later starts from its pin's level. */
void stm32f4_exti_pin(void *exti, unsigned port, unsigned pin, int level)
{
    stm32f4_exti_t *e = exti;
    if (port >= STM32F4_EXTI_PORTS || pin >= 16) return;
    uint16_t b = (uint16_t)(1u << pin);
    bool was = e->pins[port] & b;
    e->pins[port] = level ? e->pins[port] | b : e->pins[port] & (uint16_t)~b;
    unsigned sel = (e->syscfg->exticr[pin / 4] >> (4 * (pin % 4))) & 0xFu;
    if (sel == port && was != (level != 0)) edge(e, pin, level);
}

void stm32f4_exti_line(stm32f4_exti_t *e, unsigned line, int level)
{
    if (line < 16 || line >= STM32F4_EXTI_LINES || ((e->lines >> line) & 1u) == (level != 0)) return;
    edge(e, line, level);
}

static uint32_t *exti_reg(stm32f4_exti_t *e, uint32_t off)
{
    switch (off) {
    case IMR: return &e->imr;
    case EMR: return &e->emr;
    case RTSR: return &e->rtsr;
    case FTSR: return &e->ftsr;
    case SWIER: return &e->swier;
    case PR: return &e->pr;
    default: return NULL;
    }
}

static mmio_status_t exti_read(void *self, uint32_t off, unsigned size, uint32_t *value)
{
    uint32_t *r = exti_reg(self, off & ~3u);
    if (!stm32_access_ok(off, size) || !r) return MMIO_UNMODELED;
    *value = stm32_read_lanes(*r, off, size);
    return MMIO_OK;
}

static mmio_status_t exti_write(void *self, uint32_t off, unsigned size, uint32_t value)
{
    stm32f4_exti_t *e = self;
    uint32_t w = off & ~3u, *r = exti_reg(e, w);
    if (!stm32_access_ok(off, size) || !r) return MMIO_UNMODELED;
    if (w == PR) { /* rc_w1; clearing PR also clears SWIER (12.3.6) */
        uint32_t c = stm32f4_lane_value(off, size, value) & LINES_MASK;
        e->pr &= ~c;
        e->swier &= ~c;
    } else if (w == SWIER) { /* a 0 -> 1 write sets the pending bit when unmasked (12.3.5) */
        uint32_t v = stm32f4_merge(e->swier, off, size, value) & LINES_MASK;
        e->pr |= v & ~e->swier & e->imr;
        e->swier = v;
    } else {
        *r = stm32f4_merge(*r, off, size, value) & LINES_MASK;
    }
    update_irq(e);
    return MMIO_OK;
}

static void exti_reset(void *self)
{
    stm32f4_exti_t *e = self;
    e->imr = e->emr = e->rtsr = e->ftsr = e->swier = e->pr = 0;
    update_irq(e);
}

const mmio_ops_t stm32f4_exti_ops = { "EXTI", exti_read, exti_write, NULL, NULL, exti_reset };

void stm32f4_exti_init(stm32f4_exti_t *e, const stm32f4_syscfg_t *syscfg, mmio_irq_t irq)
{
    *e = (stm32f4_exti_t){ 0 };
    e->syscfg = syscfg;
    e->irq = irq;
    exti_reset(e);
}

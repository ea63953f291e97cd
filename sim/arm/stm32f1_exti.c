/* stm32f1_exti.c - AFIO and EXTI (stm32f1_exti.h): RM0008 9.4 (AFIO
 * registers), 10.2 (EXTI functional description and registers). */
#include "arm/stm32f1_exti.h"

#include <string.h>

#include "arm/stm32f1_reg.h"

#define LINES_MASK ((1u << STM32F1_EXTI_LINES) - 1u)
#define MAPR_SWJ_CFG (7u << 24)   /* write-only (RM0008 9.4.2) */
#define MAPR_WMASK 0x071FFFFFu
#define EVCR_WMASK 0xFFu          /* PIN 3:0, PORT 6:4, EVOE 7 */

/* ---- AFIO ---- */

void stm32f1_afio_init(stm32f1_afio_t *a) { memset(a, 0, sizeof *a); }

int stm32f1_afio_tim_remap(const stm32f1_afio_t *a, unsigned tim)
{
    switch (tim) {
    case 1: return (int)((a->mapr >> 6) & 3u);
    case 2: return (int)((a->mapr >> 8) & 3u);
    case 3: return (int)((a->mapr >> 10) & 3u);
    case 4: return (int)((a->mapr >> 12) & 1u);
    default: return -1;
    }
}

static void afio_reset(void *self) { stm32f1_afio_init(self); }

static mmio_status_t afio_write(void *self, uint32_t off, unsigned size, uint32_t value)
{
    stm32f1_afio_t *a = self;
    uint32_t v = stm32f1_reg_wvalue(off, size, value), m = stm32f1_reg_mask(off, size);
    uint32_t w = stm32f1_reg_word(off);
    if (w == 0x00) a->evcr = stm32f1_reg_merge(a->evcr, v, m, EVCR_WMASK);
    else if (w == 0x04) a->mapr = stm32f1_reg_merge(a->mapr, v, m, MAPR_WMASK);
    else if (w >= 0x08 && w <= 0x14) a->exticr[(w - 8) / 4] = stm32f1_reg_merge(a->exticr[(w - 8) / 4], v, m, 0xFFFFu);
    else return MMIO_UNMODELED; /* MAPR2: value line and XL-density only */
    return MMIO_OK;
}

static mmio_status_t afio_read(void *self, uint32_t off, unsigned size, uint32_t *value)
{
    const stm32f1_afio_t *a = self;
    uint32_t w = stm32f1_reg_word(off), reg;
    if (w == 0x00) reg = a->evcr;
    else if (w == 0x04) reg = a->mapr & ~MAPR_SWJ_CFG; /* SWJ_CFG reads 0 */
    else if (w >= 0x08 && w <= 0x14) reg = a->exticr[(w - 8) / 4];
    else return MMIO_UNMODELED;
    *value = stm32f1_reg_rvalue(off, size, reg);
    return MMIO_OK;
}

const mmio_ops_t stm32f1_afio_ops = {
    .name = "AFIO", .read = afio_read, .write = afio_write, .advance = NULL, .next_event = NULL, .reset = afio_reset,
};

/* ---- EXTI ---- */

/* The NVIC line of each group of EXTI lines (RM0008 table 63). */
static const struct { uint32_t lines; unsigned irq; } groups[] = {
    { 1u << 0, 6 }, { 1u << 1, 7 }, { 1u << 2, 8 }, { 1u << 3, 9 }, { 1u << 4, 10 },
    { 0x3E0u, 23 }, { 0xFC00u, 40 }, { 1u << 16, 1 }, { 1u << 17, 41 }, { 1u << 18, 42 },
};
#define NGROUPS (sizeof groups / sizeof groups[0])

static void update_irq(stm32f1_exti_t *e)
{
    uint32_t req = e->pr & e->imr;
    for (unsigned g = 0; g < NGROUPS; g++) {
        uint32_t on = (req & groups[g].lines) != 0, was = (e->irq_out >> g) & 1u;
        if (on == was) continue;
        e->irq_out ^= 1u << g;
        if (e->irq.set) e->irq.set(e->irq.ctx, groups[g].irq, on);
    }
}

/* Lines 0-15's levels from the pins EXTICR selects. */
static uint32_t pin_lines(const stm32f1_exti_t *e)
{
    uint32_t l = 0;
    for (unsigned line = 0; line < 16; line++) {
        unsigned port = (e->afio->exticr[line / 4] >> (4 * (line % 4))) & 0xFu;
        if (port < STM32F1_EXTI_PORTS && ((e->pins[port] >> line) & 1u)) l |= 1u << line;
    }
    return l;
}

/* New line levels: the enabled edges on unmasked lines pend (RM0008 10.2.3). */
static void lines_now(stm32f1_exti_t *e, uint32_t now)
{
    uint32_t rise = now & ~e->lines & e->rtsr, fall = ~now & e->lines & e->ftsr;
    e->lines = now;
    e->pr |= (rise | fall) & e->imr & LINES_MASK;
    update_irq(e);
}

void stm32f1_exti_pin(stm32f1_exti_t *e, unsigned port, unsigned pin, int level)
{
    if (port >= STM32F1_EXTI_PORTS || pin >= 16) return;
    e->pins[port] = (uint16_t)((e->pins[port] & ~(1u << pin)) | (level ? 1u << pin : 0));
    lines_now(e, (e->lines & ~0xFFFFu) | pin_lines(e));
}

void stm32f1_exti_line(stm32f1_exti_t *e, unsigned line, int level)
{
    if (line < 16 || line >= STM32F1_EXTI_LINES) return;
    lines_now(e, (e->lines & ~(1u << line)) | (level ? 1u << line : 0));
}

static void exti_reset(void *self)
{
    stm32f1_exti_t *e = self;
    e->imr = e->emr = e->rtsr = e->ftsr = e->swier = e->pr = 0;
    e->lines = (e->lines & ~0xFFFFu) | pin_lines(e);
    update_irq(e);
}

void stm32f1_exti_init(stm32f1_exti_t *e, const stm32f1_afio_t *afio, mmio_irq_t irq)
{
    memset(e, 0, sizeof *e);
    e->afio = afio, e->irq = irq;
    exti_reset(e);
}

/* SWIER: a 1 written over a 0 pends the line if it is unmasked; PR: a 1
 * clears the pending bit and the line's SWIER bit (RM0008 10.3.5, 10.3.6). */
static mmio_status_t exti_write(void *self, uint32_t off, unsigned size, uint32_t value)
{
    stm32f1_exti_t *e = self;
    uint32_t v = stm32f1_reg_wvalue(off, size, value) & LINES_MASK, m = stm32f1_reg_mask(off, size);
    switch (stm32f1_reg_word(off)) {
    case 0x00: e->imr = stm32f1_reg_merge(e->imr, v, m, LINES_MASK); break;
    case 0x04: e->emr = stm32f1_reg_merge(e->emr, v, m, LINES_MASK); break;
    case 0x08: e->rtsr = stm32f1_reg_merge(e->rtsr, v, m, LINES_MASK); break;
    case 0x0C: e->ftsr = stm32f1_reg_merge(e->ftsr, v, m, LINES_MASK); break;
    case 0x10: {
        uint32_t set = v & m & ~e->swier;
        e->swier |= v & m;
        e->pr |= set & e->imr;
        break;
    }
    case 0x14:
        e->pr &= ~(v & m);
        e->swier &= ~(v & m);
        break;
    default: return MMIO_UNMODELED;
    }
    update_irq(e);
    return MMIO_OK;
}

static mmio_status_t exti_read(void *self, uint32_t off, unsigned size, uint32_t *value)
{
    const stm32f1_exti_t *e = self;
    uint32_t reg;
    switch (stm32f1_reg_word(off)) {
    case 0x00: reg = e->imr; break;
    case 0x04: reg = e->emr; break;
    case 0x08: reg = e->rtsr; break;
    case 0x0C: reg = e->ftsr; break;
    case 0x10: reg = e->swier; break;
    case 0x14: reg = e->pr; break;
    default: return MMIO_UNMODELED;
    }
    *value = stm32f1_reg_rvalue(off, size, reg);
    return MMIO_OK;
}

const mmio_ops_t stm32f1_exti_ops = {
    .name = "EXTI", .read = exti_read, .write = exti_write, .advance = NULL, .next_event = NULL, .reset = exti_reset,
};

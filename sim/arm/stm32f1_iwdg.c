/* stm32f1_iwdg.c - the independent watchdog (stm32f1_iwdg.h): RM0008
 * 19.3 (functional description), 19.4 (registers). */
#include "arm/stm32f1_iwdg.h"

#include <string.h>

#include "arm/stm32f1_reg.h"

#define KEY_START 0xCCCCu
#define KEY_RELOAD 0xAAAAu
#define KEY_ACCESS 0x5555u
#define RLR_RESET 0xFFFu
#define SR_PVU (1u << 0)
#define SR_RVU (1u << 1)
#define UPDATE_LSI 5u /* LSI periods an update of PR or RLR takes (RM0008 19.4.4) */

static uint32_t prescaler(uint32_t pr) { return 4u << (pr > 6 ? 6 : pr); } /* /4 .. /256; 7: /256 */

/* Core cycles from now until n more LSI periods have passed. */
static uint64_t lsi_cycles(const stm32f1_iwdg_t *w, uint64_t n)
{
    unsigned __int128 need = (unsigned __int128)n * w->clk->hclk;
    if (need <= w->acc) return 0;
    return (uint64_t)((need - w->acc + STM32F1_IWDG_LSI_HZ - 1) / STM32F1_IWDG_LSI_HZ);
}

static void land_updates(stm32f1_iwdg_t *w)
{
    if (w->pvu_at <= w->now) w->pr_act = w->pr, w->pvu_at = MMIO_NEVER;
    if (w->rvu_at <= w->now) w->rlr_act = w->rlr, w->rvu_at = MMIO_NEVER;
}

/* n LSI periods of counting; the decrement past 0 resets the chip. */
static void run_lsi(stm32f1_iwdg_t *w, uint64_t n)
{
    uint64_t p = prescaler(w->pr_act);
    uint64_t to_reset = (uint64_t)w->cnt * p + (p - w->pc); /* LSI periods to the decrement past 0 */
    if (n < to_reset) {
        uint64_t t = w->pc + n;
        w->cnt -= (uint32_t)(t / p);
        w->pc = (uint32_t)(t % p);
        return;
    }
    w->resets++;
    w->running = 0; /* the system reset stops it (an erased chip's software watchdog) */
    if (w->hooks.reset) w->hooks.reset(w->hooks.ctx);
}

static void iwdg_advance(void *self, uint64_t now)
{
    stm32f1_iwdg_t *w = self;
    if (now <= w->now) return;
    uint64_t dc = now - w->now;
    if (w->running && w->clk->hclk) {
        unsigned __int128 x = (unsigned __int128)dc * STM32F1_IWDG_LSI_HZ + w->acc;
        w->acc = (uint64_t)(x % w->clk->hclk);
        w->now = now;
        land_updates(w);
        run_lsi(w, (uint64_t)(x / w->clk->hclk));
        return;
    }
    w->now = now;
    land_updates(w);
}

static uint64_t iwdg_next_event(void *self)
{
    const stm32f1_iwdg_t *w = self;
    uint64_t t = w->pvu_at < w->rvu_at ? w->pvu_at : w->rvu_at;
    if (w->running && w->clk->hclk) {
        uint64_t p = prescaler(w->pr_act);
        uint64_t r = w->now + lsi_cycles(w, (uint64_t)w->cnt * p + (p - w->pc));
        if (r < t) t = r;
    }
    return t;
}

static void iwdg_reset(void *self)
{
    stm32f1_iwdg_t *w = self;
    w->pr = w->pr_act = 0;
    w->rlr = w->rlr_act = RLR_RESET;
    w->cnt = RLR_RESET, w->pc = 0;
    w->running = w->unlocked = 0;
    w->acc = 0;
    w->pvu_at = w->rvu_at = MMIO_NEVER;
}

void stm32f1_iwdg_init(stm32f1_iwdg_t *w, const mmio_clocks_t *clk, stm32f1_iwdg_hooks_t hooks)
{
    memset(w, 0, sizeof *w);
    w->clk = clk, w->hooks = hooks;
    iwdg_reset(w);
}

static void write_key(stm32f1_iwdg_t *w, uint32_t key)
{
    w->unlocked = key == KEY_ACCESS;
    if (key == KEY_START && !w->running) {
        w->running = 1, w->cnt = w->rlr_act, w->pc = 0, w->acc = 0;
        if (w->hooks.started) w->hooks.started(w->hooks.ctx);
    } else if (key == KEY_RELOAD || key == KEY_START) {
        w->cnt = w->rlr_act;
    }
}

static mmio_status_t iwdg_write(void *self, uint32_t off, unsigned size, uint32_t value)
{
    stm32f1_iwdg_t *w = self;
    uint32_t v = stm32f1_reg_wvalue(off, size, value), m = stm32f1_reg_mask(off, size);
    uint64_t lands = w->now + lsi_cycles(w, UPDATE_LSI);
    switch (stm32f1_reg_word(off)) {
    case 0x00: write_key(w, v & m & 0xFFFFu); break;
    case 0x04:
        if (!w->unlocked) break; /* protected (RM0008 19.4.2) */
        w->pr = stm32f1_reg_merge(w->pr, v, m, 7u), w->pvu_at = lands;
        break;
    case 0x08:
        if (!w->unlocked) break;
        w->rlr = stm32f1_reg_merge(w->rlr, v, m, 0xFFFu), w->rvu_at = lands;
        break;
    case 0x0C: break; /* SR: read-only */
    default: return MMIO_UNMODELED;
    }
    return MMIO_OK;
}

static mmio_status_t iwdg_read(void *self, uint32_t off, unsigned size, uint32_t *value)
{
    const stm32f1_iwdg_t *w = self;
    uint32_t reg;
    switch (stm32f1_reg_word(off)) {
    case 0x00: reg = 0; break; /* KR: write-only */
    case 0x04: reg = w->pr; break;
    case 0x08: reg = w->rlr; break;
    case 0x0C: reg = (w->pvu_at != MMIO_NEVER ? SR_PVU : 0) | (w->rvu_at != MMIO_NEVER ? SR_RVU : 0); break;
    default: return MMIO_UNMODELED;
    }
    *value = stm32f1_reg_rvalue(off, size, reg);
    return MMIO_OK;
}

const mmio_ops_t stm32f1_iwdg_ops = {
    .name = "IWDG", .read = iwdg_read, .write = iwdg_write,
    .advance = iwdg_advance, .next_event = iwdg_next_event, .reset = iwdg_reset,
};

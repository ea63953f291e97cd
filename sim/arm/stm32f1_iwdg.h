/* stm32f1_iwdg.h - the STM32F1's independent watchdog (IWDG), RM0008
 * section 19: KR (0xCCCC start, 0xAAAA reload, 0x5555 write access to PR
 * and RLR, any other key protects them again), PR (/4 .. /256), RLR
 * (12 bits), SR (PVU, RVU while an update crosses to the LSI domain: 5 LSI
 * periods, RM0008 19.4.4). A 12-bit down-counter clocked by LSI / prescaler
 * from the reload value; the decrement past 0 asks for a system reset
 * (a callback the core handles), so the timeout is (RLR+1) x prescaler /
 * LSI (RM0008 table 96: 0.1 ms at /4 and RLR 0 .. 26.2 s at /256, 0xFFF).
 *
 * LSI: the nominal 40 kHz (RM0008 19.3.4, DS5319 section 5.3: 30-60 kHz
 * over voltage and temperature); the run uses 40 kHz exactly, so a
 * firmware's timeout is the nominal one. The watchdog counts whatever RCC's
 * LSION says (starting it forces LSI on, RM0008 19.3.2): the board tells
 * RCC through the started callback. The option byte's hardware watchdog
 * (WDG_SW = 0) is not set on an erased chip: the IWDG starts stopped. */
#ifndef STM32F1_IWDG_H
#define STM32F1_IWDG_H

#include <stdint.h>

#include "arm/mmio.h"

#define STM32F1_IWDG_LSI_HZ 40000u /* Hz: LSI's nominal frequency (RM0008 19.3.4) */

typedef struct {
    void (*reset)(void *ctx);   /* the watchdog's system reset request */
    void (*started)(void *ctx); /* KR 0xCCCC: LSI forced on; NULL: none */
    void *ctx;
} stm32f1_iwdg_hooks_t;

typedef struct {
    uint32_t pr, rlr;           /* as written */
    uint32_t pr_act, rlr_act;   /* in effect in the LSI domain */
    uint32_t cnt;               /* the down-counter */
    uint32_t pc;                /* LSI periods since the last decrement */
    int running, unlocked;
    uint64_t now, acc;          /* core cycle; LSI progress in 1/hclk of a period */
    uint64_t pvu_at, rvu_at;    /* core cycle each update lands (MMIO_NEVER: none) */
    uint64_t resets;            /* resets requested */
    const mmio_clocks_t *clk;
    stm32f1_iwdg_hooks_t hooks;
} stm32f1_iwdg_t;

extern const mmio_ops_t stm32f1_iwdg_ops;

/* Power-on: stopped, PR 0 (/4), RLR 0xFFF. */
void stm32f1_iwdg_init(stm32f1_iwdg_t *w, const mmio_clocks_t *clk, stm32f1_iwdg_hooks_t hooks);

#endif

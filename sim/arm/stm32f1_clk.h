/* stm32f1_clk.h - time conversions shared by the STM32F1 peripheral models:
 * a count of a peripheral's clock ticks as core clock (HCLK) cycles, the
 * unit every model's advance()/next_event() uses (arm/mmio.h). Integer
 * arithmetic only, so a run is bit-identical on any host. */
#ifndef ARM_STM32F1_CLK_H
#define ARM_STM32F1_CLK_H

#include <stdint.h>

/* Core cycles of `half_ticks`/2 ticks of a clock at f_hz, rounded up (an
 * event never lands before its time); f_hz 0 (a clock not running) gives
 * UINT64_MAX. half_ticks * hclk stays below 2^64 for any half_ticks below
 * 2^36 (hclk <= 72 MHz < 2^27). */
static inline uint64_t stm32_half_ticks_to_cycles(uint64_t half_ticks, uint32_t hclk_hz, uint32_t f_hz)
{
    if (f_hz == 0) return UINT64_MAX;
    uint64_t den = 2u * (uint64_t)f_hz;
    return (half_ticks * hclk_hz + den - 1) / den;
}

static inline uint64_t stm32_ticks_to_cycles(uint64_t ticks, uint32_t hclk_hz, uint32_t f_hz)
{
    return stm32_half_ticks_to_cycles(2 * ticks, hclk_hz, f_hz);
}

/* t + d with MMIO_NEVER (UINT64_MAX) absorbing. */
static inline uint64_t stm32_at(uint64_t t, uint64_t d)
{
    return (d == UINT64_MAX || t > UINT64_MAX - d) ? UINT64_MAX : t + d;
}

#endif

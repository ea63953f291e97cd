/* stm32f1_clk.h - what the STM32F1 peripheral models share: a count of a
 * peripheral's clock ticks as core clock (HCLK) cycles, the unit every
 * model's advance()/next_event() uses (arm/mmio.h), in integer arithmetic
 * so a run is bit-identical on any host; and the byte lanes of an access. */
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

/* A byte or half-word write reaches an APB register as a word with the data
 * repeated on every lane (RM0008 13.3.4, "Addressing an AHB peripheral that
 * does not support byte or halfword write operations": 0xB0 -> 0xB0B0B0B0,
 * 0xB1B0 -> 0xB1B0B1B0). */
static inline uint32_t stm32_write_lanes(uint32_t value, unsigned size)
{
    if (size == 1) return (value & 0xFFu) * 0x01010101u;
    if (size == 2) return (value & 0xFFFFu) * 0x00010001u;
    return value;
}

/* The lanes of a register word a read of `size` bytes at `off` sees. */
static inline uint32_t stm32_read_lanes(uint32_t word, uint32_t off, unsigned size)
{
    word >>= 8 * (off & 3u);
    return size == 4 ? word : word & ((1u << (8 * size)) - 1);
}

/* An access the models take: 1, 2 or 4 bytes, aligned to its size. */
static inline int stm32_access_ok(uint32_t off, unsigned size)
{
    return (size == 1 || size == 2 || size == 4) && (off & (size - 1)) == 0;
}

#endif

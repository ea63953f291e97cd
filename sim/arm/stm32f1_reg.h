/* stm32f1_reg.h - the STM32F1 peripheral models' shared register access:
 * a bus access of 1, 2 or 4 bytes at any byte offset turned into the
 * 32-bit register it falls in, and the bytes it covers as a mask. RM0008
 * 2.1 (the APB bridges): a byte or half-word write to a 32-bit register
 * writes only those bytes; so a write handler gets (value, mask) and
 * treats the bytes outside the mask as untouched, which matters for the
 * write-1-to-clear and write-0-to-clear flags (EXTI PR, TIM SR). */
#ifndef STM32F1_REG_H
#define STM32F1_REG_H

#include <stdint.h>

/* The 32-bit register (its offset, a multiple of 4) an access falls in. */
static inline uint32_t stm32f1_reg_word(uint32_t off) { return off & ~3u; }

/* The bytes an access of size at off covers, as a mask of the register. */
static inline uint32_t stm32f1_reg_mask(uint32_t off, unsigned size)
{
    uint32_t m = size >= 4 ? 0xFFFFFFFFu : ((1u << (8u * size)) - 1u);
    return m << (8u * (off & 3u));
}

/* A written value placed at its bytes in the register. */
static inline uint32_t stm32f1_reg_wvalue(uint32_t off, unsigned size, uint32_t value)
{
    return (value << (8u * (off & 3u))) & stm32f1_reg_mask(off, size);
}

/* A register's value as an access of size at off reads it. */
static inline uint32_t stm32f1_reg_rvalue(uint32_t off, unsigned size, uint32_t reg)
{
    uint32_t v = reg >> (8u * (off & 3u));
    return size >= 4 ? v : v & ((1u << (8u * size)) - 1u);
}

/* A plain read/write register's bytes under mask replaced by value's,
 * only the writable bits (wmask) changing. */
static inline uint32_t stm32f1_reg_merge(uint32_t reg, uint32_t value, uint32_t mask, uint32_t wmask)
{
    uint32_t m = mask & wmask;
    return (reg & ~m) | (value & m);
}

/* Core cycles from `from` until `ticks` ticks of a clock of hz have passed,
 * the core running at hclk Hz: ceil(ticks * hclk / hz). */
static inline uint64_t stm32f1_cycles_for(uint64_t ticks, uint32_t hz, uint32_t hclk)
{
    if (hz == 0) return UINT64_MAX;
    unsigned __int128 c = ((unsigned __int128)ticks * hclk + hz - 1) / hz;
    return c > UINT64_MAX ? UINT64_MAX : (uint64_t)c;
}

#endif

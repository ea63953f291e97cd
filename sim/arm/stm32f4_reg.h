/* stm32f4_reg.h - what the STM32F4 register models share: an access of 1, 2
 * or 4 bytes turned into the 32-bit register it falls in. On the F4 the
 * AHB and APB peripherals take byte and half-word writes as writes of those
 * bytes only (RM0090 rev 19 section 2.1.10 "AHB/APB bridges (APB)" and the
 * "can be accessed by byte (8-bit), half-word (16-bit) or word (32-bit)"
 * line of each register section, e.g. 8.4 for GPIO; old CMSIS headers
 * write GPIO BSRR as two half-words BSRRL/BSRRH), unlike the F1's
 * lane-duplicated APB writes (stm32f1_clk.h). */
#ifndef ARM_STM32F4_REG_H
#define ARM_STM32F4_REG_H

#include <stdint.h>

/* The bytes an access of size at off covers, as a mask of its register word. */
static inline uint32_t stm32f4_lane_mask(uint32_t off, unsigned size)
{
    uint32_t m = size >= 4 ? 0xFFFFFFFFu : ((1u << (8u * size)) - 1u);
    return m << (8u * (off & 3u));
}

/* A written value placed at its bytes in the register word. */
static inline uint32_t stm32f4_lane_value(uint32_t off, unsigned size, uint32_t value)
{
    return (value << (8u * (off & 3u))) & stm32f4_lane_mask(off, size);
}

/* A register word with the written bytes replaced: the new word a read-write
 * register holds after the access (the caller masks the writable bits). */
static inline uint32_t stm32f4_merge(uint32_t old, uint32_t off, unsigned size, uint32_t value)
{
    uint32_t m = stm32f4_lane_mask(off, size);
    return (old & ~m) | stm32f4_lane_value(off, size, value);
}

#endif

/* bitband.h - the Cortex-M3/M4 bit-band aliases (ARMv7-M Architecture
 * Reference Manual, B3.1 "bit-banding"; Cortex-M4 TRM / RM0090 rev 19
 * 2.3.2 "Bit banding"): a word in an alias region reads and writes one bit
 * of the bit-band region,
 *   alias = alias_base + byte_offset x 32 + bit_number x 4,
 * SRAM 0x22000000-0x23FFFFFF -> 0x20000000-0x200FFFFF and peripherals
 * 0x42000000-0x43FFFFFF -> 0x40000000-0x400FFFFF. A write of the alias
 * sets the bit to the written value's bit 0 by a read-modify-write of the
 * target (atomic: no interrupt between), a read gives the bit in bit 0.
 * Cube HAL switches the PLL on through it (RCC CR PLLON at 0x42470060).
 * The core calls these for an access in an alias region; the word it
 * reads and writes is the aligned word holding the bit (a target access
 * of the alias access's size is the processor's, the word is equivalent
 * for a read-write register; stated limit). */
#ifndef ARM_BITBAND_H
#define ARM_BITBAND_H

#include <stdbool.h>
#include <stdint.h>

#include "arm/mmio.h"

#define BITBAND_SRAM_ALIAS   0x22000000u
#define BITBAND_SRAM_BASE    0x20000000u
#define BITBAND_PERIPH_ALIAS 0x42000000u
#define BITBAND_PERIPH_BASE  0x40000000u
#define BITBAND_ALIAS_SIZE   0x02000000u /* 32 MiB of alias for 1 MiB of target */

/* Whether alias is in an alias region; then *addr is the target word
 * (4-byte aligned) and *bit the bit within it (0..31). */
bool bitband_addr(uint32_t alias, uint32_t *addr, unsigned *bit);
/* An access of the alias through bus: false if alias is not an alias
 * address or the target access faults. A read gives 0 or 1. */
bool bitband_read(const mmio_bus_t *bus, uint32_t alias, uint32_t *value);
bool bitband_write(const mmio_bus_t *bus, uint32_t alias, uint32_t value);

#endif

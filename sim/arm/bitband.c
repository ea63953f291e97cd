/* bitband.c - bit-band alias to (word, bit) and its read-modify-write
 * (ARMv7-M ARM B3.1, RM0090 rev 19 2.3.2; formula in bitband.h). */
#include "arm/bitband.h"

bool bitband_addr(uint32_t alias, uint32_t *addr, unsigned *bit)
{
    uint32_t alias_base, target_base;
    if (alias - BITBAND_SRAM_ALIAS < BITBAND_ALIAS_SIZE) {
        alias_base = BITBAND_SRAM_ALIAS;
        target_base = BITBAND_SRAM_BASE;
    } else if (alias - BITBAND_PERIPH_ALIAS < BITBAND_ALIAS_SIZE) {
        alias_base = BITBAND_PERIPH_ALIAS;
        target_base = BITBAND_PERIPH_BASE;
    } else {
        return false;
    }
    uint32_t off = alias - alias_base;
    uint32_t byte = off / 32u;                 /* byte_offset */
    unsigned bitnum = (off / 4u) & 7u;         /* bit_number within that byte */
    *addr = target_base + (byte & ~3u);
    *bit = 8u * (byte & 3u) + bitnum;
    return true;
}

bool bitband_read(const mmio_bus_t *bus, uint32_t alias, uint32_t *value)
{
    uint32_t addr, w;
    unsigned bit;
    if (!bitband_addr(alias, &addr, &bit) || !bus->read || !bus->read(bus->ctx, addr, 4, &w)) return false;
    *value = (w >> bit) & 1u;
    return true;
}

bool bitband_write(const mmio_bus_t *bus, uint32_t alias, uint32_t value)
{
    uint32_t addr, w;
    unsigned bit;
    if (!bitband_addr(alias, &addr, &bit) || !bus->read || !bus->write) return false;
    if (!bus->read(bus->ctx, addr, 4, &w)) return false;
    w = (value & 1u) ? w | (1u << bit) : w & ~(1u << bit);
    return bus->write(bus->ctx, addr, 4, w);
}

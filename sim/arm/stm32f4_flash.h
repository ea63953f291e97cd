/* stm32f4_flash.h - the STM32F4's flash interface at register level:
 * RM0090 rev 19 section 3 (3.3 organization: sectors 0-3 of 16 KiB, 4 of 64
 * KiB, 5-11 of 128 KiB on a 1 MiB F405/407; 3.4 read interface: ACR; 3.5
 * erase and program: unlock 3.5.1, sector and mass erase 3.5.3, programming
 * 3.5.4 with its errors; 3.8 registers) and RM0383 rev 3 section 3 (F411:
 * the same sectors up to 5-7, LATENCY 4 bits). The flash memory is a byte
 * array the core maps and reads directly; the core routes the firmware's
 * writes into the flash's range to stm32f4_flash_mem_write, and this model
 * writes the array through the pointer it was handed. */
#ifndef ARM_STM32F4_FLASH_H
#define ARM_STM32F4_FLASH_H

#include <stdbool.h>
#include <stdint.h>

#include "arm/mmio.h"
#include "arm/stm32f4_rcc.h"

#define STM32F4_FLASH_REG_BASE 0x40023C00u
#define STM32F4_FLASH_REG_SIZE 0x400u
#define STM32F4_FLASH_BASE     0x08000000u /* RM0090 3.3: main memory */
#define STM32F4_FLASH_IRQ      4u          /* RM0090 table 61: FLASH global interrupt */
#define STM32F4_FLASH_SECTORS  12

typedef struct {
    stm32f4_part_t part;
    uint32_t acr, sr, cr, optcr;
    int key_step;             /* 1: KEY1 written, KEY2 expected next */
    bool locked_out;          /* a wrong key sequence: CR locked until reset (RM0090 3.5.1) */
    uint8_t *mem;             /* the flash memory, size bytes */
    uint32_t size;
    const mmio_clocks_t *clk;
    mmio_irq_t irq;
    uint64_t now, busy_until; /* core cycles; BSY while now < busy_until */
    uint32_t erase_off, erase_len; /* the erase in progress (applied when BSY falls), len 0: none */
    bool eop_due;             /* EOP to set when BSY falls (with EOPIE) */
    bool irq_level;
    uint64_t programmed, sectors_erased;
} stm32f4_flash_t;

extern const mmio_ops_t stm32f4_flash_ops;

/* Power-on: registers at their reset values, CR locked. mem/size: the
 * flash memory (256 KiB to 1 MiB, whole sectors). */
void stm32f4_flash_init(stm32f4_flash_t *f, stm32f4_part_t part, uint8_t *mem, uint32_t size,
                        const mmio_clocks_t *clk, mmio_irq_t irq);
/* Sector n's offset and size in bytes (RM0090 3.3 table 5); false past the memory. */
bool stm32f4_flash_sector(const stm32f4_flash_t *f, unsigned n, uint32_t *off, uint32_t *len);
/* The firmware's write of size bytes at off (from STM32F4_FLASH_BASE) into
 * the flash memory: programmed when CR.PG is set and the access matches
 * PSIZE (RM0090 3.5.4); otherwise PGSERR, PGPERR or PGAERR and no change.
 * Always MMIO_OK: the errors are the flash interface's flags, not bus errors. */
mmio_status_t stm32f4_flash_mem_write(stm32f4_flash_t *f, uint32_t off, unsigned size, uint32_t value);

#endif

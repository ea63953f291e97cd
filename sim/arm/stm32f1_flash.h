/* stm32f1_flash.h - the STM32F1's flash memory interface (FPEC): RM0008
 * 3.3.3 (embedded flash, read interface: ACR) and the flash programming
 * manual PM0075 (sections 2.3 and 3: unlock, programming, page and mass
 * erase, the registers). The flash memory itself is a byte array the core
 * maps and reads directly; the core routes the firmware's writes into
 * the flash's range to stm32f1_flash_mem_write, and this model writes the
 * array through the pointer it was handed.
 *
 * Modeled: ACR (LATENCY, HLFCYA, PRFTBE, PRFTBS read back; the wait states
 * themselves are the core's, which counts none), KEYR's unlock sequence
 * (a wrong key: a bus error and the FPEC locked until reset), SR (BSY, EOP,
 * PGERR, WRPRTERR), CR (PG, PER, MER, STRT, LOCK, EOPIE, ERRIE), AR; the
 * option bytes read as erased (OBR, WRPR: no read or write protection),
 * OPTKEYR and the option byte programming (OPTPG, OPTER) answer
 * unmodeled. BSY lasts the datasheet's programming and erase times; the
 * core's stall on a flash read meanwhile is not modeled (a read sees the
 * new contents at once).
 *
 * The contents can be kept in a file across runs like the AVR board's
 * --eeprom (sim/io/memfile): loaded at power-on, saved whole at the end. */
#ifndef STM32F1_FLASH_H
#define STM32F1_FLASH_H

#include <stddef.h>
#include <stdint.h>

#include "arm/mmio.h"

#define STM32F1_FLASH_IRQ 4            /* RM0008 table 63: flash global interrupt */
#define STM32F1_FLASH_BASE 0x08000000u /* RM0008 3.3.3: main flash memory */
#define STM32F1_FLASH_PAGE_MD 1024u    /* bytes: a page on low/medium density (RM0008 3.3.3, table 5) */
#define STM32F1_FLASH_PAGE_HD 2048u    /* bytes: a page on high density and connectivity line */

typedef struct {
    uint32_t acr, sr, cr, ar;
    int key1_seen;           /* KEY1 written, KEY2 expected next */
    int locked_out;          /* a wrong key sequence: CR locked until reset */
    uint8_t *mem;            /* the flash memory, size bytes */
    uint32_t size, page;     /* bytes; page: the erase unit */
    const mmio_clocks_t *clk;
    mmio_irq_t irq;
    uint64_t now, busy_until;   /* core cycles; BSY while now < busy_until */
    uint64_t programmed, erased; /* half-words programmed, pages erased (a mass erase counts them all) */
    int changed;             /* programmed or erased since power-on */
} stm32f1_flash_t;

extern const mmio_ops_t stm32f1_flash_ops;

/* Power-on: registers at their reset values, the FPEC locked. mem/size:
 * the flash memory (size a multiple of page). */
void stm32f1_flash_init(stm32f1_flash_t *f, uint8_t *mem, uint32_t size, uint32_t page, const mmio_clocks_t *clk,
                        mmio_irq_t irq);
/* The firmware's write of size bytes at off into the flash memory (off
 * from STM32F1_FLASH_BASE, inside size): a half-word programmed if CR.PG
 * is set (PM0075 2.3.3). MMIO_BUS_FAULT for a write with PG set that is
 * not a half-word; MMIO_UNMODELED for a write without PG (dropped). */
mmio_status_t stm32f1_flash_mem_write(stm32f1_flash_t *f, uint32_t off, unsigned size, uint32_t value);

/* The flash memory from path (missing: erased, every byte 0xFF); call it
 * before the image is written into the flash. what names the memory in
 * messages ("STM32F103C8's flash"). 0, or -1 with one line in err. */
int stm32f1_flash_load(stm32f1_flash_t *f, const char *path, const char *what, char *err, size_t errn);
/* The whole flash memory to path, whole or not at all. 0, or -1 with one line in err. */
int stm32f1_flash_save(const stm32f1_flash_t *f, const char *path, char *err, size_t errn);

#endif

/* armimage.h - an ARM Cortex-M firmware image (ELF) checked as untrusted
 * input before unicorn sees any of it, against the MCU it is to run on
 * (armimage_mcu: a table of figures, each with its source). Checked: the
 * ELF's structure (sim/io/elf32.c, shared with the AVR's image.c), an
 * EABI5 EM_ARM image for the MCU's core (e_flags' float ABI;
 * .ARM.attributes' profile 'M', architecture and FP use when present),
 * every loaded segment's flash bytes (LMA) within flash and its run
 * addresses within flash or SRAM, the vector table in flash, the initial
 * SP within SRAM (its end included), the reset vector a Thumb address in
 * flash. Each fault is one line in err, "IMAGE: PATH: what" (exit 2). */
#ifndef ARMIMAGE_H
#define ARMIMAGE_H

#include <stddef.h>
#include <stdint.h>

#define ARMIMAGE_MAX_BYTES (64u << 20) /* an ELF with its debug sections */

typedef enum { ARMCORE_M3 = 3, ARMCORE_M4 = 4 } armcore_kind_t;

/* An MCU's memories and interrupts as its datasheet and reference manual give them. */
typedef struct {
    const char *name;       /* "stm32f103x8" */
    armcore_kind_t core;    /* Cortex-M3 or M4 */
    int fpu;                /* 1: single-precision FPU (FPv4-SP) */
    uint32_t flash_base, flash_bytes;
    uint32_t sram_base, sram_bytes;
    unsigned nirq;          /* external interrupt lines (vector table entries past the 16 of the core) */
    unsigned prio_bits;     /* NVIC priority bits implemented (the upper bits of each priority byte) */
    uint32_t cpuid;         /* SCB CPUID */
    uint32_t fsize_addr;    /* the device electronic signature's flash size register (16 bits, KiB) */
    uint32_t uid_addr;      /* its 96-bit unique device ID */
    const char *source;
} armimage_mcu_t;

/* The image as the MCU's flash holds it. */
typedef struct {
    const armimage_mcu_t *mcu;
    uint8_t *flash;       /* mcu->flash_bytes, erased bytes 0xFF (free with armimage_free) */
    uint32_t flash_end;   /* one past the highest flash byte the image writes, from flash_base */
    uint32_t initial_sp;  /* vector table word 0 */
    uint32_t reset;       /* vector table word 1 (its Thumb bit set) */
} armimage_t;

/* The MCU named name (case as written in the table), NULL if none. */
const armimage_mcu_t *armimage_mcu(const char *name);
/* The table's names, comma-separated, for a message. */
const char *armimage_mcu_names(void);
/* Read and check the ELF at path for mcu. 0 with *out filled, -1 with one line in err. */
int armimage_read(const char *path, const armimage_mcu_t *mcu, armimage_t *out, char *err, size_t errn);
/* The same on n bytes in memory (the tests' crafted images); path names them in messages. */
int armimage_check(const uint8_t *b, size_t n, const char *path, const armimage_mcu_t *mcu, armimage_t *out, char *err,
                   size_t errn);
void armimage_free(armimage_t *img);

#endif

/* image.h - an AVR firmware image checked as untrusted input before simavr
 * reads it. An ELF's structure is checked by our own reader (header,
 * program and section header tables, every section's bytes, section and
 * symbol names within their string tables, the .mmcu tags within their
 * section and within the fields simavr copies them into); an Intel HEX file
 * is parsed strictly (checksums, record types, lengths, addresses that never
 * wrap, one end record) into the bytes handed to simavr instead of the
 * file. Each problem is one line in err: "IMAGE: ..." or "IMAGE:LINE: ...". */
#ifndef IMAGE_H
#define IMAGE_H

#include <stddef.h>
#include <stdint.h>

#define IMAGE_FLASH_MAX_BYTES (256u << 10) /* the largest AVR flash simavr models (ATmega2560) */
#define IMAGE_MCU_NAME_BYTES 64u           /* simavr's MCU name field, its NUL included */
#define IMAGE_TRACE_NAME_BYTES 128u        /* simavr's VCD file name field, its NUL included */
#define IMAGE_TRACES_MAX 32                /* simavr's VCD trace slots */
#define IMAGE_FUSE_MAX_BYTES 6u            /* simavr's fuse bytes */

/* What an ELF's .mmcu section declares. */
typedef struct {
    char mcu[IMAGE_MCU_NAME_BYTES]; /* the MCU name ("" if none) */
    uint32_t f_cpu;                 /* the clock, Hz (0 if none) */
    unsigned arch;                  /* e_flags' AVR architecture (5: avr5, 25: avr25; 0 if none) */
} image_elf_t;

/* A contiguous run of bytes at one flash address. */
typedef struct {
    uint32_t base, size; /* flash byte address and length */
} image_chunk_t;

/* An Intel HEX image: its bytes indexed by flash address and the runs the
 * data records wrote. */
typedef struct {
    uint8_t *flash;        /* IMAGE_FLASH_MAX_BYTES bytes, 0xFF where unwritten */
    image_chunk_t *chunks;
    int nchunks;
    uint32_t end;          /* one past the highest byte written */
} image_hex_t;

/* Check the ELF at path (the whole file, at most max_bytes). 0 with what
 * its .mmcu declares in *out, or -1 with one line in err. */
int image_check_elf(const char *path, size_t max_bytes, image_elf_t *out, char *err, size_t errn);
/* Parse the Intel HEX file at path (at most max_bytes). 0 with the bytes
 * in *out (image_hex_free frees them), or -1 with one line in err
 * (nothing to free). */
int image_read_hex(const char *path, size_t max_bytes, image_hex_t *out, char *err, size_t errn);
void image_hex_free(image_hex_t *h);
/* The AVR architecture number avr-gcc puts in e_flags for mcu (5 for the
 * atmega328p), or 0 if not in our table. */
unsigned image_mcu_arch(const char *mcu);

#endif

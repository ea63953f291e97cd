/* elfvar.h - a firmware's global variables read by name (mmsim --watch
 * NAME[,NAME...]) in an ELF image of either machine (an AVR's, an ARM's):
 * each name looked up in the ELF's symbol table (an object symbol in the
 * machine's data space, its SRAM: its address and size; a C++ file-scope
 * static by its _ZL name as g++ writes it; a static LTO renamed
 * NAME.lto_priv.N by its DWARF entry alone), its type from the image's
 * DWARF (.debug_info's base type behind typedefs, volatile, const and
 * enums: signed or unsigned 8/16/32-bit integer, float; a pointer is
 * unsigned) when the image has it, else from its size (an unsigned integer
 * of 1, 2 or 4 bytes, and a note says so). The image is untrusted input:
 * its structure is checked (elf32.c) before a symbol is read, and libdw
 * reads its DWARF with bounded walks. The machines differ only in where
 * their data space lies among the ELF's addresses (elfvar_space_t); both
 * store numbers little-endian, as IEEE 754 single floats. */
#ifndef ELFVAR_H
#define ELFVAR_H

#include <stddef.h>
#include <stdint.h>
#include <stdio.h>

#define ELFVAR_MAX 16          /* variables per run */
#define ELFVAR_NAME_BYTES 64   /* a variable's name, its NUL included */

typedef enum { ELFVAR_UNSIGNED, ELFVAR_SIGNED, ELFVAR_FLOAT } elfvar_kind_t;

typedef struct {
    char name[ELFVAR_NAME_BYTES];
    uint32_t addr;      /* the byte's offset in the data space (an AVR's data address, an ARM's from the SRAM's base) */
    uint32_t size;      /* bytes: 1, 2 or 4 */
    elfvar_kind_t kind;
    int typed;          /* 1: the type is DWARF's; 0: taken from the size (no DWARF for it) */
    char type[8];       /* "u8", "i16", "f32", ...: kind and size as a word */
} elfvar_t;

typedef struct {
    int n;
    elfvar_t v[ELFVAR_MAX];
    const char *names[ELFVAR_MAX]; /* v[i].name, for the telemetry and the report */
    const char *types[ELFVAR_MAX]; /* v[i].type */
} elfvar_list_t;

/* A machine's data space among its ELF's addresses. */
typedef struct {
    unsigned machine;          /* the e_machine the image must have: 83 AVR, 40 ARM */
    const char *kind;          /* "AVR", "ARM": the machine in messages */
    uint32_t lo, hi;           /* ELF addresses of the data space [lo, hi) (avr-gcc: 0x800000-0x810000; ARM: the SRAM) */
    uint32_t base;             /* the ELF address of the data space's byte 0 */
    uint32_t bytes;            /* the data space's size: a variable lies within it */
    size_t image_max;          /* the image file's largest size, bytes */
} elfvar_space_t;

/* Look up each name of list ("a,b,c") in the ELF at image for space sp.
 * note (may be NULL) gets a line per variable typed by its size alone
 * (when every name was found). 0, or -1 with one line in err: "--watch: no
 * global variable 'foo' in IMAGE", an ELF without a symbol table, a type or
 * size that is not an 8/16/32-bit integer or a float, a bad list, an Intel
 * HEX image (IMAGE.hex: no symbols). */
int elfvar_open(elfvar_list_t *w, const char *image, const char *list, const elfvar_space_t *sp, FILE *note, char *err,
                size_t errn);
/* A variable's value from its v->size bytes as the firmware stores them (little-endian). */
double elfvar_value(const elfvar_t *v, const uint8_t *bytes);

#endif

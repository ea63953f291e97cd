/* watch.h - a firmware's global variables read by name (mmsim --watch
 * NAME[,NAME...]): each name looked up in the ELF image's symbol table (an
 * object symbol in the AVR data space: its SRAM address and size; a C++
 * file-scope static by its _ZL name as g++ writes it), its
 * type from the image's DWARF (.debug_info's base type behind typedefs,
 * volatile and const: signed or unsigned 8/16/32-bit integer, float) when
 * the image has it, else from its size (an unsigned integer of 1, 2 or 4
 * bytes, and a note says so). The image is untrusted input: every offset
 * and size is checked against the file before it is read. Sampling reads
 * the bytes from simavr's SRAM (little-endian, as the AVR stores them) and
 * writes nothing: a run is the same with or without a watch. */
#ifndef WATCH_H
#define WATCH_H

#include <stddef.h>
#include <stdint.h>
#include <stdio.h>

struct avr_t;

#define WATCH_MAX 16              /* variables per run */
#define WATCH_NAME_BYTES 64       /* a variable's name, its NUL included */
#define WATCH_DATA_OFFSET 0x800000u /* avr-gcc's data-space addresses in an ELF: SRAM address + this */
#define WATCH_EEPROM_OFFSET 0x810000u /* ... and where its EEPROM addresses start */

typedef enum { WATCH_UNSIGNED, WATCH_SIGNED, WATCH_FLOAT } watch_kind_t;

typedef struct {
    char name[WATCH_NAME_BYTES];
    uint32_t addr;      /* data-space (SRAM) byte address */
    uint32_t size;      /* bytes: 1, 2 or 4 */
    watch_kind_t kind;
    int typed;          /* 1: the type is DWARF's; 0: taken from the size (no DWARF for it) */
    char type[8];       /* "u8", "i16", "f32", ...: kind and size as a word */
} watch_var_t;

typedef struct {
    int n;
    watch_var_t v[WATCH_MAX];
    const char *names[WATCH_MAX]; /* v[i].name, for the telemetry and the report */
    const char *types[WATCH_MAX]; /* v[i].type */
} watch_list_t;

/* Look up each name of list ("a,b,c") in the ELF at image, run on avr:
 * each variable must lie in its data space (simavr's ramend + 1 bytes).
 * note (may be NULL) gets a line per variable typed by its size alone
 * (when every name was found).
 * 0, or -1 with one line in err: "--watch: no global variable 'foo' in
 * IMAGE", a HEX image or an ELF without a symbol table, a type or size
 * that is not an 8/16/32-bit integer or a float, a bad list. */
int watch_open(watch_list_t *w, const char *image, const char *list, const struct avr_t *avr, FILE *note, char *err,
               size_t errn);
/* Every variable's value now, from the AVR's SRAM, into values[0..w->n). */
void watch_sample(const watch_list_t *w, const struct avr_t *avr, double *values);

#endif

/* watch.h - a firmware's global variables read by name (mmsim --watch
 * NAME[,NAME...]) on an AVR: the ELF lookup and the DWARF types are
 * sim/io/elfvar.c's, shared with the ARM board (sim/arm/armwatch.c); here,
 * the AVR's data space among avr-gcc's ELF addresses (SRAM address +
 * 0x800000) and sampling from simavr's SRAM, which reads the bytes and
 * writes nothing: a run is the same with or without a watch. */
#ifndef WATCH_H
#define WATCH_H

#include <stddef.h>
#include <stdint.h>
#include <stdio.h>

#include "io/elfvar.h"

struct avr_t;

#define WATCH_MAX ELFVAR_MAX
#define WATCH_NAME_BYTES ELFVAR_NAME_BYTES
#define WATCH_DATA_OFFSET 0x800000u /* avr-gcc's data-space addresses in an ELF: SRAM address + this */
#define WATCH_EEPROM_OFFSET 0x810000u /* ... and where its EEPROM addresses start */
#define WATCH_UNSIGNED ELFVAR_UNSIGNED
#define WATCH_SIGNED ELFVAR_SIGNED
#define WATCH_FLOAT ELFVAR_FLOAT

typedef elfvar_t watch_var_t;
typedef elfvar_list_t watch_list_t;

/* Look up each name of list ("a,b,c") in the ELF at image, run on avr:
 * each variable must lie in its data space (simavr's ramend + 1 bytes).
 * As elfvar_open. */
int watch_open(watch_list_t *w, const char *image, const char *list, const struct avr_t *avr, FILE *note, char *err,
               size_t errn);
/* Every variable's value now, from the AVR's SRAM, into values[0..w->n). */
void watch_sample(const watch_list_t *w, const struct avr_t *avr, double *values);

#endif

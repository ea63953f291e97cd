/* armwatch.h - mmsim --watch NAME[,NAME...] on an ARM image: the names
 * looked up and typed by sim/io/elfvar.c (the same code as the AVR's), in
 * the MCU's SRAM (arm-none-eabi-gcc's ELF addresses are the bus's: SRAM at
 * its base, 0x20000000 on the STM32); sampling copies the bytes from the
 * core's SRAM (armcore_read: no bus access, no model touched), so a run is
 * the same with or without a watch. */
#ifndef ARMWATCH_H
#define ARMWATCH_H

#include <stddef.h>
#include <stdio.h>

#include "armcore.h"
#include "armimage.h"
#include "io/elfvar.h"

/* Look up each name of list in the ELF at image for mcu: each variable in
 * its SRAM. As elfvar_open: 0, or -1 with one line in err. */
int armwatch_open(elfvar_list_t *w, const char *image, const char *list, const armimage_mcu_t *mcu, FILE *note, char *err,
                  size_t errn);
/* Every variable's value now, from the core's SRAM, into values[0..w->n). */
void armwatch_sample(const elfvar_list_t *w, armcore_t *core, const armimage_mcu_t *mcu, double *values);

#endif

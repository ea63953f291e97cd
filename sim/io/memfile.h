/* memfile.h - a chip's non-volatile memory kept in a file across runs (an
 * AVR's EEPROM, an STM32's flash), as the chip keeps it across power
 * cycles: loaded at power-on, saved at the end. The file is a raw image of
 * all of the memory, byte 0 first; a missing file is a blank chip (every
 * byte the erased value). It is written whole or not at all (outfile). */
#ifndef MEMFILE_H
#define MEMFILE_H

#include <stddef.h>
#include <stdint.h>

/* Fill mem[size] from path, or with erased if the file does not exist;
 * then check that path can be written at the end. what names the memory
 * in messages ("atmega328p's EEPROM"). 0, or -1 with one line in err
 * ("PATH: 10 bytes, the atmega328p's EEPROM holds 1024 (...)",
 * "PATH: cannot read: ...", "PATH: cannot write: ..."). */
int memfile_load(const char *path, uint8_t *mem, size_t size, uint8_t erased, const char *what, char *err,
                 size_t errn);
/* Write mem[size] to path, whole or not at all. 0, or -1 with one line in err. */
int memfile_save(const char *path, const uint8_t *mem, size_t size, char *err, size_t errn);

#endif

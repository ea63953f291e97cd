/* board_eeprom.h - the MCU's EEPROM kept in a file (--eeprom FILE), as the
 * chip keeps it across power cycles: loaded at power-on, saved at the end.
 * The file is a raw image of the whole EEPROM (1024 bytes on the
 * ATmega328P), byte 0 first; a missing file is a blank chip (every byte
 * 0xFF, erased). It is written whole or not at all (sim/io/outfile). */
#ifndef BOARD_EEPROM_H
#define BOARD_EEPROM_H

#include <stddef.h>
#include <stdint.h>

struct avr_t;
struct avr_eeprom_t;

#define BOARD_EEPROM_MAX 4096 /* bytes: the largest EEPROM of a classic megaAVR */

typedef struct {
    const char *path;          /* NULL: not kept */
    struct avr_eeprom_t *chip; /* simavr's EEPROM part */
    uint8_t at_load[BOARD_EEPROM_MAX]; /* the contents at power-on */
    int written;               /* the firmware finished a write (the EEPROM-ready event) */
} board_eeprom_t;

/* Fill avr's EEPROM from path (missing: 0xFF); then watch for writes.
 * mcu names the chip in messages. 0, or -1 with one line in err ("PATH: N bytes, the atmega328p's EEPROM
 * holds 1024", "PATH: cannot write: ...", the MCU has no EEPROM). */
int board_eeprom_load(board_eeprom_t *e, struct avr_t *avr, const char *mcu, const char *path, char *err, size_t errn);
/* 1 if the contents differ from what was loaded. */
int board_eeprom_changed(const board_eeprom_t *e);
/* Write the EEPROM's contents to the file, whole or not at all. 0, or -1
 * with one line in err. */
int board_eeprom_save(const board_eeprom_t *e, char *err, size_t errn);

#endif

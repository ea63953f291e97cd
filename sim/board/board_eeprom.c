/* board_eeprom.c - the EEPROM kept in a file (board_eeprom.h). */
#include "board_eeprom.h"

#include <stdio.h>
#include <string.h>

#include <simavr/avr_eeprom.h>
#include <simavr/sim_avr.h>
#include <simavr/sim_interrupts.h>
#include <simavr/sim_io.h>
#include <simavr/sim_irq.h>

#include "io/memfile.h"

/* simavr raises the EEPROM-ready vector 3.4 ms after each write it does,
 * whether or not the firmware enabled that interrupt. */
static void on_ready(struct avr_irq_t *irq, uint32_t value, void *param)
{
    board_eeprom_t *e = param;
    (void)irq;
    if (value) e->written = 1;
}

static avr_eeprom_t *find_chip(avr_t *avr)
{
    for (avr_io_t *io = avr->io_port; io; io = io->next)
        if (!strcmp(io->kind, "eeprom")) return (avr_eeprom_t *)io;
    return NULL;
}

int board_eeprom_load(board_eeprom_t *e, avr_t *avr, const char *mcu, const char *path, char *err, size_t errn)
{
    memset(e, 0, sizeof *e);
    avr_eeprom_t *chip = find_chip(avr);
    if (!chip || !chip->eeprom || chip->size > BOARD_EEPROM_MAX)
        return snprintf(err, errn, "--eeprom: the %s has no EEPROM in simavr", mcu), -1;
    char what[64];
    snprintf(what, sizeof what, "%s's EEPROM", mcu);
    if (memfile_load(path, chip->eeprom, chip->size, 0xFF, what, err, errn) != 0) return -1; /* missing: erased */
    e->path = path;
    e->chip = chip;
    memcpy(e->at_load, chip->eeprom, chip->size);
    if (chip->ready.vector) avr_irq_register_notify(chip->ready.irq + AVR_INT_IRQ_PENDING, on_ready, e);
    return 0;
}

int board_eeprom_changed(const board_eeprom_t *e)
{
    return e->chip && memcmp(e->at_load, e->chip->eeprom, e->chip->size) != 0;
}

int board_eeprom_save(const board_eeprom_t *e, char *err, size_t errn)
{
    if (!e->path) return 0;
    return memfile_save(e->path, e->chip->eeprom, e->chip->size, err, errn);
}

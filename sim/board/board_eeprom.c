/* board_eeprom.c - the EEPROM kept in a file (board_eeprom.h). */
#include "board_eeprom.h"

#include <errno.h>
#include <stdio.h>
#include <string.h>
#include <sys/stat.h>

#include <simavr/avr_eeprom.h>
#include <simavr/sim_avr.h>
#include <simavr/sim_interrupts.h>
#include <simavr/sim_io.h>
#include <simavr/sim_irq.h>

#include "io/infile.h"
#include "io/outfile.h"

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

/* The file's bytes into the chip: 0, or -1 with one line in err. */
static int read_file(avr_eeprom_t *chip, const char *path, const char *mcu, char *err, size_t errn)
{
    uint64_t size = 0;
    FILE *f = infile_open(path, INFILE_NO_LIMIT, &size, err, errn);
    if (!f) return -1;
    int rc = -1;
    if (size != chip->size)
        snprintf(err, errn, "%s: %llu bytes, the %s's EEPROM holds %u (the file is a raw image of all of it)", path,
                 (unsigned long long)size, mcu, (unsigned)chip->size);
    else if (fread(chip->eeprom, 1, chip->size, f) != chip->size)
        snprintf(err, errn, "%s: cannot read: %s", path, ferror(f) ? strerror(errno) : "shorter than it was");
    else rc = 0;
    fclose(f);
    return rc;
}

int board_eeprom_load(board_eeprom_t *e, avr_t *avr, const char *mcu, const char *path, char *err, size_t errn)
{
    memset(e, 0, sizeof *e);
    avr_eeprom_t *chip = find_chip(avr);
    if (!chip || !chip->eeprom || chip->size > BOARD_EEPROM_MAX)
        return snprintf(err, errn, "--eeprom: the %s has no EEPROM in simavr", mcu), -1;
    struct stat st;
    if (stat(path, &st) != 0 && errno == ENOENT) memset(chip->eeprom, 0xFF, chip->size); /* a blank chip */
    else if (read_file(chip, path, mcu, err, errn) != 0) return -1;
    if (outfile_probe(path, err, errn) != 0) return -1;
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
    outfile_t o;
    if (!e->path) return 0;
    if (outfile_open(&o, e->path, err, errn) != 0) return -1;
    if (fwrite(e->chip->eeprom, 1, e->chip->size, o.f) != e->chip->size) {
        snprintf(err, errn, "%s: cannot write: %s", e->path, strerror(errno));
        outfile_abort(&o);
        return -1;
    }
    return outfile_commit(&o, err, errn);
}

/* watch.c - a firmware's global variables by name on an AVR (see watch.h). */
#include "watch.h"

#include <simavr/sim_avr.h>

#include "avrhost.h"

#define EM_AVR_MACHINE 83u /* e_machine of an AVR ELF */

int watch_open(watch_list_t *w, const char *image, const char *list, const struct avr_t *avr, FILE *note, char *err,
               size_t errn)
{
    const elfvar_space_t sp = { .machine = EM_AVR_MACHINE, .kind = "AVR", .lo = WATCH_DATA_OFFSET, .hi = WATCH_EEPROM_OFFSET,
                                .base = WATCH_DATA_OFFSET, .bytes = (uint32_t)avr->ramend + 1u,
                                .image_max = AVRHOST_IMAGE_MAX_BYTES };
    return elfvar_open(w, image, list, &sp, note, err, errn);
}

void watch_sample(const watch_list_t *w, const struct avr_t *avr, double *values)
{
    uint32_t ram_bytes = (uint32_t)avr->ramend + 1u;
    for (int i = 0; i < w->n; i++) {
        const watch_var_t *v = &w->v[i];
        if (v->addr > ram_bytes || v->size > ram_bytes - v->addr) values[i] = 0.0; /* checked at open; never read outside */
        else values[i] = elfvar_value(v, avr->data + v->addr);
    }
}

/* armwatch.c - a firmware's global variables by name on the ARM core (see armwatch.h). */
#include "armwatch.h"

#define EM_ARM_MACHINE 40u /* e_machine of an ARM ELF */

int armwatch_open(elfvar_list_t *w, const char *image, const char *list, const armimage_mcu_t *mcu, FILE *note, char *err,
                  size_t errn)
{
    const elfvar_space_t sp = { .machine = EM_ARM_MACHINE, .kind = "ARM", .lo = mcu->sram_base,
                                .hi = mcu->sram_base + mcu->sram_bytes, .base = mcu->sram_base, .bytes = mcu->sram_bytes,
                                .image_max = ARMIMAGE_MAX_BYTES };
    return elfvar_open(w, image, list, &sp, note, err, errn);
}

void armwatch_sample(const elfvar_list_t *w, armcore_t *core, const armimage_mcu_t *mcu, double *values)
{
    for (int i = 0; i < w->n; i++) {
        const elfvar_t *v = &w->v[i];
        uint8_t b[4];
        if (v->size > sizeof b || armcore_read(core, mcu->sram_base + v->addr, b, v->size) != 0) values[i] = 0.0; /* checked at open */
        else values[i] = elfvar_value(v, b);
    }
}

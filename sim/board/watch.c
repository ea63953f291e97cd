/* watch.c - a firmware's global variables by name (see watch.h). The
 * ELF's symbol table is read by image.c's checked reader
 * (image_elf_object); the types come from watch_dwarf.c. */
#include "watch.h"

#include <ctype.h>
#include <simavr/sim_avr.h>
#include <stdlib.h>
#include <string.h>

#include "avrhost.h"
#include "image.h"
#include "io/infile.h"
#include "watch_dwarf.h"

static uint32_t le(const uint8_t *p, int bytes)
{
    uint32_t v = 0;
    for (int i = bytes - 1; i >= 0; i--) v = v << 8 | p[i];
    return v;
}

static void type_word(watch_var_t *v)
{
    snprintf(v->type, sizeof v->type, "%c%u", v->kind == WATCH_FLOAT ? 'f' : v->kind == WATCH_SIGNED ? 'i' : 'u',
             (unsigned)(v->size * 8));
}

/* The source name behind a symbol: g++'s _ZL<length> prefix of a file-scope
 * static and LTO's .lto_priv.N suffix off ("_ZL13s_robot_angle.lto_priv.82"
 * -> "s_robot_angle"); any other name as it is. */
static void source_name(const char *sym, char *out, size_t outn)
{
    const char *dot = strstr(sym, ".lto_priv.");
    size_t n = dot ? (size_t)(dot - sym) : strlen(sym);
    const char *p = sym;
    if (!strncmp(sym, "_ZL", 3) && isdigit((unsigned char)sym[3])) {
        char *end;
        unsigned long k = strtoul(sym + 3, &end, 10);
        if (k > 0 && k == n - (size_t)(end - sym)) p = end, n = k;
    }
    snprintf(out, outn, "%.*s", (int)n, p);
}

/* The symbol's type from DWARF by its name, else by its source name: 1, 0 (no entry), -1 with why. */
static int symbol_type(char *buf, size_t len, uint32_t value, watch_var_t *v, char *why, size_t whyn)
{
    int typed = watch_dwarf_type(buf, len, value, v, why, whyn);
    watch_var_t src = *v;
    source_name(v->name, src.name, sizeof src.name);
    if (typed != 0 || !strcmp(src.name, v->name)) return typed;
    typed = watch_dwarf_type(buf, len, value, &src, why, whyn);
    v->kind = src.kind, v->size = src.size;
    return typed;
}

/* A name's ELF data address and type: its object symbol (or the _ZL name of
 * a C++ file-scope static), else its DWARF entry alone (a static LTO
 * renamed NAME.lto_priv.N). 0 with *value, v->typed (and v's type when
 * typed) and *size, or -1 with err. */
static int find_var(char *buf, size_t len, const char *image, watch_var_t *v, uint32_t *value, uint32_t *size,
                    char *err, size_t errn)
{
    char zl[WATCH_NAME_BYTES + 24]; /* "_ZL", the length's digits, the name */
    snprintf(zl, sizeof zl, "_ZL%zu%s", strlen(v->name), v->name); /* C++'s name for a file-scope static */
    int f = image_elf_object((const uint8_t *)buf, len, v->name, value, size);
    if (f == 0) f = image_elf_object((const uint8_t *)buf, len, zl, value, size);
    if (f == -2) return snprintf(err, errn, "--watch: %s has no symbol table (a stripped image?): --watch needs one", image), -1;
    if (f < 0) return snprintf(err, errn, "--watch: '%s' names two static variables in %s", v->name, image), -1;
    if (f == 1 && (*value < WATCH_DATA_OFFSET || *value >= WATCH_EEPROM_OFFSET))
        return snprintf(err, errn, "--watch: '%s' in %s is not in SRAM (address 0x%X): --watch reads SRAM variables",
                        v->name, image, (unsigned)*value), -1;
    char why[200] = "";
    int typed = f == 1 ? symbol_type(buf, len, *value, v, why, sizeof why)
                       : watch_dwarf_find(buf, len, WATCH_DATA_OFFSET, WATCH_EEPROM_OFFSET, value, v, why, sizeof why);
    if (typed == -2) return snprintf(err, errn, "--watch: '%s' in %s: %s", v->name, image, why), -1;
    if (typed < 0)
        return snprintf(err, errn, "--watch: '%s' in %s: %s: --watch reads 8/16/32-bit integers and floats", v->name,
                        image, why), -1;
    if (f == 0 && typed == 0) return snprintf(err, errn, "--watch: no global variable '%s' in %s", v->name, image), -1;
    if (f == 0) *size = v->size;
    v->typed = typed;
    return 0;
}

/* One name looked up and typed: 0, or -1 with err. */
static int look_up(char *buf, size_t len, const char *image, uint32_t ram_bytes, watch_var_t *v, char *err, size_t errn)
{
    uint32_t value = 0, size = 0;
    if (find_var(buf, len, image, v, &value, &size, err, errn) != 0) return -1;
    v->addr = value - WATCH_DATA_OFFSET;
    if (!v->typed) v->kind = WATCH_UNSIGNED, v->size = size;
    if (v->size != 1 && v->size != 2 && v->size != 4)
        return snprintf(err, errn, "--watch: '%s' in %s is %u bytes: --watch reads 8/16/32-bit integers and floats",
                        v->name, image, (unsigned)v->size), -1;
    if (v->kind == WATCH_FLOAT && v->size != 4)
        return snprintf(err, errn, "--watch: '%s' in %s is a %u-byte float: --watch reads 4-byte floats", v->name, image,
                        (unsigned)v->size), -1;
    if (v->addr > ram_bytes || v->size > ram_bytes - v->addr)
        return snprintf(err, errn, "--watch: '%s' in %s lies outside the MCU's %u bytes of data space", v->name, image,
                        (unsigned)ram_bytes), -1;
    type_word(v);
    return 0;
}

/* The names of list into w (each 1..WATCH_NAME_BYTES - 1 characters, at most WATCH_MAX): 0, or -1 with err. */
static int split_names(watch_list_t *w, const char *list, char *err, size_t errn)
{
    const char *p = list;
    w->n = 0;
    for (;;) {
        size_t k = strcspn(p, ",");
        if (k == 0 || k >= WATCH_NAME_BYTES)
            return snprintf(err, errn, "--watch: expected NAME[,NAME...] (names of 1 to %d characters), got '%s'",
                            WATCH_NAME_BYTES - 1, list), -1;
        if (w->n == WATCH_MAX) return snprintf(err, errn, "--watch: at most %d variables, got '%s'", WATCH_MAX, list), -1;
        watch_var_t *v = &w->v[w->n];
        memset(v, 0, sizeof *v);
        memcpy(v->name, p, k);
        w->names[w->n] = v->name;
        w->types[w->n] = v->type;
        w->n++;
        if (!p[k]) return 0;
        p += k + 1;
    }
}

int watch_open(watch_list_t *w, const char *image, const char *list, const struct avr_t *avr, FILE *note, char *err,
               size_t errn)
{
    uint32_t ram_bytes = (uint32_t)avr->ramend + 1u;
    if (split_names(w, list, err, errn) != 0) return -1;
    size_t n = strlen(image);
    if (n > 4 && !strcmp(image + n - 4, ".hex"))
        return snprintf(err, errn, "--watch: %s is Intel HEX: --watch needs the ELF image (its symbol table)", image), -1;
    size_t len;
    char *buf = infile_read(image, AVRHOST_IMAGE_MAX_BYTES, &len, err, errn);
    if (!buf) return -1;
    int rc = 0;
    for (int i = 0; i < w->n && rc == 0; i++) rc = look_up(buf, len, image, ram_bytes, &w->v[i], err, errn);
    free(buf);
    for (int i = 0; i < w->n && rc == 0 && note; i++) /* once every name is good: an error stays one line */
        if (!w->v[i].typed)
            fprintf(note, "mmsim: --watch: %s has no DWARF type for '%s': read as %s (an unsigned integer of its size)\n",
                    image, w->v[i].name, w->v[i].type);
    return rc;
}

void watch_sample(const watch_list_t *w, const struct avr_t *avr, double *values)
{
    uint32_t ram_bytes = (uint32_t)avr->ramend + 1u;
    for (int i = 0; i < w->n; i++) {
        const watch_var_t *v = &w->v[i];
        if (v->addr > ram_bytes || v->size > ram_bytes - v->addr) { /* checked at open; never read outside */
            values[i] = 0.0;
            continue;
        }
        uint32_t raw = le(avr->data + v->addr, (int)v->size);
        float f;
        memcpy(&f, &raw, sizeof f); /* the host's float is IEEE 754 single, as avr-gcc's */
        if (v->kind == WATCH_FLOAT) values[i] = f;
        else if (v->kind == WATCH_UNSIGNED) values[i] = raw;
        else if (v->size == 1) values[i] = (int8_t)raw;
        else if (v->size == 2) values[i] = (int16_t)raw;
        else values[i] = (int32_t)raw;
    }
}

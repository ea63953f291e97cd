/* elfvar.c - a firmware's global variables by name in an ELF image (see
 * elfvar.h). The ELF's structure and its symbol table are elf32.c's checked
 * reader; the types come from elfvar_dwarf.c. */
#include "elfvar.h"

#include <ctype.h>
#include <stdlib.h>
#include <string.h>

#include "elf32.h"
#include "elfvar_dwarf.h"
#include "infile.h"

static uint32_t le(const uint8_t *p, int bytes)
{
    uint32_t v = 0;
    for (int i = bytes - 1; i >= 0; i--) v = v << 8 | p[i];
    return v;
}

static void type_word(elfvar_t *v)
{
    snprintf(v->type, sizeof v->type, "%c%u", v->kind == ELFVAR_FLOAT ? 'f' : v->kind == ELFVAR_SIGNED ? 'i' : 'u',
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
static int symbol_type(char *buf, size_t len, uint32_t value, elfvar_t *v, char *why, size_t whyn)
{
    int typed = elfvar_dwarf_type(buf, len, value, v, why, whyn);
    elfvar_t src = *v;
    source_name(v->name, src.name, sizeof src.name);
    if (typed != 0 || !strcmp(src.name, v->name)) return typed;
    typed = elfvar_dwarf_type(buf, len, value, &src, why, whyn);
    v->kind = src.kind, v->size = src.size;
    return typed;
}

/* A name's ELF data address and type: its object symbol (or the _ZL name of
 * a C++ file-scope static), else its DWARF entry alone (a static LTO
 * renamed NAME.lto_priv.N). 0 with *value, v->typed (and v's type when
 * typed) and *size, or -1 with err. */
static int find_var(elf32_t *e, char *buf, const elfvar_space_t *sp, elfvar_t *v, uint32_t *value, uint32_t *size,
                    char *err, size_t errn)
{
    char zl[ELFVAR_NAME_BYTES + 24]; /* "_ZL", the length's digits, the name */
    snprintf(zl, sizeof zl, "_ZL%zu%s", strlen(v->name), v->name); /* C++'s name for a file-scope static */
    const char *image = e->path;
    size_t len = e->n;
    int f = elf32_object(e, v->name, value, size);
    if (f == 0) f = elf32_object(e, zl, value, size);
    if (f == -2) return snprintf(err, errn, "--watch: %s has no symbol table (a stripped image?): --watch needs one", image), -1;
    if (f < 0) return snprintf(err, errn, "--watch: '%s' names two static variables in %s", v->name, image), -1;
    if (f == 1 && (*value < sp->lo || *value >= sp->hi))
        return snprintf(err, errn, "--watch: '%s' in %s is not in SRAM (address 0x%X): --watch reads SRAM variables",
                        v->name, image, (unsigned)*value), -1;
    char why[200] = "";
    int typed = f == 1 ? symbol_type(buf, len, *value, v, why, sizeof why)
                       : elfvar_dwarf_find(buf, len, sp->lo, sp->hi, value, v, why, sizeof why);
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
static int look_up(elf32_t *e, char *buf, const elfvar_space_t *sp, elfvar_t *v, char *err, size_t errn)
{
    uint32_t value = 0, size = 0, ram_bytes = sp->bytes;
    const char *image = e->path;
    if (find_var(e, buf, sp, v, &value, &size, err, errn) != 0) return -1;
    v->addr = value - sp->base;
    if (!v->typed) v->kind = ELFVAR_UNSIGNED, v->size = size;
    if (v->size != 1 && v->size != 2 && v->size != 4)
        return snprintf(err, errn, "--watch: '%s' in %s is %u bytes: --watch reads 8/16/32-bit integers and floats",
                        v->name, image, (unsigned)v->size), -1;
    if (v->kind == ELFVAR_FLOAT && v->size != 4)
        return snprintf(err, errn, "--watch: '%s' in %s is a %u-byte float: --watch reads 4-byte floats", v->name, image,
                        (unsigned)v->size), -1;
    if (v->addr > ram_bytes || v->size > ram_bytes - v->addr)
        return snprintf(err, errn, "--watch: '%s' in %s lies outside the MCU's %u bytes of data space", v->name, image,
                        (unsigned)ram_bytes), -1;
    type_word(v);
    return 0;
}

/* The names of list into w (each 1..ELFVAR_NAME_BYTES - 1 characters, at most ELFVAR_MAX): 0, or -1 with err. */
static int split_names(elfvar_list_t *w, const char *list, char *err, size_t errn)
{
    const char *p = list;
    w->n = 0;
    for (;;) {
        size_t k = strcspn(p, ",");
        if (k == 0 || k >= ELFVAR_NAME_BYTES)
            return snprintf(err, errn, "--watch: expected NAME[,NAME...] (names of 1 to %d characters), got '%s'",
                            ELFVAR_NAME_BYTES - 1, list), -1;
        if (w->n == ELFVAR_MAX) return snprintf(err, errn, "--watch: at most %d variables, got '%s'", ELFVAR_MAX, list), -1;
        elfvar_t *v = &w->v[w->n];
        memset(v, 0, sizeof *v);
        memcpy(v->name, p, k);
        w->names[w->n] = v->name;
        w->types[w->n] = v->type;
        w->n++;
        if (!p[k]) return 0;
        p += k + 1;
    }
}

int elfvar_open(elfvar_list_t *w, const char *image, const char *list, const elfvar_space_t *sp, FILE *note, char *err,
                size_t errn)
{
    if (split_names(w, list, err, errn) != 0) return -1;
    size_t n = strlen(image);
    if (n > 4 && !strcmp(image + n - 4, ".hex"))
        return snprintf(err, errn, "--watch: %s is Intel HEX: --watch needs the ELF image (its symbol table)", image), -1;
    size_t len;
    char *buf = infile_read(image, sp->image_max, &len, err, errn);
    if (!buf) return -1;
    char why[300];
    elf32_t e = { .b = (const uint8_t *)buf, .n = len, .path = image, .kind = sp->kind, .machine = sp->machine, .err = why,
                  .errn = sizeof why };
    int rc = elf32_check_header(&e) == 0 && elf32_check_sections(&e) == 0 ? 0 : -1;
    if (rc != 0) snprintf(err, errn, "--watch: %s", why);
    for (int i = 0; i < w->n && rc == 0; i++) rc = look_up(&e, buf, sp, &w->v[i], err, errn);
    free(buf);
    for (int i = 0; i < w->n && rc == 0 && note; i++) /* once every name is good: an error stays one line */
        if (!w->v[i].typed)
            fprintf(note, "mmsim: --watch: %s has no DWARF type for '%s': read as %s (an unsigned integer of its size)\n",
                    image, w->v[i].name, w->v[i].type);
    return rc;
}

double elfvar_value(const elfvar_t *v, const uint8_t *bytes)
{
    uint32_t raw = le(bytes, (int)v->size);
    float f;
    memcpy(&f, &raw, sizeof f); /* the host's float is IEEE 754 single, as avr-gcc's and arm-none-eabi-gcc's */
    if (v->kind == ELFVAR_FLOAT) return f;
    if (v->kind == ELFVAR_UNSIGNED) return raw;
    if (v->size == 1) return (int8_t)raw;
    if (v->size == 2) return (int16_t)raw;
    return (int32_t)raw;
}

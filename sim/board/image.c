/* image.c - AVR firmware images checked before simavr reads them (see image.h). */
#include "image.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "io/elf32.h"
#include "io/infile.h"

#define EM_AVR_MACHINE 83u

/* .mmcu tags (simavr's avr_mcu_section.h) and the bytes simavr reads of each */
enum { TAG_NAME = 1, TAG_FREQUENCY = 2, TAG_VCC = 3, TAG_AVCC = 4, TAG_AREF = 5, TAG_LFUSE = 6, TAG_HFUSE = 7, TAG_EFUSE = 8,
       TAG_SIGNATURE = 9, TAG_COMMAND = 10, TAG_CONSOLE = 11, TAG_VCD_FILENAME = 12, TAG_VCD_PERIOD = 13, TAG_VCD_TRACE = 14,
       TAG_VCD_PORTPIN = 15, TAG_VCD_IRQ = 16, TAG_EXTERNAL_PULL = 17 };

#define le32 elf32_le32

/* the generic ELF32 structure (sim/io/elf32.c) and what the .mmcu tags add */
typedef struct {
    elf32_t x;
    int traces; /* VCD trace tags seen in all .mmcu sections */
    int has_fuse, has_lock;
} elf_t;

static const uint8_t *shdr(const elf_t *e, uint32_t i) { return elf32_shdr(&e->x, i); }
static int fail(const elf_t *e, const char *what) { return elf32_fail(&e->x, what); }
static const char *str_at(const elf_t *e, uint32_t t, uint32_t off) { return elf32_str(&e->x, t, off); }
static int elf_open(elf_t *e, const uint8_t *b, size_t n, const char *path, char *err, size_t errn)
{
    memset(e, 0, sizeof *e);
    e->x = (elf32_t){ .b = b, .n = n, .path = path, .kind = "AVR", .machine = EM_AVR_MACHINE, .err = err, .errn = errn };
    if (elf32_check_header(&e->x) != 0) return -1;
    return elf32_check_sections(&e->x);
}

/* a NUL-ended string of fewer than max bytes in the n bytes at v */
static int tag_string(const elf_t *e, const uint8_t *v, uint32_t n, uint32_t max, const char *what)
{
    char m[200];
    const uint8_t *z = memchr(v, 0, n);
    if (!z) return snprintf(m, sizeof m, ".mmcu: its %s does not end within its tag", what), fail(e, m);
    if ((uint32_t)(z - v) >= max)
        return snprintf(m, sizeof m, ".mmcu: its %s is %u characters (at most %u)", what, (unsigned)(z - v), max - 1),
               fail(e, m);
    return 0;
}

/* the bytes simavr reads of a tag's value (0: a string checked by tag_string) */
static uint32_t tag_min_bytes(unsigned tag)
{
    switch (tag) {
    case TAG_FREQUENCY: case TAG_VCC: case TAG_AVCC: case TAG_AREF: case TAG_VCD_PERIOD: case TAG_EXTERNAL_PULL:
    case TAG_SIGNATURE: return 4;
    case TAG_COMMAND: case TAG_CONSOLE: return 2;
    case TAG_LFUSE: case TAG_HFUSE: case TAG_EFUSE: return 1;
    case TAG_VCD_TRACE: case TAG_VCD_PORTPIN: case TAG_VCD_IRQ: return 4; /* mask, address, a name of at least its NUL */
    default: return 0;
    }
}

static int check_tag(elf_t *e, unsigned tag, const uint8_t *v, uint32_t len, image_elf_t *out)
{
    char m[200];
    if (len < tag_min_bytes(tag))
        return snprintf(m, sizeof m, ".mmcu: tag %u has %u bytes (simavr reads %u)", tag, len, tag_min_bytes(tag)),
               fail(e, m);
    if (tag == TAG_NAME) {
        if (tag_string(e, v, len, IMAGE_MCU_NAME_BYTES, "MCU name") != 0) return -1;
        for (const uint8_t *c = v; *c; c++) /* the name goes into our one-line messages */
            if (*c < 0x21 || *c > 0x7E)
                return snprintf(m, sizeof m, ".mmcu: its MCU name has a byte 0x%02X (letters, digits and marks only)", *c),
                       fail(e, m);
        snprintf(out->mcu, sizeof out->mcu, "%s", (const char *)v);
    } else if (tag == TAG_FREQUENCY) {
        out->f_cpu = le32(v);
    } else if (tag == TAG_VCD_FILENAME) {
        return tag_string(e, v, len, IMAGE_TRACE_NAME_BYTES, "trace file name");
    } else if (tag == TAG_VCD_TRACE || tag == TAG_VCD_PORTPIN || tag == TAG_VCD_IRQ) { /* each takes one of simavr's trace slots */
        if (++e->traces > IMAGE_TRACES_MAX)
            return snprintf(m, sizeof m, ".mmcu: more than %d trace tags", IMAGE_TRACES_MAX), fail(e, m);
        return tag_string(e, v + 3, len - 3, len - 2, "trace name");
    }
    return 0;
}

/* the .mmcu tags: each {tag, length, value} within the section */
static int check_mmcu(elf_t *e, uint32_t i, image_elf_t *out)
{
    const uint8_t *s = shdr(e, i);
    const uint8_t *p = e->x.b + le32(s + 16);
    uint32_t size = le32(s + 20), at = 0;
    char m[200];
    while (at < size) {
        if (size - at < 2 || p[at + 1] > size - at - 2)
            return snprintf(m, sizeof m, ".mmcu: the tag at byte %u runs past its section (%u bytes)", at, size), fail(e, m);
        if (check_tag(e, p[at], p + at + 2, p[at + 1], out) != 0) return -1;
        at += 2u + p[at + 1];
    }
    return 0;
}

/* the sections simavr copies by name: bytes in the file, .fuse within simavr's fuse bytes, .lock beside a .fuse */
static int check_named(elf_t *e, uint32_t i, image_elf_t *out)
{
    static const char *const copied[] = { ".text", ".data", ".eeprom", ".fuse", ".lock", ".mmcu" };
    const uint8_t *s = shdr(e, i);
    const char *name = str_at(e, e->x.shstr, le32(s));
    char m[200];
    uint32_t type = le32(s + 4);
    for (size_t k = 0; k < sizeof copied / sizeof copied[0]; k++) {
        if (strcmp(name, copied[k])) continue;
        if (type == ELF32_SHT_NOBITS) return snprintf(m, sizeof m, "section %s has no bytes in the file (NOBITS)", name), fail(e, m);
        if (type != ELF32_SHT_PROGBITS) /* libelf would convert other types' bytes, or fail and give simavr none */
            return snprintf(m, sizeof m, "section %s is of type %u, not program bytes (PROGBITS)", name, type), fail(e, m);
    }
    if (!strcmp(name, ".bss") && type != ELF32_SHT_NOBITS && type != ELF32_SHT_PROGBITS)
        return snprintf(m, sizeof m, "section .bss is of type %u, not NOBITS", type), fail(e, m);
    if (!strcmp(name, ".fuse")) {
        e->has_fuse = 1;
        if (le32(s + 20) > IMAGE_FUSE_MAX_BYTES)
            return snprintf(m, sizeof m, "section .fuse has %u bytes (an AVR has at most %u)", le32(s + 20),
                            IMAGE_FUSE_MAX_BYTES), fail(e, m);
    }
    if (!strcmp(name, ".lock")) e->has_lock = 1;
    if (!strcmp(name, ".mmcu")) return check_mmcu(e, i, out);
    return 0;
}

int image_check_elf(const char *path, size_t max_bytes, image_elf_t *out, char *err, size_t errn)
{
    memset(out, 0, sizeof *out);
    size_t n = 0;
    char *buf = infile_read(path, max_bytes, &n, err, errn);
    if (!buf) return -1;
    elf_t e;
    int rc = elf_open(&e, (const uint8_t *)buf, n, path, err, errn);
    for (uint32_t i = 0; rc == 0 && i < e.x.shnum; i++) {
        if (le32(shdr(&e, i) + 4) == ELF32_SHT_SYMTAB) rc = elf32_check_symtab(&e.x, i);
        if (rc == 0) rc = check_named(&e, i, out);
    }
    if (rc == 0 && e.has_lock && !e.has_fuse) rc = fail(&e, "a .lock section without a .fuse section (simavr needs both)");
    if (rc == 0) out->arch = le32(e.x.b + 36) & 0x7Fu;
    free(buf);
    return rc;
}

unsigned image_mcu_arch(const char *mcu)
{
    static const struct { const char *mcu; unsigned arch; } tab[] = {
        { "atmega48", 4 }, { "atmega48p", 4 }, { "atmega88", 4 }, { "atmega88p", 4 }, { "atmega8", 4 },
        { "atmega168", 5 }, { "atmega168p", 5 }, { "atmega328", 5 }, { "atmega328p", 5 }, { "atmega16", 5 },
        { "atmega32", 5 }, { "atmega164p", 5 }, { "atmega324p", 5 }, { "atmega644", 5 }, { "atmega644p", 5 },
        { "atmega32u4", 5 }, { "atmega128", 51 }, { "atmega1280", 51 }, { "atmega1281", 51 }, { "atmega1284p", 51 },
        { "atmega2560", 6 }, { "atmega2561", 6 }, { "attiny85", 25 }, { "attiny45", 25 }, { "attiny25", 25 },
        { "attiny84", 25 }, { "attiny44", 25 }, { "attiny13", 25 }, { "attiny2313", 25 },
    };
    for (size_t i = 0; i < sizeof tab / sizeof tab[0]; i++)
        if (!strcmp(tab[i].mcu, mcu)) return tab[i].arch;
    return 0;
}

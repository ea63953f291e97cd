/* image.c - AVR firmware images checked before simavr reads them (see image.h). */
#include "image.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "io/infile.h"

/* ELF32 layout (the System V ABI): offsets in bytes into each structure */
#define EHDR_BYTES 52u
#define PHDR_BYTES 32u
#define SHDR_BYTES 40u
#define SYM_BYTES 16u
#define EM_AVR_MACHINE 83u
#define SHT_NULL_TYPE 0u
#define SHT_PROGBITS_TYPE 1u
#define SHT_SYMTAB_TYPE 2u
#define SHT_STRTAB_TYPE 3u
#define SHT_NOBITS_TYPE 8u
#define SHN_LORESERVE_INDEX 0xFF00u
#define STT_OBJECT_TYPE 1u /* a symbol's type: a variable */
#define STB_GLOBAL_BIND 1u /* a symbol's binding: global (0: local) */
#define SHF_COMPRESSED_FLAG 0x800u /* libelf would inflate the section: simavr reads such a name table as none */

/* .mmcu tags (simavr's avr_mcu_section.h) and the bytes simavr reads of each */
enum { TAG_NAME = 1, TAG_FREQUENCY = 2, TAG_VCC = 3, TAG_AVCC = 4, TAG_AREF = 5, TAG_LFUSE = 6, TAG_HFUSE = 7, TAG_EFUSE = 8,
       TAG_SIGNATURE = 9, TAG_COMMAND = 10, TAG_CONSOLE = 11, TAG_VCD_FILENAME = 12, TAG_VCD_PERIOD = 13, TAG_VCD_TRACE = 14,
       TAG_VCD_PORTPIN = 15, TAG_VCD_IRQ = 16, TAG_EXTERNAL_PULL = 17 };

static uint32_t le16(const uint8_t *p) { return (uint32_t)p[0] | (uint32_t)p[1] << 8; }
static uint32_t le32(const uint8_t *p) { return le16(p) | le16(p + 2) << 16; }
/* off + n bytes lie within size bytes (no overflow: 64-bit sums of 32-bit values) */
static int within(uint64_t off, uint64_t n, uint64_t size) { return off <= size && n <= size - off; }

typedef struct {
    const uint8_t *b;
    size_t n;
    const char *path;
    char *err;
    size_t errn;
    uint32_t shoff, shnum, shstr; /* section header table, its entries, the name table's index */
    int traces;                   /* VCD trace tags seen in all .mmcu sections */
    int has_fuse, has_lock;
} elf_t;

static const uint8_t *shdr(const elf_t *e, uint32_t i) { return e->b + e->shoff + (size_t)i * SHDR_BYTES; }

static int fail(const elf_t *e, const char *what)
{
    snprintf(e->err, e->errn, "%s: %s", e->path, what);
    return -1;
}

static int check_header(elf_t *e)
{
    const uint8_t *b = e->b;
    char m[200];
    if (e->n < EHDR_BYTES || memcmp(b, "\x7f" "ELF", 4) != 0) return fail(e, "not an AVR ELF image (no ELF header)");
    if (b[4] != 1) return fail(e, "a 64-bit ELF: an AVR image is 32-bit (ELFCLASS32)");
    if (b[5] != 1) return fail(e, "a big-endian ELF: an AVR image is little-endian");
    if (le16(b + 18) != EM_AVR_MACHINE)
        return snprintf(m, sizeof m, "an ELF for machine %u, not an AVR (83)", le16(b + 18)), fail(e, m);
    uint32_t phoff = le32(b + 28), phnum = le16(b + 44);
    e->shoff = le32(b + 32), e->shnum = le16(b + 48), e->shstr = le16(b + 50);
    if (phnum > 0 && (le16(b + 42) != PHDR_BYTES || !within(phoff, (uint64_t)phnum * PHDR_BYTES, e->n)))
        return snprintf(m, sizeof m, "its program header table (%u entries at byte %u) is not within the file (%zu bytes)",
                        phnum, phoff, e->n), fail(e, m);
    for (uint32_t i = 0; i < phnum; i++) {
        const uint8_t *p = b + phoff + (size_t)i * PHDR_BYTES;
        if (!within(le32(p + 4), le32(p + 16), e->n))
            return snprintf(m, sizeof m, "segment %u (%u bytes at byte %u) is not within the file (%zu bytes)", i,
                            le32(p + 16), le32(p + 4), e->n), fail(e, m);
    }
    if (e->shnum == 0 || le16(b + 46) != SHDR_BYTES || !within(e->shoff, (uint64_t)e->shnum * SHDR_BYTES, e->n))
        return snprintf(m, sizeof m, "its section header table (%u entries at byte %u) is not within the file (%zu bytes)",
                        e->shnum, e->shoff, e->n), fail(e, m);
    if (e->shstr >= e->shnum || e->shstr >= SHN_LORESERVE_INDEX || le32(shdr(e, e->shstr) + 4) != SHT_STRTAB_TYPE)
        return snprintf(m, sizeof m, "its section name table index %u is not a string table (%u sections)", e->shstr,
                        e->shnum), fail(e, m);
    return 0;
}

/* the string at off in string table section t, or NULL if it does not end within the table */
static const char *str_at(const elf_t *e, uint32_t t, uint32_t off)
{
    const uint8_t *s = shdr(e, t);
    uint32_t base = le32(s + 16), size = le32(s + 20);
    if (off >= size) return NULL;
    return memchr(e->b + base + off, 0, size - off) ? (const char *)e->b + base + off : NULL;
}

/* every section's bytes within the file, and its name within the name table */
static int check_sections(elf_t *e)
{
    char m[200];
    for (uint32_t i = 0; i < e->shnum; i++) {
        const uint8_t *s = shdr(e, i);
        uint32_t type = le32(s + 4), off = le32(s + 16), size = le32(s + 20);
        if (type != SHT_NOBITS_TYPE && type != SHT_NULL_TYPE && !within(off, size, e->n))
            return snprintf(m, sizeof m, "section %u (%u bytes at byte %u) is not within the file (%zu bytes)", i, size,
                            off, e->n), fail(e, m);
        if (le32(s + 8) & SHF_COMPRESSED_FLAG)
            return snprintf(m, sizeof m, "section %u is compressed (SHF_COMPRESSED): an AVR image's sections are not", i),
                   fail(e, m);
    }
    for (uint32_t i = 0; i < e->shnum; i++)
        if (!str_at(e, e->shstr, le32(shdr(e, i))))
            return snprintf(m, sizeof m, "section %u's name (at 0x%x) is not within the section name table (%u bytes)", i,
                            le32(shdr(e, i)), le32(shdr(e, e->shstr) + 20)), fail(e, m);
    return 0;
}

/* a symbol table simavr walks: whole entries, its names within its string table */
static int check_symtab(elf_t *e, uint32_t i)
{
    const uint8_t *s = shdr(e, i);
    uint32_t off = le32(s + 16), size = le32(s + 20), link = le32(s + 24);
    char m[200];
    if (le32(s + 36) != SYM_BYTES || size % SYM_BYTES != 0)
        return snprintf(m, sizeof m, "symbol table section %u has entries of %u bytes (an ELF32 symbol is 16)", i,
                        le32(s + 36)), fail(e, m);
    if (link >= e->shnum || le32(shdr(e, link) + 4) != SHT_STRTAB_TYPE)
        return snprintf(m, sizeof m, "symbol table section %u links to section %u, not a string table", i, link), fail(e, m);
    for (uint32_t k = 0; k < size / SYM_BYTES; k++)
        if (!str_at(e, link, le32(e->b + off + (size_t)k * SYM_BYTES)))
            return snprintf(m, sizeof m, "symbol %u's name (at 0x%x) is not within its string table", k,
                            le32(e->b + off + (size_t)k * SYM_BYTES)), fail(e, m);
    return 0;
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
    const uint8_t *p = e->b + le32(s + 16);
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
    const char *name = str_at(e, e->shstr, le32(s));
    char m[200];
    uint32_t type = le32(s + 4);
    for (size_t k = 0; k < sizeof copied / sizeof copied[0]; k++) {
        if (strcmp(name, copied[k])) continue;
        if (type == SHT_NOBITS_TYPE) return snprintf(m, sizeof m, "section %s has no bytes in the file (NOBITS)", name), fail(e, m);
        if (type != SHT_PROGBITS_TYPE) /* libelf would convert other types' bytes, or fail and give simavr none */
            return snprintf(m, sizeof m, "section %s is of type %u, not program bytes (PROGBITS)", name, type), fail(e, m);
    }
    if (!strcmp(name, ".bss") && type != SHT_NOBITS_TYPE && type != SHT_PROGBITS_TYPE)
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
    elf_t e = { .b = (const uint8_t *)buf, .n = n, .path = path, .err = err, .errn = errn };
    int rc = check_header(&e);
    if (rc == 0) rc = check_sections(&e);
    for (uint32_t i = 0; rc == 0 && i < e.shnum; i++) {
        if (le32(shdr(&e, i) + 4) == SHT_SYMTAB_TYPE) rc = check_symtab(&e, i);
        if (rc == 0) rc = check_named(&e, i, out);
    }
    if (rc == 0 && e.has_lock && !e.has_fuse) rc = fail(&e, "a .lock section without a .fuse section (simavr needs both)");
    if (rc == 0) out->arch = le32(e.b + 36) & 0x7Fu;
    free(buf);
    return rc;
}

/* The object symbol name in symbol table section t (checked): a global one
 * before a local one; 1 with its value and size, 0 none, -1 two locals of
 * that name and no global. */
static int find_object(const elf_t *e, uint32_t t, const char *name, uint32_t *value, uint32_t *size)
{
    const uint8_t *s = shdr(e, t);
    uint32_t off = le32(s + 16), count = le32(s + 20) / SYM_BYTES, link = le32(s + 24);
    int locals = 0;
    for (uint32_t k = 0; k < count; k++) {
        const uint8_t *sym = e->b + off + (size_t)k * SYM_BYTES;
        if ((sym[12] & 0xFu) != STT_OBJECT_TYPE) continue;
        const char *n = str_at(e, link, le32(sym));
        if (!n || strcmp(n, name) != 0) continue;
        int global = (sym[12] >> 4) == STB_GLOBAL_BIND;
        if (!global && locals++) continue; /* the first local is kept */
        *value = le32(sym + 4);
        *size = le32(sym + 8);
        if (global) return 1;
    }
    return locals > 1 ? -1 : locals;
}

int image_elf_object(const uint8_t *b, size_t n, const char *name, uint32_t *value, uint32_t *size)
{
    char err[200];
    elf_t e = { .b = b, .n = n, .path = "", .err = err, .errn = sizeof err };
    if (check_header(&e) != 0 || check_sections(&e) != 0) return -2;
    for (uint32_t i = 0; i < e.shnum; i++)
        if (le32(shdr(&e, i) + 4) == SHT_SYMTAB_TYPE) return check_symtab(&e, i) != 0 ? -2 : find_object(&e, i, name, value, size);
    return -2;
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

/* elf32.c - an ELF32 little-endian file's structure checked (see elf32.h). */
#include "elf32.h"

#include <stdio.h>
#include <string.h>

#define SHN_LORESERVE_INDEX 0xFF00u
#define SHF_COMPRESSED_FLAG 0x800u /* libelf would inflate the section: not an MCU image's */

/* off + n bytes lie within size bytes (no overflow: 64-bit sums of 32-bit values) */
static int within(uint64_t off, uint64_t n, uint64_t size) { return off <= size && n <= size - off; }

const uint8_t *elf32_shdr(const elf32_t *e, uint32_t i) { return e->b + e->shoff + (size_t)i * ELF32_SHDR_BYTES; }
const uint8_t *elf32_phdr(const elf32_t *e, uint32_t i) { return e->b + e->phoff + (size_t)i * ELF32_PHDR_BYTES; }

int elf32_fail(const elf32_t *e, const char *what)
{
    snprintf(e->err, e->errn, "%s: %s", e->path, what);
    return -1;
}

int elf32_check_header(elf32_t *e)
{
    const uint8_t *b = e->b;
    char m[200];
    if (e->n < ELF32_EHDR_BYTES || memcmp(b, "\x7f" "ELF", 4) != 0)
        return snprintf(m, sizeof m, "not an %s ELF image (no ELF header)", e->kind), elf32_fail(e, m);
    if (b[4] != 1) return snprintf(m, sizeof m, "a 64-bit ELF: an %s image is 32-bit (ELFCLASS32)", e->kind), elf32_fail(e, m);
    if (b[5] != 1) return snprintf(m, sizeof m, "a big-endian ELF: an %s image is little-endian", e->kind), elf32_fail(e, m);
    if (elf32_le16(b + 18) != e->machine)
        return snprintf(m, sizeof m, "an ELF for machine %u, not an %s (%u)", elf32_le16(b + 18), e->kind, e->machine),
               elf32_fail(e, m);
    e->phoff = elf32_le32(b + 28), e->phnum = elf32_le16(b + 44);
    e->shoff = elf32_le32(b + 32), e->shnum = elf32_le16(b + 48), e->shstr = elf32_le16(b + 50);
    if (e->phnum > 0 && (elf32_le16(b + 42) != ELF32_PHDR_BYTES || !within(e->phoff, (uint64_t)e->phnum * ELF32_PHDR_BYTES, e->n)))
        return snprintf(m, sizeof m, "its program header table (%u entries at byte %u) is not within the file (%zu bytes)",
                        e->phnum, e->phoff, e->n), elf32_fail(e, m);
    for (uint32_t i = 0; i < e->phnum; i++) {
        const uint8_t *p = elf32_phdr(e, i);
        if (!within(elf32_le32(p + 4), elf32_le32(p + 16), e->n))
            return snprintf(m, sizeof m, "segment %u (%u bytes at byte %u) is not within the file (%zu bytes)", i,
                            elf32_le32(p + 16), elf32_le32(p + 4), e->n), elf32_fail(e, m);
    }
    if (e->shnum == 0 || elf32_le16(b + 46) != ELF32_SHDR_BYTES || !within(e->shoff, (uint64_t)e->shnum * ELF32_SHDR_BYTES, e->n))
        return snprintf(m, sizeof m, "its section header table (%u entries at byte %u) is not within the file (%zu bytes)",
                        e->shnum, e->shoff, e->n), elf32_fail(e, m);
    if (e->shstr >= e->shnum || e->shstr >= SHN_LORESERVE_INDEX || elf32_le32(elf32_shdr(e, e->shstr) + 4) != ELF32_SHT_STRTAB)
        return snprintf(m, sizeof m, "its section name table index %u is not a string table (%u sections)", e->shstr,
                        e->shnum), elf32_fail(e, m);
    return 0;
}

const char *elf32_str(const elf32_t *e, uint32_t t, uint32_t off)
{
    const uint8_t *s = elf32_shdr(e, t);
    uint32_t base = elf32_le32(s + 16), size = elf32_le32(s + 20);
    if (off >= size) return NULL;
    return memchr(e->b + base + off, 0, size - off) ? (const char *)e->b + base + off : NULL;
}

int elf32_check_sections(elf32_t *e)
{
    char m[200];
    for (uint32_t i = 0; i < e->shnum; i++) {
        const uint8_t *s = elf32_shdr(e, i);
        uint32_t type = elf32_le32(s + 4), off = elf32_le32(s + 16), size = elf32_le32(s + 20);
        if (type != ELF32_SHT_NOBITS && type != ELF32_SHT_NULL && !within(off, size, e->n))
            return snprintf(m, sizeof m, "section %u (%u bytes at byte %u) is not within the file (%zu bytes)", i, size,
                            off, e->n), elf32_fail(e, m);
        if (elf32_le32(s + 8) & SHF_COMPRESSED_FLAG)
            return snprintf(m, sizeof m, "section %u is compressed (SHF_COMPRESSED): an %s image's sections are not", i,
                            e->kind), elf32_fail(e, m);
    }
    for (uint32_t i = 0; i < e->shnum; i++)
        if (!elf32_str(e, e->shstr, elf32_le32(elf32_shdr(e, i))))
            return snprintf(m, sizeof m, "section %u's name (at 0x%x) is not within the section name table (%u bytes)", i,
                            elf32_le32(elf32_shdr(e, i)), elf32_le32(elf32_shdr(e, e->shstr) + 20)), elf32_fail(e, m);
    return 0;
}

int elf32_check_symtab(elf32_t *e, uint32_t i)
{
    const uint8_t *s = elf32_shdr(e, i);
    uint32_t off = elf32_le32(s + 16), size = elf32_le32(s + 20), link = elf32_le32(s + 24);
    char m[200];
    if (elf32_le32(s + 36) != ELF32_SYM_BYTES || size % ELF32_SYM_BYTES != 0)
        return snprintf(m, sizeof m, "symbol table section %u has entries of %u bytes (an ELF32 symbol is 16)", i,
                        elf32_le32(s + 36)), elf32_fail(e, m);
    if (link >= e->shnum || elf32_le32(elf32_shdr(e, link) + 4) != ELF32_SHT_STRTAB)
        return snprintf(m, sizeof m, "symbol table section %u links to section %u, not a string table", i, link),
               elf32_fail(e, m);
    for (uint32_t k = 0; k < size / ELF32_SYM_BYTES; k++)
        if (!elf32_str(e, link, elf32_le32(e->b + off + (size_t)k * ELF32_SYM_BYTES)))
            return snprintf(m, sizeof m, "symbol %u's name (at 0x%x) is not within its string table", k,
                            elf32_le32(e->b + off + (size_t)k * ELF32_SYM_BYTES)), elf32_fail(e, m);
    return 0;
}

#define STT_OBJECT_TYPE 1u /* a symbol's type: a variable (System V ABI, "Symbol Table") */
#define STB_GLOBAL_BIND 1u /* a symbol's binding: global (0: local) */

/* The object symbol name in symbol table section t (checked). */
static int find_object(const elf32_t *e, uint32_t t, const char *name, uint32_t *value, uint32_t *size)
{
    const uint8_t *s = elf32_shdr(e, t);
    uint32_t off = elf32_le32(s + 16), count = elf32_le32(s + 20) / ELF32_SYM_BYTES, link = elf32_le32(s + 24);
    int locals = 0;
    for (uint32_t k = 0; k < count; k++) {
        const uint8_t *sym = e->b + off + (size_t)k * ELF32_SYM_BYTES;
        if ((sym[12] & 0xFu) != STT_OBJECT_TYPE) continue;
        const char *n = elf32_str(e, link, elf32_le32(sym));
        if (!n || strcmp(n, name) != 0) continue;
        int global = (sym[12] >> 4) == STB_GLOBAL_BIND;
        if (!global && locals++) continue; /* the first local is kept */
        *value = elf32_le32(sym + 4);
        *size = elf32_le32(sym + 8);
        if (global) return 1;
    }
    return locals > 1 ? -1 : locals;
}

int elf32_object(elf32_t *e, const char *name, uint32_t *value, uint32_t *size)
{
    for (uint32_t i = 0; i < e->shnum; i++)
        if (elf32_le32(elf32_shdr(e, i) + 4) == ELF32_SHT_SYMTAB) return elf32_check_symtab(e, i) != 0 ? -2 : find_object(e, i, name, value, size);
    return -2;
}

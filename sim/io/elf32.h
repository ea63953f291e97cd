/* elf32.h - the structure of an ELF32 little-endian file checked as
 * untrusted input (the System V ABI's layout): the header, the program and
 * section header tables and every segment's and section's bytes within the
 * file, section and symbol names within their string tables. What a
 * machine's image must say beyond that (the AVR's .mmcu tags, an ARM
 * image's vector table and memories) is its own reader's (sim/board/image.c,
 * sim/arm/armimage.c). Each fault is one line in err: "PATH: what". */
#ifndef ELF32_H
#define ELF32_H

#include <stddef.h>
#include <stdint.h>

#define ELF32_EHDR_BYTES 52u
#define ELF32_PHDR_BYTES 32u
#define ELF32_SHDR_BYTES 40u
#define ELF32_SYM_BYTES 16u
#define ELF32_SHT_NULL 0u
#define ELF32_SHT_PROGBITS 1u
#define ELF32_SHT_SYMTAB 2u
#define ELF32_SHT_STRTAB 3u
#define ELF32_SHT_NOBITS 8u
#define ELF32_PT_LOAD 1u

typedef struct {
    const uint8_t *b;    /* the file's bytes */
    size_t n;            /* their count */
    const char *path;    /* for messages */
    const char *kind;    /* "AVR", "ARM": the image's machine in messages */
    unsigned machine;    /* the e_machine it must have (83 AVR, 40 ARM) */
    char *err;
    size_t errn;
    uint32_t phoff, phnum;        /* program header table, its entries */
    uint32_t shoff, shnum, shstr; /* section header table, its entries, the name table's index */
} elf32_t;

static inline uint32_t elf32_le16(const uint8_t *p) { return (uint32_t)p[0] | (uint32_t)p[1] << 8; }
static inline uint32_t elf32_le32(const uint8_t *p) { return elf32_le16(p) | elf32_le16(p + 2) << 16; }

/* The header (class, byte order, machine) and both tables within the file,
 * every segment's file bytes within it. 0, or -1 with its line. */
int elf32_check_header(elf32_t *e);
/* Every section's bytes within the file, none compressed, every name within
 * the section name table. */
int elf32_check_sections(elf32_t *e);
/* Symbol table section i: whole entries, its names within its string table. */
int elf32_check_symtab(elf32_t *e, uint32_t i);
/* Section i's header, program header i (both checked within the file). */
const uint8_t *elf32_shdr(const elf32_t *e, uint32_t i);
const uint8_t *elf32_phdr(const elf32_t *e, uint32_t i);
/* The string at off in string table section t, NULL if it does not end within it. */
const char *elf32_str(const elf32_t *e, uint32_t t, uint32_t off);
/* The object symbol name (a variable) in the file's symbol table, checked:
 * a global one before a local one. 1 with its value and size, 0 none, -1
 * two locals of that name and no global, -2 no symbol table (or a bad one). */
int elf32_object(elf32_t *e, const char *name, uint32_t *value, uint32_t *size);
/* "PATH: what" into err; -1. */
int elf32_fail(const elf32_t *e, const char *what);

#endif

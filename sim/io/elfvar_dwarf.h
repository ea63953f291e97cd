/* elfvar_dwarf.h - a global variable's type from an ELF image's DWARF
 * (.debug_info, read with elfutils' libdw), for elfvar.c. */
#ifndef ELFVAR_DWARF_H
#define ELFVAR_DWARF_H

#include <stddef.h>
#include <stdint.h>

#include "elfvar.h"

/* The type of the variable v->name at ELF data address elf_addr in the
 * image's bytes (buf, len: the whole file, already checked as an ELF).
 * 1 with v->kind and v->size set from its base type (through typedefs,
 * volatile, const, enums and pointers); 0 if the image has no DWARF entry
 * for it; -1 with one line in err if it has one of a type --watch cannot
 * read (a struct, an array, a 64-bit number). */
int elfvar_dwarf_type(char *buf, size_t len, uint32_t elf_addr, elfvar_t *v, char *err, size_t errn);
/* The variable v->name found by its DWARF entry alone (a static whose
 * symbol the linker renamed, as LTO's NAME.lto_priv.N): the compilation
 * units' top-level variables of that name whose DW_AT_location is one
 * DW_OP_addr in [lo, hi) (ELF data addresses). 1 with *elf_addr and v's
 * type, 0 none, -1 with one line in err for a type --watch cannot read,
 * -2 with one line in err for two such variables at different addresses. */
int elfvar_dwarf_find(char *buf, size_t len, uint32_t lo, uint32_t hi, uint32_t *elf_addr, elfvar_t *v, char *err,
                     size_t errn);

#endif

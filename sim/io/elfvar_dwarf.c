/* elfvar_dwarf.c - a global variable's type from the image's DWARF (see
 * elfvar_dwarf.h). libdw reads .debug_info from the bytes in memory; each
 * compilation unit's top-level DW_TAG_variable entries are searched for
 * the name (and, where the entry has one, a DW_OP_addr location equal to
 * the symbol's address, so a static of the same name elsewhere is not
 * taken). Every walk is bounded: a crafted image cannot loop. */
#include "elfvar_dwarf.h"

#include <dwarf.h>
#include <elfutils/libdw.h>
#include <libelf.h>
#include <stdio.h>
#include <string.h>

#define DIES_MAX 1000000 /* top-level entries searched in all, a bound for a crafted image */
#define TYPE_DEPTH_MAX 16 /* typedef/volatile/const links followed to the base type */

/* Is die a variable named name? -1 no; 0 yes, without a location that starts
 * with DW_OP_addr; 1 yes, that address into *addr and the location's length into *nops. */
static int var_named(Dwarf_Die *die, const char *name, uint32_t *addr, size_t *nops)
{
    if (dwarf_tag(die) != DW_TAG_variable) return -1;
    const char *n = dwarf_diename(die);
    if (!n || strcmp(n, name) != 0) return -1;
    Dwarf_Attribute a;
    Dwarf_Op *ops;
    if (!dwarf_attr(die, DW_AT_location, &a) || dwarf_getlocation(&a, &ops, nops) != 0 || *nops < 1 ||
        ops[0].atom != DW_OP_addr)
        return 0;
    *addr = (uint32_t)ops[0].number;
    return 1;
}

/* Does die define the variable name at elf_addr (or with no address of its own)? */
static int is_var(Dwarf_Die *die, const char *name, uint32_t elf_addr)
{
    uint32_t at = 0;
    size_t nops = 0;
    int k = var_named(die, name, &at, &nops);
    return k == 0 || (k == 1 && at == elf_addr);
}

/* The entry die's DW_AT_type into *out: 0, or -1 (none). */
static int type_ref(Dwarf_Die *die, Dwarf_Die *out)
{
    Dwarf_Attribute a;
    if (!dwarf_attr_integrate(die, DW_AT_type, &a)) return -1;
    return dwarf_formref_die(&a, out) ? 0 : -1;
}

static const char *tag_words(int tag)
{
    switch (tag) {
    case DW_TAG_structure_type: return "a struct";
    case DW_TAG_class_type: return "a class";
    case DW_TAG_union_type: return "a union";
    case DW_TAG_array_type: return "an array";
    default: return "not a number";
    }
}

/* A base type's encoding and size into v: 1, or -1 with err. */
static int base_kind(Dwarf_Die *t, elfvar_t *v, char *err, size_t errn)
{
    Dwarf_Attribute a;
    Dwarf_Word enc = 0;
    int size = dwarf_bytesize(t);
    if (!dwarf_attr(t, DW_AT_encoding, &a) || dwarf_formudata(&a, &enc) != 0 || size <= 0) {
        snprintf(err, errn, "its DWARF base type has no encoding or size");
        return -1;
    }
    if (enc == DW_ATE_float) v->kind = ELFVAR_FLOAT;
    else if (enc == DW_ATE_signed || enc == DW_ATE_signed_char) v->kind = ELFVAR_SIGNED;
    else if (enc == DW_ATE_unsigned || enc == DW_ATE_unsigned_char || enc == DW_ATE_boolean) v->kind = ELFVAR_UNSIGNED;
    else {
        snprintf(err, errn, "its DWARF base type (encoding %u) is not an integer or a float", (unsigned)enc);
        return -1;
    }
    v->size = (uint32_t)size;
    return 1;
}

/* The variable's type through typedefs, qualifiers, enums (their
 * underlying type, else signed) and pointers (unsigned): 1, or -1 with err. */
static int resolve(Dwarf_Die *var, elfvar_t *v, char *err, size_t errn)
{
    Dwarf_Die t;
    if (type_ref(var, &t) != 0) return snprintf(err, errn, "its DWARF entry has no type"), -1;
    for (int depth = 0; depth < TYPE_DEPTH_MAX; depth++) {
        int tag = dwarf_tag(&t);
        if (tag == DW_TAG_base_type) return base_kind(&t, v, err, errn);
        if (tag == DW_TAG_pointer_type || tag == DW_TAG_enumeration_type) {
            Dwarf_Die under;
            if (tag == DW_TAG_enumeration_type && type_ref(&t, &under) == 0) {
                t = under;
                continue;
            }
            int size = dwarf_bytesize(&t);
            if (size <= 0) return snprintf(err, errn, "its DWARF type has no size"), -1;
            v->kind = tag == DW_TAG_pointer_type ? ELFVAR_UNSIGNED : ELFVAR_SIGNED;
            v->size = (uint32_t)size;
            return 1;
        }
        if (tag != DW_TAG_typedef && tag != DW_TAG_volatile_type && tag != DW_TAG_const_type &&
            tag != DW_TAG_restrict_type)
            return snprintf(err, errn, "its type is %s", tag_words(tag)), -1;
        if (type_ref(&t, &t) != 0) return snprintf(err, errn, "its DWARF type chain is broken"), -1;
    }
    return snprintf(err, errn, "its DWARF type chain is deeper than %d", TYPE_DEPTH_MAX), -1;
}

/* Search the compilation units of dw: 1 found and typed, 0 none, -1 err. */
static int search(Dwarf *dw, uint32_t elf_addr, elfvar_t *v, char *err, size_t errn)
{
    Dwarf_Off off = 0, next;
    size_t hsize;
    long seen = 0;
    while (dwarf_nextcu(dw, off, &next, &hsize, NULL, NULL, NULL) == 0 && next > off) {
        Dwarf_Die cu, die;
        if (dwarf_offdie(dw, off + hsize, &cu) && dwarf_child(&cu, &die) == 0) {
            do {
                if (++seen > DIES_MAX) return 0;
                if (is_var(&die, v->name, elf_addr)) return resolve(&die, v, err, errn);
            } while (dwarf_siblingof(&die, &die) == 0);
        }
        off = next;
    }
    return 0;
}

/* Does die define a variable named name with a DW_OP_addr location in [lo, hi)? Its address into *addr. */
static int is_placed_var(Dwarf_Die *die, const char *name, uint32_t lo, uint32_t hi, uint32_t *addr)
{
    uint32_t at = 0;
    size_t nops = 0;
    if (var_named(die, name, &at, &nops) != 1 || nops != 1 || at < lo || at >= hi) return 0;
    *addr = at;
    return 1;
}

/* Every compilation unit's top-level variables named v->name placed in
 * [lo, hi): 1 with the one address and its type, 0 none, -1 with err (two
 * places, or a type --watch cannot read). */
static int search_placed(Dwarf *dw, uint32_t lo, uint32_t hi, uint32_t *elf_addr, elfvar_t *v, char *err,
                         size_t errn)
{
    Dwarf_Off off = 0, next;
    size_t hsize;
    long seen = 0;
    int found = 0;
    Dwarf_Die hit;
    while (dwarf_nextcu(dw, off, &next, &hsize, NULL, NULL, NULL) == 0 && next > off) {
        Dwarf_Die cu, die;
        if (dwarf_offdie(dw, off + hsize, &cu) && dwarf_child(&cu, &die) == 0) {
            do {
                uint32_t a;
                if (++seen > DIES_MAX) break;
                if (!is_placed_var(&die, v->name, lo, hi, &a) || (found && a == *elf_addr)) continue;
                if (found)
                    return snprintf(err, errn, "its DWARF has two variables of that name (at 0x%X and 0x%X): watch one by its symbol (nm lists them)",
                                    (unsigned)*elf_addr, (unsigned)a), -2;
                found = 1, *elf_addr = a, hit = die;
            } while (dwarf_siblingof(&die, &die) == 0);
        }
        off = next;
    }
    return found ? resolve(&hit, v, err, errn) : 0;
}

int elfvar_dwarf_find(char *buf, size_t len, uint32_t lo, uint32_t hi, uint32_t *elf_addr, elfvar_t *v, char *err,
                     size_t errn)
{
    if (elf_version(EV_CURRENT) == EV_NONE) return 0;
    Elf *e = elf_memory(buf, len);
    if (!e) return 0;
    Dwarf *dw = dwarf_begin_elf(e, DWARF_C_READ, NULL);
    int rc = dw ? search_placed(dw, lo, hi, elf_addr, v, err, errn) : 0;
    if (dw) dwarf_end(dw);
    elf_end(e);
    return rc;
}

int elfvar_dwarf_type(char *buf, size_t len, uint32_t elf_addr, elfvar_t *v, char *err, size_t errn)
{
    if (elf_version(EV_CURRENT) == EV_NONE) return 0;
    Elf *e = elf_memory(buf, len);
    if (!e) return 0;
    Dwarf *dw = dwarf_begin_elf(e, DWARF_C_READ, NULL);
    int rc = dw ? search(dw, elf_addr, v, err, errn) : 0;
    if (dw) dwarf_end(dw);
    elf_end(e);
    return rc;
}

/* armimage.c - ARM Cortex-M images checked before unicorn sees them (see armimage.h). */
#include "armimage.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "io/elf32.h"
#include "io/infile.h"

#define EM_ARM_MACHINE 40u
#define EF_ARM_EABIMASK 0xFF000000u
#define EF_ARM_EABI_VER5 0x05000000u
#define EF_ARM_ABI_FLOAT_HARD 0x400u /* AAELF 4.3.3: the VFP (hard-float) procedure call variant */
#define SHT_ARM_ATTRIBUTES 0x70000003u
#define SHF_ALLOC_FLAG 0x2u
#define VECTOR_BYTES 8u /* the vector table's first two words: initial SP, reset */

/* AAELF / ARM build attributes (the "aeabi" subsection, IHI 0045) */
enum { TAG_FILE = 1, TAG_CPU_RAW_NAME = 4, TAG_CPU_NAME = 5, TAG_CPU_ARCH = 6, TAG_CPU_ARCH_PROFILE = 7, TAG_FP_ARCH = 10,
       TAG_ABI_VFP_ARGS = 28, TAG_COMPATIBILITY = 32, TAG_ALSO_COMPATIBLE_WITH = 65, TAG_CONFORMANCE = 67 };
enum { ARCH_V7 = 10, ARCH_V6M = 11, ARCH_V6SM = 12, ARCH_V7EM = 13 }; /* Tag_CPU_arch values */

/* The MCUs we run. Figures: flash and SRAM from each datasheet's memory
 * map; nirq from the reference manual's vector table; CPUID and priority
 * bits from the programming manual. */
static const armimage_mcu_t mcus[] = {
    { "stm32f103x8", ARMCORE_M3, 0, 0x08000000u, 64u << 10, 0x20000000u, 20u << 10, 43, 4, 0x411FC231u,
      0x1FFFF7E0u, 0x1FFFF7E8u,
      "DS5319 Rev 17 table 2 (64 KB flash, 20 KB SRAM), figure 11 memory map; RM0008 Rev 21 table 63 (medium density, "
      "positions 0-42), 30.1.1-30.2 (F_SIZE at 0x1FFFF7E0, UID at 0x1FFFF7E8); PM0056 Rev 7 4.3.7 (4 priority bits), "
      "4.4.1 (CPUID 0x411FC231)" },
    { "stm32f103xb", ARMCORE_M3, 0, 0x08000000u, 128u << 10, 0x20000000u, 20u << 10, 43, 4, 0x411FC231u,
      0x1FFFF7E0u, 0x1FFFF7E8u,
      "DS5319 Rev 17 table 2 (128 KB flash, 20 KB SRAM); RM0008 Rev 21 table 63, 30.1.1-30.2; PM0056 Rev 7 4.3.7, 4.4.1" },
    { "stm32f405xg", ARMCORE_M4, 1, 0x08000000u, 1024u << 10, 0x20000000u, 128u << 10, 82, 4, 0x410FC241u,
      0x1FFF7A22u, 0x1FFF7A10u,
      "DS8626 Rev 9 table 2 (1 MB flash, 112+16 KB contiguous SRAM at 0x20000000; CCM not mapped); RM0090 Rev 19 "
      "table 61 (positions 0-81), 39.1-39.2 (UID at 0x1FFF7A10, F_SIZE at 0x1FFF7A22); PM0214 Rev 10 4.3.7 (4 priority bits), 4.4.1 (CPUID 0x410FC241)" },
};

const armimage_mcu_t *armimage_mcu(const char *name)
{
    for (size_t i = 0; i < sizeof mcus / sizeof mcus[0]; i++)
        if (!strcmp(mcus[i].name, name)) return &mcus[i];
    return NULL;
}

const char *armimage_mcu_names(void) { return "stm32f103x8, stm32f103xb, stm32f405xg"; }

static int in_range(uint64_t a, uint64_t n, uint32_t base, uint32_t bytes) { return a >= base && a + n <= (uint64_t)base + bytes; }

/* A ULEB128 at *at within n bytes of p; 0, or -1 if it runs past them or overflows 32 bits. */
static int uleb(const uint8_t *p, uint32_t n, uint32_t *at, uint32_t *v)
{
    *v = 0;
    for (unsigned sh = 0; *at < n; sh += 7) {
        uint8_t c = p[(*at)++];
        if (sh > 28) return -1;
        *v |= (uint32_t)(c & 0x7Fu) << sh;
        if (!(c & 0x80u)) return 0;
    }
    return -1;
}

/* A NUL-ended string at *at within n bytes of p: 0 with *at past it, or -1. */
static int ntbs(const uint8_t *p, uint32_t n, uint32_t *at)
{
    const uint8_t *z = *at < n ? memchr(p + *at, 0, n - *at) : NULL;
    if (!z) return -1;
    *at = (uint32_t)(z - p) + 1;
    return 0;
}

typedef struct { uint32_t arch, profile, fp_arch, vfp_args; int has_arch, has_profile; } attrs_t;

/* One attribute (tag, value) at *at; the tags whose value is a string by the ABI's rule (odd above 32). */
static int attr(const uint8_t *p, uint32_t n, uint32_t *at, attrs_t *a)
{
    uint32_t tag, v;
    if (uleb(p, n, at, &tag)) return -1;
    if (tag == TAG_CPU_RAW_NAME || tag == TAG_CPU_NAME || tag == TAG_ALSO_COMPATIBLE_WITH || tag == TAG_CONFORMANCE ||
        (tag > TAG_COMPATIBILITY && (tag & 1u)))
        return ntbs(p, n, at);
    if (uleb(p, n, at, &v)) return -1;
    if (tag == TAG_COMPATIBILITY) return ntbs(p, n, at);
    if (tag == TAG_CPU_ARCH) a->arch = v, a->has_arch = 1;
    if (tag == TAG_CPU_ARCH_PROFILE) a->profile = v, a->has_profile = 1;
    if (tag == TAG_FP_ARCH) a->fp_arch = v;
    if (tag == TAG_ABI_VFP_ARGS) a->vfp_args = v;
    return 0;
}

/* The "aeabi" subsection's file-scope attributes (format 'A'; other vendors' subsections skipped). */
static int parse_attrs(const uint8_t *p, uint32_t n, attrs_t *a)
{
    if (n < 1 || p[0] != 'A') return -1;
    for (uint32_t at = 1; at < n;) {
        if (n - at < 4) return -1;
        uint32_t len = elf32_le32(p + at), end = at + len, k = at + 4;
        if (len < 4 || len > n - at) return -1;
        if (ntbs(p, end, &k)) return -1;
        int aeabi = !strcmp((const char *)p + at + 4, "aeabi");
        while (aeabi && k < end) { /* sub-subsections: tag, size, attributes */
            if (end - k < 5) return -1;
            uint32_t tag = p[k], sl = elf32_le32(p + k + 1), se = k + sl;
            if (sl < 5 || sl > end - k) return -1;
            for (uint32_t j = k + 5; tag == TAG_FILE && j < se;)
                if (attr(p, se, &j, a)) return -1;
            k = se;
        }
        at = end;
    }
    return 0;
}

typedef struct {
    elf32_t x;
    const armimage_mcu_t *mcu;
    int vectors; /* a segment loads the vector table's first words at the start of flash */
} img_t;

static int check_attrs(img_t *e, const uint8_t *s)
{
    const armimage_mcu_t *m = e->mcu;
    attrs_t a = { 0 };
    char msg[240];
    if (parse_attrs(e->x.b + elf32_le32(s + 16), elf32_le32(s + 20), &a))
        return elf32_fail(&e->x, ".ARM.attributes is not well formed (IHI 0045 build attributes)");
    if (a.has_profile && a.profile != 'M' && a.profile != 0)
        return snprintf(msg, sizeof msg, "built for the %c profile (.ARM.attributes Tag_CPU_arch_profile): a %s runs M-profile code",
                        a.profile >= 0x20 && a.profile < 0x7F ? (int)a.profile : '?', m->name), elf32_fail(&e->x, msg);
    int ok = a.arch == ARCH_V7 || a.arch == ARCH_V6M || a.arch == ARCH_V6SM || (a.arch == ARCH_V7EM && m->core == ARMCORE_M4);
    if (a.has_arch && !ok)
        return snprintf(msg, sizeof msg, "built for architecture %u (.ARM.attributes Tag_CPU_arch; 10 v7, 13 v7E-M): a %s is a Cortex-M%d",
                        a.arch, m->name, (int)m->core), elf32_fail(&e->x, msg);
    if ((a.fp_arch || a.vfp_args == 1) && !m->fpu)
        return snprintf(msg, sizeof msg, "uses floating-point instructions or registers (.ARM.attributes Tag_FP_arch %u): a %s has no FPU",
                        a.fp_arch, m->name), elf32_fail(&e->x, msg);
    return 0;
}

static int check_header(img_t *e)
{
    uint32_t flags = elf32_le32(e->x.b + 36);
    char msg[240];
    if ((flags & EF_ARM_EABIMASK) != EF_ARM_EABI_VER5)
        return snprintf(msg, sizeof msg, "not an EABI version 5 image (e_flags 0x%08x): arm-none-eabi-gcc writes 0x05000200",
                        flags), elf32_fail(&e->x, msg);
    if ((flags & EF_ARM_ABI_FLOAT_HARD) && !e->mcu->fpu)
        return snprintf(msg, sizeof msg, "built for the hard-float ABI (e_flags 0x%08x): a %s has no FPU", flags, e->mcu->name),
               elf32_fail(&e->x, msg);
    for (uint32_t i = 0; i < e->x.shnum; i++) {
        const uint8_t *s = elf32_shdr(&e->x, i);
        if (elf32_le32(s + 4) == SHT_ARM_ATTRIBUTES && check_attrs(e, s)) return -1;
        if (elf32_le32(s + 4) == ELF32_SHT_SYMTAB && elf32_check_symtab(&e->x, i)) return -1;
    }
    return 0;
}

/* Each PT_LOAD: its file bytes at their LMA within flash; its run addresses within flash or SRAM. */
static int check_segments(img_t *e, armimage_t *out)
{
    const armimage_mcu_t *m = e->mcu;
    char msg[240];
    for (uint32_t i = 0; i < e->x.phnum; i++) {
        const uint8_t *p = elf32_phdr(&e->x, i);
        uint32_t off = elf32_le32(p + 4), va = elf32_le32(p + 8), pa = elf32_le32(p + 12);
        uint32_t filesz = elf32_le32(p + 16), memsz = elf32_le32(p + 20);
        if (elf32_le32(p) != ELF32_PT_LOAD || (filesz == 0 && memsz == 0)) continue;
        if (memsz < filesz)
            return snprintf(msg, sizeof msg, "segment %u has %u bytes in the file but %u in memory", i, filesz, memsz), elf32_fail(&e->x, msg);
        if (!in_range(va, memsz, m->flash_base, m->flash_bytes) && !in_range(va, memsz, m->sram_base, m->sram_bytes))
            return snprintf(msg, sizeof msg, "segment %u (%u bytes at 0x%08x) is not within the %s's flash (0x%08x, %u bytes) or SRAM "
                            "(0x%08x, %u bytes)", i, memsz, va, m->name, m->flash_base, m->flash_bytes, m->sram_base, m->sram_bytes),
                   elf32_fail(&e->x, msg);
        if (filesz == 0) continue;
        if (!in_range(pa, filesz, m->flash_base, m->flash_bytes))
            return snprintf(msg, sizeof msg, "segment %u's %u bytes load at 0x%08x, not within the %s's flash (0x%08x, %u bytes)", i,
                            filesz, pa, m->name, m->flash_base, m->flash_bytes), elf32_fail(&e->x, msg);
        memcpy(out->flash + (pa - m->flash_base), e->x.b + off, filesz);
        if (pa == m->flash_base && filesz >= VECTOR_BYTES) e->vectors = 1;
        if (pa - m->flash_base + filesz > out->flash_end) out->flash_end = pa - m->flash_base + filesz;
    }
    return 0;
}

/* The vector table at the start of flash: initial SP within SRAM, reset a Thumb address in flash. */
static int check_vectors(img_t *e, armimage_t *out)
{
    const armimage_mcu_t *m = e->mcu;
    char msg[240];
    if (!e->vectors)
        return snprintf(msg, sizeof msg, "no vector table at the start of flash (0x%08x): the image loads %u bytes there", m->flash_base,
                        out->flash_end), elf32_fail(&e->x, msg);
    out->initial_sp = elf32_le32(out->flash), out->reset = elf32_le32(out->flash + 4);
    if (out->initial_sp < m->sram_base || out->initial_sp > m->sram_base + m->sram_bytes)
        return snprintf(msg, sizeof msg, "its initial stack pointer 0x%08x (vector 0) is not within the %s's SRAM (0x%08x-0x%08x)",
                        out->initial_sp, m->name, m->sram_base, m->sram_base + m->sram_bytes), elf32_fail(&e->x, msg);
    if (!(out->reset & 1u))
        return snprintf(msg, sizeof msg, "its reset vector 0x%08x has no Thumb bit (bit 0): a Cortex-M would fault", out->reset),
               elf32_fail(&e->x, msg);
    uint32_t pc = out->reset & ~1u;
    if (!in_range(pc, 2, m->flash_base, out->flash_end) && !in_range(pc, 2, 0, out->flash_end))
        return snprintf(msg, sizeof msg, "its reset vector 0x%08x is not within the image's flash bytes (0x%08x-0x%08x)", out->reset,
                        m->flash_base, m->flash_base + out->flash_end), elf32_fail(&e->x, msg);
    return 0;
}

int armimage_check(const uint8_t *b, size_t n, const char *path, const armimage_mcu_t *mcu, armimage_t *out, char *err,
                   size_t errn)
{
    char inner[400];
    memset(out, 0, sizeof *out);
    img_t e = { .x = { .b = b, .n = n, .path = path, .kind = "ARM", .machine = EM_ARM_MACHINE, .err = inner, .errn = sizeof inner },
                .mcu = mcu };
    out->mcu = mcu;
    out->flash = malloc(mcu->flash_bytes);
    if (!out->flash) return snprintf(err, errn, "IMAGE: %s: out of memory", path), -1;
    memset(out->flash, 0xFF, mcu->flash_bytes);
    int rc = elf32_check_header(&e.x);
    if (rc == 0) rc = elf32_check_sections(&e.x);
    if (rc == 0) rc = check_header(&e);
    if (rc == 0) rc = check_segments(&e, out);
    if (rc == 0) rc = check_vectors(&e, out);
    if (rc != 0) {
        snprintf(err, errn, "IMAGE: %s", inner);
        armimage_free(out);
    }
    return rc;
}

int armimage_read(const char *path, const armimage_mcu_t *mcu, armimage_t *out, char *err, size_t errn)
{
    size_t n = 0;
    char inner[300];
    memset(out, 0, sizeof *out);
    char *buf = infile_read(path, ARMIMAGE_MAX_BYTES, &n, inner, sizeof inner);
    if (!buf) return snprintf(err, errn, "IMAGE: %s", inner), -1;
    int rc = armimage_check((const uint8_t *)buf, n, path, mcu, out, err, errn);
    free(buf);
    return rc;
}

void armimage_free(armimage_t *img)
{
    free(img->flash);
    img->flash = NULL;
}

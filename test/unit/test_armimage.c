/* test_armimage.c - ARM images checked before unicorn sees them
 * (sim/arm/armimage.c): from our test firmware (build/arm/coretest.elf,
 * `make arm-test-firmware`), crafted images in memory, one per kind of
 * fault, each giving one line "IMAGE: ..." and never a signal (the test is
 * built with ASan and UBSan): not an ELF, 64-bit, big-endian, another
 * machine, tables and segments outside the file, not EABI5, hard-float on an
 * MCU without an FPU, .ARM.attributes for the A profile, for v7E-M on an
 * M3, for an FPU, malformed; segments outside flash and SRAM, no vector
 * table, the initial SP outside SRAM, a reset vector without the Thumb bit
 * or outside flash; a missing file; and images with random bytes in their
 * headers. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <cmocka.h>

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "arm/armimage.h"

#define IMAGE "build/arm/coretest.elf"
#define FUZZ_IMAGES 300
#define FUZZ_BYTES 3

static uint8_t *base, *buf;
static size_t n;

static uint32_t rd16(const uint8_t *p) { return (uint32_t)p[0] | (uint32_t)p[1] << 8; }
static uint32_t rd32(const uint8_t *p) { return rd16(p) | rd16(p + 2) << 16; }
static void wr32(uint8_t *p, uint32_t v) { p[0] = (uint8_t)v, p[1] = (uint8_t)(v >> 8), p[2] = (uint8_t)(v >> 16), p[3] = (uint8_t)(v >> 24); }

static int setup(void **state)
{
    FILE *f = fopen(IMAGE, "rb");
    if (!f) return fprintf(stderr, "%s missing: make arm-test-firmware\n", IMAGE), -1;
    fseek(f, 0, SEEK_END);
    n = (size_t)ftell(f);
    rewind(f);
    base = malloc(n), buf = malloc(n);
    if (!base || !buf || fread(base, 1, n, f) != n) return -1;
    fclose(f);
    return 0;
}

static int teardown(void **state) { free(base), free(buf); return 0; }
static void fresh(void) { memcpy(buf, base, n); }
static uint8_t *phdr(uint32_t i) { return buf + rd32(buf + 28) + 32u * i; }
static uint8_t *shdr(uint32_t i) { return buf + rd32(buf + 32) + 40u * i; }

static uint8_t *section(const char *name)
{
    uint8_t *names = buf + rd32(shdr(rd16(buf + 50)) + 16);
    for (uint32_t i = 0; i < rd16(buf + 48); i++)
        if (!strcmp((char *)names + rd32(shdr(i)), name)) return shdr(i);
    fail_msg("%s has no %s", IMAGE, name);
    return NULL;
}

/* The value byte of file-scope attribute tag in .ARM.attributes (gcc's: one-byte tags and values, names NUL-ended). */
static uint8_t *attr(unsigned tag)
{
    uint8_t *s = section(".ARM.attributes"), *p = buf + rd32(s + 16), *end = p + rd32(s + 20);
    uint8_t *a = p + 1 + 4 + 6 + 5; /* 'A', length, "aeabi\0", File tag and size */
    while (a < end) {
        if (*a == 4 || *a == 5 || *a == 67) { a += strlen((char *)a + 1) + 2; continue; }
        if (*a == tag) return a + 1;
        a += 2;
    }
    return NULL;
}

/* buf checked for the MCU: want NULL (it loads) or a piece of its one line. */
static void expect(const char *mcu, const char *want)
{
    armimage_t img;
    char err[400] = "";
    int rc = armimage_check(buf, n, "crafted.elf", armimage_mcu(mcu), &img, err, sizeof err);
    if (!want) {
        if (rc != 0) fail_msg("want it loaded, got %s", err);
        armimage_free(&img);
        return;
    }
    if (rc == 0) {
        armimage_free(&img);
        fail_msg("want '%s', it loaded", want);
    }
    if (strncmp(err, "IMAGE: crafted.elf: ", 20) || strchr(err, '\n') || !strstr(err, want)) fail_msg("want '%s', got '%s'", want, err);
}

static uint8_t *text_segment(void) { return phdr(0); } /* the vector table and code (the linker's first) */
static uint8_t *vectors(void) { return buf + rd32(text_segment() + 4); }

static void test_good(void **state)
{
    armimage_t img;
    char err[400];
    fresh();
    assert_int_equal(armimage_check(buf, n, "ok.elf", armimage_mcu("stm32f103x8"), &img, err, sizeof err), 0);
    assert_int_equal(img.initial_sp, 0x20005000u);
    assert_int_equal(img.reset & 1u, 1);
    assert_int_equal(rd32(img.flash + 4), img.reset);
    armimage_free(&img);
    expect("stm32f405xg", NULL); /* an M3 image runs on an M4 */
}

static void test_elf_structure(void **state)
{
    fresh(), memcpy(buf, "\x7f" "ELX", 4), expect("stm32f103x8", "not an ARM ELF image");
    fresh(), buf[4] = 2, expect("stm32f103x8", "64-bit");
    fresh(), buf[5] = 2, expect("stm32f103x8", "big-endian");
    fresh(), buf[18] = 83, expect("stm32f103x8", "machine 83, not an ARM (40)");
    fresh(), wr32(buf + 28, (uint32_t)n - 8), expect("stm32f103x8", "program header table");
    fresh(), wr32(buf + 32, (uint32_t)n), expect("stm32f103x8", "section header table");
    fresh(), wr32(text_segment() + 16, (uint32_t)n), expect("stm32f103x8", "segment 0");
    fresh(), wr32(section(".text") + 16, (uint32_t)n - 4), expect("stm32f103x8", "not within the file");
}

static void test_core_and_abi(void **state)
{
    fresh(), wr32(buf + 36, 0x04000000u), expect("stm32f103x8", "not an EABI version 5 image");
    fresh(), wr32(buf + 36, 0x05000400u), expect("stm32f103x8", "hard-float ABI");
    fresh(), wr32(buf + 36, 0x05000400u), expect("stm32f405xg", NULL);
    fresh(), *attr(7) = 'A', expect("stm32f103x8", "built for the A profile");
    fresh(), *attr(6) = 13, expect("stm32f103x8", "architecture 13");
    fresh(), *attr(6) = 13, expect("stm32f405xg", NULL); /* v7E-M is the M4's */
    fresh(), *attr(6) = 17, expect("stm32f405xg", "architecture 17"); /* v8-M mainline */
    uint8_t *isa;                                                   /* Tag_THUMB_ISA_use made Tag_FP_arch VFPv4 */
    fresh(), isa = attr(9), isa[-1] = 10, isa[0] = 5, expect("stm32f103x8", "has no FPU");
    fresh(), buf[rd32(section(".ARM.attributes") + 16)] = 'B', expect("stm32f103x8", ".ARM.attributes is not well formed");
}

static void test_memories(void **state)
{
    fresh(), wr32(text_segment() + 12, 0x08010000u), expect("stm32f103x8", "not within the stm32f103x8's flash");
    fresh(), wr32(text_segment() + 8, 0x30000000u), expect("stm32f103x8", "is not within the stm32f103x8's flash");
    fresh(), wr32(text_segment() + 20, 0x20000u), expect("stm32f103x8", "(131072 bytes at 0x08000000) is not within the stm32f103x8's flash");
    fresh(), wr32(text_segment() + 20, 0x20000u), expect("stm32f103xb", NULL); /* 128 KiB: the xB's flash */
    fresh(), wr32(text_segment() + 12, 0x08000100u), wr32(text_segment() + 8, 0x08000100u), expect("stm32f103x8", "no vector table");
    fresh(), wr32(vectors(), 0x20006000u), expect("stm32f103x8", "initial stack pointer 0x20006000");
    fresh(), wr32(vectors(), 0x08000000u), expect("stm32f103x8", "initial stack pointer");
    fresh(), wr32(vectors() + 4, rd32(vectors() + 4) & ~1u), expect("stm32f103x8", "no Thumb bit");
    fresh(), wr32(vectors() + 4, 0x08008001u), expect("stm32f103x8", "is not within the image's flash bytes");
    fresh(), wr32(vectors() + 4, 0x20000001u), expect("stm32f103x8", "is not within the image's flash bytes");
}

static void test_files(void **state)
{
    armimage_t img;
    char err[400];
    assert_int_equal(armimage_read("/nonexistent/x.elf", armimage_mcu("stm32f103x8"), &img, err, sizeof err), -1);
    assert_non_null(strstr(err, "IMAGE: /nonexistent/x.elf: cannot open"));
    assert_int_equal(armimage_read("/dev/zero", armimage_mcu("stm32f103x8"), &img, err, sizeof err), -1);
    assert_non_null(strstr(err, "not a regular file"));
    assert_null(armimage_mcu("stm32f999"));
    assert_int_equal(armimage_read(IMAGE, armimage_mcu("stm32f103x8"), &img, err, sizeof err), 0);
    armimage_free(&img);
    for (size_t cut = 0; cut < 600; cut += 37) { /* truncated */
        int rc = armimage_check(base, cut, "cut.elf", armimage_mcu("stm32f103x8"), &img, err, sizeof err);
        assert_int_equal(rc, -1);
        assert_int_equal(strncmp(err, "IMAGE: cut.elf: ", 16), 0);
    }
}

static void test_fuzz(void **state)
{
    uint32_t x = 1;
    int loaded = 0;
    for (int k = 0; k < FUZZ_IMAGES; k++) {
        fresh();
        size_t span = rd32(buf + 32) + 40u * rd16(buf + 48); /* the headers and tables, the section headers' end */
        if (span > n) span = n;
        for (int j = 0; j < FUZZ_BYTES; j++) {
            x = x * 1103515245u + 12345u;
            size_t at = (x >> 8) % 200 < 100 ? (x >> 8) % 52 : (x >> 8) % span;
            buf[at] = (uint8_t)(x >> 24);
        }
        armimage_t img;
        char err[400] = "";
        if (armimage_check(buf, n, "fuzz.elf", armimage_mcu("stm32f103x8"), &img, err, sizeof err) == 0) loaded++, armimage_free(&img);
        else if (strncmp(err, "IMAGE: fuzz.elf: ", 17) || strchr(err, '\n')) fail_msg("image %d: '%s'", k, err);
    }
    assert_true(loaded > 0 && loaded < FUZZ_IMAGES);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_good), cmocka_unit_test(test_elf_structure), cmocka_unit_test(test_core_and_abi),
        cmocka_unit_test(test_memories), cmocka_unit_test(test_files), cmocka_unit_test(test_fuzz),
    };
    return cmocka_run_group_tests(tests, setup, teardown);
}

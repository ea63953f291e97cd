/* test_bitband.c - the Cortex-M bit-band aliases (sim/arm/bitband.h,
 * ARMv7-M ARM B3.1, RM0090 2.3.2): the manual's two worked examples, the
 * region edges, a read-modify-write of one SRAM bit leaving the others. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <cmocka.h>

#include <stdint.h>
#include <string.h>

#include "arm/bitband.h"

static uint8_t sram[64];
static unsigned writes;

static bool bus_read(void *ctx, uint32_t addr, unsigned size, uint32_t *v)
{
    if (addr < 0x20000000u || addr + size > 0x20000000u + sizeof sram) return false;
    *v = 0;
    memcpy(v, sram + (addr - 0x20000000u), size);
    return true;
}
static bool bus_write(void *ctx, uint32_t addr, unsigned size, uint32_t v)
{
    if (addr < 0x20000000u || addr + size > 0x20000000u + sizeof sram) return false;
    memcpy(sram + (addr - 0x20000000u), &v, size);
    writes++;
    return true;
}
static const mmio_bus_t bus = { bus_read, bus_write, NULL };

static void test_mapping(void **state)
{
    uint32_t a;
    unsigned b;
    /* RM0090 2.3.2: bit 2 of byte 0x20000300 at 0x22006008 */
    assert_true(bitband_addr(0x22006008u, &a, &b));
    assert_int_equal(a, 0x20000300u);
    assert_int_equal(b, 2);
    /* ARMv7-M ARM B3.1 example: 0x2200001C -> bit 7 of 0x20000000 */
    assert_true(bitband_addr(0x2200001Cu, &a, &b));
    assert_int_equal(a, 0x20000000u);
    assert_int_equal(b, 7);
    /* the last alias word: bit 7 of byte 0x200FFFFF = bit 31 of word 0x200FFFFC */
    assert_true(bitband_addr(0x23FFFFFCu, &a, &b));
    assert_int_equal(a, 0x200FFFFCu);
    assert_int_equal(b, 31);
    /* RCC CR (0x40023800) PLLON, bit 24: Cube HAL's RCC_CR_PLLON_BB */
    assert_true(bitband_addr(0x42470060u, &a, &b));
    assert_int_equal(a, 0x40023800u);
    assert_int_equal(b, 24);
    assert_true(bitband_addr(0x42000000u, &a, &b));
    assert_int_equal(a, 0x40000000u);
    assert_false(bitband_addr(0x24000000u, &a, &b));
    assert_false(bitband_addr(0x21FFFFFCu, &a, &b));
    assert_false(bitband_addr(0x44000000u, &a, &b));
    assert_false(bitband_addr(0x40000000u, &a, &b));
}

static void test_rmw(void **state)
{
    memset(sram, 0xA5, sizeof sram);
    writes = 0;
    /* bit 8 of word 0x20000010: byte 0x20000011, bit 0 */
    uint32_t alias = 0x22000000u + 0x11u * 32u;
    assert_true(bitband_write(&bus, alias, 0xFFFFFFFEu)); /* only bit 0 of the value counts */
    assert_int_equal(sram[0x11], 0xA4);
    assert_int_equal(sram[0x10], 0xA5);
    assert_int_equal(sram[0x12], 0xA5);
    uint32_t v = 9;
    assert_true(bitband_read(&bus, alias, &v));
    assert_int_equal(v, 0);
    assert_true(bitband_write(&bus, alias, 1));
    assert_int_equal(sram[0x11], 0xA5);
    assert_true(bitband_read(&bus, alias, &v));
    assert_int_equal(v, 1);
    assert_int_equal(writes, 2);
    /* a target the bus faults on: the access faults */
    assert_false(bitband_write(&bus, 0x22000000u + 4096u * 32u, 1));
    assert_false(bitband_read(&bus, 0x20000000u, &v)); /* not an alias */
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_mapping),
        cmocka_unit_test(test_rmw),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}

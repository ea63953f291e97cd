/* test_stm32f4_flash.c - the STM32F4 flash interface model
 * (sim/arm/stm32f4_flash.h) against RM0090 section 3: ACR read back as
 * Cube HAL checks it (LATENCY 5 with PRFTEN/ICEN/DCEN), the unlock sequence
 * and a wrong key, the sector map (16/64/128 KiB), sector 2 erase with its
 * BSY time and EOP interrupt, word programming (x32) clearing bits only,
 * PGPERR/PGAERR/PGSERR. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <cmocka.h>

#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "arm/stm32f4_flash.h"

enum { ACR = 0x00, KEYR = 0x04, SR = 0x0C, CR = 0x10, OPTCR = 0x14 };
#define BSY (1u << 16)
#define EOP 1u
#define PGAERR (1u << 5)
#define PGPERR (1u << 6)
#define PGSERR (1u << 7)
#define PG 1u
#define SER 2u
#define SNB(n) ((uint32_t)(n) << 3)
#define PSIZE32 (2u << 8)
#define STRT (1u << 16)
#define EOPIE (1u << 24)
#define LOCK (1u << 31)

static const mmio_clocks_t clk = { 168000000, 168000000, 42000000, 84000000, 84000000, 168000000, 42000000 };
static stm32f4_flash_t fl;
static uint8_t *mem;
static bool irq4;

static void irq_set(void *ctx, unsigned irq, bool level) { assert_int_equal(irq, 4); irq4 = level; }

static int setup(void **state)
{
    mem = malloc(1u << 20);
    memset(mem, 0x5A, 1u << 20);
    irq4 = false;
    stm32f4_flash_init(&fl, STM32F4_F405, mem, 1u << 20, &clk, (mmio_irq_t){ irq_set, NULL });
    return 0;
}
static int teardown(void **state) { free(mem); return 0; }

static uint32_t rd(uint32_t off, uint64_t now)
{
    uint32_t v;
    stm32f4_flash_ops.advance(&fl, now);
    assert_int_equal(stm32f4_flash_ops.read(&fl, off, 4, &v), MMIO_OK);
    return v;
}
static void wr(uint32_t off, uint32_t v, uint64_t now)
{
    stm32f4_flash_ops.advance(&fl, now);
    assert_int_equal(stm32f4_flash_ops.write(&fl, off, 4, v), MMIO_OK);
}
static void unlock(void)
{
    wr(KEYR, 0x45670123u, 0);
    wr(KEYR, 0xCDEF89ABu, 0);
    assert_int_equal(rd(CR, 0), 0);
}

static void test_acr_readback(void **state)
{
    assert_int_equal(rd(ACR, 0), 0);
    assert_int_equal(rd(CR, 0), LOCK);
    assert_int_equal(rd(OPTCR, 0), 0x0FFFAAEDu);
    /* HAL: FLASH->ACR = LATENCY_5 | PRFTEN | ICEN | DCEN, then reads LATENCY back */
    wr(ACR, 5u | (7u << 8), 0);
    assert_int_equal(rd(ACR, 0), 5u | (7u << 8));
    /* __HAL_FLASH_SET_LATENCY as a byte write of ACR's low byte */
    assert_int_equal(stm32f4_flash_ops.write(&fl, ACR, 1, 3u), MMIO_OK);
    assert_int_equal(rd(ACR, 0), 3u | (7u << 8));
}

static void test_sector_map(void **state)
{
    uint32_t off, len;
    assert_true(stm32f4_flash_sector(&fl, 2, &off, &len));
    assert_int_equal(off, 0x8000);
    assert_int_equal(len, 0x4000);
    assert_true(stm32f4_flash_sector(&fl, 4, &off, &len));
    assert_int_equal(off, 0x10000);
    assert_int_equal(len, 0x10000);
    assert_true(stm32f4_flash_sector(&fl, 11, &off, &len));
    assert_int_equal(off, 0xE0000);
    assert_int_equal(len, 0x20000);
    assert_false(stm32f4_flash_sector(&fl, 12, &off, &len));
    fl.size = 512u * 1024u; /* an F411CE: sectors 0-7 */
    assert_true(stm32f4_flash_sector(&fl, 7, &off, &len));
    assert_false(stm32f4_flash_sector(&fl, 8, &off, &len));
}

static void test_wrong_key_locks(void **state)
{
    wr(KEYR, 0x45670123u, 0);
    assert_int_equal(stm32f4_flash_ops.write(&fl, KEYR, 4, 0x12345678u), MMIO_BUS_FAULT);
    assert_int_equal(stm32f4_flash_ops.write(&fl, KEYR, 4, 0x45670123u), MMIO_BUS_FAULT);
    assert_int_equal(rd(CR, 0), LOCK);
    wr(CR, PG, 0); /* locked: ignored */
    assert_int_equal(rd(CR, 0), LOCK);
    stm32f4_flash_ops.reset(&fl);
    unlock();
}

static void test_sector2_erase(void **state)
{
    unlock();
    wr(CR, SER | SNB(2) | PSIZE32 | EOPIE, 1000);
    wr(CR, SER | SNB(2) | PSIZE32 | EOPIE | STRT, 1000);
    assert_true(rd(SR, 1000) & BSY);
    /* tERASE16KB at x32: 250 ms at 168 MHz = 42,000,000 cycles */
    assert_int_equal(stm32f4_flash_ops.next_event(&fl), 1000 + 42000000u);
    assert_true(rd(SR, 1000 + 41999999u) & BSY);
    assert_int_equal(mem[0x8000], 0x5A);
    uint32_t sr = rd(SR, 1000 + 42000000u);
    assert_int_equal(sr, EOP);
    assert_true(irq4);
    for (uint32_t i = 0x8000; i < 0xC000; i++) if (mem[i] != 0xFF) fail_msg("byte %x not erased", i);
    assert_int_equal(mem[0x7FFF], 0x5A);
    assert_int_equal(mem[0xC000], 0x5A);
    wr(SR, EOP, 42001000u); /* rc_w1 */
    assert_false(irq4);
    assert_int_equal(fl.sectors_erased, 1);
}

static void test_program_word(void **state)
{
    unlock();
    memset(mem + 0x8000, 0xFF, 16);
    wr(CR, PG | PSIZE32, 0);
    assert_int_equal(stm32f4_flash_mem_write(&fl, 0x8000, 4, 0x12345678u), MMIO_OK);
    /* tprog 16 us = 2688 cycles at 168 MHz */
    assert_true(rd(SR, 2687) & BSY);
    assert_false(rd(SR, 2688) & BSY);
    assert_int_equal(mem[0x8000], 0x78);
    assert_int_equal(mem[0x8003], 0x12);
    /* programming only clears bits: 0x12345678 & 0xFFFF0000 */
    stm32f4_flash_mem_write(&fl, 0x8000, 4, 0xFFFF0000u);
    assert_int_equal(mem[0x8000], 0x00);
    assert_int_equal(mem[0x8003], 0x12);
    assert_int_equal(fl.programmed, 2);
    /* a half-word at x32: PGPERR; a misaligned word: PGAERR; nothing written */
    stm32f4_flash_mem_write(&fl, 0x8004, 2, 0u);
    assert_int_equal(rd(SR, 10000) & PGPERR, PGPERR);
    assert_int_equal(mem[0x8004], 0xFF);
    stm32f4_flash_mem_write(&fl, 0x8006, 4, 0u);
    assert_int_equal(rd(SR, 10000) & PGAERR, PGAERR);
    assert_int_equal(mem[0x8006], 0xFF);
    /* without PG: PGSERR */
    wr(CR, PSIZE32, 10000);
    stm32f4_flash_mem_write(&fl, 0x8008, 4, 0u);
    assert_int_equal(rd(SR, 10000) & PGSERR, PGSERR);
    assert_int_equal(mem[0x8008], 0xFF);
    wr(CR, LOCK, 10000);
    assert_int_equal(rd(CR, 10000), LOCK);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test_setup_teardown(test_acr_readback, setup, teardown),
        cmocka_unit_test_setup_teardown(test_sector_map, setup, teardown),
        cmocka_unit_test_setup_teardown(test_wrong_key_locks, setup, teardown),
        cmocka_unit_test_setup_teardown(test_sector2_erase, setup, teardown),
        cmocka_unit_test_setup_teardown(test_program_word, setup, teardown),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}

/* test_stm32_flash.c - the STM32F1 flash interface (sim/arm/stm32f1_flash.c)
 * against RM0008 3.3.3 and PM0075: reset values, ACR read back, the
 * KEYR unlock sequence (a wrong key: bus error, locked until reset), page
 * erase then half-word programming with BSY for the datasheet's times and
 * EOP, PGERR on programming a half-word that is not erased (0x0000 is
 * allowed), a non-half-word write a bus error, the EOP interrupt, and the
 * contents kept in a file across power-on (sim/io/memfile). */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <cmocka.h>

#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "arm/stm32f1_flash.h"

#define ACR 0x00
#define KEYR 0x04
#define SR 0x0C
#define CR 0x10
#define AR 0x14
#define SIZE (64u * 1024u)

static unsigned irq_level[64];
static void irq_set(void *ctx, unsigned irq, bool level) { (void)ctx; irq_level[irq] = level; }

static uint8_t mem[SIZE];
static stm32f1_flash_t fl;
static mmio_clocks_t clk = { .sysclk = 72000000, .hclk = 72000000 };

static uint32_t rd(uint32_t off)
{
    uint32_t v = 0xDEADBEEF;
    assert_int_equal(stm32f1_flash_ops.read(&fl, off, 4, &v), MMIO_OK);
    return v;
}

static mmio_status_t wr(uint32_t off, uint32_t v) { return stm32f1_flash_ops.write(&fl, off, 4, v); }
static void at(uint64_t now) { stm32f1_flash_ops.advance(&fl, now); }
static uint16_t hw(uint32_t off) { return (uint16_t)(mem[off] | mem[off + 1] << 8); }

static int setup(void **state)
{
    memset(mem, 0xA5, sizeof mem);
    stm32f1_flash_init(&fl, mem, SIZE, STM32F1_FLASH_PAGE_MD, &clk, (mmio_irq_t){ irq_set, NULL });
    return 0;
}

static void unlock(void)
{
    assert_int_equal(wr(KEYR, 0x45670123), MMIO_OK);
    assert_int_equal(wr(KEYR, 0xCDEF89AB), MMIO_OK);
    assert_false(rd(CR) & 0x80);
}

static void test_reset_and_acr(void **state)
{
    assert_int_equal(rd(ACR), 0x30);
    assert_int_equal(rd(SR), 0);
    assert_int_equal(rd(CR), 0x80); /* LOCK */
    assert_int_equal(rd(0x1C), 0x03FFFFFC);
    assert_int_equal(rd(0x20), 0xFFFFFFFF);
    wr(ACR, 0x12); /* LATENCY 2, PRFTBE */
    assert_int_equal(rd(ACR), 0x32); /* PRFTBS follows PRFTBE */
    wr(ACR, 0x02);
    assert_int_equal(rd(ACR), 0x02);
    assert_int_equal(wr(0x08, 0x08192A3B), MMIO_UNMODELED); /* OPTKEYR */
}

static void test_locked_cr_ignores_writes(void **state)
{
    wr(CR, 0x02);
    assert_int_equal(rd(CR), 0x80);
    unlock();
    wr(CR, 0x02);
    assert_int_equal(rd(CR), 0x02);
    wr(CR, 0x80); /* LOCK again */
    assert_int_equal(rd(CR), 0x80);
    unlock();
}

static void test_wrong_key_locks_until_reset(void **state)
{
    assert_int_equal(wr(KEYR, 0x45670123), MMIO_OK);
    assert_int_equal(wr(KEYR, 0x12345678), MMIO_BUS_FAULT);
    assert_int_equal(wr(KEYR, 0x45670123), MMIO_BUS_FAULT);
    assert_int_equal(wr(KEYR, 0xCDEF89AB), MMIO_BUS_FAULT);
    assert_true(rd(CR) & 0x80);
    stm32f1_flash_ops.reset(&fl);
    unlock();
    /* a wrong first key is a bus error too */
    stm32f1_flash_ops.reset(&fl);
    assert_int_equal(wr(KEYR, 0xCDEF89AB), MMIO_BUS_FAULT);
    assert_true(rd(CR) & 0x80);
}

/* erase page 63 (0x0800FC00) then program two half-words */
static void test_erase_then_program(void **state)
{
    unlock();
    at(100);
    wr(CR, 0x02);                   /* PER */
    wr(AR, 0x0800FC10);             /* any address in the page */
    wr(CR, 0x02 | 0x40);            /* STRT */
    assert_int_equal(rd(SR) & 1, 1); /* BSY */
    assert_int_equal(rd(CR) & 0x40, 0x40);
    /* 30 ms at 72 MHz = 2,160,000 cycles */
    assert_int_equal(stm32f1_flash_ops.next_event(&fl), 100 + 2160000);
    for (uint32_t i = 0xFC00; i < 0x10000; i++) assert_int_equal(mem[i], 0xFF);
    assert_int_equal(mem[0xFBFF], 0xA5); /* the page before untouched */
    at(100 + 2159999);
    assert_int_equal(rd(SR), 1);
    at(100 + 2160000);
    assert_int_equal(rd(SR), 0x20); /* EOP, not BSY */
    assert_int_equal(rd(CR) & 0x40, 0); /* STRT falls with BSY */
    wr(SR, 0x20);
    assert_int_equal(rd(SR), 0);
    wr(CR, 0x01); /* PG */
    assert_int_equal(stm32f1_flash_mem_write(&fl, 0xFC00, 2, 0x1234), MMIO_OK);
    assert_int_equal(hw(0xFC00), 0x1234);
    assert_int_equal(rd(SR), 1);
    /* 52.5 us at 72 MHz = 3,780 cycles */
    assert_int_equal(stm32f1_flash_ops.next_event(&fl), 100 + 2160000 + 3780);
    at(100 + 2160000 + 3780);
    assert_int_equal(rd(SR), 0x20);
    assert_int_equal(fl.programmed, 1);
    assert_int_equal(fl.erased, 1);
}

static void test_pgerr_on_programmed_halfword(void **state)
{
    unlock();
    wr(CR, 0x04); /* MER */
    wr(CR, 0x44);
    at(3000000);
    for (uint32_t i = 0; i < SIZE; i++) assert_int_equal(mem[i], 0xFF);
    wr(CR, 0x01);
    stm32f1_flash_mem_write(&fl, 0x100, 2, 0xBEEF);
    at(4000000);
    wr(SR, 0x20);
    assert_int_equal(stm32f1_flash_mem_write(&fl, 0x100, 2, 0x0F0F), MMIO_OK);
    assert_int_equal(rd(SR), 0x04); /* PGERR, nothing written */
    assert_int_equal(hw(0x100), 0xBEEF);
    wr(SR, 0x04);
    assert_int_equal(rd(SR), 0);
    /* 0x0000 may be written over a programmed half-word */
    stm32f1_flash_mem_write(&fl, 0x100, 2, 0);
    assert_int_equal(hw(0x100), 0);
    assert_false(rd(SR) & 0x04);
    /* a byte or a word write with PG: a bus error */
    assert_int_equal(stm32f1_flash_mem_write(&fl, 0x200, 1, 0), MMIO_BUS_FAULT);
    assert_int_equal(stm32f1_flash_mem_write(&fl, 0x200, 4, 0), MMIO_BUS_FAULT);
    /* without PG: dropped and reported */
    wr(CR, 0);
    assert_int_equal(stm32f1_flash_mem_write(&fl, 0x300, 2, 0), MMIO_UNMODELED);
    assert_int_equal(hw(0x300), 0xFFFF);
}

static void test_eop_interrupt(void **state)
{
    unlock();
    wr(CR, 0x01 | 1u << 12); /* PG, EOPIE */
    at(10);
    memset(mem + 0x400, 0xFF, 2);
    stm32f1_flash_mem_write(&fl, 0x400, 2, 0x5555);
    assert_false(irq_level[STM32F1_FLASH_IRQ]);
    at(10 + 3780);
    assert_true(irq_level[STM32F1_FLASH_IRQ]);
    wr(SR, 0x20);
    assert_false(irq_level[STM32F1_FLASH_IRQ]);
}

/* libopencm3's flash_unlock (LOCK set first, then the keys) twice, then
 * bulebule's eeprom_flash_page: erase, status EOP only, a word as two
 * half-words, status EOP only after each */
static uint64_t t_now;
static uint32_t wait_status(void)
{
    while (rd(SR) & 1) at(t_now += 100);
    return rd(SR) & (0x01 | 0x04 | 0x10 | 0x20);
}

static void test_libopencm3_page_write(void **state)
{
    t_now = 0;
    for (int i = 0; i < 2; i++) {
        wr(CR, rd(CR) | 0x80);
        assert_int_equal(wr(KEYR, 0x45670123), MMIO_OK);
        assert_int_equal(wr(KEYR, 0xCDEF89AB), MMIO_OK);
    }
    wr(CR, rd(CR) | 0x02);
    wr(AR, 0x0800F800);
    wr(CR, rd(CR) | 0x40);
    assert_int_equal(wait_status(), 0x20);
    wr(CR, rd(CR) & ~0x02u);
    for (int h = 0; h < 2; h++) {
        wr(CR, rd(CR) | 0x01);
        assert_int_equal(stm32f1_flash_mem_write(&fl, 0xF800 + 2 * h, 2, h ? 0xDEAD : 0xBEEF), MMIO_OK);
        assert_int_equal(wait_status(), 0x20);
        wr(CR, rd(CR) & ~0x01u);
    }
    assert_int_equal(hw(0xF800), 0xBEEF);
    assert_int_equal(hw(0xF802), 0xDEAD);
}

static void test_file_round_trip(void **state)
{
    char dir[] = "/tmp/test_stm32_flash_XXXXXX", path[600], err[700];
    assert_non_null(mkdtemp(dir));
    snprintf(path, sizeof path, "%s/flash.bin", dir);
    /* missing file: a blank chip */
    assert_int_equal(stm32f1_flash_load(&fl, path, "STM32F103C8's flash", err, sizeof err), 0);
    for (uint32_t i = 0; i < SIZE; i++) assert_int_equal(mem[i], 0xFF);
    unlock();
    wr(CR, 0x01);
    stm32f1_flash_mem_write(&fl, 0xFC00, 2, 0xCAFE);
    assert_int_equal(fl.changed, 1);
    assert_int_equal(stm32f1_flash_save(&fl, path, err, sizeof err), 0);
    /* the next power-on */
    memset(mem, 0, sizeof mem);
    stm32f1_flash_init(&fl, mem, SIZE, STM32F1_FLASH_PAGE_MD, &clk, (mmio_irq_t){ irq_set, NULL });
    assert_int_equal(stm32f1_flash_load(&fl, path, "STM32F103C8's flash", err, sizeof err), 0);
    assert_int_equal(hw(0xFC00), 0xCAFE);
    assert_int_equal(mem[0], 0xFF);
    assert_int_equal(fl.changed, 0);
    /* a file of the wrong size: one line */
    FILE *f = fopen(path, "w");
    fputs("short", f);
    fclose(f);
    assert_int_equal(stm32f1_flash_load(&fl, path, "STM32F103C8's flash", err, sizeof err), -1);
    assert_non_null(strstr(err, "5 bytes, the STM32F103C8's flash holds 65536"));
    assert_null(strchr(err, '\n'));
    unlink(path);
    rmdir(dir);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test_setup(test_reset_and_acr, setup),
        cmocka_unit_test_setup(test_locked_cr_ignores_writes, setup),
        cmocka_unit_test_setup(test_wrong_key_locks_until_reset, setup),
        cmocka_unit_test_setup(test_erase_then_program, setup),
        cmocka_unit_test_setup(test_pgerr_on_programmed_halfword, setup),
        cmocka_unit_test_setup(test_eop_interrupt, setup),
        cmocka_unit_test_setup(test_libopencm3_page_write, setup),
        cmocka_unit_test_setup(test_file_round_trip, setup),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}

/* test_stm32f1_soc.c - the STM32F103 as one chip (sim/arm/stm32f1_soc.c)
 * running our own firmware (test/firmware/arm/soctest.c, build/arm/soctest.elf):
 * every peripheral it touches answers at its RM0008 address, through its
 * RCC gate, with its interrupt into the NVIC and its DMA channel (RM0008
 * tables 63 and 78); CPU stores into flash reach the FLASH controller
 * (PM0075: programmed, refused over written bytes, erased) and the flash
 * is kept in a file. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <cmocka.h>

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "arm/stm32f1_soc.h"
#include "../test/firmware/arm/armtest.h"

#define IMAGE "build/arm/soctest.elf"
#define PAGE_OFF 0xFC00u           /* soctest.c's FLASH_PAGE from the flash's start */
#define ADC_V 1.65                 /* volts on ADC12_IN0 */

typedef struct {
    char out[64];
    unsigned n;
    uint64_t last_cycle;
} sink_t;

static void sink(void *ctx, uint8_t byte, uint64_t cycle)
{
    sink_t *s = ctx;
    if (s->n < sizeof s->out - 1) s->out[s->n++] = (char)byte;
    s->last_cycle = cycle;
}

static double volts(void *ctx, unsigned ch, uint64_t cycle) { return ch == 0 ? ADC_V : 0.0; }

typedef struct {
    armimage_t img;
    sink_t con;
    stm32f1_soc_t *soc;
} rig_t;

static rig_t *rig_new(const char *flash_path)
{
    rig_t *r = calloc(1, sizeof *r);
    char err[300];
    assert_non_null(r);
    if (armimage_read(IMAGE, armimage_mcu("stm32f103x8"), &r->img, err, sizeof err) != 0) fail_msg("%s (make %s)", err, IMAGE);
    stm32f1_soc_cfg_t cfg = { .image = &r->img, .hse_hz = 8000000u, .vdda_v = 3.3, .flash_path = flash_path,
                              .volts = volts };
    cfg.sink[2] = sink, cfg.sink_ctx[2] = &r->con;
    r->soc = stm32f1_soc_new(&cfg, err, sizeof err);
    if (!r->soc) fail_msg("%s", err);
    stm32f1_gpio_drive(&r->soc->gpio[0], 12, STM32F1_DRIVE_HIGH);
    return r;
}

static void rig_free(rig_t *r)
{
    stm32f1_soc_free(r->soc);
    armimage_free(&r->img);
    free(r);
}

static mailbox_t run(rig_t *r, uint64_t ms)
{
    mailbox_t mb;
    armcore_run_until_ps(r->soc->core, ms * 1000000000ull);
    uint32_t pc;
    const char *cause;
    if (armcore_crashed(r->soc->core, &pc, &cause)) fail_msg("crashed at 0x%08x: %s", pc, cause);
    assert_int_equal(armcore_read(r->soc->core, 0x20000000u, &mb, sizeof mb), 0);
    return mb;
}

static void test_soc_peripherals(void **state)
{
    rig_t *r = rig_new(NULL);
    mailbox_t mb = run(r, 60);
    assert_int_equal(mb.done, 1);
    /* RM0008 7.3.2: SWS = PLL; the clocks RCC derives: 72 MHz HCLK, PCLK1 36 MHz */
    assert_int_equal((mb.v[0] >> 2) & 3u, 2);
    assert_int_equal(r->soc->rcc.clocks.hclk, 72000000u);
    assert_int_equal(r->soc->rcc.clocks.pclk1, 36000000u);
    assert_int_equal(mb.v[1], 0);                       /* TIM4 with its clock off reads 0 */
    assert_true(r->soc->gate[0].rcc->gated >= 1);
    assert_true(mb.v[2] & (1u << 12));                  /* PA12 driven high by the host */
    assert_int_equal(stm32f1_gpio_pin(&r->soc->gpio[2], 13).level, 0); /* PC13 low */
    assert_int_equal(stm32f1_gpio_pin(&r->soc->gpio[2], 13).output, 1);
    /* 1.65 V of 3.3 V: code 2048 +- 1 (12 bits, RM0008 11.1) */
    assert_true(mb.v[3] >= 2047 && mb.v[3] <= 2048);
    stm32f1_tim_out_t o = stm32f1_tim_output(&r->soc->tim[2], 1);
    assert_true(o.enabled && o.pwm);
    assert_float_equal(o.duty, 250.0 / 750.0, 1e-9);
    assert_float_equal(o.freq_hz, 24000.0, 1e-6);
    assert_int_equal(mb.v[4], 3);                       /* TIM2's update interrupt three times */
    assert_int_equal(r->soc->irq_count[28], 3);         /* on NVIC line 28 (RM0008 table 63) */
    assert_string_equal(r->con.out, "soc ok\n");       /* USART3 through DMA1 channel 2 */
    assert_true(mb.v[5] & (1u << 5));                   /* TCIF2 */
    /* TIM3's update TRGO: ADC2's conversions (EXTSEL 100) and TIM4's counts through ITR2 (external clock
     * mode 1), one each per update: ten counts, ten conversions of the 1.65 V */
    assert_int_equal(mb.v[11], 10);
    assert_true(mb.v[12] >= 9 && mb.v[12] <= 10);
    assert_true(mb.v[13] >= 2047 && mb.v[13] <= 2048);
    assert_int_equal(r->soc->tim[2].trig_want, 1u << STM32_TIM_TRGO); /* TIM3's TRGO taken, nothing else */
    assert_int_equal(r->soc->tim[0].trig_want, 0);
        /* FLASH: EOP after programming; PGERR over a written half-word, which keeps its value; erased; programmed */
    assert_true(mb.v[6] & (1u << 5));
    assert_true(mb.v[7] & (1u << 2));
    assert_int_equal(mb.v[8], 0x1234);
    assert_int_equal(mb.v[9], 0xFFFF);
    assert_int_equal(mb.v[10], 0xBEEF);
    int n;
    armcore_unmodeled(r->soc->core, &n);
    assert_int_equal(n, 0);
    rig_free(r);
}

/* The flash kept in a file: loaded under the image at power-on, saved whole. */
static void test_soc_flash_file(void **state)
{
    char path[] = "/tmp/test_soc_flashXXXXXX", err[300];
    int fd = mkstemp(path);
    assert_true(fd >= 0);
    close(fd);
    unlink(path);
    rig_t *r = rig_new(path);
    uint16_t hw = 0;
    assert_int_equal(armcore_read(r->soc->core, 0x08000000u + PAGE_OFF + 2, &hw, 2), 0);
    assert_int_equal(hw, 0xFFFF);                       /* no file: erased */
    run(r, 60);
    assert_int_equal(stm32f1_soc_save(r->soc, err, sizeof err), 0);
    rig_free(r);
    r = rig_new(path);
    assert_int_equal(armcore_read(r->soc->core, 0x08000000u + PAGE_OFF + 2, &hw, 2), 0);
    assert_int_equal(hw, 0xBEEF);                       /* the file's bytes at power-on */
    rig_free(r);
    unlink(path);
}

/* The same run twice: the same state (determinism). */
static void test_soc_deterministic(void **state)
{
    rig_t *a = rig_new(NULL), *b = rig_new(NULL);
    mailbox_t ma = run(a, 30), mbx = run(b, 30);
    assert_memory_equal(&ma, &mbx, sizeof ma);
    assert_int_equal(armcore_cycles(a->soc->core), armcore_cycles(b->soc->core));
    assert_int_equal(a->con.last_cycle, b->con.last_cycle);
    rig_free(a);
    rig_free(b);
}

/* The SoC's reports of one model changing another (a DMA request, a timer's trigger, RCC) against a core that
 * asks every model its next event at every check: the same run (an event a missing report delayed would move
 * the DMA's console bytes, an interrupt or a conversion). */
static void test_soc_links(void **state)
{
    rig_t *a = rig_new(NULL), *b = rig_new(NULL);
    armcore_set_links(b->soc->core, false);
    mailbox_t ma = run(a, 60), mbx = run(b, 60);
    assert_int_equal(ma.done, 1);
    assert_memory_equal(&ma, &mbx, sizeof ma);
    assert_int_equal(armcore_cycles(a->soc->core), armcore_cycles(b->soc->core));
    assert_int_equal(a->con.last_cycle, b->con.last_cycle);
    assert_memory_equal(a->soc->irq_count, b->soc->irq_count, sizeof a->soc->irq_count);
    armcore_stats_t sa = armcore_stats(a->soc->core), sb = armcore_stats(b->soc->core);
    assert_int_equal(sa.exceptions, sb.exceptions);
    rig_free(a);
    rig_free(b);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_soc_peripherals),
        cmocka_unit_test(test_soc_flash_file),
        cmocka_unit_test(test_soc_deterministic),
        cmocka_unit_test(test_soc_links),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}

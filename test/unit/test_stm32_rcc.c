/* test_stm32_rcc.c - the STM32F1 RCC model (sim/arm/stm32f1_rcc.c) against
 * RM0008 section 7: reset values, the oscillators' ready bits after their
 * start-up times, the PLL from an 8 MHz crystal x9 -> 72 MHz, the APB and
 * timer clocks, SWS following SW only once the source is ready, the locks
 * on running oscillators and the PLL's configuration, ready interrupts,
 * the clock gate (reads 0, drops writes, counts) and peripheral resets. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <cmocka.h>

#include <stdint.h>

#include "arm/stm32f1_map.h"
#include "arm/stm32f1_rcc.h"
#include "arm/stm32f1_tim.h"

#define CR 0x00
#define CFGR 0x04
#define CIR 0x08
#define APB2RSTR 0x0C
#define APB1ENR 0x1C
#define CSR 0x24

static unsigned irq_level[64];
static void irq_set(void *ctx, unsigned irq, bool level) { (void)ctx; irq_level[irq] = level; }

static stm32f1_rcc_t rcc;

static uint32_t rd(uint32_t off)
{
    uint32_t v = 0xDEADBEEF;
    assert_int_equal(stm32f1_rcc_ops.read(&rcc, off, 4, &v), MMIO_OK);
    return v;
}

static mmio_status_t wr(uint32_t off, uint32_t v) { return stm32f1_rcc_ops.write(&rcc, off, 4, v); }

static void at(uint64_t now) { stm32f1_rcc_ops.advance(&rcc, now); }

static int setup(void **state)
{
    stm32f1_rcc_init(&rcc, 8000000, (mmio_irq_t){ irq_set, NULL });
    return 0;
}

static void test_reset_values(void **state)
{
    assert_int_equal(rd(CR), 0x00000083);
    assert_int_equal(rd(CFGR), 0);
    assert_int_equal(rd(0x14), 0x14); /* AHBENR: SRAMEN, FLITFEN */
    assert_int_equal(rd(CSR), 0x0C000000);
    const mmio_clocks_t *c = stm32f1_rcc_clocks(&rcc);
    assert_int_equal(c->sysclk, 8000000);
    assert_int_equal(c->hclk, 8000000);
    assert_int_equal(c->pclk1, 8000000);
    assert_int_equal(c->tim_apb1, 8000000);
    assert_int_equal(c->adcclk, 4000000); /* ADCPRE /2 */
    uint32_t v;
    assert_int_equal(stm32f1_rcc_ops.read(&rcc, 0x28, 4, &v), MMIO_UNMODELED); /* AHBRSTR: connectivity line */
    assert_int_equal(stm32f1_rcc_ops.next_event(&rcc), MMIO_NEVER);
}

/* HSE: 2 ms start-up (DS5319) at HCLK 8 MHz = 16,000 cycles */
static void test_hse_ready_after_startup(void **state)
{
    at(1000);
    assert_int_equal(wr(CR, 0x83 | 1u << 16), MMIO_OK);
    assert_false(rd(CR) & (1u << 17));
    assert_int_equal(stm32f1_rcc_ops.next_event(&rcc), 1000 + 16000);
    at(1000 + 15999);
    assert_false(rd(CR) & (1u << 17));
    at(1000 + 16000);
    assert_true(rd(CR) & (1u << 17));
}

static void pll_72mhz(void)
{
    wr(CR, 0x83 | 1u << 16);
    at(16000);
    /* PLLMUL x9 (0111), PLLSRC HSE, PPRE1 /2 (100), ADCPRE /6 (10) */
    wr(CFGR, 7u << 18 | 1u << 16 | 4u << 8 | 2u << 14);
    wr(CR, rd(CR) | 1u << 24);
    assert_false(rd(CR) & (1u << 25));
}

static void test_pll_72mhz_and_switch(void **state)
{
    pll_72mhz();
    /* SW = PLL before it is locked: SWS stays HSI */
    wr(CFGR, rd(CFGR) | 2u);
    assert_int_equal((rd(CFGR) >> 2) & 3u, 0);
    assert_int_equal(stm32f1_rcc_clocks(&rcc)->sysclk, 8000000);
    /* tLOCK 200 us at 8 MHz = 1,600 cycles */
    assert_int_equal(stm32f1_rcc_ops.next_event(&rcc), 16000 + 1600);
    at(16000 + 1600);
    assert_true(rd(CR) & (1u << 25));
    assert_int_equal((rd(CFGR) >> 2) & 3u, 2);
    const mmio_clocks_t *c = stm32f1_rcc_clocks(&rcc);
    assert_int_equal(c->sysclk, 72000000);
    assert_int_equal(c->hclk, 72000000);
    assert_int_equal(c->pclk1, 36000000);
    assert_int_equal(c->pclk2, 72000000);
    assert_int_equal(c->tim_apb1, 72000000); /* x2: PPRE1 != 1 */
    assert_int_equal(c->tim_apb2, 72000000);
    assert_int_equal(c->adcclk, 12000000);
    /* the PLL clocks the system: PLLON and HSEON stay set, PLLMUL stays x9 */
    wr(CR, 0x83);
    assert_true(rd(CR) & (1u << 24));
    assert_true(rd(CR) & (1u << 16));
    wr(CFGR, (rd(CFGR) & ~(0xFu << 18)) | 4u << 18);
    assert_int_equal((rd(CFGR) >> 18) & 0xFu, 7);
    /* AHB /2 and APB2 /2: the timers on APB2 see 2 x 18 MHz */
    wr(CFGR, rd(CFGR) | 8u << 4 | 4u << 11);
    assert_int_equal(c->hclk, 36000000);
    assert_int_equal(c->pclk2, 18000000);
    assert_int_equal(c->tim_apb2, 36000000);
}

/* libopencm3's rcc_clock_setup_in_hse_8mhz_out_72mhz as bulebule calls it:
 * HSI, SW HSI; HSE, wait, SW HSE; prescalers (ADC /8, APB1 /2); PLL x9
 * from HSE; PLLON, wait; SW PLL. Each wait polls the ready bit. */
static uint64_t now_cycle;
static void poll_cr(uint32_t bit)
{
    for (int i = 0; i < 100000 && !(rd(CR) & bit); i++) at(now_cycle += 10);
    assert_true(rd(CR) & bit);
}

static void test_libopencm3_72mhz_sequence(void **state)
{
    now_cycle = 0;
    wr(CR, rd(CR) | 1u);
    poll_cr(1u << 1);
    wr(CFGR, rd(CFGR) & ~3u);
    wr(CR, rd(CR) | 1u << 16);
    poll_cr(1u << 17);
    assert_true(now_cycle >= 16000 && now_cycle < 16010); /* 2 ms at 8 MHz */
    wr(CFGR, (rd(CFGR) & ~3u) | 1u);
    assert_int_equal((rd(CFGR) >> 2) & 3u, 1); /* HSE ready: switched at once */
    wr(CFGR, (rd(CFGR) & ~(0xFu << 4)));
    wr(CFGR, (rd(CFGR) & ~(3u << 14)) | 3u << 14);
    wr(CFGR, (rd(CFGR) & ~(7u << 8)) | 4u << 8);
    wr(CFGR, (rd(CFGR) & ~(7u << 11)));
    wr(CFGR, (rd(CFGR) & ~(0xFu << 18)) | 7u << 18);
    wr(CFGR, rd(CFGR) | 1u << 16);
    wr(CFGR, rd(CFGR) & ~(1u << 17));
    wr(CR, rd(CR) | 1u << 24);
    uint64_t pll_on = now_cycle;
    poll_cr(1u << 25);
    assert_true(now_cycle - pll_on >= 1600 && now_cycle - pll_on < 1610); /* 200 us at 8 MHz */
    wr(CFGR, (rd(CFGR) & ~3u) | 2u);
    assert_int_equal((rd(CFGR) >> 2) & 3u, 2);
    const mmio_clocks_t *c = stm32f1_rcc_clocks(&rcc);
    assert_int_equal(c->hclk, 72000000);
    assert_int_equal(c->pclk1, 36000000);
    assert_int_equal(c->pclk2, 72000000);
    assert_int_equal(c->tim_apb1, 72000000);
    assert_int_equal(c->adcclk, 9000000);
}

static void test_hsi_pll_and_no_crystal(void **state)
{
    stm32f1_rcc_init(&rcc, 0, (mmio_irq_t){ irq_set, NULL });
    wr(CR, 0x83 | 1u << 16); /* no crystal on this board */
    assert_int_equal(stm32f1_rcc_ops.next_event(&rcc), MMIO_NEVER);
    wr(CFGR, 1u); /* SW HSE: never happens */
    at(1000000);
    assert_int_equal((rd(CFGR) >> 2) & 3u, 0);
    wr(CFGR, 14u << 18); /* HSI/2 x16 = 64 MHz */
    wr(CR, 0x83 | 1u << 24);
    at(2000000);
    wr(CFGR, rd(CFGR) | 2u);
    assert_int_equal(stm32f1_rcc_clocks(&rcc)->sysclk, 64000000);
}

/* the PLL does not lock on a stopped input: HSE enabled with the PLL, lock 200 us after HSE's 2 ms */
static void test_pll_waits_for_its_input(void **state)
{
    wr(CFGR, 7u << 18 | 1u << 16);
    wr(CR, 0x83 | 1u << 16 | 1u << 24);
    at(1600);
    assert_false(rd(CR) & (1u << 25));
    at(16000);
    assert_true(rd(CR) & (1u << 17));
    assert_false(rd(CR) & (1u << 25));
    assert_int_equal(stm32f1_rcc_ops.next_event(&rcc), 16000 + 1600);
    at(16000 + 1600);
    assert_true(rd(CR) & (1u << 25));
}

static void test_ready_interrupt(void **state)
{
    wr(CIR, 1u << 11); /* HSERDYIE */
    at(10);
    wr(CR, 0x83 | 1u << 16);
    assert_false(irq_level[STM32F1_RCC_IRQ]);
    at(10 + 16000);
    assert_int_equal(rd(CIR) & 0xFF, 1u << 3);
    assert_true(irq_level[STM32F1_RCC_IRQ]);
    wr(CIR, 1u << 11 | 1u << 19); /* HSERDYC */
    assert_int_equal(rd(CIR) & 0xFF, 0);
    assert_false(irq_level[STM32F1_RCC_IRQ]);
}

static void test_csr_flags(void **state)
{
    wr(CSR, 1u << 24); /* RMVF */
    assert_int_equal(rd(CSR), 0);
    stm32f1_rcc_ops.reset(&rcc);
    stm32f1_rcc_reset_cause(&rcc, STM32F1_RST_IWDG);
    assert_int_equal(rd(CSR), 1u << 29);
    wr(CSR, 1); /* LSION: 85 us at 8 MHz = 680 cycles */
    assert_int_equal(stm32f1_rcc_ops.next_event(&rcc), 680);
    at(680);
    assert_int_equal(rd(CSR) & 3u, 3u);
}

/* a peripheral that remembers its register and its resets */
typedef struct { uint32_t reg; int resets; } fake_t;
static mmio_status_t f_read(void *s, uint32_t off, unsigned size, uint32_t *v) { *v = ((fake_t *)s)->reg; return MMIO_OK; }
static mmio_status_t f_write(void *s, uint32_t off, unsigned size, uint32_t v) { ((fake_t *)s)->reg = v; return MMIO_OK; }
static void f_reset(void *s) { ((fake_t *)s)->reg = 0, ((fake_t *)s)->resets++; }
static const mmio_ops_t fake_ops = { .name = "TIM2", .read = f_read, .write = f_write, .reset = f_reset };

static void test_gate(void **state)
{
    fake_t p = { 7, 0 };
    stm32f1_gate_t g;
    assert_int_equal(stm32f1_gate_init(&g, &rcc, STM32F1_APB1, 1u << 0, &fake_ops, &p), 0);
    assert_string_equal(g.bus_ops.name, "TIM2");
    uint32_t v = 99;
    assert_int_equal(g.bus_ops.read(&g, 0, 4, &v), MMIO_OK);
    assert_int_equal(v, 0); /* clock off: reads 0 */
    g.bus_ops.write(&g, 0, 4, 5);
    assert_int_equal(p.reg, 7); /* and drops the write */
    assert_int_equal(g.off_reads, 1);
    assert_int_equal(g.off_writes, 1);
    assert_int_equal(rcc.gated, 2);
    wr(APB1ENR, 1);
    g.bus_ops.write(&g, 0, 4, 5);
    g.bus_ops.read(&g, 0, 4, &v);
    assert_int_equal(v, 5);
    assert_int_equal(rcc.gated, 2);
    /* TIM2's reset bit is APB1RSTR bit 0 */
    wr(0x10, 1);
    assert_int_equal(p.resets, 1);
    assert_int_equal(p.reg, 0);
    wr(0x10, 1); /* held: no new reset */
    assert_int_equal(p.resets, 1);
    wr(APB2RSTR, 1); /* AFIO's bit on APB2: not this one */
    assert_int_equal(p.resets, 1);
}

/* TIM1 behind its gate (APB2 bit 11): off until rcc_periph_clock_enable;
 * rcc_periph_reset_pulse(RST_TIM1) (APB2RSTR bit 11 set then cleared)
 * resets its registers */
static void test_tim1_gate_and_reset_pulse(void **state)
{
    stm32f1_tim_t tim;
    stm32f1_gate_t g;
    stm32f1_tim_init(&tim, 1, stm32f1_rcc_clocks(&rcc), (mmio_irq_t){ irq_set, NULL }, (mmio_dma_req_t){ NULL, NULL });
    assert_int_equal(stm32f1_gate_init(&g, &rcc, STM32F1_APB2, STM32F1_EN_TIM1, &stm32f1_tim_ops[0], &tim), 0);
    assert_string_equal(g.bus_ops.name, "TIM1");
    g.bus_ops.write(&g, 0x28, 4, 449); /* PSC, clock off: dropped */
    assert_int_equal(tim.psc, 0);
    assert_int_equal(g.off_writes, 1);
    wr(0x18, STM32F1_EN_TIM1);
    g.bus_ops.write(&g, 0x28, 4, 449);
    uint32_t v = 0;
    g.bus_ops.read(&g, 0x28, 4, &v);
    assert_int_equal(v, 449);
    wr(APB2RSTR, STM32F1_EN_TIM1);
    wr(APB2RSTR, 0);
    g.bus_ops.read(&g, 0x28, 4, &v);
    assert_int_equal(v, 0);
    assert_int_equal(stm32f1_rcc_clocks(&rcc)->tim_apb2, 8000000); /* the clock TIM1 counts */
}

static void test_subword_access(void **state)
{
    /* a byte write to CFGR's second byte: PPRE1 /2 without touching SW */
    assert_int_equal(stm32f1_rcc_ops.write(&rcc, CFGR + 1, 1, 4u), MMIO_OK);
    assert_int_equal(rd(CFGR), 4u << 8);
    uint32_t v;
    stm32f1_rcc_ops.read(&rcc, CR, 1, &v);
    assert_int_equal(v, 0x83);
    stm32f1_rcc_ops.read(&rcc, CSR + 2, 2, &v);
    assert_int_equal(v, 0x0C00);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test_setup(test_reset_values, setup),
        cmocka_unit_test_setup(test_hse_ready_after_startup, setup),
        cmocka_unit_test_setup(test_pll_72mhz_and_switch, setup),
        cmocka_unit_test_setup(test_libopencm3_72mhz_sequence, setup),
        cmocka_unit_test_setup(test_hsi_pll_and_no_crystal, setup),
        cmocka_unit_test_setup(test_pll_waits_for_its_input, setup),
        cmocka_unit_test_setup(test_ready_interrupt, setup),
        cmocka_unit_test_setup(test_csr_flags, setup),
        cmocka_unit_test_setup(test_gate, setup),
        cmocka_unit_test_setup(test_tim1_gate_and_reset_pulse, setup),
        cmocka_unit_test_setup(test_subword_access, setup),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}

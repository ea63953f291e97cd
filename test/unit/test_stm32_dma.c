/* test_stm32_dma.c - the STM32F1 DMA1 model (sim/arm/stm32f1_dma.h) against
 * RM0008 section 13, on a small bus of SRAM, USART3 and ADC1: a USART TX by
 * DMA (bulebule's serial_send) raises DMA TCIF after the last transfer and
 * the USART's TC after the last frame; a circular ADC scan wraps; a bad
 * address is a transfer error; the arbiter serves the higher priority. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <cmocka.h>

#include <stdint.h>
#include <string.h>

#include "arm/stm32f1_adc.h"
#include "arm/stm32f1_dma.h"
#include "arm/stm32f1_usart.h"

static const mmio_clocks_t clk = { 72000000, 72000000, 36000000, 72000000, 72000000, 72000000, 9000000 };

#define RAM 0x20000000u
static uint8_t ram[4096];
static stm32_dma_t dma;
static stm32_usart_t usart;
static stm32_adc_t adc;
static uint64_t now;
static bool irq[64];
static char sent[64];
static unsigned nsent;
static uint64_t sent_at[64];
static uint32_t write_log[32];
static unsigned nwrites;

static void irq_set(void *ctx, unsigned n, bool level) { irq[n] = level; }
static void sink(void *ctx, uint8_t b, uint64_t cycle)
{
    sent_at[nsent] = cycle;
    sent[nsent++] = (char)b;
}

typedef struct { uint32_t base; const mmio_ops_t *ops; void *self; } region_t;
static region_t regions[3];

static region_t *find(uint32_t addr)
{
    for (unsigned i = 0; i < 3; i++)
        if (addr - regions[i].base < 0x400u) return &regions[i];
    return NULL;
}

static bool bus_read(void *ctx, uint32_t addr, unsigned size, uint32_t *v)
{
    if (addr - RAM + size <= sizeof ram) {
        *v = 0;
        memcpy(v, ram + (addr - RAM), size); /* little-endian host */
        return true;
    }
    region_t *r = find(addr);
    if (!r) return false;
    r->ops->advance(r->self, now);
    return r->ops->read(r->self, addr - r->base, size, v) == MMIO_OK;
}

static bool bus_write(void *ctx, uint32_t addr, unsigned size, uint32_t v)
{
    if (nwrites < 32) write_log[nwrites++] = addr;
    if (addr - RAM + size <= sizeof ram) {
        memcpy(ram + (addr - RAM), &v, size);
        return true;
    }
    region_t *r = find(addr);
    if (!r) return false;
    r->ops->advance(r->self, now);
    return r->ops->write(r->self, addr - r->base, size, v) == MMIO_OK;
}

/* The board's loop: every model to each event in turn, then to `to`. */
static void run_to(uint64_t to)
{
    for (;;) {
        uint64_t t = MMIO_NEVER;
        for (unsigned i = 0; i < 3; i++) {
            uint64_t e = regions[i].ops->next_event(regions[i].self);
            if (e < t) t = e;
        }
        if (t > to) break;
        if (t > now) now = t;
        for (unsigned i = 0; i < 3; i++) regions[i].ops->advance(regions[i].self, now);
    }
    now = to;
    for (unsigned i = 0; i < 3; i++) regions[i].ops->advance(regions[i].self, now);
}

static void wr(uint32_t addr, uint32_t v)
{
    run_to(now);
    assert_true(bus_write(NULL, addr, 4, v));
}
static uint32_t rd(uint32_t addr)
{
    uint32_t v;
    run_to(now);
    assert_true(bus_read(NULL, addr, 4, &v));
    return v;
}

static void setup_bus(void)
{
    memset(ram, 0, sizeof ram);
    memset(irq, 0, sizeof irq);
    nsent = nwrites = 0;
    now = 0;
    mmio_irq_t i = { irq_set, NULL };
    mmio_dma_req_t req = { stm32_dma_request, &dma };
    stm32_dma_init(&dma, (mmio_bus_t){ bus_read, bus_write, NULL }, i);
    stm32_usart_init(&usart, 3, &clk, i, req, sink, NULL);
    stm32_adc_init(&adc, 1, &clk, i, req, NULL, NULL, 3.3);
    regions[0] = (region_t){ STM32_DMA1_BASE, &stm32_dma_ops, &dma };
    regions[1] = (region_t){ STM32_USART3_BASE, &stm32_usart_ops, &usart };
    regions[2] = (region_t){ STM32_ADC1_BASE, &stm32_adc_ops, &adc };
}

#define CH(n, r) (STM32_DMA1_BASE + 0x08u + 20u * ((n) - 1) + (r))
#define CCR 0
#define CNDTR 4
#define CPAR 8
#define CMAR 12
#define EN 1u
#define TCIE 2u
#define HTIE 4u
#define TEIE 8u
#define DIR 16u
#define CIRC 32u
#define MINC 128u
#define MEM2MEM (1u << 14)
#define PL(x) ((uint32_t)(x) << 12)
#define ISR_BIT(ch, f) ((uint32_t)(f) << (4 * ((ch) - 1)))

/* bulebule's serial_send on USART3 at 921600 baud: BRR 39 at PCLK1 36 MHz,
 * a 10-bit frame = 390 PCLK1 cycles = 780 core cycles. */
static void test_usart_tx_by_dma(void **state)
{
    setup_bus();
    const uint32_t U = STM32_USART3_BASE;
    wr(U + 0x08, 39);                   /* BRR */
    wr(U + 0x0C, (1u << 13) | (1u << 3)); /* UE, TE: an idle frame until 780 */
    wr(U + 0x00, ~(1u << 6));           /* clear TC */
    memcpy(ram, "hello", 5);
    wr(CH(2, CPAR), U + 0x04);
    wr(CH(2, CMAR), RAM);
    wr(CH(2, CNDTR), 5);
    wr(CH(2, CCR), DIR | MINC | TCIE | PL(3) | EN); /* 8-bit sizes */
    wr(U + 0x14, 1u << 7);              /* DMAT */
    /* transfers at 0 ('h' to TDR), 780, 1560, 2340, 3120: the shifter frees TDR at each frame end */
    run_to(3119);
    assert_int_equal(rd(CH(2, CNDTR)), 1);
    assert_false(irq[STM32_DMA1_IRQ(2)]);
    run_to(3120);
    assert_int_equal(rd(CH(2, CNDTR)), 0);
    assert_true(rd(STM32_DMA1_BASE) & ISR_BIT(2, 2)); /* TCIF2 */
    assert_true(rd(STM32_DMA1_BASE) & ISR_BIT(2, 1)); /* GIF2 */
    assert_true(irq[STM32_DMA1_IRQ(2)]);
    /* the USART: byte n leaves at 780 (n + 2); TC after the last frame */
    run_to(4679);
    assert_int_equal(nsent, 4);
    assert_false(rd(U) & (1u << 6));
    run_to(4680);
    assert_true(rd(U) & (1u << 6));
    assert_int_equal(nsent, 5);
    assert_memory_equal(sent, "hello", 5);
    for (unsigned k = 0; k < 5; k++) assert_int_equal(sent_at[k], 780u * (k + 2));
    wr(STM32_DMA1_BASE + 4, ISR_BIT(2, 1)); /* CGIF2 clears all of channel 2's flags */
    assert_int_equal(rd(STM32_DMA1_BASE), 0);
    assert_false(irq[STM32_DMA1_IRQ(2)]);
}

/* bulebule's serial_receive and usart3_isr: DMA1 channel 3 moves each
 * received byte to SRAM; the idle line after the command raises IDLE. */
static void test_usart_rx_by_dma_and_idle(void **state)
{
    setup_bus();
    const uint32_t U = STM32_USART3_BASE;
    wr(U + 0x08, 39);
    wr(U + 0x0C, (1u << 13) | (1u << 4) | (1u << 3) | (1u << 2)); /* UE, IDLEIE, TE, RE */
    wr(CH(3, CPAR), U + 0x04);
    wr(CH(3, CMAR), RAM + 0x200);
    wr(CH(3, CNDTR), 64);
    wr(CH(3, CCR), MINC | TCIE | PL(2) | EN); /* peripheral to memory, 8-bit */
    wr(U + 0x14, 1u << 6);                    /* DMAR */
    run_to(1000);
    for (const char *c = "run"; ; c++) {
        assert_true(stm32_usart_push(&usart, (uint8_t)*c, now));
        if (!*c) break;
    }
    run_to(1000 + 4 * 780 - 1);
    assert_int_equal(rd(CH(3, CNDTR)), 61);
    run_to(1000 + 4 * 780);
    assert_int_equal(rd(CH(3, CNDTR)), 60);
    assert_memory_equal(ram + 0x200, "run", 4);
    assert_false(usart.sr & (1u << 5)); /* the DMA read DR: RXNE clear */
    run_to(1000 + 5 * 780 - 1);
    assert_false(irq[STM32_USART_IRQ(3)]);
    run_to(1000 + 5 * 780);
    assert_true(usart.sr & (1u << 4)); /* IDLE one frame after the last byte */
    assert_true(irq[STM32_USART_IRQ(3)]);
    rd(U);        /* usart_clear_idle_line_detected: SR, then DR */
    rd(U + 0x04);
    assert_false(usart.sr & (1u << 4));
    assert_false(irq[STM32_USART_IRQ(3)]);
}

/* ADC1 scans two channels continuously; DMA1 channel 1 circular, 16-bit, 2 items. */
static unsigned conv;
static double ramp(void *ctx, unsigned ch, uint64_t cycle) { return 0.1 * ++conv; }

static void test_circular_adc_dma(void **state)
{
    setup_bus();
    conv = 0;
    adc.volts = ramp;
    const uint32_t A = STM32_ADC1_BASE;
    wr(CH(1, CPAR), A + 0x4C);
    wr(CH(1, CMAR), RAM);
    wr(CH(1, CNDTR), 2);
    wr(CH(1, CCR), CIRC | MINC | (1u << 8) | (1u << 10) | HTIE | TCIE | EN); /* PSIZE, MSIZE 16 */
    wr(A + 0x04, 1u << 8);                /* SCAN */
    wr(A + 0x2C, 1u << 20);               /* L: 2 ranks */
    wr(A + 0x34, (1u << 5) | 0u);
    wr(A + 0x08, 1u | 2u | (1u << 8));    /* ADON, CONT, DMA */
    wr(A + 0x08, 1u | 2u | (1u << 8));    /* start: first conversion ends at 1 + 16 + 14 x 8 = 129 */
    uint64_t t0 = 1 + 16, conv_cycles = 14 * 8; /* 1.5 + 12.5 ADC clocks */
    run_to(t0 + conv_cycles);
    assert_int_equal(rd(CH(1, CNDTR)), 1);
    assert_true(rd(STM32_DMA1_BASE) & ISR_BIT(1, 4)); /* HTIF1 after one of two */
    run_to(t0 + 2 * conv_cycles);
    assert_int_equal(rd(CH(1, CNDTR)), 2);            /* reloaded */
    assert_true(rd(STM32_DMA1_BASE) & ISR_BIT(1, 2)); /* TCIF1 */
    run_to(t0 + 3 * conv_cycles);
    uint16_t m0, m1;
    memcpy(&m0, ram, 2);
    memcpy(&m1, ram + 2, 2);
    assert_int_equal(m0, 372); /* the third conversion (0.3 V) wrapped onto the first item */
    assert_int_equal(m1, 248); /* 0.2 V */
    assert_int_equal(rd(CH(1, CNDTR)), 1);
}

static void test_transfer_error(void **state)
{
    setup_bus();
    wr(CH(4, CPAR), 0x10000000u); /* nothing there */
    wr(CH(4, CMAR), RAM);
    wr(CH(4, CNDTR), 3);
    wr(CH(4, CCR), MEM2MEM | MINC | TEIE | EN);
    run_to(10);
    uint32_t isr = rd(STM32_DMA1_BASE);
    assert_true(isr & ISR_BIT(4, 8)); /* TEIF4 */
    assert_true(isr & ISR_BIT(4, 1));
    assert_false(rd(CH(4, CCR)) & EN); /* disabled by hardware (RM0008 13.3.5) */
    assert_int_equal(rd(CH(4, CNDTR)), 3);
    assert_true(irq[STM32_DMA1_IRQ(4)]);
}

/* Two memory-to-memory channels enabled together: the higher PL first, then
 * at equal PL the lower channel number (RM0008 13.3.2). */
static void test_priority(void **state)
{
    setup_bus();
    for (unsigned ch = 5; ch <= 7; ch++) {
        wr(CH(ch, CPAR), RAM + 0x100);
        wr(CH(ch, CMAR), RAM + 0x100u * ch);
        wr(CH(ch, CNDTR), 2);
    }
    nwrites = 0;
    /* the CCRs written without advancing the controller, so no transfer runs between them */
    const uint32_t ccr[3] = { MEM2MEM | MINC | PL(1) | EN, MEM2MEM | MINC | PL(3) | EN, MEM2MEM | MINC | PL(1) | EN };
    for (unsigned ch = 5; ch <= 7; ch++)
        assert_int_equal(stm32_dma_ops.write(&dma, CH(ch, CCR) - STM32_DMA1_BASE, 4, ccr[ch - 5]), MMIO_OK);
    nwrites = 0;
    run_to(now + 1);
    assert_int_equal(nwrites, 6);
    const uint32_t want[6] = { RAM + 0x600, RAM + 0x601, RAM + 0x500, RAM + 0x501, RAM + 0x700, RAM + 0x701 };
    for (unsigned k = 0; k < 6; k++) assert_int_equal(write_log[k], want[k]);
}

static void test_registers(void **state)
{
    setup_bus();
    uint32_t v;
    assert_int_equal(stm32_dma_ops.read(&dma, 0x08 + 20 * 6 + 16, 4, &v), MMIO_UNMODELED); /* reserved */
    wr(CH(3, CNDTR), 0x12345);
    assert_int_equal(rd(CH(3, CNDTR)), 0x2345);
    wr(CH(3, CCR), EN);
    wr(CH(3, CNDTR), 7); /* ignored while enabled */
    assert_int_equal(rd(CH(3, CNDTR)), 0x2345);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_usart_tx_by_dma),
        cmocka_unit_test(test_usart_rx_by_dma_and_idle),
        cmocka_unit_test(test_circular_adc_dma),
        cmocka_unit_test(test_transfer_error),
        cmocka_unit_test(test_priority),
        cmocka_unit_test(test_registers),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}

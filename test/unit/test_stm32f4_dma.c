/* test_stm32f4_dma.c - the STM32F4 DMA model (sim/arm/stm32f4_dma.h)
 * against RM0090 section 10, on a bus of SRAM, ADC1 and GPIOA: the request
 * map (tables 42/43), reset values and IRQ lines; DMA2 stream 0 channel 0
 * circular from ADC1's 4-channel continuous scan wraps, raising HT after the
 * 2nd item then TC after the 4th (IRQ 56); memory-to-memory on DMA2 ends
 * with EN cleared, and DMA1 refuses it; TIM1 CH2 requests carry a table
 * into GPIOA BSRR through DMA2 stream 2 channel 6 (the Cube mouse's emitter
 * pulses); a bus error; a stream disabled mid-transfer; flag clearing. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <cmocka.h>

#include <stdint.h>
#include <string.h>

#include "arm/stm32f4_adc.h"
#include "arm/stm32f4_dma.h"
#include "arm/stm32f4_gpio.h"

static const mmio_clocks_t clk = { 168000000, 168000000, 42000000, 84000000, 84000000, 168000000, 42000000 };

#define RAM 0x20000000u
static uint8_t ram[4096];
static stm32f4_dma_t dma1, dma2;
static stm32f4_adc_common_t adcc;
static stm32f4_adc_t adc;
static stm32f4_gpio_t gpioa;
static uint64_t now;
static bool irq[96];
static unsigned irq_rises[96];

static void irq_set(void *ctx, unsigned n, bool level)
{
    if (level && !irq[n]) irq_rises[n]++;
    irq[n] = level;
}

typedef struct { uint32_t base, size; const mmio_ops_t *ops; void *self; } region_t;
static region_t regions[5];
#define NREG 5

static region_t *find(uint32_t addr)
{
    for (unsigned i = 0; i < NREG; i++)
        if (addr - regions[i].base < regions[i].size) return &regions[i];
    return NULL;
}

static bool bus_read(void *ctx, uint32_t addr, unsigned size, uint32_t *v)
{
    if (addr - RAM + size <= sizeof ram) {
        *v = 0;
        memcpy(v, ram + (addr - RAM), size);
        return true;
    }
    region_t *r = find(addr);
    if (!r) return false;
    if (r->ops->advance) r->ops->advance(r->self, now);
    return r->ops->read(r->self, addr - r->base, size, v) == MMIO_OK;
}

static bool bus_write(void *ctx, uint32_t addr, unsigned size, uint32_t v)
{
    if (addr - RAM + size <= sizeof ram) {
        memcpy(ram + (addr - RAM), &v, size);
        return true;
    }
    region_t *r = find(addr);
    if (!r) return false;
    if (r->ops->advance) r->ops->advance(r->self, now);
    return r->ops->write(r->self, addr - r->base, size, v) == MMIO_OK;
}

static void run_to(uint64_t to)
{
    for (;;) {
        uint64_t t = MMIO_NEVER;
        for (unsigned i = 0; i < NREG; i++) {
            uint64_t e = regions[i].ops->next_event ? regions[i].ops->next_event(regions[i].self) : MMIO_NEVER;
            if (e < t) t = e;
        }
        if (t > to) break;
        if (t > now) now = t;
        for (unsigned i = 0; i < NREG; i++)
            if (regions[i].ops->advance) regions[i].ops->advance(regions[i].self, now);
    }
    now = to;
    for (unsigned i = 0; i < NREG; i++)
        if (regions[i].ops->advance) regions[i].ops->advance(regions[i].self, now);
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

#define D1 STM32F4_DMA1_BASE
#define D2 STM32F4_DMA2_BASE
#define SCR(b, s) ((b) + 0x10 + 0x18 * (s))
#define SNDTR(b, s) (SCR(b, s) + 4)
#define SPAR(b, s) (SCR(b, s) + 8)
#define SM0AR(b, s) (SCR(b, s) + 12)
#define SFCR(b, s) (SCR(b, s) + 20)
#define EN 1u
#define TEIE (1u << 2)
#define HTIE (1u << 3)
#define TCIE (1u << 4)
#define DIR_M2P (1u << 6)
#define DIR_M2M (2u << 6)
#define CIRC (1u << 8)
#define PINC (1u << 9)
#define MINC (1u << 10)
#define PSIZE16 (1u << 11)
#define PSIZE32 (2u << 11)
#define MSIZE16 (1u << 13)
#define MSIZE32 (2u << 13)
#define CHSEL(c) ((uint32_t)(c) << 25)

static unsigned conv;
static double ramp(void *ctx, unsigned ch, uint64_t cycle) { return 0.1 * ++conv; }

static void setup_bus(void)
{
    memset(ram, 0, sizeof ram);
    memset(irq, 0, sizeof irq);
    memset(irq_rises, 0, sizeof irq_rises);
    now = 0;
    conv = 0;
    mmio_bus_t bus = { bus_read, bus_write, NULL };
    mmio_irq_t ir = { irq_set, NULL };
    stm32f4_dma_init(&dma1, 1, bus, ir);
    stm32f4_dma_init(&dma2, 2, bus, ir);
    stm32f4_adc_common_init(&adcc, &clk, ir);
    stm32f4_adc_init(&adc, &adcc, 1, (mmio_dma_req_t){ stm32f4_dma_request, &dma2 }, STM32F4_DREQ_ADC1, ramp, NULL,
                     3.3);
    stm32f4_gpio_init(&gpioa, 0, NULL, NULL);
    regions[0] = (region_t){ D1, 0x400, &stm32f4_dma_ops, &dma1 };
    regions[1] = (region_t){ D2, 0x400, &stm32f4_dma_ops, &dma2 };
    regions[2] = (region_t){ STM32F4_ADC_BASE(1), 0x100, &stm32f4_adc_ops, &adc };
    regions[3] = (region_t){ STM32F4_ADC_COMMON_BASE, 0x100, &stm32f4_adc_common_ops, &adcc };
    regions[4] = (region_t){ STM32F4_GPIO_BASE(0), 0x400, &stm32f4_gpio_ops, &gpioa };
}

static void test_map_and_reset(void **state)
{
    setup_bus();
    assert_int_equal(stm32f4_dma_map[1][0][0][0], STM32F4_DREQ_ADC1);
    assert_int_equal(stm32f4_dma_map[1][4][0][0], STM32F4_DREQ_ADC1);
    assert_int_equal(stm32f4_dma_map[1][2][1][0], STM32F4_DREQ_ADC2);
    assert_int_equal(stm32f4_dma_map[1][2][6][0], STM32F4_DREQ_TIM1_CH2);
    assert_int_equal(stm32f4_dma_map[1][4][6][0], STM32F4_DREQ_TIM1_CH4);
    assert_int_equal(stm32f4_dma_map[1][6][0][2], STM32F4_DREQ_TIM1_CH3);
    assert_int_equal(stm32f4_dma_map[1][7][4][0], STM32F4_DREQ_USART1_TX);
    assert_int_equal(stm32f4_dma_map[1][2][4][0], STM32F4_DREQ_USART1_RX);
    assert_int_equal(stm32f4_dma_map[0][3][0][0], STM32F4_DREQ_SPI2_RX);
    assert_int_equal(stm32f4_dma_map[0][4][0][0], STM32F4_DREQ_SPI2_TX);
    assert_int_equal(stm32f4_dma_map[0][1][3][1], STM32F4_DREQ_TIM2_CH3);
    assert_int_equal(stm32f4_dma_map[0][0][1][0], STM32F4_DREQ_I2C1_RX);
    assert_int_equal(stm32f4_dma_map[0][1][0][0], STM32F4_DREQ_NONE);
    assert_string_equal(stm32f4_dreq_name(STM32F4_DREQ_TIM1_CH3), "TIM1_CH3");
    assert_int_equal(stm32f4_dma_irq(1, 0), 11);
    assert_int_equal(stm32f4_dma_irq(1, 6), 17);
    assert_int_equal(stm32f4_dma_irq(1, 7), 47);
    assert_int_equal(stm32f4_dma_irq(2, 0), 56);
    assert_int_equal(stm32f4_dma_irq(2, 4), 60);
    assert_int_equal(stm32f4_dma_irq(2, 5), 68);
    assert_int_equal(stm32f4_dma_irq(2, 7), 70);
    assert_int_equal(rd(SFCR(D2, 3)), 0x21);
    assert_int_equal(rd(SCR(D2, 3)), 0);
    assert_int_equal(rd(D2 + 0x00), 0);
}

/* ADC1 scans 4 channels continuously (HAL_ADC_Start_DMA); DMA2 stream 0 circular, 16-bit, 4 items. */
static void test_circular_adc(void **state)
{
    setup_bus();
    const uint16_t *buf = (const uint16_t *)ram;
    wr(SPAR(D2, 0), STM32F4_ADC_BASE(1) + 0x4C);
    wr(SM0AR(D2, 0), RAM);
    wr(SNDTR(D2, 0), 4);
    wr(SCR(D2, 0), CHSEL(0) | CIRC | MINC | PSIZE16 | MSIZE16 | HTIE | TCIE | EN);
    const uint32_t A = STM32F4_ADC_BASE(1);
    wr(A + 0x04, 1u << 8);                                   /* SCAN */
    wr(A + 0x2C, 3u << 20);                                  /* L: 4 ranks */
    wr(A + 0x34, 0u | (1u << 5) | (2u << 10) | (3u << 15)); /* channels 0-3 */
    wr(A + 0x08, 1u | 2u | (1u << 8) | (1u << 9));          /* ADON, CONT, DMA, DDS */
    wr(A + 0x08, 1u | 2u | (1u << 8) | (1u << 9) | (1u << 30)); /* SWSTART */
    /* ADCCLK = 84 MHz / 2 = 42 MHz: 4 HCLK per ADC clock; 3 + 12 = 15 ADC clocks a conversion
     * (60 cycles) after a 2-clock (8-cycle) trigger latency */
    uint64_t t0 = now;
    run_to(t0 + 8 + 60 - 1);
    assert_int_equal(rd(SNDTR(D2, 0)), 4);
    run_to(t0 + 8 + 60);
    assert_int_equal(rd(SNDTR(D2, 0)), 3);
    assert_int_equal(buf[0], 124); /* 0.1 V: round(0.1 x 4096 / 3.3) */
    run_to(t0 + 8 + 120);
    assert_int_equal(rd(D2 + 0x00) & 0x3Du, 0x10); /* HTIF0 */
    assert_true(irq[56]);
    wr(D2 + 0x08, 0x10u);                          /* CHTIF0 */
    assert_false(irq[56]);
    run_to(t0 + 8 + 240);
    assert_int_equal(rd(D2 + 0x00) & 0x3Du, 0x20); /* TCIF0 */
    assert_true(irq[56]);
    assert_int_equal(rd(SNDTR(D2, 0)), 4);         /* reloaded */
    assert_true(rd(SCR(D2, 0)) & EN);              /* circular: stays enabled */
    assert_int_equal(buf[3], 496);                 /* 0.4 V */
    wr(D2 + 0x08, 0x3Du);
    run_to(t0 + 8 + 300); /* the 5th conversion lands on buf[0] again */
    assert_int_equal(buf[0], 621); /* 0.5 V */
    assert_int_equal(rd(SNDTR(D2, 0)), 3);
    assert_int_equal(rd(A + 0x00) & (1u << 5), 0); /* no overrun: DMA read every result */
    assert_int_equal(irq_rises[56], 2);
}

/* The Cube mouse's sensor scan: TIM1 CC3 starts a 3-channel scan (not
 * continuous) each period; DMA2 stream 4 channel 0 (ADC1's other stream)
 * circular over 2 scans: HT after the 1st scan, TC after the 2nd, the 3rd
 * wraps onto the buffer's start. */
static void test_timer_triggered_adc(void **state)
{
    setup_bus();
    const uint16_t *buf = (const uint16_t *)ram;
    const uint32_t A = STM32F4_ADC_BASE(1);
    wr(SPAR(D2, 4), A + 0x4C);
    wr(SM0AR(D2, 4), RAM);
    wr(SNDTR(D2, 4), 6);
    wr(SCR(D2, 4), CHSEL(0) | CIRC | MINC | PSIZE16 | MSIZE16 | HTIE | TCIE | EN);
    wr(A + 0x04, 1u << 8);                                  /* SCAN */
    wr(A + 0x2C, 2u << 20);                                 /* 3 ranks */
    wr(A + 0x08, 1u | (1u << 8) | (1u << 9) | (2u << 24) | (1u << 28)); /* ADON, DMA, DDS, TIM1_CC3 rising */
    for (unsigned k = 0; k < 3; k++) {
        uint64_t t = 10000u * (k + 1);
        run_to(t);
        stm32f4_adc_ext_trigger(&adc, false, STM32F4_ADC_EXT_TIM1_CC3, true, t);
        run_to(t + 8 + 3 * 60 - 1);
        assert_int_equal(rd(SNDTR(D2, 4)), k == 2 ? 4 : 6 - 3 * k - 2); /* the 3rd rank still converting */
        run_to(t + 8 + 3 * 60);
        if (k == 0) { assert_int_equal(rd(D2 + 0x04) & 0x3Du, 0x10); wr(D2 + 0x0C, 0x3Du); }
        if (k == 1) { assert_int_equal(rd(D2 + 0x04) & 0x3Du, 0x20); wr(D2 + 0x0C, 0x3Du); }
    }
    assert_int_equal(conv, 9);
    assert_int_equal(buf[0], 869); /* the 7th conversion: 0.7 V */
    assert_int_equal(buf[5], 745); /* the 6th: 0.6 V */
    assert_int_equal(rd(SNDTR(D2, 4)), 3);
    assert_int_equal(irq_rises[60], 3); /* HT, TC, and HT again half-way through the wrapped buffer */
    assert_int_equal(rd(A + 0x00) & (1u << 5), 0);
}

static void test_mem_to_mem(void **state)
{
    setup_bus();
    for (unsigned i = 0; i < 8; i++) ((uint32_t *)ram)[i] = 0x11111111u * (i + 1);
    wr(SPAR(D2, 1), RAM);
    wr(SM0AR(D2, 1), RAM + 0x100);
    wr(SNDTR(D2, 1), 8);
    wr(SFCR(D2, 1), 1u << 2); /* DMDIS: FIFO mode, as memory-to-memory needs */
    wr(SCR(D2, 1), DIR_M2M | PINC | MINC | PSIZE32 | MSIZE32 | TCIE | EN);
    run_to(now + 1);
    assert_int_equal(memcmp(ram, ram + 0x100, 32), 0);
    assert_int_equal(rd(SNDTR(D2, 1)), 0);
    assert_false(rd(SCR(D2, 1)) & EN); /* cleared at the end */
    assert_int_equal(rd(D2 + 0x00) & (0x3Du << 6), 0x30u << 6); /* HTIF1, TCIF1 */
    assert_true(irq[57]);
    /* DMA1 has no memory-to-memory: reported, nothing moves */
    wr(SPAR(D1, 0), RAM);
    wr(SM0AR(D1, 0), RAM + 0x200);
    wr(SNDTR(D1, 0), 8);
    assert_true(bus_write(NULL, SCR(D1, 0), 4, DIR_M2M | PINC | MINC | PSIZE32 | MSIZE32 | EN) == false);
    run_to(now + 10);
    assert_int_equal(rd(SNDTR(D1, 0)), 8);
    assert_int_equal(ram[0x200], 0);
}

/* TIM1 CH2 compare events (the timer's DMA request) carry a table into GPIOA BSRR. */
static void test_timer_to_bsrr(void **state)
{
    setup_bus();
    uint32_t table[3] = { 1u << 5, 1u << 21, (1u << 6) | (1u << 5) };
    memcpy(ram + 0x40, table, sizeof table);
    wr(SPAR(D2, 2), STM32F4_GPIO_BASE(0) + 0x18);
    wr(SM0AR(D2, 2), RAM + 0x40);
    wr(SNDTR(D2, 2), 3);
    wr(SCR(D2, 2), CHSEL(6) | DIR_M2P | CIRC | MINC | PSIZE32 | MSIZE32 | EN);
    wr(SCR(D2, 4), CHSEL(6) | DIR_M2P | MINC | PSIZE32 | MSIZE32); /* not enabled: untouched */
    uint32_t seen[4];
    for (unsigned k = 0; k < 4; k++) {
        stm32f4_dma_request(&dma2, STM32F4_DREQ_TIM1_CH2, true);
        run_to(now + 100);
        stm32f4_dma_request(&dma2, STM32F4_DREQ_TIM1_CH2, false); /* the timer's request is served */
        seen[k] = rd(STM32F4_GPIO_BASE(0) + 0x14) & 0xFFFFu;
    }
    assert_int_equal(seen[0], 1u << 5);
    assert_int_equal(seen[1], 0);
    assert_int_equal(seen[2], (1u << 6) | (1u << 5));
    assert_int_equal(seen[3], (1u << 6) | (1u << 5)); /* the table again: PA5 set */
    /* a request another channel selects does not move stream 2 */
    stm32f4_dma_request(&dma2, STM32F4_DREQ_TIM1_CH4, true);
    run_to(now + 100);
    assert_int_equal(rd(SNDTR(D2, 2)), 2);
}

static void test_errors_and_disable(void **state)
{
    setup_bus();
    /* a peripheral address nothing answers: TEIF, EN cleared (stream 5: HISR bits 6-11) */
    wr(SPAR(D2, 5), 0x50000000u);
    wr(SM0AR(D2, 5), RAM);
    wr(SNDTR(D2, 5), 2);
    wr(SCR(D2, 5), DIR_M2M | PSIZE32 | MSIZE32 | TEIE | EN);
    run_to(now + 1);
    assert_int_equal(rd(D2 + 0x04), 0x08u << 6);
    assert_false(rd(SCR(D2, 5)) & EN);
    assert_true(irq[68]);
    wr(D2 + 0x0C, 0x3Du << 6); /* HIFCR */
    assert_false(irq[68]);
    assert_int_equal(rd(D2 + 0x04), 0);
    /* registers hold while EN; software disable mid-transfer sets TCIF (10.3.17) */
    wr(SPAR(D1, 3), 0x40003800u + 0x0C);
    wr(SM0AR(D1, 3), RAM);
    wr(SNDTR(D1, 3), 10);
    wr(SCR(D1, 3), CHSEL(0) | MINC | TCIE | EN);
    wr(SNDTR(D1, 3), 99);
    wr(SCR(D1, 3), CHSEL(1) | MINC | TCIE | EN);
    assert_int_equal(rd(SNDTR(D1, 3)), 10);
    assert_int_equal(rd(SCR(D1, 3)), CHSEL(0) | MINC | TCIE | EN);
    wr(SCR(D1, 3), CHSEL(0) | MINC | TCIE);
    assert_int_equal(rd(D1 + 0x00), 0x20u << 22); /* TCIF3 */
    assert_true(irq[14]);
    /* unmodeled: double buffer, FIFO mode in a peripheral transfer */
    assert_false(bus_write(NULL, SCR(D1, 6), 4, (1u << 18)));
    wr(SFCR(D1, 6), 1u << 2);
    assert_false(bus_write(NULL, SCR(D1, 6), 4, EN));
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_map_and_reset),
        cmocka_unit_test(test_circular_adc),
        cmocka_unit_test(test_timer_triggered_adc),
        cmocka_unit_test(test_mem_to_mem),
        cmocka_unit_test(test_timer_to_bsrr),
        cmocka_unit_test(test_errors_and_disable),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}

/* test_stm32_usart.c - the STM32F1 USART model (sim/arm/stm32f1_usart.h)
 * against RM0008 section 27: TXE/TC timing at 921600 baud from PCLK1 36 MHz
 * (BRR 39 as libopencm3 rounds it: a 10-bit frame of 390 PCLK1 = 780 core
 * cycles), the idle frame TE sends, RXNE and overrun, IDLE after a frame,
 * the clearing sequences, the interrupt line, the unmodeled bits. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <cmocka.h>

#include <stdint.h>

#include "arm/stm32f1_usart.h"

static const mmio_clocks_t clk = { 72000000, 72000000, 36000000, 72000000, 72000000, 72000000, 9000000 };

enum { SR = 0x00, DR = 0x04, BRR = 0x08, CR1 = 0x0C, CR2 = 0x10, CR3 = 0x14 };
#define S_ORE (1u << 3)
#define S_IDLE (1u << 4)
#define S_RXNE (1u << 5)
#define S_TC (1u << 6)
#define S_TXE (1u << 7)
#define RE (1u << 2)
#define TE (1u << 3)
#define IDLEIE (1u << 4)
#define RXNEIE (1u << 5)
#define PCE (1u << 10)
#define UE (1u << 13)
#define FRAME 780u

static stm32_usart_t u;
static bool irq_level;
static unsigned irq_n;
static uint8_t sent[16];
static uint64_t sent_at[16];
static unsigned nsent;

static void irq_set(void *ctx, unsigned irq, bool level) { irq_n = irq; irq_level = level; }
static void sink(void *ctx, uint8_t b, uint64_t cycle) { sent_at[nsent] = cycle; sent[nsent++] = b; }

static void setup_usart(void)
{
    nsent = 0;
    irq_level = false;
    stm32_usart_init(&u, 3, &clk, (mmio_irq_t){ irq_set, NULL }, (mmio_dma_req_t){ NULL, NULL }, sink, NULL);
}
static uint32_t rd(uint32_t off, uint64_t now)
{
    uint32_t v;
    stm32_usart_ops.advance(&u, now);
    assert_int_equal(stm32_usart_ops.read(&u, off, 4, &v), MMIO_OK);
    return v;
}
static void wr(uint32_t off, uint32_t v, uint64_t now)
{
    stm32_usart_ops.advance(&u, now);
    assert_int_equal(stm32_usart_ops.write(&u, off, 4, v), MMIO_OK);
}

static void test_reset(void **state)
{
    setup_usart();
    assert_int_equal(rd(SR, 0), 0xC0); /* RM0008 27.6.1 */
    assert_int_equal(rd(CR1, 0), 0);
}

static void test_tx_timing(void **state)
{
    setup_usart();
    wr(BRR, 39, 0);
    wr(CR1, UE | TE, 0); /* an idle frame first (27.3.2): the shifter is busy until 780 */
    assert_int_equal(stm32_usart_ops.next_event(&u), FRAME);
    assert_true(rd(SR, 1000) & S_TC);
    wr(DR, 'A', 1000); /* SR read, then DR write: TC clears */
    uint32_t sr = rd(SR, 1000);
    assert_true(sr & S_TXE); /* the shifter took it at once */
    assert_false(sr & S_TC);
    wr(DR, 'B', 1001);
    assert_false(rd(SR, 1001) & S_TXE); /* TDR full behind the shifter */
    assert_false(rd(SR, 1000 + FRAME - 1) & S_TXE);
    assert_int_equal(nsent, 0);
    assert_true(rd(SR, 1000 + FRAME) & S_TXE); /* 'A' out, 'B' into the shifter */
    assert_int_equal(nsent, 1);
    assert_int_equal(sent_at[0], 1000 + FRAME);
    assert_false(rd(SR, 1000 + 2 * FRAME - 1) & S_TC);
    assert_true(rd(SR, 1000 + 2 * FRAME) & S_TC);
    assert_int_equal(nsent, 2);
    assert_int_equal(sent[1], 'B');
    assert_int_equal(sent_at[1], 1000 + 2 * FRAME);
}

/* 2 stop bits and 9 data bits: 1 + 9 + 2 = 12 bits = 936 core cycles. */
static void test_frame_format(void **state)
{
    setup_usart();
    wr(BRR, 39, 0);
    wr(CR2, 2u << 12, 0);
    wr(CR1, UE | TE | (1u << 12), 0);
    assert_int_equal(stm32_usart_ops.next_event(&u), 12 * 78);
}

static void test_rx_overrun_idle(void **state)
{
    setup_usart();
    wr(BRR, 39, 0);
    wr(CR1, UE | RE | RXNEIE | IDLEIE, 0);
    assert_true(stm32_usart_push(&u, 'x', 100));
    assert_true(stm32_usart_push(&u, 'y', 100));
    assert_true(stm32_usart_push(&u, 'z', 100));
    assert_false(rd(SR, 100 + FRAME - 1) & S_RXNE);
    assert_false(irq_level);
    assert_true(rd(SR, 100 + FRAME) & S_RXNE);
    assert_true(irq_level);
    assert_int_equal(irq_n, 39); /* USART3 */
    uint32_t sr = rd(SR, 100 + 2 * FRAME); /* 'y' arrived with RXNE set: overrun, lost */
    assert_true(sr & S_ORE);
    assert_int_equal(rd(DR, 100 + 2 * FRAME), 'x'); /* SR then DR: ORE and RXNE clear */
    assert_int_equal(rd(SR, 100 + 2 * FRAME) & (S_ORE | S_RXNE), 0);
    assert_false(irq_level);
    assert_true(rd(SR, 100 + 3 * FRAME) & S_RXNE);
    assert_int_equal(rd(DR, 100 + 3 * FRAME), 'z');
    /* one idle frame after the last byte (27.6.1 IDLE) */
    assert_false(rd(SR, 100 + 4 * FRAME - 1) & S_IDLE);
    assert_false(irq_level);
    assert_true(rd(SR, 100 + 4 * FRAME) & S_IDLE);
    assert_true(irq_level);
    rd(DR, 100 + 4 * FRAME); /* SR read then DR read: IDLE clears (bulebule's usart_clear_idle_line_detected) */
    assert_false(rd(SR, 100 + 4 * FRAME) & S_IDLE);
    assert_false(irq_level);
    /* no new IDLE until RXNE is set again */
    assert_int_equal(stm32_usart_ops.next_event(&u), MMIO_NEVER);
}

/* A byte arriving within the idle frame: the line was not idle. */
static void test_no_idle_between_bytes(void **state)
{
    setup_usart();
    wr(BRR, 39, 0);
    wr(CR1, UE | RE, 0);
    stm32_usart_push(&u, 'a', 0);
    stm32_usart_push(&u, 'b', FRAME + FRAME / 2);
    assert_false(rd(SR, 2 * FRAME + FRAME / 2 - 1) & S_IDLE);
    rd(DR, 2 * FRAME);
    assert_int_equal(rd(DR, 2 * FRAME + FRAME / 2), 'b');
    assert_true(rd(SR, 3 * FRAME + FRAME / 2) & S_IDLE);
}

static void test_unmodeled(void **state)
{
    setup_usart();
    uint32_t v;
    assert_int_equal(stm32_usart_ops.write(&u, CR1, 4, UE | PCE), MMIO_UNMODELED);
    assert_int_equal(stm32_usart_ops.write(&u, CR3, 4, 1u << 8), MMIO_UNMODELED); /* RTSE */
    assert_int_equal(stm32_usart_ops.write(&u, CR1, 4, UE | 1u << 15), MMIO_UNMODELED); /* the F4's OVER8 */
    assert_int_equal(stm32_usart_ops.write(&u, CR3, 4, 1u << 11), MMIO_UNMODELED); /* the F4's ONEBIT */
    assert_int_equal(stm32_usart_ops.read(&u, 0x1C, 4, &v), MMIO_UNMODELED);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_reset),
        cmocka_unit_test(test_tx_timing),
        cmocka_unit_test(test_frame_format),
        cmocka_unit_test(test_rx_overrun_idle),
        cmocka_unit_test(test_no_idle_between_bytes),
        cmocka_unit_test(test_unmodeled),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}

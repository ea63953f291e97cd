/* stm32f1_usart.h - the STM32F1's USART1-3 in asynchronous mode at register
 * level (RM0008 rev 21, section 27). Bytes sent go to a sink the board gives
 * (the console) at the cycle their frame's stop bit ends; bytes received are
 * pushed by the host into an input queue and arrive one frame time apart. */
#ifndef ARM_STM32F1_USART_H
#define ARM_STM32F1_USART_H

#include <stdbool.h>
#include <stdint.h>

#include "arm/mmio.h"

#define STM32_USART1_BASE 0x40013800u
#define STM32_USART2_BASE 0x40004400u
#define STM32_USART3_BASE 0x40004800u
#define STM32_USART_SIZE  0x400u
#define STM32_USART_IRQ(n) (36u + (n)) /* USART1..3: IRQ 37..39 (RM0008 Table 63) */
#define STM32_USART_RXQ 256            /* host bytes waiting to be received */

/* A byte whose frame ended (its stop bit sent) at core cycle `cycle`. */
typedef void (*stm32_usart_sink_fn)(void *ctx, uint8_t byte, uint64_t cycle);

typedef struct {
    /* wiring, kept across reset */
    const mmio_clocks_t *clk;
    mmio_irq_t irq;
    mmio_dma_req_t dma;
    unsigned index;                 /* 1..3: USART1 on PCLK2, USART2/3 on PCLK1; the F4's 4..6: UART4/5, USART6 */
    unsigned irq_n;                 /* its NVIC line (STM32_USART_IRQ; the F4's UART4/5, USART6 their own) */
    unsigned apb;                   /* 2: clocked by PCLK2 (USART1, the F4's USART6), 1: PCLK1 */
    unsigned dma_tx, dma_rx;        /* the request numbers: DMA1 channels (RM0008 Table 78) or stm32f4_dreq_t */
    stm32_usart_sink_fn sink;
    void *sink_ctx;
    /* registers (RM0008 27.6) */
    uint32_t sr, rdr, tdr, brr, cr1, cr2, cr3, gtpr;
    /* transmitter */
    uint64_t now;                   /* the cycle advance() last reached */
    uint64_t tx_end;                /* the shifted frame's end, MMIO_NEVER: shifter empty */
    bool tx_idle_frame;             /* the shifter sends the idle preamble of a TE 0->1 */
    uint16_t tx_shift;
    /* receiver */
    uint8_t rxq[STM32_USART_RXQ];
    unsigned rxq_head, rxq_count;
    uint64_t rx_end;                /* the received frame's end, MMIO_NEVER: line idle */
    uint64_t idle_at;               /* when the idle frame after the last byte completes */
    bool idle_armed;                /* RXNE was set since the last IDLE (RM0008 27.6.1) */
    unsigned long rx_dropped;       /* host bytes lost: queue full */
    uint32_t sr_seen;               /* SR as last read: the first half of a clearing sequence */
    bool irq_level, tx_req, rx_req;
} stm32_usart_t;

extern const mmio_ops_t stm32_usart_ops;

/* index 1..6 (the F1's 1..3: IRQ, clock and DMA channels follow from it;
 * the F4 SoC sets irq_n, dma_tx and dma_rx after, UART4/5 and USART6's
 * from RM0090 table 61 and tables 42/43). */
void stm32_usart_init(stm32_usart_t *u, unsigned index, const mmio_clocks_t *clk, mmio_irq_t irq,
                      mmio_dma_req_t dma, stm32_usart_sink_fn sink, void *sink_ctx);
/* The host sends a byte at core cycle now (>= the last advance). false: the
 * input queue is full and the byte is dropped. */
bool stm32_usart_push(stm32_usart_t *u, uint8_t byte, uint64_t now);

#endif

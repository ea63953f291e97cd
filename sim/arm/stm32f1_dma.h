/* stm32f1_dma.h - the STM32F1's DMA1 controller at register level (RM0008
 * rev 21, section 13): 7 channels, each served on its peripheral's request
 * line (mmio_dma_req_t, channel 1..7) or, in memory-to-memory mode, as soon
 * as it is enabled; transfers go through the bus the board gives
 * (mmio_bus_t), at the cycle the controller is advanced to. */
#ifndef ARM_STM32F1_DMA_H
#define ARM_STM32F1_DMA_H

#include <stdbool.h>
#include <stdint.h>

#include "arm/mmio.h"

#define STM32_DMA1_BASE 0x40020000u
#define STM32_DMA_SIZE  0x400u
#define STM32_DMA1_IRQ(ch) (10u + (ch)) /* DMA1_Channel1..7: IRQ 11..17 (RM0008 Table 63) */
#define STM32_DMA_CHANNELS 7

typedef struct {
    uint32_t ccr, cndtr, cpar, cmar;
    uint32_t reload;   /* CNDTR as programmed: circular mode's reload, the half-transfer point */
    uint32_t done;     /* transfers since the channel was enabled or reloaded: the address offset */
    bool req;          /* the peripheral's request line */
} stm32_dma_chan_t;

typedef struct {
    mmio_bus_t bus;
    mmio_irq_t irq;
    uint32_t isr;
    stm32_dma_chan_t ch[STM32_DMA_CHANNELS];
    uint64_t now;      /* the cycle advance() last reached: transfers happen there */
    bool irq_level[STM32_DMA_CHANNELS];
} stm32_dma_t;

extern const mmio_ops_t stm32_dma_ops;

void stm32_dma_init(stm32_dma_t *d, mmio_bus_t bus, mmio_irq_t irq);
/* The request callback peripherals are given: mmio_dma_req_t{ stm32_dma_request, dma }.
 * It only records the line; the transfers happen in advance(), so a transfer
 * never runs inside the requesting peripheral's own access. */
void stm32_dma_request(void *dma, unsigned channel, bool level);

#endif

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

/* The transfer step both families' controllers share (RM0008 13.3.3-13.3.5,
 * RM0090 10.3.6-10.3.10): one item moved, the peripheral address advanced
 * by done items of psize bytes with pinc, the memory address by done items
 * of msize with minc, read from the source at its size and written to the
 * destination at its (RM0008 table 79: zero-extended or its low part kept;
 * the F4's direct mode: one size); false: a bus error. */
typedef struct {
    uint32_t par, mar;
    unsigned psize, msize;     /* bytes: 1, 2, 4 */
    bool pinc, minc, from_mem; /* from_mem: memory to peripheral */
} stm32_dma_item_t;
bool stm32_dma_move(mmio_bus_t bus, const stm32_dma_item_t *it, uint32_t done);
/* The item counted: *ndtr down, *done up; STM32_DMA_HT when the count
 * passes half of reload, STM32_DMA_TC at its end (circular: both reloaded). */
#define STM32_DMA_HT 1u
#define STM32_DMA_TC 2u
unsigned stm32_dma_count(uint32_t *ndtr, uint32_t *done, uint32_t reload, bool circular);
/* One item moved (stm32_dma_move) and, moved, counted (stm32_dma_count):
 * STM32_DMA_TE on a bus error (nothing counted), else the count's HT/TC. */
#define STM32_DMA_TE 4u
unsigned stm32_dma_step(mmio_bus_t bus, const stm32_dma_item_t *it, uint32_t *ndtr, uint32_t *done, uint32_t reload,
                        bool circular);
/* A controller's flags of a step's: te, ht and tc for STM32_DMA_TE, _HT and _TC. */
static inline unsigned stm32_dma_flags(unsigned k, unsigned te, unsigned ht, unsigned tc)
{
    return ((k & STM32_DMA_TE) ? te : 0u) | ((k & STM32_DMA_HT) ? ht : 0u) | ((k & STM32_DMA_TC) ? tc : 0u);
}

/* The arbiter and service loop both controllers share (RM0008 13.3.2,
 * RM0090 10.3.4): among the channels (streams) ready, the highest priority
 * level PL, then the lowest number, is served one transfer; then again,
 * until none is ready. Inline, so that each controller's calls take its own
 * functions directly. */
typedef struct {
    unsigned count;          /* channels or streams */
    unsigned max_transfers;  /* a guard against a request that never falls in circular mode (a peripheral model's bug) */
    unsigned (*ready_pl)(const void *ctl, unsigned i); /* channel i's PL + 1 when it is ready, 0 when not */
    void (*serve)(void *ctl, unsigned i);              /* one transfer of channel i */
} stm32_dma_arbiter_t;

/* The channel served next, -1 if none. */
static inline int stm32_dma_arbitrate(const stm32_dma_arbiter_t *a, const void *ctl)
{
    int best = -1;
    unsigned best_pl = 0;
    for (unsigned i = 0; i < a->count; i++) {
        unsigned pl = a->ready_pl(ctl, i);
        if (pl > best_pl) { best = (int)i; best_pl = pl; }
    }
    return best;
}

/* The controller advanced to now (*at: the cycle it reached, where transfers happen). */
static inline void stm32_dma_run(const stm32_dma_arbiter_t *a, void *ctl, uint64_t *at, uint64_t now)
{
    if (now > *at) *at = now;
    for (unsigned n = 0; n < a->max_transfers; n++) {
        int i = stm32_dma_arbitrate(a, ctl);
        if (i < 0) break;
        a->serve(ctl, (unsigned)i);
    }
}

/* next_event: the cycle reached while a channel is ready (its transfer is due there), else none. */
static inline uint64_t stm32_dma_next(const stm32_dma_arbiter_t *a, const void *ctl, uint64_t at)
{
    return stm32_dma_arbitrate(a, ctl) >= 0 ? at : MMIO_NEVER;
}

#endif

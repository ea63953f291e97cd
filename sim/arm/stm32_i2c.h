/* stm32_i2c.h - the STM32F1/F4 I2C peripheral as a bus master at register
 * level (the same registers on both: RM0008 rev 21 section 26 and RM0090
 * rev 19 section 27): CR1, CR2, OAR1, OAR2, DR, SR1, SR2, CCR, TRISE. The
 * board attaches up to 4 slave devices by 7-bit address; a byte on the bus
 * takes 9 SCL periods of the CCR's clock, in core cycles. */
#ifndef ARM_STM32_I2C_H
#define ARM_STM32_I2C_H

#include <stdbool.h>
#include <stdint.h>

#include "arm/mmio.h"

#define STM32_I2C_SIZE 0x400u
#define STM32F4_I2C_BASE(n) (0x40005400u + 0x400u * ((n) - 1u)) /* I2C1..3 (RM0090 table 1; F1: I2C1/2 the same) */
#define STM32_I2C_EV_IRQ(n) ((n) == 3 ? 72u : 31u + 2u * ((n) - 1u)) /* I2Cx_EV (RM0008 table 63, RM0090 table 61) */
#define STM32_I2C_ER_IRQ(n) (STM32_I2C_EV_IRQ(n) + 1u)
#define STM32_I2C_SLAVES 4

/* A slave on the bus: a START addressed to it (read: the R/W bit; false:
 * no acknowledge), a byte written (false: NACK), a byte read, the STOP. */
typedef struct {
    uint8_t addr; /* 7-bit */
    bool (*start)(void *dev, bool read, uint64_t cycle);
    bool (*write)(void *dev, uint8_t byte, uint64_t cycle);
    uint8_t (*read)(void *dev, uint64_t cycle);
    void (*stop)(void *dev, uint64_t cycle);
    void *dev;
} stm32_i2c_slave_t;

typedef struct {
    /* wiring */
    unsigned index;             /* 1..3 */
    const mmio_clocks_t *clk;   /* PCLK1 drives the peripheral */
    mmio_irq_t irq;
    mmio_dma_req_t dma;
    unsigned dma_tx, dma_rx;    /* the request numbers the DMA model knows them by */
    stm32_i2c_slave_t slave[STM32_I2C_SLAVES];
    unsigned nslaves;
    /* registers (RM0090 27.6) */
    uint32_t cr1, cr2, oar1, oar2, sr1, sr2, ccr, trise;
    uint8_t dr;
    /* state */
    uint64_t now, phase_end;
    int phase;                  /* what the bus is doing (stm32_i2c.c) */
    uint8_t shift;              /* the byte on the wire */
    bool dr_full;               /* transmitter: a byte waits in DR behind the shift register */
    bool rx_held, rx_ack;       /* receiver: a byte held in the shift register (BTF), and its (N)ACK */
    bool ack_latched;           /* CR1.ACK at the end of the previous byte (POS = 1 uses it) */
    bool sr1_read;              /* SR1 read since: clears SB with a DR write, ADDR with an SR2 read */
    int cur;                    /* the addressed slave, -1: none */
    bool ev_level, er_level, tx_level, rx_level;
    unsigned long bytes;        /* data bytes moved, both directions */
} stm32_i2c_t;

extern const mmio_ops_t stm32_i2c_ops;

/* index 1..3; dma.request NULL for none, else dma_tx/dma_rx the request numbers. */
void stm32_i2c_init(stm32_i2c_t *i, unsigned index, const mmio_clocks_t *clk, mmio_irq_t irq, mmio_dma_req_t dma,
                    unsigned dma_tx, unsigned dma_rx);
/* A slave on the bus (false: 4 already). */
bool stm32_i2c_attach(stm32_i2c_t *i, stm32_i2c_slave_t s);

#endif

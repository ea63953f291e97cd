/* stm32f1_spi.h - the STM32F1's SPI1/SPI2 as a full-duplex master at
 * register level (RM0008 rev 21, section 25), and the interface of the
 * slave devices on its bus: one exchange per byte, the slave seeing the
 * byte on MOSI and answering on MISO. Chip select is the board's: it wires
 * the GPIO pin to the slave (mpu6500_select for the MPU-6500). */
#ifndef ARM_STM32F1_SPI_H
#define ARM_STM32F1_SPI_H

#include <stdbool.h>
#include <stdint.h>

#include "arm/mmio.h"

#define STM32_SPI1_BASE 0x40013000u
#define STM32_SPI2_BASE 0x40003800u
#define STM32_SPI_SIZE  0x400u
#define STM32_SPI_IRQ(n) (34u + (n)) /* SPI1 35, SPI2 36 (RM0008 Table 63) */

/* A slave on the bus: one byte in each direction, MSB first as on the wire
 * (an LSB-first master's bytes arrive bit-reversed), at the core cycle the
 * byte's last clock edge ends. A slave not selected answers 0xFF. */
typedef struct {
    uint8_t (*exchange)(void *dev, uint8_t mosi, uint64_t cycle);
    void *dev;
} stm32_spi_slave_t;

typedef struct {
    /* wiring, kept across reset */
    const mmio_clocks_t *clk;
    mmio_irq_t irq;
    mmio_dma_req_t dma;
    unsigned index;               /* 1: SPI1 on PCLK2, 2: SPI2 on PCLK1 */
    unsigned dma_rx, dma_tx;      /* DMA1 channels (RM0008 Table 78) */
    stm32_spi_slave_t slave;      /* .exchange NULL: nothing on the bus (MISO reads 0xFF) */
    /* registers (RM0008 25.5) */
    uint32_t cr1, cr2, sr, rxdr, txdr, crcpr;
    /* state */
    uint64_t now;
    uint64_t end;                 /* the frame in the shifter ends, MMIO_NEVER: none */
    uint16_t shift;
    bool dr_read;                 /* DR read since: the first half of OVR's clearing sequence */
    bool modf_seen;               /* SR read with MODF set: the first half of MODF's */
    bool irq_level, tx_req, rx_req;
} stm32_spi_t;

extern const mmio_ops_t stm32_spi_ops;

void stm32_spi_init(stm32_spi_t *s, unsigned index, const mmio_clocks_t *clk, mmio_irq_t irq,
                    mmio_dma_req_t dma, stm32_spi_slave_t slave);

#endif

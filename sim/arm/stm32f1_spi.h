/* stm32f1_spi.h - the STM32's SPI as a full-duplex master at register
 * level: the STM32F1's SPI1/SPI2 (RM0008 rev 21, section 25) and the
 * STM32F4's SPI1-3 (RM0090 rev 19, section 28: the same registers, bits
 * and sequences in SPI mode; CR2's FRF (TI mode) and SR's FRE added, the
 * F4 SoC setting the instance's interrupt line and DMA requests), and the
 * interface of the slave devices on its bus: one exchange per byte, the
 * slave seeing the byte on MOSI and answering on MISO. Chip select is the
 * board's: it wires the GPIO pin to the slave (mpu6500_select for the
 * MPU-6500). */
#ifndef ARM_STM32F1_SPI_H
#define ARM_STM32F1_SPI_H

#include <stdbool.h>
#include <stdint.h>

#include "arm/mmio.h"

#define STM32_SPI1_BASE 0x40013000u
#define STM32_SPI2_BASE 0x40003800u
#define STM32_SPI_SIZE  0x400u
#define STM32_SPI_IRQ(n) (34u + (n)) /* SPI1 35, SPI2 36 (RM0008 Table 63; RM0090 table 61 the same) */

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
    unsigned index;               /* 1: SPI1 on PCLK2, 2 and 3: SPI2/SPI3 on PCLK1 */
    unsigned irq_n;               /* its NVIC line (STM32_SPI_IRQ; the F4's SPI3 51) */
    unsigned dma_rx, dma_tx;      /* the request numbers: DMA1 channels (RM0008 Table 78) or stm32f4_dreq_t */
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

/* index 1..3 (SPI3: the F4's); the F1's NVIC line and DMA1 channels
 * follow from it (another family sets irq_n, dma_rx and dma_tx after). */
void stm32_spi_init(stm32_spi_t *s, unsigned index, const mmio_clocks_t *clk, mmio_irq_t irq,
                    mmio_dma_req_t dma, stm32_spi_slave_t slave);
/* The slave on the bus from now on (a board attaching its part). */
void stm32_spi_attach(stm32_spi_t *s, stm32_spi_slave_t slave);

#endif

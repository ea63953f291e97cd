/* stm32f4_dma.h - the STM32F4's DMA1/DMA2 controllers at register level
 * (RM0090 rev 19 section 10, RM0383 rev 3 section 9): 8 streams each, a
 * stream's CHSEL picking one of 8 request channels; the request mapping
 * (RM0090 tables 42 and 43) is data here, so a peripheral raises its named
 * request (stm32f4_dreq_t) and every stream that selects it is served.
 * Transfers go through the bus the board gives (mmio_bus_t), at the cycle
 * the controller is advanced to. */
#ifndef ARM_STM32F4_DMA_H
#define ARM_STM32F4_DMA_H

#include <stdbool.h>
#include <stdint.h>

#include "arm/mmio.h"

#define STM32F4_DMA1_BASE 0x40026000u
#define STM32F4_DMA2_BASE 0x40026400u
#define STM32F4_DMA_SIZE  0x400u
#define STM32F4_DMA_STREAMS 8

/* The requests of RM0090 tables 42 and 43 (a slash in the table: several
 * requests on one stream and channel; UART7/8 and SPI4-6 exist on the
 * F42x/F411 parts that have them). */
#define STM32F4_DREQ_LIST(X) \
    X(SPI1_RX) X(SPI1_TX) X(SPI2_RX) X(SPI2_TX) X(SPI3_RX) X(SPI3_TX) X(SPI4_RX) X(SPI4_TX) \
    X(SPI5_RX) X(SPI5_TX) X(SPI6_RX) X(SPI6_TX) X(I2S2_EXT_RX) X(I2S2_EXT_TX) X(I2S3_EXT_RX) \
    X(I2S3_EXT_TX) X(I2C1_RX) X(I2C1_TX) X(I2C2_RX) X(I2C2_TX) X(I2C3_RX) X(I2C3_TX) \
    X(USART1_RX) X(USART1_TX) X(USART2_RX) X(USART2_TX) X(USART3_RX) X(USART3_TX) X(UART4_RX) \
    X(UART4_TX) X(UART5_RX) X(UART5_TX) X(USART6_RX) X(USART6_TX) X(UART7_RX) X(UART7_TX) \
    X(UART8_RX) X(UART8_TX) X(ADC1) X(ADC2) X(ADC3) X(DAC1) X(DAC2) X(DCMI) X(SDIO) X(CRYP_IN) \
    X(CRYP_OUT) X(HASH_IN) \
    X(TIM1_UP) X(TIM1_CH1) X(TIM1_CH2) X(TIM1_CH3) X(TIM1_CH4) X(TIM1_TRIG) X(TIM1_COM) \
    X(TIM2_UP) X(TIM2_CH1) X(TIM2_CH2) X(TIM2_CH3) X(TIM2_CH4) X(TIM3_UP) X(TIM3_CH1) X(TIM3_CH2) \
    X(TIM3_CH3) X(TIM3_CH4) X(TIM3_TRIG) X(TIM4_UP) X(TIM4_CH1) X(TIM4_CH2) X(TIM4_CH3) \
    X(TIM5_UP) X(TIM5_CH1) X(TIM5_CH2) X(TIM5_CH3) X(TIM5_CH4) X(TIM5_TRIG) X(TIM6_UP) X(TIM7_UP) \
    X(TIM8_UP) X(TIM8_CH1) X(TIM8_CH2) X(TIM8_CH3) X(TIM8_CH4) X(TIM8_TRIG) X(TIM8_COM)

#define STM32F4_DREQ_ENUM(name) STM32F4_DREQ_##name,
typedef enum { STM32F4_DREQ_NONE = 0, STM32F4_DREQ_LIST(STM32F4_DREQ_ENUM) STM32F4_DREQ_COUNT } stm32f4_dreq_t;
#undef STM32F4_DREQ_ENUM

/* The requests on (controller 1/2, stream, channel), up to 3, NONE-terminated. */
#define STM32F4_DREQ_PER_CELL 3
extern const uint8_t stm32f4_dma_map[2][STM32F4_DMA_STREAMS][8][STM32F4_DREQ_PER_CELL];
/* A request's name as the reference manual writes it ("ADC1", "TIM1_CH3"). */
const char *stm32f4_dreq_name(stm32f4_dreq_t r);

typedef struct {
    uint32_t cr, ndtr, par, m0ar, m1ar, fcr;
    uint32_t reload;   /* NDTR as programmed: circular mode's reload, the half-transfer point */
    uint32_t done;     /* transfers since the stream was enabled or reloaded: the address offset */
} stm32f4_dma_stream_t;

typedef struct {
    unsigned index;    /* 1 or 2 */
    mmio_bus_t bus;
    mmio_irq_t irq;
    uint32_t isr[2];   /* LISR, HISR */
    stm32f4_dma_stream_t s[STM32F4_DMA_STREAMS];
    bool req[STM32F4_DREQ_COUNT];     /* the request lines as the peripherals hold them */
    bool pending[STM32F4_DREQ_COUNT]; /* a rise not yet acknowledged by a transfer */
    uint64_t now;
    bool irq_level[STM32F4_DMA_STREAMS];
} stm32f4_dma_t;

extern const mmio_ops_t stm32f4_dma_ops;

/* index 1 or 2 (DMA2 alone does memory-to-memory, RM0090 10.3.6). */
void stm32f4_dma_init(stm32f4_dma_t *d, unsigned index, mmio_bus_t bus, mmio_irq_t irq);
/* The request callback peripherals are given: mmio_dma_req_t{ stm32f4_dma_request, dma },
 * channel an stm32f4_dreq_t. It records the line; transfers happen in
 * advance(). A rise asks for one transfer: the transfer acknowledges it
 * (RM0090 10.3.2: the request is kept until the controller's acknowledge,
 * even if the line falls first: a timer's compare event is a pulse its
 * model raises and lowers at once), and a line still high after it asks
 * again only once it has fallen and risen. */
void stm32f4_dma_request(void *dma, unsigned channel, bool level);
/* Stream n's NVIC line (RM0090 table 61). */
unsigned stm32f4_dma_irq(unsigned index, unsigned stream);

#endif

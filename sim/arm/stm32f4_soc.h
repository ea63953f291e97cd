/* stm32f4_soc.h - an STM32F405 (RM0090 rev 19, datasheet DS8626 rev 9) as a
 * system on chip: every STM32F4 model placed on a Cortex-M4 core
 * (armcore.h) at its RM0090 2.3 table 1 address, its interrupt lines to the
 * NVIC by RM0090 table 61 (each model's own numbers), its DMA requests to
 * both controllers (RM0090 tables 42/43: a stream serves a request when its
 * CHSEL selects it, stm32f4_dma.h), the timers' TRGO and compare events to
 * the ADCs' external triggers (tables 69/70: a timer stops only at the
 * events an ADC's EXTEN/EXTSEL or JEXTEN/JEXTSEL take), each timer's TRGO
 * to the timers whose ITRx it is (RM0090 17.4.3, 18.4.3, 19.4.2: their
 * reset, gated, trigger and external clock 1 slave modes), the GPIO ports' pins to EXTI
 * through SYSCFG, the clocks from RCC, and each peripheral's registers
 * behind its RCC enable bit (RM0090 6.3.10-6.3.14: with the clock off the
 * registers read 0 and ignore writes; each such access counted).
 * The peripheral bit-band alias (0x42000000, RM0090 2.3.2) is the core's.
 *
 * Placed: RCC, PWR, FLASH interface, GPIOA-I, SYSCFG, EXTI, DMA1/2,
 * ADC1-3 and their common registers, TIM1-14, I2C1-3, USART1-3, UART4/5
 * and USART6 (the STM32F1 USART model: the same registers, RM0090 30.6;
 * OVER8 and ONEBIT are reported unmodeled by it), SPI1-3 (the STM32F1 SPI
 * model in SPI mode, RM0090 28.5; TI mode and I2S reported unmodeled).
 * Not placed (a firmware's access is listed unmodeled by the core):
 * IWDG/WWDG, RTC, DAC, CAN, USB, SDIO, the CCM SRAM. */
#ifndef ARM_STM32F4_SOC_H
#define ARM_STM32F4_SOC_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#include "arm/armcore.h"
#include "arm/stm32_i2c.h"
#include "arm/stm32f1_spi.h"
#include "arm/stm32f1_usart.h"
#include "arm/stm32f4_adc.h"
#include "arm/stm32f4_dma.h"
#include "arm/stm32f4_flash.h"
#include "arm/stm32f4_gpio.h"
#include "arm/stm32f4_pwr.h"
#include "arm/stm32f4_rcc.h"
#include "arm/stm32f4_syscfg.h"
#include "arm/stm32f4_tim.h"

#define STM32F4_SOC_PORTS 9    /* GPIOA..GPIOI */
#define STM32F4_SOC_I2CS 3
#define STM32F4_SOC_USARTS 6   /* USART1-3, UART4, UART5, USART6 */
#define STM32F4_SOC_SPIS 3
#define STM32F4_SOC_ADCS 3
#define STM32F4_SOC_GATES 56
#define STM32F4_SOC_REGIONS 56
/* RM0090 table 1 (USART2/3, SPI1/2 at the STM32F1's addresses) */
#define STM32F4_USART1_BASE 0x40011000u
#define STM32F4_USART6_BASE 0x40011400u
#define STM32F4_UART4_BASE 0x40004C00u
#define STM32F4_UART5_BASE 0x40005000u
#define STM32F4_SPI3_BASE 0x40003C00u

/* What the board connects: the analog inputs, the pins it watches, the serial sinks. */
typedef struct {
    stm32f4_adc_volts_fn volts;  /* ADC1-3's channels (NULL: 0 V) */
    void *volts_ctx;
    double vref_v;               /* VREF+ (0: 3.3 V) */
    stm32f4_gpio_pin_fn pin;     /* a pin's level changed (NULL: none) */
    void *pin_ctx;
    stm32_usart_sink_fn usart_sink; /* bytes USART1-3, UART4/5, USART6 sent (NULL: dropped) */
    void *usart_ctx;
} stm32f4_soc_io_t;

/* A peripheral's registers behind its RCC clock enable bit. */
typedef struct {
    mmio_ops_t ops;              /* the peripheral's, reads and writes through the gate */
    const mmio_ops_t *inner;
    void *self;
    const uint32_t *enr;         /* the RCC enable register */
    uint32_t bit;
    unsigned long off_accesses;  /* accesses while the clock was off */
} stm32f4_gate_t;

typedef struct {
    armcore_t *core;
    stm32f4_soc_io_t io;
    stm32f4_rcc_t rcc;
    stm32f4_pwr_t pwr;
    stm32f4_flash_t flash;
    stm32f4_gpio_t gpio[STM32F4_SOC_PORTS];
    stm32f4_syscfg_t syscfg;
    stm32f4_exti_t exti;
    stm32f4_dma_t dma[2];
    stm32f4_adc_common_t adc_common;
    stm32f4_adc_t adc[STM32F4_SOC_ADCS];
    mmio_ops_t adc_ops;          /* the ADC's, its writes telling the timers the events the triggers take */
    stm32f1_tim_t tim[STM32F4_TIM_COUNT];
    mmio_ops_t tim_ops[STM32F4_TIM_COUNT]; /* the timers', their writes telling the masters the TRGOs slaves take */
    stm32_tim_links_t links;     /* TIM1-14 through stm32f4_tim_itr */
    stm32_i2c_t i2c[STM32F4_SOC_I2CS];
    stm32_usart_t usart[STM32F4_SOC_USARTS];
    stm32_spi_t spi[STM32F4_SOC_SPIS];
    stm32f4_gate_t gate[STM32F4_SOC_GATES];
    unsigned ngates;
    mmio_region_t region[STM32F4_SOC_REGIONS];
    int nregions;
    bool overflow;               /* a region or gate past the tables (init fails) */
} stm32f4_soc_t;

/* The models at power-on and the core that runs them: cfg's image (an
 * stm32f405xg one), verbose and no_idle_skip are the caller's, its
 * regions and clocks the SoC's; *core is the new core (also soc->core).
 * hse_hz: the board's crystal (0: none). 0, or -1 with one line in err.
 * soc must stay where it is while the core lives. */
int stm32f4_soc_init(stm32f4_soc_t *soc, armcore_t **core, const armcore_cfg_t *cfg, uint32_t hse_hz,
                     const stm32f4_soc_io_t *io, char *err, size_t errn);
/* The core freed (the models need no freeing). */
void stm32f4_soc_free(stm32f4_soc_t *soc);

/* What a board reaches: the GPIO port (0 = A), an I2C bus (1..3: attach
 * its slaves), a USART (1..6: USARTn or UARTn, push received bytes), an
 * SPI (1..3: stm32_spi_attach its slave; the chip select is a GPIO pin the
 * board watches), a timer (STM32F4_TIMn: its outputs, encoder, inputs),
 * the clocks. */
stm32f4_gpio_t *stm32f4_soc_gpio(stm32f4_soc_t *soc, unsigned port);
stm32_i2c_t *stm32f4_soc_i2c(stm32f4_soc_t *soc, unsigned n);
stm32_usart_t *stm32f4_soc_usart(stm32f4_soc_t *soc, unsigned n);
stm32_spi_t *stm32f4_soc_spi(stm32f4_soc_t *soc, unsigned n);
stm32f1_tim_t *stm32f4_soc_tim(stm32f4_soc_t *soc, unsigned i);
const mmio_clocks_t *stm32f4_soc_clocks(const stm32f4_soc_t *soc);
/* Register accesses made while the peripheral's clock was off (all gates). */
unsigned long stm32f4_soc_gated_accesses(const stm32f4_soc_t *soc);

#endif

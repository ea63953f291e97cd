/* stm32f1_soc.h - an STM32F103 (medium density: x8, xB) as one chip: the
 * Cortex-M3 core (armcore) with every peripheral model of sim/arm placed at
 * its RM0008 address (section 3.3, table 3), behind its RCC clock enable
 * (RM0008 7.3.6-7.3.8), its interrupt lines into the NVIC by RM0008's
 * vector table (table 63: each model raises its own numbers) and its DMA
 * requests on DMA1's channels (table 78: each model names its channel).
 *
 *   AHB   DMA1 0x40020000 (AHBENR DMAEN), RCC 0x40021000, FLASH 0x40022000
 *   APB2  AFIO 0x40010000, EXTI 0x40010400, GPIOA-E 0x40010800-0x40011800,
 *         ADC1 0x40012400, ADC2 0x40012800, TIM1 0x40012C00, SPI1 0x40013000,
 *         USART1 0x40013800
 *   APB1  TIM2-4 0x40000000-0x40000800, SPI2 0x40003800, USART2 0x40004400,
 *         USART3 0x40004800, IWDG 0x40003000
 * Not on the bus (their accesses are listed as unmodeled): RTC, BKP, PWR,
 * WWDG, I2C1/2, USB, CAN, CRC, TIM5-8 and the other high-density parts.
 *
 * The flash memory is the core's array; the firmware's stores into it reach
 * the FLASH controller (PM0075: programmed only with CR.PG, a half-word into
 * an erased location). An IWDG timeout and SYSRESETREQ reset the chip.
 * The board (armboard.c) connects the outside: what the ADC samples, what
 * a USART sends, the SPI slaves, the pins. */
#ifndef STM32F1_SOC_H
#define STM32F1_SOC_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#include "arm/armcore.h"
#include "arm/armimage.h"
#include "arm/stm32f1_adc.h"
#include "arm/stm32f1_dma.h"
#include "arm/stm32f1_exti.h"
#include "arm/stm32f1_flash.h"
#include "arm/stm32f1_gpio.h"
#include "arm/stm32f1_iwdg.h"
#include "arm/stm32f1_rcc.h"
#include "arm/stm32f1_spi.h"
#include "arm/stm32f1_tim.h"
#include "arm/stm32f1_usart.h"

#define STM32F1_SOC_REGIONS 24

/* What the outside of the chip is, given at creation. */
typedef struct {
    const armimage_t *image;      /* checked against an stm32f103x8 / xb */
    uint32_t hse_hz;              /* the board's crystal, 0: none */
    double vdda_v;                /* VREF+ = VDDA: the ADCs' full scale */
    const char *flash_path;       /* the flash memory kept in this file (NULL: erased at power-on) */
    stm32_adc_volts_fn volts;     /* the analog pins (both ADCs) */
    void *volts_ctx;
    stm32_usart_sink_fn sink[3];  /* USART1-3's transmitted bytes (NULL: dropped) */
    void *sink_ctx[3];
    stm32_spi_slave_t spi_slave[2]; /* on SPI1, SPI2 (.exchange NULL: none) */
    stm32f1_pin_cb pin_cb;        /* each pin's level change (NULL: none) */
    void *pin_ctx;
    bool verbose, no_idle_skip;
} stm32f1_soc_cfg_t;

typedef struct stm32f1_soc {
    armcore_t *core;
    stm32f1_rcc_t rcc;
    stm32f1_flash_t flash;
    stm32f1_afio_t afio;
    stm32f1_exti_t exti;
    stm32f1_gpio_t gpio[STM32F1_GPIO_PORTS];
    stm32f1_tim_t tim[4];         /* TIM1-TIM4 */
    mmio_ops_t tim_ops[4];        /* the timers', their writes telling the others what triggers are taken */
    stm32_tim_links_t links;      /* TIM1-4 through stm32f1_tim_itr */
    stm32f1_iwdg_t iwdg;
    stm32_adc_t adc[2];
    mmio_ops_t adc_ops;           /* the ADC's, its CR2 telling the timers the (J)EXTSEL sources taken */
    mmio_ops_t rcc_ops;           /* RCC's, its accesses and events telling the core every model may have changed (clocks, resets) */
    stm32_dma_t dma;
    stm32_usart_t usart[3];
    stm32_spi_t spi[2];
    stm32f1_gate_t gate[STM32F1_SOC_REGIONS];
    int ngates;
    mmio_region_t region[STM32F1_SOC_REGIONS];
    int nregions;
    uint64_t irq_count[CORTEXM_IRQ_MAX]; /* rising edges of each interrupt line */
    bool irq_level[CORTEXM_IRQ_MAX];
    uint64_t resets;              /* system resets (IWDG, SYSRESETREQ) */
    char flash_path[512];
} stm32f1_soc_t;

/* The chip at power-on running the image. NULL with one line in err. */
stm32f1_soc_t *stm32f1_soc_new(const stm32f1_soc_cfg_t *cfg, char *err, size_t errn);
/* The flash memory saved to cfg->flash_path if it changed (whole or not at all). 0, or -1 with one line in err. */
int stm32f1_soc_save(stm32f1_soc_t *s, char *err, size_t errn);
void stm32f1_soc_free(stm32f1_soc_t *s);
/* The reset button (NRST): a system reset at the core's next block, RCC_CSR's PINRSTF set (RM0008 7.1.2). */
void stm32f1_soc_reset_pin(stm32f1_soc_t *s);
/* The name of NVIC line irq on the F101/F102/F103 (RM0008 table 63: "TIM1_UP"), NULL past 42. */
const char *stm32f1_irq_name(unsigned irq);
/* The core's PC now (where a stopped or waiting firmware is). */
uint32_t stm32f1_soc_pc(stm32f1_soc_t *s);
/* Port p (0 = A) pin n's model. */
static inline stm32f1_gpio_t *stm32f1_soc_port(stm32f1_soc_t *s, unsigned p) { return &s->gpio[p]; }

#endif

/* stm32f4_adc.h - the STM32F4's ADC1-3 and their common registers at
 * register level (RM0090 rev 19 section 13, RM0383 rev 3 section 11: ADC1
 * alone on the F411; timing and analog figures from the F405/407
 * datasheet DS8626 rev 9, 6.3.20 "12-bit ADC characteristics" and 6.3.21-22
 * temperature sensor and VREFINT). The board gives each ADC the voltage of
 * a channel at the instant its sampling ends, wires the shared IRQ (ADC,
 * IRQ 18) through the common block and each ADC's DMA request (ADC1:
 * STM32F4_DREQ_ADC1 on DMA2), and calls stm32f4_adc_ext_trigger when a
 * timer or EXTI line makes an edge on a trigger source. */
#ifndef ARM_STM32F4_ADC_H
#define ARM_STM32F4_ADC_H

#include <stdbool.h>
#include <stdint.h>

#include "arm/mmio.h"
#include "arm/stm32_adcseq.h"

#define STM32F4_ADC_BASE(n)    (0x40012000u + 0x100u * ((n) - 1u)) /* ADC1..3 */
#define STM32F4_ADC_SIZE       0x100u
#define STM32F4_ADC_COMMON_BASE 0x40012300u
#define STM32F4_ADC_IRQ        18u /* ADC1, ADC2 and ADC3 global interrupts (RM0090 table 61) */

/* The analog voltage on channel (0..15: the pins; 18: VBAT, divided by the
 * model) at core cycle `cycle`, volts. */
typedef double (*stm32f4_adc_volts_fn)(void *ctx, unsigned channel, uint64_t cycle);

/* Regular external trigger sources, the EXTSEL codes (RM0090 13.6 table 69). */
enum {
    STM32F4_ADC_EXT_TIM1_CC1 = 0, STM32F4_ADC_EXT_TIM1_CC2, STM32F4_ADC_EXT_TIM1_CC3, STM32F4_ADC_EXT_TIM2_CC2,
    STM32F4_ADC_EXT_TIM2_CC3, STM32F4_ADC_EXT_TIM2_CC4, STM32F4_ADC_EXT_TIM2_TRGO, STM32F4_ADC_EXT_TIM3_CC1,
    STM32F4_ADC_EXT_TIM3_TRGO, STM32F4_ADC_EXT_TIM4_CC4, STM32F4_ADC_EXT_TIM5_CC1, STM32F4_ADC_EXT_TIM5_CC2,
    STM32F4_ADC_EXT_TIM5_CC3, STM32F4_ADC_EXT_TIM8_CC1, STM32F4_ADC_EXT_TIM8_TRGO, STM32F4_ADC_EXT_EXTI11,
};
/* Injected external trigger sources, the JEXTSEL codes (table 70). */
enum {
    STM32F4_ADC_JEXT_TIM1_CC4 = 0, STM32F4_ADC_JEXT_TIM1_TRGO, STM32F4_ADC_JEXT_TIM2_CC1, STM32F4_ADC_JEXT_TIM2_TRGO,
    STM32F4_ADC_JEXT_TIM3_CC2, STM32F4_ADC_JEXT_TIM3_CC4, STM32F4_ADC_JEXT_TIM4_CC1, STM32F4_ADC_JEXT_TIM4_CC2,
    STM32F4_ADC_JEXT_TIM4_CC3, STM32F4_ADC_JEXT_TIM4_TRGO, STM32F4_ADC_JEXT_TIM5_CC4, STM32F4_ADC_JEXT_TIM5_TRGO,
    STM32F4_ADC_JEXT_TIM8_CC2, STM32F4_ADC_JEXT_TIM8_CC3, STM32F4_ADC_JEXT_TIM8_CC4, STM32F4_ADC_JEXT_EXTI15,
};

typedef struct stm32f4_adc_common stm32f4_adc_common_t;

typedef struct {
    stm32_adcseq_t seq;          /* the registers and the conversion engine (first: the ops take the model) */
    /* wiring, kept across reset */
    stm32f4_adc_common_t *common;
    stm32f4_adc_volts_fn volts;
    void *volts_ctx;
    unsigned index;              /* 1..3: channels 16-18 are ADC1's */
    double temp_c;               /* the die temperature, degC */
} stm32f4_adc_t;

struct stm32f4_adc_common {
    const mmio_clocks_t *clk;
    mmio_irq_t irq;
    uint32_t ccr;
    stm32f4_adc_t *adc[3];       /* ADC1..3 as placed (NULL: absent) */
    bool irq_level;
};

extern const mmio_ops_t stm32f4_adc_ops;
extern const mmio_ops_t stm32f4_adc_common_ops;

void stm32f4_adc_common_init(stm32f4_adc_common_t *c, const mmio_clocks_t *clk, mmio_irq_t irq);
/* index 1..3; dma_request: its stm32f4_dreq_t (dma.request NULL: none). */
void stm32f4_adc_init(stm32f4_adc_t *a, stm32f4_adc_common_t *common, unsigned index, mmio_dma_req_t dma,
                      unsigned dma_request, stm32f4_adc_volts_fn volts, void *volts_ctx, double vref_v);
/* An edge on a trigger source at core cycle now: starts the group if its
 * (J)EXTEN accepts this edge (rising or falling) and (J)EXTSEL selects it. */
void stm32f4_adc_ext_trigger(stm32f4_adc_t *a, bool injected, unsigned source, bool rising, uint64_t now);
/* The ADC clock (PCLK2 / ADCPRE), Hz. */
uint32_t stm32f4_adc_clock(const stm32f4_adc_common_t *c);

#endif

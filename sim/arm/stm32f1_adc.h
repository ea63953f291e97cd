/* stm32f1_adc.h - the STM32F1's ADC1/ADC2 at register level (RM0008 rev 21,
 * section 11; timing figures from the STM32F103x8/B datasheet, DS5319).
 * The board gives each ADC the voltage of a channel at the instant the
 * sample-and-hold opens (the end of the channel's sampling time), wires its
 * IRQ (ADC1_2, IRQ 18, shared: stm32_adc_share_irq) and, for ADC1, its DMA
 * request (DMA1 channel 1), and calls stm32_adc_ext_trigger when a timer or
 * EXTI line makes a trigger event. */
#ifndef ARM_STM32F1_ADC_H
#define ARM_STM32F1_ADC_H

#include <stdbool.h>
#include <stdint.h>

#include "arm/mmio.h"
#include "arm/stm32_adcseq.h"

#define STM32_ADC1_BASE 0x40012400u
#define STM32_ADC2_BASE 0x40012800u
#define STM32_ADC_SIZE  0x400u
#define STM32_ADC_IRQ   18u /* ADC1_2 (RM0008 Table 63, vector 0x88) */
#define STM32_ADC1_DMA_CH 1u /* DMA1 channel 1 (RM0008 Table 78) */

/* The analog voltage on channel (0..15: the pins ADCx_IN0..15) at core cycle
 * `cycle`, volts. Channels 16 and 17 (temperature sensor, VREFINT) are the
 * model's own. */
typedef double (*stm32_adc_volts_fn)(void *ctx, unsigned channel, uint64_t cycle);

/* External trigger sources by group, numbered as the EXTSEL/JEXTSEL codes of
 * RM0008 Tables 69 and 70 (ADC1 and ADC2); code 7 is the software start. */
enum {
    STM32_ADC_EXT_TIM1_CC1 = 0, STM32_ADC_EXT_TIM1_CC2, STM32_ADC_EXT_TIM1_CC3, STM32_ADC_EXT_TIM2_CC2,
    STM32_ADC_EXT_TIM3_TRGO, STM32_ADC_EXT_TIM4_CC4, STM32_ADC_EXT_EXTI11,
};
enum {
    STM32_ADC_JEXT_TIM1_TRGO = 0, STM32_ADC_JEXT_TIM1_CC4, STM32_ADC_JEXT_TIM2_TRGO, STM32_ADC_JEXT_TIM2_CC1,
    STM32_ADC_JEXT_TIM3_CC4, STM32_ADC_JEXT_TIM4_TRGO, STM32_ADC_JEXT_EXTI15,
};

typedef struct stm32_adc stm32_adc_t;
struct stm32_adc {
    stm32_adcseq_t seq;          /* the registers and the conversion engine (first: the ops take the model) */
    /* wiring, kept across reset */
    const mmio_clocks_t *clk;
    mmio_irq_t irq;
    stm32_adc_volts_fn volts;
    void *volts_ctx;
    unsigned index;              /* 1 or 2: channels 16/17 exist on ADC1 only */
    double temp_c;               /* the die temperature the sensor sees, degC */
    stm32_adc_t *partner;        /* the other ADC on the shared IRQ line, or NULL */
};

extern const mmio_ops_t stm32_adc_ops;

/* index 1 or 2; vref_v: VREF+ (3.3 V on a 3.3 V board); dma.request NULL for none. */
void stm32_adc_init(stm32_adc_t *a, unsigned index, const mmio_clocks_t *clk, mmio_irq_t irq,
                    mmio_dma_req_t dma, stm32_adc_volts_fn volts, void *volts_ctx, double vref_v);
/* ADC1 and ADC2 drive one NVIC line (ADC1_2): the line is the OR of both. */
void stm32_adc_share_irq(stm32_adc_t *a, stm32_adc_t *b);
/* A trigger event at core cycle now (>= the last advance): starts the group
 * if its (J)EXTTRIG is set and its (J)EXTSEL selects this source. */
void stm32_adc_ext_trigger(stm32_adc_t *a, bool injected, unsigned source, uint64_t now);

#endif

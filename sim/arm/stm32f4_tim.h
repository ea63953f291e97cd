/* stm32f4_tim.h - the STM32F4's timers (RM0090 rev 19 sections 17-20;
 * RM0383 for the F411, which has TIM1-5 and TIM9-11 only): the model of
 * stm32f1_tim.h under per-instance descriptions. TIM1/TIM8 advanced
 * (section 17), TIM2-TIM5 general-purpose with a 32-bit TIM2 and TIM5
 * (18), TIM9/TIM12 two channels and TIM10/11/13/14 one, upcounting only
 * (19), TIM6/TIM7 basic (20). Where each sits (RM0090 2.3 table 1), which
 * RCC bit clocks it (6.3.13 APB1ENR, 6.3.14 APB2ENR) and its interrupt
 * lines (table 61) are data here; the board places
 * {base, STM32F4_TIM_SIZE, &stm32f4_tim_ops[i], &tim} behind the gate.
 *
 * DMA requests: a timer raises its update and CC1-CC4 requests on its
 * mmio_dma_req_t as the stm32f4_dreq_t of RM0090 tables 42 and 43
 * (STM32F4_DREQ_TIM1_UP, STM32F4_DREQ_TIM1_CH1, ...: the numbers
 * stm32f4_dma_request serves); the requests that exist on the F4 are in the
 * descriptions (TIM4 has no CH4 request), TIM9-14 have none. Triggers: the ADC's regular (EXTSEL, table 69) and injected
 * (JEXTSEL, table 70) sources are data too (stm32f4_tim_extsel). */
#ifndef ARM_STM32F4_TIM_H
#define ARM_STM32F4_TIM_H

#include <stdint.h>

#include "arm/stm32f1_tim.h"
#include "arm/stm32f4_dma.h"

#define STM32F4_TIM_SIZE 0x400u

/* The instances, index into stm32f4_tim[] and stm32f4_tim_ops[]. */
enum {
    STM32F4_TIM1, STM32F4_TIM2, STM32F4_TIM3, STM32F4_TIM4, STM32F4_TIM5, STM32F4_TIM6, STM32F4_TIM7,
    STM32F4_TIM8, STM32F4_TIM9, STM32F4_TIM10, STM32F4_TIM11, STM32F4_TIM12, STM32F4_TIM13, STM32F4_TIM14,
    STM32F4_TIM_COUNT
};

typedef struct {
    stm32_tim_desc_t d;
    uint32_t base;     /* bus address */
    uint32_t enable;   /* its TIMxEN bit in RCC APB1ENR (d.apb 1) or APB2ENR (d.apb 2) */
    uint8_t on_f411;   /* RM0383: present on the STM32F411 */
} stm32f4_tim_inst_t;

extern const stm32f4_tim_inst_t stm32f4_tim[STM32F4_TIM_COUNT];
extern const mmio_ops_t stm32f4_tim_ops[STM32F4_TIM_COUNT];

/* EXTSEL (injected 0) or JEXTSEL (injected 1) code 0-15 -> the trigger
 * source (STM32_TIM_TRIG) it selects; code 15 is an EXTI line (11 or 15):
 * STM32F4_TIM_EXTI. */
#define STM32F4_TIM_EXTI 0xFFFFu
extern const uint16_t stm32f4_tim_extsel[2][16];

/* The internal trigger connections (RM0090 rev 19 17.4.3 TIM1/TIM8, 18.4.3
 * TIM2-5, 19.4.2 TIM9/TIM12 SMCR: the tables "TIMx internal trigger
 * connection"): stm32f4_tim_itr[i][x] is the timer n whose TRGO reaches
 * instance i's ITRx, 0: none (no SMCR, or TIM9/12's ITR2/3, which are
 * TIM10/11/13/14's OC1 and not routed). */
extern const uint8_t stm32f4_tim_itr[STM32F4_TIM_COUNT][4];

/* Power-on for instance i (STM32F4_TIMn). */
void stm32f4_tim_init(stm32f1_tim_t *t, unsigned i, const mmio_clocks_t *clk, mmio_irq_t irq, mmio_dma_req_t dma,
                      stm32_tim_trigger_t trig);
/* The sources of timer n an ADC with EXTSEL code ext and JEXTSEL code jext
 * takes (the want mask for stm32_tim_trigger_want). */
uint32_t stm32f4_tim_adc_wants(unsigned n, unsigned ext, unsigned jext);
/* The code (0-15) a source has in EXTSEL (injected 0) or JEXTSEL (1), -1: none. */
int stm32f4_tim_extsel_code(unsigned source, int injected);

#endif

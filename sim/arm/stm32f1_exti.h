/* stm32f1_exti.h - the STM32F1's alternate-function I/O (AFIO: EVCR, MAPR,
 * EXTICR1-4; RM0008 9.3-9.4) and external interrupt controller (EXTI: IMR,
 * EMR, RTSR, FTSR, SWIER, PR; RM0008 10.2-10.3) with its lines into the
 * NVIC (RM0008 table 63: EXTI0-4 -> IRQ 6-10, EXTI9_5 -> 23, EXTI15_10 ->
 * 40; lines 16-18 PVD -> 1, RTC alarm -> 41, USB wakeup -> 42).
 *
 * The GPIO ports tell EXTI each pin's level (stm32f1_exti_pin); EXTICR
 * picks the port each line 0-15 follows; an enabled edge on an unmasked
 * line sets its pending bit (RM0008 figure 21: IMR gates the pending
 * register) and raises the line's NVIC interrupt until PR is cleared by
 * writing 1. EMR (events to the core's WFE) is stored and read back: the
 * event itself is the core's to model. AFIO's remaps (MAPR) are read by
 * the board to know which pins a timer or USART uses. */
#ifndef STM32F1_EXTI_H
#define STM32F1_EXTI_H

#include <stdint.h>

#include "arm/mmio.h"

#define STM32F1_EXTI_LINES 19      /* F101/F102/F103: lines 0-18 (RM0008 10.2.5) */
#define STM32F1_EXTI_PORTS 7       /* EXTICR selects port A-G */

typedef struct {
    uint32_t evcr, mapr, exticr[4];
} stm32f1_afio_t;

typedef struct {
    uint32_t imr, emr, rtsr, ftsr, swier, pr;
    uint16_t pins[STM32F1_EXTI_PORTS]; /* each port's pin levels as the ports last told them */
    uint32_t lines;                    /* each line's input level now */
    uint32_t irq_out;                  /* the NVIC lines held high, by group */
    const stm32f1_afio_t *afio;
    mmio_irq_t irq;
} stm32f1_exti_t;

extern const mmio_ops_t stm32f1_afio_ops;
extern const mmio_ops_t stm32f1_exti_ops;

void stm32f1_afio_init(stm32f1_afio_t *a);
/* A timer's remap from MAPR (RM0008 9.4.2): TIM1 and TIM2 0-3, TIM3 0, 2
 * or 3, TIM4 0-1; -1 for another timer. */
int stm32f1_afio_tim_remap(const stm32f1_afio_t *a, unsigned tim);

void stm32f1_exti_init(stm32f1_exti_t *e, const stm32f1_afio_t *afio, mmio_irq_t irq);
/* Port port's (0 = A) pin now at level (0/1): an edge on the line that
 * follows it, if EXTICR selects this port. */
void stm32f1_exti_pin(stm32f1_exti_t *e, unsigned port, unsigned pin, int level);
/* A line 16-18 (PVD, RTC alarm, USB wakeup) at level, from its peripheral. */
void stm32f1_exti_line(stm32f1_exti_t *e, unsigned line, int level);

#endif

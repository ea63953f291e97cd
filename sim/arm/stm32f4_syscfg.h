/* stm32f4_syscfg.h - the STM32F4's system configuration controller (SYSCFG:
 * MEMRMP, PMC, EXTICR1-4, CMPCR; RM0090 rev 19 section 9, RM0383 rev 3
 * section 7) and its external interrupt controller (EXTI: IMR, EMR, RTSR,
 * FTSR, SWIER, PR; RM0090 section 12.3, the same registers as the F1's with
 * 23 lines) with the lines' NVIC interrupts (RM0090 table 61: EXTI0-4 ->
 * IRQ 6-10, EXTI9_5 -> 23, EXTI15_10 -> 40; line 16 PVD -> 1, 17 RTC alarm
 * -> 41, 18 OTG FS wakeup -> 42, 19 Ethernet wakeup -> 62, 20 OTG HS wakeup
 * -> 76, 21 tamper/time stamp -> 2, 22 RTC wakeup -> 3).
 *
 * The GPIO ports tell EXTI each pin's level (stm32f4_exti_pin, the
 * stm32f4_gpio_pin_fn the board wires); SYSCFG's EXTICR picks the port each
 * line 0-15 follows. */
#ifndef ARM_STM32F4_SYSCFG_H
#define ARM_STM32F4_SYSCFG_H

#include <stdint.h>

#include "arm/mmio.h"

#define STM32F4_SYSCFG_BASE 0x40013800u
#define STM32F4_EXTI_BASE   0x40013C00u
#define STM32F4_SYSCFG_SIZE 0x400u
#define STM32F4_EXTI_LINES  23
#define STM32F4_EXTI_PORTS  9 /* EXTICR codes 0000 (A) .. 1000 (I) */

typedef struct {
    uint32_t memrmp, pmc, exticr[4], cmpcr;
    uint32_t boot_mode; /* MEM_MODE after reset: the BOOT pins' choice (0: main flash at 0) */
} stm32f4_syscfg_t;

typedef struct {
    uint32_t imr, emr, rtsr, ftsr, swier, pr;
    uint16_t pins[STM32F4_EXTI_PORTS]; /* each port's pin levels as the ports last told them */
    uint32_t lines;                    /* each line's input level now */
    uint32_t irq_out;                  /* the NVIC lines held high, one bit per output group */
    const stm32f4_syscfg_t *syscfg;
    mmio_irq_t irq;
} stm32f4_exti_t;

extern const mmio_ops_t stm32f4_syscfg_ops;
extern const mmio_ops_t stm32f4_exti_ops;

void stm32f4_syscfg_init(stm32f4_syscfg_t *s, uint32_t boot_mode);
/* What is mapped at 0x00000000 (MEM_MODE, RM0090 9.2.1): 0 main flash,
 * 1 system flash, 2 FSMC bank 1, 3 embedded SRAM. The core's to apply. */
unsigned stm32f4_syscfg_mem_mode(const stm32f4_syscfg_t *s);

void stm32f4_exti_init(stm32f4_exti_t *e, const stm32f4_syscfg_t *syscfg, mmio_irq_t irq);
/* Port port's (0 = A) pin now at level: an edge on line pin if EXTICR
 * selects this port. The signature of stm32f4_gpio_pin_fn (ctx: the EXTI). */
void stm32f4_exti_pin(void *exti, unsigned port, unsigned pin, int level);
/* A line 16-22 at level, from its peripheral (PVD, RTC, OTG, Ethernet). */
void stm32f4_exti_line(stm32f4_exti_t *e, unsigned line, int level);

#endif

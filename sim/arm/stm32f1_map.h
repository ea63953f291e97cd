/* stm32f1_map.h - where the STM32F1 peripheral models of stm32f1_rcc,
 * _flash, _gpio, _exti, _tim and _iwdg sit on the bus and which RCC bit
 * clocks each: RM0008 section 3.3 (memory map, table 3: boundary
 * addresses, 1 KiB per peripheral here) and 7.3.6-7.3.8 (AHBENR, APB2ENR,
 * APB1ENR). The board places each one as {base, STM32F1_PERIPH_SIZE, ...},
 * behind an RCC gate (stm32f1_gate_init) with the bus and bit given here;
 * EXTI and IWDG have no enable bit, and the FLASH interface's FLITFEN only
 * matters in Sleep mode (RM0008 7.3.6): they are placed ungated. */
#ifndef STM32F1_MAP_H
#define STM32F1_MAP_H

#define STM32F1_PERIPH_SIZE 0x400u

#define STM32F1_TIM2_BASE 0x40000000u  /* APB1ENR bit 0 (TIM2EN), IRQ 28 */
#define STM32F1_TIM3_BASE 0x40000400u  /* APB1ENR bit 1 (TIM3EN), IRQ 29 */
#define STM32F1_TIM4_BASE 0x40000800u  /* APB1ENR bit 2 (TIM4EN), IRQ 30 */
#define STM32F1_IWDG_BASE 0x40003000u  /* no enable bit: LSI */
#define STM32F1_AFIO_BASE 0x40010000u  /* APB2ENR bit 0 (AFIOEN) */
#define STM32F1_EXTI_BASE 0x40010400u  /* no enable bit; IRQs 6-10, 23, 40 */
#define STM32F1_GPIOA_BASE 0x40010800u /* port p at GPIOA + 0x400 p; APB2ENR bit 2 + p (IOPxEN) */
#define STM32F1_TIM1_BASE 0x40012C00u  /* APB2ENR bit 11 (TIM1EN), IRQs 24-27 */
#define STM32F1_RCC_BASE 0x40021000u   /* IRQ 5 */
#define STM32F1_FLASHIF_BASE 0x40022000u /* IRQ 4; the flash memory itself at 0x08000000 */

#define STM32F1_EN_TIM2 (1u << 0)       /* APB1 */
#define STM32F1_EN_TIM3 (1u << 1)       /* APB1 */
#define STM32F1_EN_TIM4 (1u << 2)       /* APB1 */
#define STM32F1_EN_AFIO (1u << 0)       /* APB2 */
#define STM32F1_EN_GPIO(p) (1u << (2 + (p))) /* APB2, p = 0 for port A */
#define STM32F1_EN_TIM1 (1u << 11)      /* APB2 */

#endif

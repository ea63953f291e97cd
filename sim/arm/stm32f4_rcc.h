/* stm32f4_rcc.h - the STM32F4's reset and clock control (RCC) at register
 * level: RM0090 rev 19 section 6 (F405/407: 6.2 clocks, 6.3 registers) and
 * RM0383 rev 3 section 6 (F411, the same layout without the F405's
 * Ethernet/USB HS/FSMC enables). The oscillators (HSI 16 MHz, HSE the
 * board's crystal, LSI 32 kHz, LSE 32.768 kHz), the main PLL (M, N, P, Q from
 * HSI or HSE) and PLLI2S with their ready bits, the system clock switch
 * (SW/SWS), the AHB/APB prescalers (HPRE, PPRE1, PPRE2), the timer clocks
 * (x2 when an APB prescaler is not 1, RM0090 6.2 "timer clock
 * frequencies"), the peripherals' enable, reset and low-power enable bits.
 * It owns the run's mmio_clocks_t.
 *
 * Ready bits rise after the oscillator's start-up time (the F405/407
 * datasheet DS8626 rev 9, section 6.3 "Operating conditions": HSE tsu 2 ms
 * typ, HSI tsu 2.2 us typ, LSI tsu 15 us typ, LSE tsu 2 s typ, main PLL tLOCK
 * 100 us, the minimum at a 432 MHz VCO, table "Main PLL characteristics"),
 * counted in core cycles at the HCLK of the moment the oscillator is
 * switched on. A system clock switch to a source not yet ready happens when
 * it becomes ready (RM0090 6.2.6). */
#ifndef ARM_STM32F4_RCC_H
#define ARM_STM32F4_RCC_H

#include <stdbool.h>
#include <stdint.h>

#include "arm/mmio.h"

#define STM32F4_RCC_BASE 0x40023800u
#define STM32F4_RCC_SIZE 0x400u
#define STM32F4_HSI_HZ   16000000u /* RM0090 6.2.2: HSI RC 16 MHz */
#define STM32F4_LSI_HZ   32000u    /* RM0090 6.2.5: LSI RC ~32 kHz */
#define STM32F4_LSE_HZ   32768u    /* RM0090 6.2.4: LSE crystal */

/* The part: register widths and reset values that differ. */
typedef enum { STM32F4_F405, STM32F4_F411 } stm32f4_part_t;

enum { STM32F4_RCC_WORDS = 0x8C / 4 + 1 }; /* CR .. DCKCFGR (F411) */

/* The oscillators with a ready bit. */
enum { STM32F4_OSC_HSI, STM32F4_OSC_HSE, STM32F4_OSC_PLL, STM32F4_OSC_PLLI2S, STM32F4_OSC_LSI,
       STM32F4_OSC_LSE, STM32F4_OSCS };

typedef struct {
    stm32f4_part_t part;
    uint32_t hse_hz;                 /* the board's crystal, Hz (0: none: HSERDY never rises) */
    uint32_t reg[STM32F4_RCC_WORDS]; /* the registers by word offset */
    uint64_t now;                    /* the cycle advance() last reached */
    uint64_t ready_at[STM32F4_OSCS]; /* when each starting oscillator becomes ready, MMIO_NEVER: none */
    uint32_t pll_hz, pll48_hz;       /* the main PLL's P and Q outputs as configured */
    bool pll_bad;                    /* PLLCFGR outside the manual's ranges (reported at PLLON) */
    mmio_clocks_t clocks;
} stm32f4_rcc_t;

extern const mmio_ops_t stm32f4_rcc_ops;

/* Power-on: registers at their reset values, HSI on and ready, every clock 16 MHz. */
void stm32f4_rcc_init(stm32f4_rcc_t *r, stm32f4_part_t part, uint32_t hse_hz);
/* The clocks as the registers now set them (a stable pointer). adcclk is
 * PCLK2 / 2, the F4 ADC's reset prescaler; the F4 ADC model applies its
 * common CCR ADCPRE to pclk2 itself. */
const mmio_clocks_t *stm32f4_rcc_clocks(const stm32f4_rcc_t *r);
/* Whether the main PLL is locked (PWR's VOSRDY follows it, RM0383 5.4.1). */
bool stm32f4_rcc_pll_ready(const stm32f4_rcc_t *r);

#endif

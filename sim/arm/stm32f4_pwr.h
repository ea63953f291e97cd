/* stm32f4_pwr.h - the STM32F4's power controller registers (PWR_CR,
 * PWR_CSR): RM0090 rev 19 section 5.4 (F405/407: VOS one bit, reset 1 =
 * scale 1) and RM0383 rev 3 section 5.4 (F411: VOS[15:14], reset 10 =
 * scale 2). VOSRDY rises when the main PLL is locked: the selected scale
 * takes effect only with the PLL on (RM0383 5.1.3 and 5.4.1 "VOS"), so a
 * firmware that waits on VOSRDY after PLLRDY continues. */
#ifndef ARM_STM32F4_PWR_H
#define ARM_STM32F4_PWR_H

#include <stdint.h>

#include "arm/mmio.h"
#include "arm/stm32f4_rcc.h"

#define STM32F4_PWR_BASE 0x40007000u
#define STM32F4_PWR_SIZE 0x400u

typedef struct {
    const stm32f4_rcc_t *rcc; /* the PLL's lock, for VOSRDY */
    stm32f4_part_t part;
    uint32_t cr, csr;
} stm32f4_pwr_t;

extern const mmio_ops_t stm32f4_pwr_ops;

void stm32f4_pwr_init(stm32f4_pwr_t *p, const stm32f4_rcc_t *rcc);
/* The voltage scale the firmware selected: 1 (highest clock), 2 or 3. */
unsigned stm32f4_pwr_scale(const stm32f4_pwr_t *p);

#endif

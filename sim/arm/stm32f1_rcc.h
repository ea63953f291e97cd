/* stm32f1_rcc.h - the STM32F1's reset and clock control (RCC), RM0008
 * section 7 (7.2 clocks, 7.3 registers; connectivity-line registers
 * AHBRSTR and CFGR2 are not on the F101/F102/F103 and answer unmodeled):
 * the oscillators (HSI 8 MHz, HSE the board's crystal, LSI 40 kHz, LSE
 * 32.768 kHz) and the PLL with their ready bits, the system clock switch,
 * the AHB/APB/ADC prescalers, the peripherals' clock enables and resets.
 * It owns the run's mmio_clocks_t: every clock a peripheral counts with is
 * derived here from the registers (RM0008 figure 8, the clock tree).
 *
 * Ready bits come after the oscillator's start-up time from the STM32F103
 * datasheet (DS5319 section 5.3), counted in core cycles
 * at the HCLK of the moment it was switched on: firmware that waits for
 * them (every F1 startup code does) spends the time the chip spends.
 *
 * A peripheral's registers are reached through a clock gate
 * (stm32f1_gate_t) that knows its enable bit: with the clock off the real
 * chip reads 0 and drops writes; the gate does the same and counts each
 * such access, so a firmware that forgot rcc_periph_clock_enable is seen. */
#ifndef STM32F1_RCC_H
#define STM32F1_RCC_H

#include <stdint.h>

#include "arm/mmio.h"

#define STM32F1_RCC_IRQ 5       /* RM0008 table 63: RCC global interrupt */
#define STM32F1_HSI_HZ 8000000u /* RM0008 7.2.2: HSI RC 8 MHz */
#define STM32F1_LSI_HZ 40000u   /* RM0008 7.2.5: LSI RC ~40 kHz (30-60 kHz over temperature and voltage) */
#define STM32F1_LSE_HZ 32768u   /* RM0008 7.2.4: LSE crystal 32.768 kHz */
#define STM32F1_RCC_GATES 48    /* peripherals a board may gate */

/* The bus a peripheral's enable and reset bits are on (RM0008 7.3.4-7.3.10). */
typedef enum { STM32F1_AHB, STM32F1_APB1, STM32F1_APB2 } stm32f1_bus_t;

/* RCC_CSR's reset flags a reset sets (RM0008 7.3.10). */
typedef enum {
    STM32F1_RST_PIN = 26, STM32F1_RST_POR = 27, STM32F1_RST_SOFT = 28,
    STM32F1_RST_IWDG = 29, STM32F1_RST_WWDG = 30, STM32F1_RST_LPWR = 31,
} stm32f1_reset_cause_t;

struct stm32f1_gate;

typedef struct stm32f1_rcc {
    uint32_t cr, cfgr, cir, apb2rstr, apb1rstr, ahbenr, apb2enr, apb1enr, bdcr, csr;
    uint32_t hse_hz;            /* the board's crystal (0: none; HSERDY never rises) */
    uint64_t now;               /* core cycle the state is at */
    /* core cycle each oscillator becomes ready (MMIO_NEVER: off or ready) */
    uint64_t hsi_at, hse_at, pll_at, lsi_at, lse_at;
    int pll_waits;              /* PLLON without a running input: locks once the input runs */
    mmio_clocks_t clocks;
    mmio_irq_t irq;
    struct stm32f1_gate *gates[STM32F1_RCC_GATES];
    unsigned ngates;
    uint64_t gated;             /* accesses to any gated peripheral with its clock off */
} stm32f1_rcc_t;

/* A peripheral behind its clock enable bit, as the bus sees it: place
 * {base, size, &gate->bus_ops, gate} on the bus instead of the peripheral
 * itself (bus_ops: the gate's table under the peripheral's name). */
typedef struct stm32f1_gate {
    stm32f1_rcc_t *rcc;
    stm32f1_bus_t bus;
    uint32_t bit;               /* its bit in RCC_xxxENR and RCC_xxxRSTR */
    const mmio_ops_t *ops;      /* the peripheral */
    void *self;
    uint64_t off_reads, off_writes; /* accesses while its clock was off */
    mmio_ops_t bus_ops;
} stm32f1_gate_t;

extern const mmio_ops_t stm32f1_rcc_ops;
extern const mmio_ops_t stm32f1_gate_ops;

/* Power-on: registers at their reset values (RM0008 7.3), CSR's PORRSTF
 * and PINRSTF set, HSI on and ready, the clocks 8 MHz everywhere.
 * hse_hz: the board's crystal, 0 for none. irq: the RCC interrupt line. */
void stm32f1_rcc_init(stm32f1_rcc_t *r, uint32_t hse_hz, mmio_irq_t irq);
/* The clocks as the registers now set them (a stable pointer). */
const mmio_clocks_t *stm32f1_rcc_clocks(const stm32f1_rcc_t *r);
/* A system reset's cause recorded in CSR (after ops.reset, which keeps
 * CSR's flags and the backup domain as RM0008 7.1.2 says). */
void stm32f1_rcc_reset_cause(stm32f1_rcc_t *r, stm32f1_reset_cause_t cause);
/* Is the peripheral's clock on? */
int stm32f1_rcc_enabled(const stm32f1_rcc_t *r, stm32f1_bus_t bus, uint32_t bit);
/* The LSI oscillator forced on (the IWDG does it when started, RM0008 19.3.2). */
void stm32f1_rcc_lsi_force(stm32f1_rcc_t *r);

/* Put a peripheral behind its enable bit; RCC_xxxRSTR's bit then resets
 * it. 0, or -1 if RCC already holds STM32F1_RCC_GATES gates. */
int stm32f1_gate_init(stm32f1_gate_t *g, stm32f1_rcc_t *r, stm32f1_bus_t bus, uint32_t bit,
                      const mmio_ops_t *ops, void *self);

#endif

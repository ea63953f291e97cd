/* cortexm.h - the Cortex-M3/M4 system peripherals at register level, as the
 * core (armcore.c) and the firmware see them through the Private Peripheral
 * Bus (0xE0000000-0xE00FFFFF): the NVIC (ISER/ICER/ISPR/ICPR/IABR/IPR,
 * STIR, ICTR), the SCB (CPUID, ICSR, VTOR, AIRCR, SCR, CCR, SHPR1-3, SHCSR,
 * CFSR, HFSR, MMFAR, BFAR), SysTick (CSR, RVR, CVR, CALIB) and the DWT's
 * cycle counter (DWT_CTRL, CYCCNT, with DEMCR.TRCENA). Sources: ARMv7-M
 * Architecture Reference Manual (DDI 0403E) B1.5 (exceptions), B3.2 (SCB),
 * B3.3 (SysTick), B3.4 (NVIC), C1.8 (DWT), B3.2.20 (the FPU's CPACR, FPCCR, FPCAR, FPDSCR); PM0056 Rev 7 (STM32F1) chapter 4.
 *
 * It is the state of exceptions only: which are pending, active, enabled,
 * their priorities. Taking and returning from one (the stack frame, the
 * registers) is the core's, which asks cortexm_best() what to take and
 * tells cortexm_take() and cortexm_return(). Time is core cycles: the
 * core calls the region's advance() before every access and at
 * next_event() (SysTick's wrap). */
#ifndef CORTEXM_H
#define CORTEXM_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#include "mmio.h"

#define CORTEXM_PPB_BASE 0xE0000000u
#define CORTEXM_PPB_BYTES 0x00100000u
#define CORTEXM_IRQ_MAX 240u                 /* ARMv7-M B3.4: at most 496 in v7-M, 240 on the M3/M4 */
#define CORTEXM_EXC_MAX (16u + CORTEXM_IRQ_MAX)
#define CORTEXM_SYSTICK_CALIB 0x00002328u    /* PM0056 4.5.4: TENMS 9000 (1 ms at HCLK/8 = 9 MHz), NOREF 0, SKEW 0 */
#define CORTEXM_SYSTICK_EXT_DIV 8u           /* RM0008 7.2 figure 8: the SysTick external clock is HCLK / 8 */

/* Exception numbers (ARMv7-M B1.5.2) */
enum { EXC_RESET = 1, EXC_NMI = 2, EXC_HARDFAULT = 3, EXC_MEMMANAGE = 4, EXC_BUSFAULT = 5, EXC_USAGEFAULT = 6,
       EXC_SVCALL = 11, EXC_DEBUGMON = 12, EXC_PENDSV = 14, EXC_SYSTICK = 15, EXC_IRQ0 = 16 };

typedef struct {
    unsigned nirq;               /* external interrupt lines */
    uint8_t prio_mask;           /* the implemented bits of a priority byte (4 bits: 0xF0) */
    uint32_t cpuid;
    uint8_t prio[CORTEXM_EXC_MAX];    /* programmable priorities by exception number (SHPR, IPR) */
    bool enabled[CORTEXM_EXC_MAX];    /* NVIC ISER for IRQs; SHCSR enables for the configurable faults */
    bool pending[CORTEXM_EXC_MAX];
    bool active[CORTEXM_EXC_MAX];
    bool line[CORTEXM_EXC_MAX];       /* an IRQ's level from its peripheral */
    unsigned npending;                /* pending exceptions */
    uint32_t vtor, prigroup, scr, ccr, shcsr, cfsr, hfsr, mmfar, bfar, demcr, actlr;
    /* SysTick: the counter value at cycle st_at; its tick is HCLK or HCLK/8 (CLKSOURCE) */
    uint32_t st_csr, st_rvr, st_cvr;
    uint64_t st_at;
    /* DWT: CYCCNT was cyc_base at cycle cyc_at while counting */
    uint32_t dwt_ctrl, cyc_base;
    uint64_t cyc_at;
    /* the FPU's (a Cortex-M4F): CPACR, FPCCR, FPCAR (the core sets it at an extended frame's stacking), FPDSCR */
    bool fpu;
    uint32_t cpacr, fpccr, fpcar, fpdscr;
    uint64_t now;          /* the cycle it was advanced to */
    bool attention;        /* something pended, unmasked or rescheduled: the core checks before its next block */
    bool reset_request;    /* AIRCR.SYSRESETREQ written with its key */
} cortexm_t;

void cortexm_init(cortexm_t *cm, unsigned nirq, unsigned prio_bits, uint32_t cpuid);
/* The core has an FPU (FPv4-SP): CPACR, FPCCR, FPCAR, FPDSCR, MVFR0/1 modeled (B3.2.20, Cortex-M4 TRM 7.2). */
void cortexm_set_fpu(cortexm_t *cm, bool fpu);
/* The PPB as a bus region. */
extern const mmio_ops_t cortexm_ops;
/* An external interrupt line (mmio_irq_t.set's shape: ctx is the cortexm_t). */
void cortexm_set_irq(void *ctx, unsigned irq, bool level);
/* Pend exception exc (a fault, SVCall, PendSV...). */
void cortexm_pend(cortexm_t *cm, unsigned exc);
/* An exception's priority as the rules compare it: -3/-2/-1 for Reset, NMI
 * and HardFault, else its byte; its group priority (AIRCR.PRIGROUP). */
int cortexm_prio(const cortexm_t *cm, unsigned exc);
int cortexm_group(const cortexm_t *cm, int prio);
/* The execution priority (B1.5.4) from the active exceptions and the masks. */
int cortexm_exec_prio(const cortexm_t *cm, uint32_t primask, uint32_t basepri, uint32_t faultmask);
/* The pending, enabled exception that would be taken (the lowest group
 * priority, then priority, then number), 0 if none; its group priority in *group. */
unsigned cortexm_best(const cortexm_t *cm, int *group);
/* exc taken: pending -> active. */
void cortexm_take(cortexm_t *cm, unsigned exc);
/* exc returned from: 0, or -1 if it was not active (an INVPC UsageFault).
 * An IRQ whose line is still high pends again. */
int cortexm_return(cortexm_t *cm, unsigned exc);
/* Active exceptions (for a return to thread mode). */
unsigned cortexm_nactive(const cortexm_t *cm);
/* The fault status registers decoded, one line into out: "CFSR 0x00008200:
 * PRECISERR BFARVALID (BFAR 0x60000000), HFSR 0x40000000: FORCED" (their
 * bits' names as ARMv7-M B3.2.15-B3.2.16 give them; MMFAR and BFAR only
 * when valid). */
void cortexm_fault_text(const cortexm_t *cm, char *out, size_t n);

#endif

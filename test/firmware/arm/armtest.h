/* armtest.h - our register-level test firmware for the Cortex-M core
 * (test/unit/test_armcore.c): the core's registers (ARMv7-M ARM DDI 0403E, PM0056),
 * the test's fake peripheral and the mailbox the host reads. */
#ifndef ARMTEST_H
#define ARMTEST_H

#include <stdint.h>

#define REG(a) (*(volatile uint32_t *)(a))
#define REG8(a) (*(volatile uint8_t *)(a))
/* SysTick (B3.3.2) */
#define SYST_CSR REG(0xE000E010u)
#define SYST_RVR REG(0xE000E014u)
#define SYST_CVR REG(0xE000E018u)
/* NVIC (B3.4.2): bank 0 */
#define NVIC_ISER0 REG(0xE000E100u)
#define NVIC_ICER0 REG(0xE000E180u)
#define NVIC_ISPR0 REG(0xE000E200u)
#define NVIC_ICPR0 REG(0xE000E280u)
#define NVIC_IABR0 REG(0xE000E300u)
#define NVIC_IPR(n) REG8(0xE000E400u + (n))
#define NVIC_STIR REG(0xE000EF00u)
/* SCB (B3.2.2) */
#define SCB_CPUID REG(0xE000ED00u)
#define SCB_ICSR REG(0xE000ED04u)
#define SCB_VTOR REG(0xE000ED08u)
#define SCB_AIRCR REG(0xE000ED0Cu)
#define SCB_SHPR(n) REG8(0xE000ED18u + (n) - 4u) /* exception n's priority byte */
#define SCB_DEMCR REG(0xE000EDFCu)
/* DWT (C1.8.7) */
#define DWT_CTRL REG(0xE0001000u)
#define DWT_CYCCNT REG(0xE0001004u)
/* The test's fake peripheral (test_armcore.c): scenario, IRQ lines, an event timer */
#define FAKE_BASE 0x40010000u
#define FAKE_SCENARIO REG(FAKE_BASE + 0x00u) /* read: the scenario the host asks for */
#define FAKE_RAISE REG(FAKE_BASE + 0x04u)    /* write n: IRQ line n high */
#define FAKE_LOWER REG(FAKE_BASE + 0x08u)    /* write n: IRQ line n low */
#define FAKE_AFTER REG(FAKE_BASE + 0x0Cu)    /* write k: IRQ line 2 high k cycles after the write */
#define FAKE_HCLK REG(FAKE_BASE + 0x10u)     /* write Hz: the core clock (as RCC would) */
#define FAKE_FAULT REG(FAKE_BASE + 0x14u)    /* any access: a bus error */

#define MAILBOX_LOG 64
typedef struct {
    uint32_t scenario, done, step;
    uint32_t nlog;
    uint32_t log[MAILBOX_LOG]; /* events in order, one word each */
    uint32_t v[16];            /* figures the scenario measured */
} mailbox_t;

#endif

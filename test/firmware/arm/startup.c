/* startup.c - the vector table and reset of our test firmware (STM32F103x8:
 * 16 core exceptions and 43 interrupts, RM0008 table 63). Every handler the
 * test does not define is default_handler, which logs the exception number
 * (IPSR | 0xDEAD0000) and sleeps. */
#include <stdint.h>

#include "armtest.h"

#define NVECTORS (16 + 43)

extern uint32_t _sidata, _sdata, _edata, _sbss, _ebss, _estack;
extern mailbox_t mb;
int main(void);
void reset_handler(void);

void default_handler(void)
{
    uint32_t ipsr;
    __asm volatile("mrs %0, ipsr" : "=r"(ipsr));
    if (mb.nlog < MAILBOX_LOG) mb.log[mb.nlog++] = 0xDEAD0000u | ipsr;
    for (;;) __asm volatile("wfi");
}

#define WEAK __attribute__((weak, alias("default_handler")))
void nmi_handler(void) WEAK;
void hardfault_handler(void) WEAK;
void svc_handler(void) WEAK;
void pendsv_handler(void) WEAK;
void systick_handler(void) WEAK;
void irq0_handler(void) WEAK;
void irq1_handler(void) WEAK;
void irq2_handler(void) WEAK;

__attribute__((section(".vectors"), used)) void (*const vectors[NVECTORS])(void) = {
    (void (*)(void))&_estack, reset_handler, nmi_handler, hardfault_handler,
    default_handler, default_handler, default_handler, 0, 0, 0, 0,
    svc_handler, default_handler, 0, pendsv_handler, systick_handler,
    irq0_handler, irq1_handler, irq2_handler,
    [19 ... NVECTORS - 1] = default_handler,
};

void reset_handler(void)
{
    uint32_t *s = &_sidata, *d = &_sdata;
    while (d < &_edata) *d++ = *s++;
    for (d = &_sbss; d < &_ebss;) *d++ = 0;
    main();
    for (;;) __asm volatile("wfi");
}

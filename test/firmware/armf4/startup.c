/* startup.c - the vector table and reset of our STM32F405 test firmware:
 * 16 core exceptions and 82 interrupts (RM0090 rev 19 table 61). Every
 * interrupt goes to irq_handler (f4test.c), which reads IPSR; a fault or an
 * unexpected exception to default_handler, which logs IPSR | 0xDEAD0000. */
#include <stdint.h>

#include "f4test.h"

#define NVECTORS (16 + 82)

extern uint32_t _sidata, _sdata, _edata, _sbss, _ebss, _estack;
int main(void);
void reset_handler(void);
void irq_handler(void);
void systick_handler(void);

void default_handler(void)
{
    uint32_t ipsr;
    __asm volatile("mrs %0, ipsr" : "=r"(ipsr));
    if (mb.nlog < MAILBOX_LOG) mb.log[mb.nlog++] = 0xDEAD0000u | ipsr;
    for (;;) __asm volatile("wfi");
}

__attribute__((section(".vectors"), used)) void (*const vectors[NVECTORS])(void) = {
    (void (*)(void))&_estack, reset_handler, default_handler, default_handler,
    default_handler, default_handler, default_handler, 0, 0, 0, 0,
    default_handler, default_handler, 0, default_handler, systick_handler,
    [16 ... NVECTORS - 1] = irq_handler,
};

void reset_handler(void)
{
    uint32_t *s = &_sidata, *d = &_sdata;
    while (d < &_edata) *d++ = *s++;
    for (d = &_sbss; d < &_ebss;) *d++ = 0;
    main();
    for (;;) __asm volatile("wfi");
}

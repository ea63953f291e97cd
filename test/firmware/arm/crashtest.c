/* crashtest.c - our firmware that faults (test/cli_board_arm.sh): after
 * 10 ms of SysTick it stores to 0x60000000, the FSMC bank an STM32F103
 * medium-density part lacks (RM0008 3.3 table 3, reserved): a precise bus
 * fault, escalated to HardFault, which ends the run as firmware_crashed. */
#include <stdint.h>

#include "armtest.h"

__attribute__((section(".mailbox"))) mailbox_t mb;
static volatile uint32_t ticks;

void systick_handler(void) { ticks++; }

int main(void)
{
    SYST_RVR = 8000u - 1u, SYST_CVR = 0, SYST_CSR = 7u; /* 1 ms at the reset clock, HSI 8 MHz */
    while (ticks < 10) __asm volatile("wfi");
    REG(0x60000000u) = 1u;
    for (;;) {}
}

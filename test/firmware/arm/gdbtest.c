/* gdbtest.c - our firmware for the gdb stub's tests (test/cli_armgdb.sh,
 * test/tools/armgdb_probe.c): a SysTick interrupt each millisecond at the 8 MHz
 * HSI (ARMv7-M B3.3: RVR + 1 processor clocks a period) and a main loop
 * that calls gdb_tick once a tick, changing globals of several types. */
#include <stdint.h>

#include "armtest.h"

__attribute__((section(".mailbox"))) mailbox_t mb;

volatile uint32_t g_ticks;    /* SysTick interrupts taken */
volatile int16_t g_speed = -5; /* signed 16-bit, from .data */
volatile float g_gain = 0.5f;  /* a float (no FP arithmetic: the M3 has no FPU and this image no libgcc) */
uint32_t g_count;              /* the sum of gdb_tick's arguments */
static const float gains[4] = { 0.5f, 1.25f, -2.0f, 3.75f };

void __attribute__((noinline)) gdb_tick(uint32_t k)
{
    g_count += k;
    g_speed = (int16_t)(g_speed + 3);
    g_gain = gains[k & 3u];
}

void systick_handler(void) { g_ticks++; }

int main(void)
{
    SYST_RVR = 7999u; /* 8000 cycles: 1 ms at 8 MHz */
    SYST_CVR = 0;
    SYST_CSR = 7u;    /* ENABLE, TICKINT, CLKSOURCE = the processor clock */
    for (uint32_t k = 1;; k++) {
        gdb_tick(k);
        while (g_ticks < k) __asm volatile("wfi");
    }
}

/* armcore_speed.c - the Cortex-M core's host cost (sim/arm/armcore.c) on our
 * test firmware (build/arm/coretest.elf): host ns per simulated instruction
 * on a loop of ALU and SRAM instructions, the same loop under SysTick every
 * 200 cycles (the exception round trip's cost: the difference per
 * exception), and the loop run to the same cycle in 1 ms chunks at 72 MHz
 * (the stops inside blocks a lockstep with the physics makes). Prints one
 * line each (bench/run.sh; docs/BENCHMARKS.md). The loop stores to SRAM
 * once every 8 instructions or so: unicorn 2.0.1 takes every store through
 * QEMU's not-dirty slow path (unicorn issue 1970), which dominates.
 * Last, an F4 at 168 MHz that idles (coretest's IDLE_BENCH on the
 * stm32f405xg: each 1 ms SysTick period some work, a CYCCNT busy wait, a
 * HAL_Delay-shaped wait on the tick, WFI): host ns per simulated ms and
 * times real time with idle skipping and without (no_idle_skip). */
#include <stdio.h>
#include <stdlib.h>
#include <time.h>

#include "arm/armcore.h"

#define SPIN 22
#define STORM 23
#define IDLE_BENCH 28
#define F4_HZ 168000000u       /* the STM32F405's HCLK at its maximum (DS8626) */
#define IDLE_SKIP_MS 2000u     /* simulated ms with skipping */
#define IDLE_NOSKIP_MS 50u     /* and without: every iteration run (slow) */
#define CYCLES 50000000ull /* 50 M instructions: 0.7 s of a 72 MHz STM32F1 */
#define CHUNK 72000u        /* 1 ms at 72 MHz */

static uint32_t scenario;
static mmio_status_t rd(void *s, uint32_t off, unsigned size, uint32_t *v) { *v = off == 0 ? scenario : 0; return MMIO_OK; }
static const mmio_ops_t ops = { "BENCH", rd, NULL, NULL, NULL, NULL };

static double now_s(void)
{
    struct timespec t;
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t); /* the host CPU this process used: the machine is shared */
    return (double)t.tv_sec + (double)t.tv_nsec * 1e-9;
}

/* Host seconds to run scenario sc to CYCLES in chunks of chunk cycles. */
static double run_on(const char *mcu, uint32_t hz, bool no_skip, uint32_t sc, uint64_t cycles, uint64_t chunk, armcore_stats_t *st)
{
    armimage_t img;
    char err[300];
    if (armimage_read("build/arm/coretest.elf", armimage_mcu(mcu), &img, err, sizeof err)) return fprintf(stderr, "%s\n", err), -1;
    scenario = sc;
    mmio_region_t reg = { 0x40010000u, 0x400, &ops, NULL };
    armcore_cfg_t cfg = { .image = &img, .regions = &reg, .nregions = 1, .hclk_hz = hz, .no_idle_skip = no_skip };
    armcore_t *c = armcore_new(&cfg, err, sizeof err);
    if (!c) return fprintf(stderr, "%s\n", err), -1;
    double t0 = now_s();
    for (uint64_t t = 0; t < cycles;) t = t + chunk < cycles ? t + chunk : cycles, armcore_run_to(c, t);
    double dt = now_s() - t0;
    *st = armcore_stats(c);
    armcore_free(c);
    armimage_free(&img);
    return dt;
}

static double run(uint32_t sc, uint64_t chunk, armcore_stats_t *st)
{
    return run_on("stm32f103x8", 72000000u, false, sc, CYCLES, chunk, st);
}

/* The idling F4 in 1 ms chunks (a lockstep with the physics), with and without skipping. */
static int idle_f4(void)
{
    armcore_stats_t a, b;
    const uint64_t ms = F4_HZ / 1000u;
    double skip = run_on("stm32f405xg", F4_HZ, false, IDLE_BENCH, IDLE_SKIP_MS * ms, ms, &a);
    double all = run_on("stm32f405xg", F4_HZ, true, IDLE_BENCH, IDLE_NOSKIP_MS * ms, ms, &b);
    if (skip < 0 || all < 0) return 3;
    printf("ARM core: idling F4 at 168 MHz (work, CYCCNT wait, HAL_Delay, WFI each 1 ms tick): %.1f us per simulated ms, %.1fx real time "
           "skipping idle (%llu loop skips); %.1f us per ms, %.2fx real time without (no_idle_skip): %.0fx faster\n",
           skip / IDLE_SKIP_MS * 1e6, IDLE_SKIP_MS * 1e-3 / skip, (unsigned long long)a.loop_skips, all / IDLE_NOSKIP_MS * 1e6,
           IDLE_NOSKIP_MS * 1e-3 / all, (all / IDLE_NOSKIP_MS) / (skip / IDLE_SKIP_MS));
    return 0;
}

int main(void)
{
    armcore_stats_t a, b, d;
    double spin = run(SPIN, CYCLES, &a), storm = run(STORM, CYCLES, &b), chunked = run(SPIN, CHUNK, &d);
    if (spin < 0 || storm < 0 || chunked < 0) return 3;
    printf("ARM core: %.2f ns/instruction (ALU and SRAM loop, one run of %llu M), %.2fx real time at 72 MHz\n", spin / CYCLES * 1e9,
           CYCLES / 1000000ull, (double)CYCLES / 72e6 / spin);
    printf("ARM core: %.2f ns/instruction under SysTick every 200 cycles (%llu exceptions): %.2f us per exception round trip\n",
           storm / CYCLES * 1e9, (unsigned long long)b.exceptions, (storm - spin) / (double)b.exceptions * 1e6);
    printf("ARM core: %.2f ns/instruction in 1 ms chunks (%llu stops inside a block)\n", chunked / CYCLES * 1e9,
           (unsigned long long)d.splits);
    return idle_f4();
}

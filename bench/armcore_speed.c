/* armcore_speed.c - the Cortex-M core's host cost (sim/arm/armcore.c) on our
 * test firmware (build/arm/coretest.elf): host ns per simulated instruction
 * on a loop of ALU and SRAM instructions, the same loop under SysTick every
 * 200 cycles (the exception round trip's cost: the difference per
 * exception), and the loop run to the same cycle in 1 ms chunks at 72 MHz
 * (the stops inside blocks a lockstep with the physics makes). Prints one
 * line each (bench/run.sh; docs/BENCHMARKS.md). The loop stores to SRAM
 * once every 8 instructions or so: unicorn 2.0.1 takes every store through
 * QEMU's not-dirty slow path (unicorn issue 1970), which dominates. */
#include <stdio.h>
#include <stdlib.h>
#include <time.h>

#include "arm/armcore.h"

#define SPIN 22
#define STORM 23
#define CYCLES 50000000ull /* 50 M instructions: 0.7 s of a 72 MHz STM32F1 */
#define CHUNK 72000u        /* 1 ms at 72 MHz */

static uint32_t scenario;
static mmio_status_t rd(void *s, uint32_t off, unsigned size, uint32_t *v) { *v = off == 0 ? scenario : 0; return MMIO_OK; }
static const mmio_ops_t ops = { "BENCH", rd, NULL, NULL, NULL, NULL };

static double now_s(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec + (double)t.tv_nsec * 1e-9;
}

/* Host seconds to run scenario sc to CYCLES in chunks of chunk cycles. */
static double run(uint32_t sc, uint64_t chunk, armcore_stats_t *st)
{
    armimage_t img;
    char err[300];
    if (armimage_read("build/arm/coretest.elf", armimage_mcu("stm32f103x8"), &img, err, sizeof err)) return fprintf(stderr, "%s\n", err), -1;
    scenario = sc;
    mmio_region_t reg = { 0x40010000u, 0x400, &ops, NULL };
    armcore_cfg_t cfg = { .image = &img, .regions = &reg, .nregions = 1, .hclk_hz = 72000000u };
    armcore_t *c = armcore_new(&cfg, err, sizeof err);
    if (!c) return fprintf(stderr, "%s\n", err), -1;
    double t0 = now_s();
    for (uint64_t t = 0; t < CYCLES;) t = t + chunk < CYCLES ? t + chunk : CYCLES, armcore_run_to(c, t);
    double dt = now_s() - t0;
    *st = armcore_stats(c);
    armcore_free(c);
    armimage_free(&img);
    return dt;
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
    return 0;
}

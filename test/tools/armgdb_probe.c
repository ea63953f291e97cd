/* armgdb_probe.c - runs an ARM test image (test/arm) on the Cortex-M core
 * alone (no peripherals but the core's own: SysTick, NVIC, SCB, DWT) at the
 * STM32F103's 8 MHz HSI, in 1 ms steps as a physics loop would, with or
 * without the gdb stub, and prints the final state: cycles, registers, an
 * FNV-1a hash of SRAM, and with --watch the variables' values read from
 * SRAM (sim/arm/armwatch.c) after the last step. test/cli_armgdb.sh checks that the state is the same
 * with gdb attached (breakpoints, steps, halts of any wall time) as without.
 *   armgdb_probe IMAGE MS [--gdb PORT] [--watch NAME[,NAME...]]
 * exit 0, 1 if the firmware crashed (its cause printed), 2 bad arguments or
 * image, 3 the port cannot be listened on. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <unicorn/unicorn.h>

#include "arm/armcore.h"
#include "arm/armgdb.h"
#include "arm/armimage.h"
#include "arm/armwatch.h"

#define HSI_HZ 8000000u           /* RM0008 7.2.1: the STM32F1 starts on its 8 MHz HSI */
#define STEP_PS 1000000000ull     /* 1 ms of simulated time a step */

static uint32_t fnv(const uint8_t *b, size_t n)
{
    uint32_t h = 2166136261u;
    for (size_t i = 0; i < n; i++) h = (h ^ b[i]) * 16777619u;
    return h;
}

static void print_state(armcore_t *c, const armimage_mcu_t *m)
{
    static const int regs[] = { UC_ARM_REG_R0, UC_ARM_REG_R1, UC_ARM_REG_R2, UC_ARM_REG_R3, UC_ARM_REG_R4, UC_ARM_REG_R5,
        UC_ARM_REG_R6, UC_ARM_REG_R7, UC_ARM_REG_R8, UC_ARM_REG_R9, UC_ARM_REG_R10, UC_ARM_REG_R11, UC_ARM_REG_R12,
        UC_ARM_REG_SP, UC_ARM_REG_LR, UC_ARM_REG_PC, UC_ARM_REG_IPSR };
    printf("cycles %llu time_ps %llu regs", (unsigned long long)armcore_cycles(c), (unsigned long long)armcore_time_ps(c));
    for (size_t i = 0; i < sizeof regs / sizeof regs[0]; i++) printf(" %08x", armcore_reg(c, regs[i]));
    uint8_t *sram = malloc(m->sram_bytes);
    if (sram && armcore_read(c, m->sram_base, sram, m->sram_bytes) == 0) printf(" sram %08x", fnv(sram, m->sram_bytes));
    printf(" exceptions %llu\n", (unsigned long long)armcore_stats(c).exceptions);
    free(sram);
}

int main(int argc, char **argv)
{
    char err[300];
    unsigned port = 0;
    const char *watch = NULL;
    int bad = argc < 3;
    for (int i = 3; i < argc && !bad; i += 2) {
        if (i + 1 >= argc) bad = 1;
        else if (!strcmp(argv[i], "--gdb")) bad = sscanf(argv[i + 1], "%u", &port) != 1;
        else if (!strcmp(argv[i], "--watch")) watch = argv[i + 1];
        else bad = 1;
    }
    if (bad) {
        fprintf(stderr, "usage: armgdb_probe IMAGE MS [--gdb PORT] [--watch NAME[,NAME...]]\n");
        return 2;
    }
    long ms = atol(argv[2]);
    const armimage_mcu_t *m = armimage_mcu("stm32f103x8");
    armimage_t img;
    if (ms < 1 || armimage_read(argv[1], m, &img, err, sizeof err) != 0) { fprintf(stderr, "%s\n", ms < 1 ? "armgdb_probe: MS >= 1" : err); return 2; }
    elfvar_list_t w = { 0 };
    if (watch && armwatch_open(&w, argv[1], watch, m, stderr, err, sizeof err) != 0) {
        fprintf(stderr, "armgdb_probe: %s\n", err);
        armimage_free(&img);
        return 2;
    }
    armcore_cfg_t cfg = { .image = &img, .hclk_hz = HSI_HZ };
    armcore_t *c = armcore_new(&cfg, err, sizeof err);
    if (!c) { fprintf(stderr, "%s\n", err); armimage_free(&img); return 3; }
    armgdb_t *g = NULL;
    if (port && !(g = armgdb_new(c, port, err, sizeof err))) {
        fprintf(stderr, "armgdb_probe: --gdb %u: %s\n", port, err);
        armcore_free(c), armimage_free(&img);
        return 3;
    }
    if (g) fprintf(stderr, "armgdb_probe: halted until gdb attaches to 127.0.0.1:%u (target remote :%u)\n", port, port);
    int rc = 0;
    for (long i = 1; i <= ms && !rc; i++) rc = g ? armgdb_run_until_ps(g, (uint64_t)i * STEP_PS) : armcore_run_until_ps(c, (uint64_t)i * STEP_PS);
    armgdb_free(g);
    print_state(c, m);
    double values[ELFVAR_MAX];
    armwatch_sample(&w, c, m, values);
    for (int i = 0; i < w.n; i++) printf("watch %s %s %.9g\n", w.v[i].name, w.v[i].type, values[i]);
    uint32_t pc;
    const char *cause;
    if (armcore_crashed(c, &pc, &cause)) printf("crashed at 0x%08x: %s\n", pc, cause);
    armcore_free(c);
    armimage_free(&img);
    return rc ? 1 : 0;
}

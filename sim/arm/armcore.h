/* armcore.h - a Cortex-M3/M4 core on libunicorn 2 (UC_ARCH_ARM, UC_MODE_THUMB,
 * the model set with uc_ctl: UC_MODE_MCLASS would give an M33), with the
 * MCU's flash (and its boot alias at 0), SRAM and both bit-band regions, the
 * peripheral space (0x40000000-0x5FFFFFFF) and the Private Peripheral Bus
 * (0xE0000000-0xE00FFFFF, the core's own cortexm.c) routed to mmio_region_t
 * tables. Exception entry and return are ours (unicorn runs none of
 * QEMU's: see ../shared/notes/platform-facts.md, "ARM Cortex-M on libunicorn").
 *
 * Time: one cycle per instruction, counted per translated block (its Thumb
 * lengths decoded once, cached), plus the Cortex-M3's exception entry (12),
 * exit (10) and tail-chain (6) cycles; a stated limit: no wait states, no
 * pipeline timing. Simulated time is an integer of picoseconds at the HCLK
 * the firmware configured (a clock switch starts a new segment: rounding at
 * most 1 ps per switch, never per step).
 *
 * Determinism: the run stops at exactly the target cycle (inside a block if
 * it must), and such a stop is invisible: pending exceptions and peripheral
 * events are taken at the start of a translated block as they would be
 * without it, so a run is the same in any chunking. WFI/WFE sleep to the
 * next event, skipped in one go (the same state as cycle by cycle); a wait
 * loop (polling DWT CYCCNT, SysTick or RAM, storing nothing) is jumped over
 * by whole iterations to the one that exits or to the next event, and so is
 * any state that recurs (a block started again with the same registers and
 * SRAM, nothing touched between: whole periods to the next event). */
#ifndef ARMCORE_H
#define ARMCORE_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#include "armimage.h"
#include "cortexm.h"
#include "mmio.h"

#define ARMCORE_REGIONS_MAX 64
#define ARMCORE_UNMODELED_MAX 64
#define ARMCORE_EXC_ENTRY_CYCLES 12u  /* ARM knowledge article 103489845: Cortex-M3/M4 entry 12, exit 10 cycles */
#define ARMCORE_EXC_EXIT_CYCLES 10u
#define ARMCORE_TAIL_CHAIN_CYCLES 6u  /* Cortex-M3 TRM r2p1 5.5.2: tail-chaining 6 cycles */
#define ARMCORE_PS_PER_S 1000000000000ull

typedef struct armcore armcore_t;

typedef struct {
    const armimage_t *image;          /* checked; the core copies its flash */
    const mmio_region_t *regions;     /* the MCU's peripherals (not the PPB: the core's own) */
    int nregions;
    const mmio_clocks_t *clocks;      /* RCC's; NULL: hclk_hz throughout */
    uint32_t hclk_hz;                 /* the clock before RCC says otherwise (the STM32F1's HSI: 8 MHz) */
    bool verbose;                     /* one line on stderr for each unmodeled register's first access */
    bool no_idle_skip;                /* sleep cycle by cycle, run every wait loop (tests: the same state as skipping) */
    /* The firmware's stores into flash (at its base or its boot alias), off
     * from the flash's start, at core cycle now: the FLASH controller's
     * (stm32f1_flash_mem_write), which programs the bytes it allows. NULL:
     * such a store is a bus fault. */
    mmio_status_t (*flash_write)(void *ctx, uint32_t off, unsigned size, uint32_t value, uint64_t now);
    void *flash_ctx;
    /* The SoC tells the core (armcore_touch) whenever a model changes
     * another's state other than through the bus (a DMA request, a timer's
     * trigger, a reset through RCC): the core then keeps each model's next
     * event and asks again only the models accessed, advanced or touched.
     * false: after any access or event it asks every model. */
    bool reports_links;
} armcore_cfg_t;

typedef struct {
    uint32_t addr;
    uint64_t reads, writes;
    char region[16];                  /* the model's name, "" if no model */
} armcore_unmodeled_t;

typedef struct {
    uint64_t exceptions;              /* exceptions entered (tail-chains included) */
    uint64_t tail_chains;
    uint64_t sleeps;                  /* WFI/WFE that slept */
    uint64_t idle_cycles;             /* cycles asleep */
    uint64_t idle_jumped;             /* of those, the cycles jumped over (a sleep advanced more than one cycle at a time; 0 with no_idle_skip) */
    uint64_t loop_skips;              /* wait loops jumped over (see armcore.c, "idle loops") */
    uint64_t loop_cycles;             /* cycles of wait loops jumped over */
    uint64_t recur_skips;             /* of loop_skips, the jumps over a recurring state (armcore.c, "recurring states") */
    uint64_t recur_cycles;            /* of loop_cycles, the cycles of those */
    uint64_t recur_snapshots;         /* states saved to compare */
    uint64_t splits;                  /* stops inside a translated block */
    uint64_t starts;                  /* uc_emu_start calls */
} armcore_stats_t;

/* A core at reset (SP and PC from the vector table). NULL with one line in err. */
armcore_t *armcore_new(const armcore_cfg_t *cfg, char *err, size_t errn);
void armcore_free(armcore_t *c);
/* Run to cycle target (or until the firmware crashes). 0, or 1 if crashed. */
int armcore_run_to(armcore_t *c, uint64_t target);
/* Run to simulated time t_ps at the clocks as they change. */
int armcore_run_until_ps(armcore_t *c, uint64_t t_ps);
uint64_t armcore_cycles(const armcore_t *c);
uint64_t armcore_time_ps(const armcore_t *c);
/* The line a peripheral raises for its interrupt; the bus a DMA model moves data on. */
mmio_irq_t armcore_irq(armcore_t *c);
mmio_bus_t armcore_bus(armcore_t *c);
cortexm_t *armcore_cortexm(armcore_t *c);
/* The flash bytes (the FLASH model programs them; armcore_flash_changed after). */
uint8_t *armcore_flash(armcore_t *c);
void armcore_flash_changed(armcore_t *c, uint32_t addr, uint32_t bytes);
/* The model placed at addr (an address in its region) changed other than through its own access or event:
 * its next event is asked again at the core's next check. armcore_touch_all: every model's. */
void armcore_touch(armcore_t *c, uint32_t addr);
void armcore_touch_all(armcore_t *c);
/* reported false: every model's next event asked after any access or event, as without reports_links (tests: the reference the SoC's reports are checked against). */
void armcore_set_links(armcore_t *c, bool reported);
/* A crash: 1 with the faulting PC and the cause, else 0. */
int armcore_crashed(const armcore_t *c, uint32_t *pc, const char **cause);
/* A core register (UC_ARM_REG_*); memory as the firmware sees it (flash, SRAM): 0, or -1 outside. */
uint32_t armcore_reg(armcore_t *c, int reg);
int armcore_read(armcore_t *c, uint32_t addr, void *buf, size_t n);
const armcore_unmodeled_t *armcore_unmodeled(const armcore_t *c, int *n);
armcore_stats_t armcore_stats(const armcore_t *c);

/* The debugger's hooks (armgdb.c). A breakpoint halts the run before the
 * instruction at its address runs (found at its translated block's start
 * and reached through the core's exact stop, so a halt is invisible to the
 * run: flash is never patched); armcore_halt_at halts it at a cycle (a
 * single step: the current cycle + 1; an exception taken at the step lands
 * at its handler's first instruction; a step over WFI/WFE ends when the core
 * wakes, as on the hardware). armcore_run_to / run_until_ps then
 * return ARMCORE_HALTED; the next run resumes there, that address's
 * breakpoint not taken again before its instruction has run. */
#define ARMCORE_HALTED 2
#define ARMCORE_BREAKS_MAX 64
/* The breakpoints (Thumb bit ignored), replacing the set: 0, or -1 if more than ARMCORE_BREAKS_MAX. */
int armcore_set_breaks(armcore_t *c, const uint32_t *addr, int n);
/* Halt at cycle (UINT64_MAX: never); cleared when reached. */
void armcore_halt_at(armcore_t *c, uint64_t cycle);
/* A core register written (PC: where the run resumes): 0, or -1. */
int armcore_set_reg(armcore_t *c, int reg, uint32_t v);
/* SRAM written (the debugger's M packet; flash and peripherals never): 0, or -1 outside SRAM. */
int armcore_write(armcore_t *c, uint32_t addr, const void *buf, size_t n);

#endif

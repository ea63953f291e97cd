/* armcore.c - a Cortex-M core on libunicorn, its bus and its run (see armcore.h). */
#include "armcore.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <unicorn/unicorn.h>

#include "thumbuse.h"
#include "ucdl.h"

#define PERIPH_BASE 0x40000000u
#define PERIPH_BYTES 0x20000000u
#define PERIPH_BB_BASE 0x42000000u /* bit-band alias of 0x40000000-0x400FFFFF (ARMv7-M A3.7, PM0056 2.2.5) */
#define SRAM_BB_BASE 0x22000000u   /* bit-band alias of 0x20000000-0x200FFFFF */
#define BB_ALIAS_BYTES 0x02000000u
#define BB_REGION_BYTES 0x00100000u
#define BLK_CACHE 8192u            /* translated blocks whose instruction count is remembered */
#define BLK_BYTES_MAX 4096u        /* a translated block's bytes (QEMU: at most 512 instructions) */
#define NO_ADDR 0xFFFFFFFFu
#define NO_TIME UINT64_MAX
#define EXC_RETURN_INTNO 8         /* QEMU's EXCP_EXCEPTION_EXIT: a bx to 0xFFFFFFFx */
#define XPSR_T (1u << 24)
#define XPSR_ALIGN (1u << 9)       /* the frame was aligned to 8 bytes (B1.5.7) */
#define CCR_STKALIGN (1u << 9)
#define CONTROL_SPSEL 2u
#define CONTROL_FPCA 4u            /* an FP context is active (B1.4.4) */
#define BASIC_FRAME_BYTES 32u      /* R0-R3, R12, LR, return address, xPSR (B1.5.7) */
#define FP_FRAME_BYTES 0x68u       /* the extended frame: the basic one, S0-S15, FPSCR, a reserved word (B1.5.7) */
#define EXC_RETURN_BASIC 0x10u     /* EXC_RETURN bit 4: 1 a basic frame, 0 an extended one (B1.5.8) */

#define LOOP_BLOCKS_MAX 4u         /* a wait loop: a cycle of at most 4 translated blocks (a call to HAL_GetTick and back) */
#define LOOP_HIST 16u              /* the last blocks run, for finding such a cycle (2 x 4 + 1 needed) */
#define LOOP_CACHE 64u             /* loops analysed, by their head's address */
#define LOOP_SKIP_MIN 16u          /* whole iterations before the next event for a skip to be worth its probes */
#define LOOP_GRID 16u              /* probes spread over the iterations before the bisection */
#define REC_PERIOD_MIN 32u         /* cycles: a recurring state's period at least this (shorter loops are the probes' above) */
#define REC_PERIOD_MAX 200000u     /* cycles: and at most this (a loop's iteration, calls included) */
#define REC_AHEAD_MIN 2u           /* whole periods ahead of the next event for a snapshot to be worth taking */
#define REC_TRIES 2u               /* snapshots per block between two disturbances */
#define REC_STRETCH_TRIES 4u       /* snapshots in all between two disturbances */
#define REC_FAILS_BAN 4u           /* failed snapshots in a row at a block before it is left alone for a while */
#define REC_REGS 22
#define REC_FP_REGS 17
#define DWT_CYCCNT_ADDR 0xE0001004u
#define SYST_CSR_ADDR 0xE000E010u
#define SYST_CVR_ADDR 0xE000E018u

enum { STOP_NONE, STOP_TAKE, STOP_SPLIT, STOP_INTR, STOP_FAULT, STOP_SKIP, STOP_RECUR };
enum { LOOP_UNKNOWN, LOOP_PURE, LOOP_NEVER };
enum { PROBE_STAYS = 0, PROBE_EXITS = 1, PROBE_AGAIN = -1, PROBE_NEVER = -2, PROBE_RUNNING = 2 };

/* A translated block: its instruction count; when it last started (and in which undisturbed stretch) for recurrences. */
typedef struct {
    uint32_t addr, size, n;
    uint32_t tries;                      /* snapshots taken at it in the stretch seen_gen */
    uint32_t last_p;                     /* the cycles between its last two starts in one stretch */
    uint32_t fails;                      /* snapshots at it that did not recur since the last that did */
    uint64_t ban_until;                  /* no snapshot at it before this cycle (an inner loop's head: its state never recurs) */
    uint64_t seen_cyc, seen_gen;
} blk_t;

/* A cycle of translated blocks that repeats: its blocks from the head, its instructions (= cycles) an iteration. */
typedef struct {
    uint32_t head, p, n;
    uint32_t written;                    /* registers (bits 0-15) and flags (thumbuse.h) an iteration writes */
    bool bits;                           /* it takes bits apart (thumbuse.h): its exit need not be monotone in time */
    uint32_t addr[LOOP_BLOCKS_MAX], size[LOOP_BLOCKS_MAX];
    int verdict;
    uint64_t retry_at;                   /* no new attempt before this cycle */
} loop_t;

struct armcore {
    uc_engine *uc;
    const armimage_mcu_t *mcu;
    uint8_t *flash, *sram;
    mmio_region_t reg[ARMCORE_REGIONS_MAX + 1];
    int nreg;
    /* each model's next event as last asked (see advance_due); asked again when dirty */
    uint64_t nev[ARMCORE_REGIONS_MAX + 1];
    uint64_t dirty[(ARMCORE_REGIONS_MAX + 64) / 64]; /* a bit per model */
    bool all_dirty, links;
    mmio_region_t *last_reg;             /* the region the last access found */
    cortexm_t cm;
    const mmio_clocks_t *clocks;
    uint32_t hclk;
    uint64_t seg_cycle, seg_ps;          /* the current clock's segment: its first cycle and time */
    uint64_t cyc, target, target_ps, ev_next, now;
    uint32_t blk_addr, blk_size;
    uint64_t blk_start;                  /* the cycle the current block started at */
    uint64_t nat_start;                  /* the cycle the current untranslated-by-stops block started at */
    bool stop_mid;                       /* the split block was a split's remainder */
    uint32_t resume_mid;                 /* a split's remainder starts here: no checks, as without the stop */
    bool partial;                        /* running the first instructions of a split block */
    int stop, intno;
    unsigned take;                       /* the exception to take (STOP_TAKE) */
    uint32_t stop_addr, pc;              /* the block a stop was asked at; where to resume */
    bool sleeping, verbose, no_idle_skip, crashed;
    mmio_status_t (*flash_write)(void *ctx, uint32_t off, unsigned size, uint32_t value, uint64_t now);
    void *flash_ctx;
    uint32_t fix_off, fix_n;             /* flash bytes to restore after a store the controller handled */
    uint8_t fix[4];
    uint32_t crash_pc, bad_addr;
    int bad_type;
    char cause[400];
    armcore_unmodeled_t unm[ARMCORE_UNMODELED_MAX];
    int nunm;
    armcore_stats_t st;
    /* the debugger's (armgdb.c): breakpoints checked at each block's start, a cycle to halt at */
    uint32_t brk[ARMCORE_BREAKS_MAX];
    int nbrk;
    uint64_t halt_at, brk_cyc, split_to; /* halt at this cycle; the first breakpoint's in this block; the split's end */
    uint32_t brk_skip;                   /* resumed here after a halt: its breakpoint not taken again at once */
    bool halted, brk_hit;
    blk_t blk[BLK_CACHE];
    /* idle loops: the blocks run last (a ring), the loops analysed, the one a probe runs */
    uint32_t hist_addr[LOOP_HIST], hist_size[LOOP_HIST];
    unsigned hist_pos, hist_n;
    loop_t loops[LOOP_CACHE];
    loop_t *skip;
    uint32_t never_head;                 /* the last head found to lead no skippable loop: no lookup while it repeats */
    bool probe, probe_timed;
    int probe_res;
    uint32_t probe_idx;
    uint32_t saved[17];                  /* the registers a probe may change (R0-R12, SP, LR, APSR), as at the loop's head */
    cortexm_t cm_saved;
    /* recurring states (see "recurring states" below) */
    uint64_t rec_gen;                    /* disturbances so far: emulation starts, peripheral accesses, events due */
    uint64_t rec_cyc, rec_at_gen, rec_land, rec_tries_gen;
    unsigned rec_tries;                  /* snapshots taken in the stretch rec_tries_gen */
    uint32_t rec_head;                   /* the block the snapshot was taken at; NO_ADDR none */
    uint64_t rec_regs[REC_REGS + REC_FP_REGS];
    uint8_t *rec_sram;
};

/* ---- memory and instruction lengths ---- */
static uint8_t *host(armcore_t *c, uint32_t addr, uint32_t n)
{
    const armimage_mcu_t *m = c->mcu;
    if (addr >= m->flash_base && (uint64_t)addr + n <= (uint64_t)m->flash_base + m->flash_bytes) return c->flash + (addr - m->flash_base);
    if ((uint64_t)addr + n <= m->flash_bytes) return c->flash + addr; /* the boot alias at 0 */
    if (addr >= m->sram_base && (uint64_t)addr + n <= (uint64_t)m->sram_base + m->sram_bytes) return c->sram + (addr - m->sram_base);
    return NULL;
}

/* Unicorn 2.0.1 completes a store into a read-only mapping after the hook
 * that handled it: the FLASH controller's result is put back before the
 * next access, block or return (and translations of those bytes dropped). */
static void flash_fix_now(armcore_t *c)
{
    memcpy(c->flash + c->fix_off, c->fix, c->fix_n);
    uc_ctl_remove_cache(c->uc, c->fix_off, (uint64_t)c->fix_off + c->fix_n);
    uc_ctl_remove_cache(c->uc, c->mcu->flash_base + c->fix_off, (uint64_t)c->mcu->flash_base + c->fix_off + c->fix_n);
    c->fix_n = 0;
}

static inline void flash_fix(armcore_t *c)
{
    if (c->fix_n) flash_fix_now(c);
}

static uint32_t rd32(const uint8_t *p) { return (uint32_t)p[0] | (uint32_t)p[1] << 8 | (uint32_t)p[2] << 16 | (uint32_t)p[3] << 24; }
static void wr32(uint8_t *p, uint32_t v) { p[0] = (uint8_t)v, p[1] = (uint8_t)(v >> 8), p[2] = (uint8_t)(v >> 16), p[3] = (uint8_t)(v >> 24); }

/* Instructions starting in [addr, end): a halfword 0b11101, 0b11110 or 0b11111 in its top five bits opens a 32-bit one (A6.1). */
static uint32_t count_insns(armcore_t *c, uint32_t addr, uint32_t end)
{
    uint8_t tmp[BLK_BYTES_MAX];
    uint32_t size = end - addr;
    if (size > BLK_BYTES_MAX) size = BLK_BYTES_MAX;
    const uint8_t *p = host(c, addr, size);
    if (!p) {
        if (uc_mem_read(c->uc, addr, tmp, size) != UC_ERR_OK) return size / 2;
        p = tmp;
    }
    uint32_t n = 0;
    for (uint32_t i = 0; i + 2 <= size; n++) i += ((p[i + 1] >> 3) >= 0x1D) ? 4u : 2u;
    return n;
}

static inline blk_t *block_of(armcore_t *c, uint32_t addr, uint32_t size)
{
    blk_t *b = &c->blk[(addr >> 1) & (BLK_CACHE - 1)];
    if (b->addr != addr || b->size != size) {
        memset(b, 0, sizeof *b);
        b->addr = addr, b->size = size, b->n = count_insns(c, addr, addr + size), b->seen_gen = UINT64_MAX;
    }
    return b;
}

static uint32_t block_insns(armcore_t *c, uint32_t addr, uint32_t size) { return block_of(c, addr, size)->n; }

/* The address of instruction k of the block at addr. */
static uint32_t insn_addr(armcore_t *c, uint32_t addr, uint32_t k)
{
    const uint8_t *p = host(c, addr, 4u * k + 4u);
    uint32_t a = addr;
    for (uint32_t i = 0; i < k; i++) {
        uint8_t hi;
        if (p) hi = p[a - addr + 1];
        else if (uc_mem_read(c->uc, a + 1, &hi, 1) != UC_ERR_OK) hi = 0;
        a += (hi >> 3) >= 0x1D ? 4u : 2u;
    }
    return a;
}

static uint32_t reg(armcore_t *c, int r) { uint32_t v = 0; uc_reg_read(c->uc, r, &v); return v; }
static void set_reg(armcore_t *c, int r, uint32_t v) { uc_reg_write(c->uc, r, &v); }

/* n registers in one call (an exception's entry and return read and write a dozen) */
static void regs_read(armcore_t *c, const int *r, uint32_t *v, int n)
{
    void *p[20];
    for (int i = 0; i < n; i++) p[i] = &v[i], v[i] = 0;
    uc_reg_read_batch(c->uc, (int *)r, p, n);
}

static void regs_write(armcore_t *c, const int *r, const uint32_t *v, int n)
{
    void *p[20];
    for (int i = 0; i < n; i++) p[i] = (void *)&v[i];
    uc_reg_write_batch(c->uc, (int *)r, p, n);
}

/* The cycle an access is made at: its translated block's start. Unicorn
 * keeps the PC at the block's start until the block ends (it syncs it per
 * instruction only under a code hook, about 7 ns an instruction), so an
 * access sees the state of the cycle its block began at: two reads of
 * DWT CYCCNT in one block read the same count. A split's remainder keeps
 * its block's start, so the cycle never depends on the chunking. */
static uint64_t access_cycle(const armcore_t *c) { return c->nat_start; }

#define HFSR_FORCED (1u << 30) /* B3.2.16: a fault escalated to HardFault */
#define HFSR_VECTTBL (1u << 1) /* a vector table read failed */

/* The run ends: the cause, then CFSR and HFSR decoded and the PC the frame would hold (what a HardFault handler reads). */
static void crash(armcore_t *c, uint32_t pc, const char *cause)
{
    if (c->crashed) return;
    char fsr[200];
    c->crashed = true, c->crash_pc = pc;
    cortexm_fault_text(&c->cm, fsr, sizeof fsr);
    snprintf(c->cause, sizeof c->cause, "%s (%s; stacked PC 0x%08x)", cause, fsr, pc);
}

/* A fault's status bits set as the hardware would (CFSR's, escalated to HardFault), then the crash. */
static void fault(armcore_t *c, uint32_t pc, uint32_t cfsr, uint32_t hfsr, const char *cause)
{
    c->cm.cfsr |= cfsr, c->cm.hfsr |= hfsr;
    crash(c, pc, cause);
}

/* ---- time ---- */
__extension__ typedef unsigned __int128 u128;

static uint64_t time_at(const armcore_t *c, uint64_t cyc)
{
    return c->seg_ps + (uint64_t)((u128)(cyc - c->seg_cycle) * ARMCORE_PS_PER_S / c->hclk);
}

/* the first cycle at or after time t (within the current clock's segment) */
static uint64_t cycle_at(const armcore_t *c, uint64_t t)
{
    if (t <= c->seg_ps) return c->seg_cycle;
    return c->seg_cycle + (uint64_t)(((u128)(t - c->seg_ps) * c->hclk + ARMCORE_PS_PER_S - 1) / ARMCORE_PS_PER_S);
}

/* RCC changed HCLK: a new segment from cycle c->now (the access that changed it, or the cycle a check runs at) */
static void clock_check(armcore_t *c)
{
    if (!c->clocks || !c->clocks->hclk || c->clocks->hclk == c->hclk) return;
    c->seg_ps = time_at(c, c->now), c->seg_cycle = c->now, c->hclk = c->clocks->hclk;
    if (c->target_ps != NO_TIME) c->target = cycle_at(c, c->target_ps);
}

/* ---- the bus ---- */
static void unmodeled(armcore_t *c, uint32_t addr, const mmio_region_t *r, bool write)
{
    int i = 0;
    while (i < c->nunm && c->unm[i].addr != addr) i++;
    if (i == c->nunm) {
        if (c->nunm == ARMCORE_UNMODELED_MAX) return; /* the list is full: the first ones are kept */
        c->nunm++;
        memset(&c->unm[i], 0, sizeof c->unm[i]);
        c->unm[i].addr = addr;
        snprintf(c->unm[i].region, sizeof c->unm[i].region, "%s", r ? r->ops->name : "");
        if (c->verbose)
            fprintf(stderr, "mmsim: the firmware %s 0x%08x (%s), a register not modeled (pc 0x%08x)\n", write ? "writes" : "reads",
                    addr, r ? r->ops->name : "no peripheral modeled there", reg(c, UC_ARM_REG_PC));
    }
    if (write) c->unm[i].writes++;
    else c->unm[i].reads++;
}

/* The region at addr: the last one found (a polling loop reads one peripheral), else a binary search. */
static mmio_region_t *region_at(armcore_t *c, uint32_t addr)
{
    mmio_region_t *r = c->last_reg;
    if (r && addr - r->base < r->size) return r;
    int lo = 0, hi = c->nreg - 1;
    while (lo <= hi) {
        int mid = (lo + hi) / 2;
        r = &c->reg[mid];
        if (addr < r->base) hi = mid - 1;
        else if (addr - r->base >= r->size) lo = mid + 1;
        else return c->last_reg = r;
    }
    return NULL;
}

/* Model r accessed or advanced: its next event asked again at the next check; every model's when the SoC
 * does not report the models' effects on each other. */
static inline void touched(armcore_t *c, const mmio_region_t *r)
{
    unsigned i = (unsigned)(r - c->reg);
    if (c->links) c->dirty[i / 64] |= 1ull << (i % 64);
    else c->all_dirty = true;
}

/* One access to a peripheral at cycle c->now: MMIO_BUS_FAULT, or OK (an unmodeled register listed, read as 0). */
static mmio_status_t periph(armcore_t *c, uint32_t addr, unsigned size, bool write, uint32_t *v)
{
    mmio_region_t *r = region_at(c, addr);
    mmio_status_t s = MMIO_UNMODELED;
    c->cm.attention = true; /* a model may have changed its next event or a line */
    if (r) {
        touched(c, r);
        if (r->ops->advance) r->ops->advance(r->self, c->now);
        s = write ? (r->ops->write ? r->ops->write(r->self, addr - r->base, size, *v) : MMIO_UNMODELED)
                  : (r->ops->read ? r->ops->read(r->self, addr - r->base, size, v) : MMIO_UNMODELED);
    }
    if (write) clock_check(c); /* RCC's write switching HCLK: the new clock from this access's cycle */
    if (s == MMIO_UNMODELED) {
        unmodeled(c, addr, r, write);
        if (!write) *v = 0;
        return MMIO_OK;
    }
    return s;
}

/* The bit-band alias (one bit of a word) or the word itself. */
static mmio_status_t periph_or_bb(armcore_t *c, uint32_t addr, unsigned size, bool write, uint32_t *v)
{
    if (addr < PERIPH_BB_BASE || addr >= PERIPH_BB_BASE + BB_ALIAS_BYTES) return periph(c, addr, size, write, v);
    uint32_t off = addr - PERIPH_BB_BASE, byte = PERIPH_BASE + off / 32, bit = (off % 32) / 4 + 8 * (byte & 3u), w = 0;
    mmio_status_t s = periph(c, byte & ~3u, 4, false, &w);
    if (s != MMIO_OK || !write) return *v = (w >> bit) & 1u, s;
    w = (*v & 1u) ? w | 1u << bit : w & ~(1u << bit);
    return periph(c, byte & ~3u, 4, true, &w);
}

static void bus_fault(armcore_t *c, uint32_t addr, bool write)
{
    char m[120];
    c->cm.bfar = addr, c->cm.cfsr |= 0x8200u; /* BFARVALID, PRECISERR (B3.2.15) */
    c->cm.hfsr |= 1u << 30;                    /* FORCED: escalated to HardFault */
    snprintf(m, sizeof m, "HardFault: precise bus fault %s 0x%08x", write ? "writing" : "reading", addr);
    crash(c, reg(c, UC_ARM_REG_PC), m);
    c->stop = STOP_FAULT;
    uc_emu_stop(c->uc);
}

/* A probe (see skip_loop) reads only registers that are functions of time, or gives up for good. */
static bool probe_access(armcore_t *c, uint32_t addr, bool write)
{
    if (!write && (addr == DWT_CYCCNT_ADDR || addr == SYST_CVR_ADDR)) return c->probe_timed = true;
    if (!write && addr == SYST_CSR_ADDR) return true; /* COUNTFLAG is set only at a wrap: a model event */
    c->probe_res = PROBE_NEVER;
    uc_emu_stop(c->uc);
    return false;
}

static uint64_t mmio_read(armcore_t *c, uint32_t addr, unsigned size)
{
    uint32_t v = 0;
    c->rec_gen++;
    if (c->probe && !probe_access(c, addr, false)) return 0;
    flash_fix(c);
    c->now = access_cycle(c);
    if (periph_or_bb(c, addr, size, false, &v) != MMIO_OK) bus_fault(c, addr, false);
    return v;
}

static void mmio_write(armcore_t *c, uint32_t addr, unsigned size, uint32_t v)
{
    c->rec_gen++;
    if (c->probe && !probe_access(c, addr, true)) return;
    flash_fix(c);
    c->now = access_cycle(c);
    if (periph_or_bb(c, addr, size, true, &v) != MMIO_OK) bus_fault(c, addr, true);
}

/* The device electronic signature (RM0008 30, RM0090 39): the flash size in KiB and a fixed 96-bit unique ID (ours:
 * the bytes 0x01..0x0C), read-only; the rest of its 4 KiB page (the system memory's boot loader, the option bytes,
 * OTP) is not modeled: listed, read as 0. */
#define SIG_PAGE_BYTES 0x1000u
static uint32_t sig_page(const armimage_mcu_t *m) { return m->fsize_addr & ~(SIG_PAGE_BYTES - 1u); }

static uint64_t on_sig_read(uc_engine *uc, uint64_t off, unsigned size, void *u)
{
    armcore_t *c = u;
    uint32_t addr = sig_page(c->mcu) + (uint32_t)off, v = 0;
    for (unsigned i = 0; i < size; i++) {
        uint32_t a = addr + i, b;
        if (a - c->mcu->fsize_addr < 2) b = ((c->mcu->flash_bytes >> 10) >> (8 * (a - c->mcu->fsize_addr))) & 0xFFu;
        else if (a - c->mcu->uid_addr < 12) b = a - c->mcu->uid_addr + 1;
        else return unmodeled(c, addr, NULL, false), 0;
        v |= b << (8 * i);
    }
    return v;
}
static void on_sig_write(uc_engine *uc, uint64_t off, unsigned size, uint64_t v, void *u)
{
    armcore_t *c = u;
    unmodeled(c, sig_page(c->mcu) + (uint32_t)off, NULL, true); /* read-only memory: the write is lost */
}

static uint64_t on_periph_read(uc_engine *uc, uint64_t off, unsigned size, void *u) { return mmio_read(u, PERIPH_BASE + (uint32_t)off, size); }
static void on_periph_write(uc_engine *uc, uint64_t off, unsigned size, uint64_t v, void *u) { mmio_write(u, PERIPH_BASE + (uint32_t)off, size, (uint32_t)v); }
static uint64_t on_ppb_read(uc_engine *uc, uint64_t off, unsigned size, void *u) { return mmio_read(u, CORTEXM_PPB_BASE + (uint32_t)off, size); }
static void on_ppb_write(uc_engine *uc, uint64_t off, unsigned size, uint64_t v, void *u) { mmio_write(u, CORTEXM_PPB_BASE + (uint32_t)off, size, (uint32_t)v); }

/* SRAM's bit-band alias: bit (off % 32) / 4 of byte off / 32 */
static uint64_t on_sram_bb_read(uc_engine *uc, uint64_t off, unsigned size, void *u)
{
    armcore_t *c = u;
    uint32_t byte = (uint32_t)off / 32;
    if (byte >= c->mcu->sram_bytes) return bus_fault(c, SRAM_BB_BASE + (uint32_t)off, false), 0;
    return (c->sram[byte] >> ((off % 32) / 4)) & 1u;
}

static void on_sram_bb_write(uc_engine *uc, uint64_t off, unsigned size, uint64_t v, void *u)
{
    armcore_t *c = u;
    uint32_t byte = (uint32_t)off / 32, bit = ((uint32_t)off % 32) / 4;
    if (byte >= c->mcu->sram_bytes) { bus_fault(c, SRAM_BB_BASE + (uint32_t)off, true); return; }
    c->sram[byte] = (uint8_t)((v & 1u) ? c->sram[byte] | 1u << bit : c->sram[byte] & ~(1u << bit));
}

/* The DMA's bus: memory and peripherals at the cycle the core is at. */
static bool dma_read(void *ctx, uint32_t addr, unsigned size, uint32_t *v)
{
    armcore_t *c = ctx;
    uint8_t *p = host(c, addr, size);
    if (p) { *v = size == 4 ? rd32(p) : size == 2 ? (uint32_t)p[0] | (uint32_t)p[1] << 8 : p[0]; return true; }
    if (addr >= PERIPH_BASE && addr - PERIPH_BASE < PERIPH_BYTES) return periph(c, addr, size, false, v) == MMIO_OK;
    return false;
}

static bool dma_write(void *ctx, uint32_t addr, unsigned size, uint32_t v)
{
    armcore_t *c = ctx;
    const armimage_mcu_t *m = c->mcu;
    if (addr >= m->sram_base && (uint64_t)addr + size <= (uint64_t)m->sram_base + m->sram_bytes) {
        for (unsigned i = 0; i < size; i++) c->sram[addr - m->sram_base + i] = (uint8_t)(v >> (8 * i));
        return true;
    }
    if (addr >= PERIPH_BASE && addr - PERIPH_BASE < PERIPH_BYTES) return periph(c, addr, size, true, &v) == MMIO_OK;
    return false; /* flash is written through the FLASH controller only */
}

/* ---- events and exceptions to take ---- */
/* Model i asked its next event again, and brought to the current cycle if it is due. */
static void ask(armcore_t *c, int i, bool *all)
{
    mmio_region_t *r = &c->reg[i];
    uint64_t e = MMIO_NEVER;
    c->dirty[i / 64] &= ~(1ull << (i % 64));
    if (r->ops->next_event) e = r->ops->next_event(r->self);
    if (e <= c->cyc && r->ops->advance) {
        r->ops->advance(r->self, c->cyc), e = r->ops->next_event(r->self);
        if (!c->links) *all = c->all_dirty = true; /* its effects on the others unknown: ask them all, now and at the next check */
    }
    c->nev[i] = e;
}

/* The first dirty model after i (c->nreg if none). */
static int next_dirty(const armcore_t *c, int i)
{
    for (int w = (i + 1) / 64; w * 64 < c->nreg; w++) {
        uint64_t m = c->dirty[w] & (~0ull << ((i + 1) % 64 * (w == (i + 1) / 64)));
        if (m) return w * 64 + __builtin_ctzll(m);
    }
    return c->nreg;
}

/* Every model whose event is due brought to the current cycle; the next event found. The models are
 * taken in address order and each one's next event asked once, as if every one were asked at every
 * check: one a later model's event changes is seen at the next check. A model's next event changes only
 * when it is accessed, advanced, or changed by another (the SoC's armcore_touch) or by the host between
 * runs, so the others' are kept from the last time they were asked (nev): when none is due, only the
 * dirty ones are asked. */
static void advance_due(armcore_t *c)
{
    bool all = c->all_dirty, every = all || c->cyc >= c->ev_next, rescan = every;
    uint64_t next = c->ev_next;
    c->now = c->cyc, c->nat_start = c->cyc, c->all_dirty = false;
    for (int i = every ? 0 : next_dirty(c, -1); i < c->nreg; i = every || c->all_dirty ? i + 1 : next_dirty(c, i)) {
        if (!all && !c->all_dirty && !(c->dirty[i / 64] >> (i % 64) & 1u) && c->nev[i] > c->cyc) continue;
        rescan |= c->nev[i] == c->ev_next; /* the earliest one may have moved later: look at them all */
        ask(c, i, &all);
        next = c->nev[i] < next ? c->nev[i] : next;
    }
    if (rescan || all) {
        next = MMIO_NEVER;
        for (int i = 0; i < c->nreg; i++) next = c->nev[i] < next ? c->nev[i] : next;
    }
    c->ev_next = next;
}

static int exec_prio(armcore_t *c)
{
    static const int masks[] = { UC_ARM_REG_PRIMASK, UC_ARM_REG_BASEPRI, UC_ARM_REG_FAULTMASK };
    uint32_t v[3];
    regs_read(c, masks, v, 3);
    return cortexm_exec_prio(&c->cm, v[0], v[1], v[2]);
}

/* At a block's start: events due, then the exception to take now, 0 if none. */
static unsigned check(armcore_t *c)
{
    c->cm.attention = false, c->never_head = NO_ADDR;
    c->now = c->cyc;
    clock_check(c);
    advance_due(c);
    if (c->cm.reset_request) return EXC_RESET;
    int group;
    unsigned best = cortexm_best(&c->cm, &group);
    if (!best) return 0;
    if (group < exec_prio(c)) return best;
    c->cm.attention = true; /* pending but masked: look again at each block (CPSIE and MSR end a block) */
    return 0;
}

/* ---- idle loops ----
 * A wait loop is a cycle of at most LOOP_BLOCKS_MAX translated blocks run
 * twice in a row, whose instructions (thumbuse.c) store nothing and whose
 * registers read before written in an iteration are never written in it:
 * every iteration starts from the same values, and what it reads is RAM or
 * flash (unchanged: nothing stores until the next event), SysTick CSR
 * (COUNTFLAG only changes at a wrap, an event), or DWT CYCCNT and SysTick
 * CVR (functions of the cycle). Whether iteration j exits is then a function
 * of its start cycle alone, found by probes (skip_loop): the iteration run
 * from the head's saved state at that cycle, the registers and the system
 * peripherals restored after. The core then starts the iteration before the
 * first that exits (or before the next event or the target) at its exact
 * cycle and runs it and the rest for real, so the state the firmware sees
 * is the one it would have had. */

/* The path from the head of a loop whose blocks were just run twice (hist), or 0. */
static uint32_t loop_period(const armcore_t *c)
{
    for (uint32_t p = 1; p <= LOOP_BLOCKS_MAX && 2 * p + 1 <= c->hist_n; p++) {
        uint32_t k = 0;
        for (; k <= p; k++) {
            unsigned a = (c->hist_pos - 1 - k) % LOOP_HIST, b = (c->hist_pos - 1 - k - p) % LOOP_HIST;
            if (c->hist_addr[a] != c->hist_addr[b] || c->hist_size[a] != c->hist_size[b]) break;
        }
        if (k > p) return p;
    }
    return 0;
}

/* LOOP_PURE if every iteration starts from the same registers and stores nothing (see above), else LOOP_NEVER. */
static int loop_analyse(armcore_t *c, loop_t *l)
{
    uint32_t live_in = 0, written = 0;
    l->n = 0;
    for (uint32_t b = 0; b < l->p; b++) {
        const uint8_t *p = host(c, l->addr[b], l->size[b]);
        if (!p) return LOOP_NEVER;
        for (uint32_t i = 0; i + 2 <= l->size[b];) {
            thumb_use_t u;
            uint16_t h1 = (uint16_t)(p[i] | p[i + 1] << 8), h2 = i + 4 <= l->size[b] ? (uint16_t)(p[i + 2] | p[i + 3] << 8) : 0;
            if (thumb_use(h1, h2, &u) != THUMB_OK || i + u.len > l->size[b]) return LOOP_NEVER;
            live_in |= u.rd & ~written, written |= u.wr, l->bits |= u.bits != 0;
            i += u.len;
        }
        l->n += block_insns(c, l->addr[b], l->size[b]);
    }
    l->written = written & ~(1u << 15);
    return (live_in & written & ~(1u << 15)) || l->n == 0 ? LOOP_NEVER : LOOP_PURE;
}

/* At an untouched block's start: true if it heads a wait loop worth a skip (c->skip set). */
static bool idle_loop(armcore_t *c, uint32_t addr, uint32_t size)
{
    c->hist_addr[c->hist_pos % LOOP_HIST] = addr, c->hist_size[c->hist_pos % LOOP_HIST] = size;
    c->hist_pos++, c->hist_n += c->hist_n < LOOP_HIST;
    if (addr == c->never_head) return false;
    uint32_t p = loop_period(c);
    if (!p) return false;
    loop_t *l = &c->loops[(addr >> 1) % LOOP_CACHE];
    bool same = l->head == addr && l->p == p;
    for (uint32_t b = 0; same && b < p; b++) {
        unsigned h = (c->hist_pos - 1 - p + b) % LOOP_HIST;
        same = l->addr[b] == c->hist_addr[h] && l->size[b] == c->hist_size[h];
    }
    if (!same) {
        memset(l, 0, sizeof *l);
        l->head = addr, l->p = p;
        for (uint32_t b = 0; b < p; b++) {
            unsigned h = (c->hist_pos - 1 - p + b) % LOOP_HIST;
            l->addr[b] = c->hist_addr[h], l->size[b] = c->hist_size[h];
        }
        l->verdict = loop_analyse(c, l);
    }
    if (l->verdict != LOOP_PURE) c->never_head = addr;
    uint64_t end = c->ev_next < c->target ? c->ev_next : c->target;
    if (l->verdict != LOOP_PURE || c->cyc < l->retry_at || end < c->cyc || (end - c->cyc) / l->n < LOOP_SKIP_MIN) return false;
    c->skip = l;
    c->hist_pos--, c->hist_n--; /* the head runs again after the skip */
    return true;
}

/* ---- recurring states ----
 * The core is a deterministic machine: from the same registers and SRAM, with
 * no peripheral access and no exception, it runs the same instructions in the
 * same cycles. So when a block starts in the state an earlier start of the
 * same block had, and nothing of that kind happened between them (one
 * emulation run, c->rec_gen unchanged: every peripheral or PPB access, store
 * into flash, emulation start or stop counts), the state recurs with that
 * period until the next model event or the target: the core jumps by whole
 * periods to the last start of the block before them, with the state it has
 * now, which is what running them would leave. A model event between the two
 * starts does not break this: it ran at its block start as in any run, took
 * no exception (that stops the emulation), and what it wrote into SRAM (a
 * DMA) is in the comparison; none falls inside the periods jumped. Nothing may
 * be pending at the jump: one pending but masked would be taken at a CPSIE
 * or MSR inside the periods (a critical section in the loop). This covers wait
 * loops of any shape: calls, pushes and pops, stores of values already there,
 * soft-float arithmetic on RAM an interrupt changes (bulebule's
 * target_straight: its state recurs from the second iteration after each
 * interrupt). A snapshot (the registers, FP ones included, and the SRAM) is
 * taken at a block started twice in one stretch REC_PERIOD_MIN to
 * REC_PERIOD_MAX cycles apart, at most REC_TRIES times per block and
 * stretch, and compared at its next start. A stated limit: the Thumb IT
 * state is in the translated block's flags, not in the registers read, so two
 * starts of a block inside an IT block and outside it would compare equal;
 * blocks start inside an IT block only where a stop split one, and a split's
 * remainder is never a snapshot's block. */
static const int rec_reg_ids[REC_REGS] = { UC_ARM_REG_R0, UC_ARM_REG_R1, UC_ARM_REG_R2, UC_ARM_REG_R3, UC_ARM_REG_R4,
    UC_ARM_REG_R5, UC_ARM_REG_R6, UC_ARM_REG_R7, UC_ARM_REG_R8, UC_ARM_REG_R9, UC_ARM_REG_R10, UC_ARM_REG_R11, UC_ARM_REG_R12,
    UC_ARM_REG_SP, UC_ARM_REG_LR, UC_ARM_REG_XPSR, UC_ARM_REG_MSP, UC_ARM_REG_PSP, UC_ARM_REG_CONTROL, UC_ARM_REG_PRIMASK,
    UC_ARM_REG_BASEPRI, UC_ARM_REG_FAULTMASK };

/* The registers a recurrence compares into v (as 64-bit values: D0-D15 are), their count. */
static int rec_read(armcore_t *c, uint64_t *v)
{
    int ids[REC_REGS + REC_FP_REGS], n = REC_REGS;
    void *p[REC_REGS + REC_FP_REGS];
    memcpy(ids, rec_reg_ids, sizeof rec_reg_ids);
    if (c->mcu->fpu) {
        for (int i = 0; i < 16; i++) ids[n++] = UC_ARM_REG_D0 + i;
        ids[n++] = UC_ARM_REG_FPSCR;
    }
    for (int i = 0; i < n; i++) v[i] = 0, p[i] = &v[i];
    uc_reg_read_batch(c->uc, ids, p, n);
    return n;
}

/* At block b's start, where the snapshot was taken: true if the state recurs (c->rec_land: the cycle to jump to). */
static bool recur_compare(armcore_t *c, blk_t *b)
{
    uint64_t end = c->ev_next < c->target ? c->ev_next : c->target, v[REC_REGS + REC_FP_REGS];
    if (c->rec_at_gen != c->rec_gen) return false; /* disturbed since */
    uint64_t p = c->cyc - c->rec_cyc, m = end > c->cyc ? (end - c->cyc) / p : 0;
    int n = rec_read(c, v);
    c->rec_head = NO_ADDR;
    if (!memcmp(v, c->rec_regs, (size_t)n * sizeof *v) && !memcmp(c->sram, c->rec_sram, c->mcu->sram_bytes)) {
        b->fails = 0;
        if (!m || cortexm_best(&c->cm, NULL)) return false; /* one pending, masked: a CPSIE in the periods would take it */
        c->rec_land = c->cyc + m * p;
        c->st.recur_skips++, c->st.recur_cycles += m * p;
        c->st.loop_skips++, c->st.loop_cycles += m * p;
        return true;
    }
    if (++b->fails >= REC_FAILS_BAN) /* left alone for REC_PERIOD_MAX x 2^k cycles, k growing with the fails */
        b->ban_until = c->cyc + ((uint64_t)REC_PERIOD_MAX << (b->fails - REC_FAILS_BAN < 10 ? b->fails - REC_FAILS_BAN : 10));
    return false;
}

/* Block b started again p cycles after its last start, as the time before: a snapshot here if it is worth one. */
static void recur_snapshot(armcore_t *c, blk_t *b, uint64_t p)
{
    uint64_t end = c->ev_next < c->target ? c->ev_next : c->target;
    if (c->rec_tries_gen != c->rec_gen) c->rec_tries_gen = c->rec_gen, c->rec_tries = 0;
    if ((c->rec_head != NO_ADDR && c->rec_at_gen == c->rec_gen) || c->cyc < b->ban_until || p < REC_PERIOD_MIN || p > REC_PERIOD_MAX
        || b->tries >= REC_TRIES || c->rec_tries >= REC_STRETCH_TRIES || end <= c->cyc || (end - c->cyc) / p < REC_AHEAD_MIN)
        return;
    b->tries++, c->rec_tries++;
    c->rec_head = b->addr, c->rec_cyc = c->cyc, c->rec_at_gen = c->rec_gen;
    rec_read(c, c->rec_regs);
    memcpy(c->rec_sram, c->sram, c->mcu->sram_bytes);
    c->st.recur_snapshots++;
}

/* At an untouched block's start: true if the state recurs here (c->rec_land set), else the block's starts noted
 * (at every block: inline, the rest out of line). */
static inline bool recur(armcore_t *c, blk_t *b)
{
    if (c->rec_head == b->addr && recur_compare(c, b)) return true;
    if (b->seen_gen != c->rec_gen) { /* its first start in this stretch */
        b->seen_gen = c->rec_gen, b->tries = 0, b->seen_cyc = c->cyc;
        return false;
    }
    uint64_t p = c->cyc - b->seen_cyc;
    bool steady = p == b->last_p; /* a loop's head: started at the same interval twice (a subroutine's block called twice an iteration is not) */
    b->last_p = p > UINT32_MAX ? UINT32_MAX : (uint32_t)p, b->seen_cyc = c->cyc;
    if (steady) recur_snapshot(c, b, p);
    return false;
}

/* A block in a probe: the loop's next one, or the exit (the block not run), or back at the head. */
static void probe_block(armcore_t *c, uint32_t addr, uint32_t size, uint32_t n)
{
    const loop_t *l = c->skip;
    if (c->probe_idx == l->p || addr != l->addr[c->probe_idx] || size != l->size[c->probe_idx]) {
        bool head = addr == l->head && size == l->size[0];
        c->probe_res = c->probe_idx == 0 ? PROBE_AGAIN : c->probe_idx == l->p && head ? PROBE_STAYS : PROBE_EXITS;
        uc_emu_stop(c->uc);
        return;
    }
    c->nat_start = c->cyc, c->cyc += n, c->probe_idx++;
}

/* The debugger's stop in the block at addr: its first breakpoint's cycle, or halt_at; at most the target. */
static uint64_t debug_stop(armcore_t *c, uint32_t addr, uint32_t size)
{
    uint64_t at = c->halt_at < c->cyc ? c->cyc : c->halt_at;
    bool skip = c->brk_skip == addr;
    c->brk_skip = NO_ADDR;
    for (int i = 0; i < c->nbrk; i++) {
        uint32_t b = c->brk[i];
        if (b < addr || b - addr >= size || (skip && b == addr)) continue;
        uint64_t k = c->cyc + (b == addr ? 0u : count_insns(c, addr, b));
        if (k < c->brk_cyc) c->brk_cyc = k;
    }
    if (c->brk_cyc < at) at = c->brk_cyc;
    return at < c->target ? at : c->target;
}

static void on_block(uc_engine *uc, uint64_t address, uint32_t size, void *u)
{
    armcore_t *c = u;
    flash_fix(c);
    uint32_t addr = (uint32_t)address;
    blk_t *bk = block_of(c, addr, size);
    uint32_t n = bk->n;
    if (c->probe) { if (c->probe_res == PROBE_RUNNING) probe_block(c, addr, size, n); return; }
    c->blk_addr = addr, c->blk_size = size, c->blk_start = c->cyc;
    if (c->partial || c->stop != STOP_NONE) return;
    c->brk_cyc = NO_TIME;
    c->stop_mid = addr == c->resume_mid;
    if (c->stop_mid) {
        c->resume_mid = NO_ADDR;
        c->hist_n = 0;
    } else {
        c->nat_start = c->cyc;
    }
    if (!c->stop_mid && (c->cm.attention || c->cyc >= c->ev_next)) {
        unsigned e = check(c);
        if (e) { c->take = e, c->stop = STOP_TAKE, c->stop_addr = addr; uc_emu_stop(uc); return; }
    }
    uint64_t stop_at = c->nbrk || c->halt_at != NO_TIME ? debug_stop(c, addr, size) : c->target;
    if (c->nbrk || stop_at != c->target) c->hist_n = 0; /* no wait loop jumped over while gdb may stop inside it */
    else if (!c->stop_mid && !c->no_idle_skip && recur(c, bk)) { c->stop = STOP_RECUR, c->stop_addr = addr; uc_emu_stop(uc); return; }
    else if (!c->stop_mid && !c->no_idle_skip && idle_loop(c, addr, size)) { c->stop = STOP_SKIP, c->stop_addr = addr; uc_emu_stop(uc); return; }
    if (c->cyc + n > stop_at) { c->stop = STOP_SPLIT, c->stop_addr = addr, c->split_to = stop_at; uc_emu_stop(uc); return; }
    c->cyc += n;
}

static void on_intr(uc_engine *uc, uint32_t intno, void *u)
{
    armcore_t *c = u;
    if (c->probe) { c->probe_res = PROBE_NEVER; uc_emu_stop(uc); return; }
    if (c->stop != STOP_NONE) return;
    c->stop = STOP_INTR, c->intno = (int)intno;
    uc_emu_stop(uc);
}

static bool on_bad_mem(uc_engine *uc, uc_mem_type type, uint64_t addr, int size, int64_t value, void *u)
{
    armcore_t *c = u;
    if (c->probe) { c->probe_res = PROBE_NEVER; return false; }
    c->rec_gen++;
    const armimage_mcu_t *m = c->mcu;
    uint32_t a = (uint32_t)addr, n = (uint32_t)size;
    if (type == UC_MEM_WRITE_PROT && c->flash_write && n <= 4 && host(c, a, n) && a < m->sram_base) {
        uint32_t off = a >= m->flash_base ? a - m->flash_base : a;
        c->now = access_cycle(c);
        flash_fix(c);
        mmio_status_t s = c->flash_write(c->flash_ctx, off, n, (uint32_t)value, c->now);
        if (s == MMIO_UNMODELED) unmodeled(c, a, NULL, true);
        if (s != MMIO_BUS_FAULT) {
            c->cm.attention = true, c->all_dirty = true; /* the controller's next event (BSY's end) moved */
            memcpy(c->fix, c->flash + off, n), c->fix_off = off, c->fix_n = n;
            return true;
        }
    }
    c->bad_addr = a, c->bad_type = (int)type;
    return false;
}

/* ---- exception entry and return (ARMv7-M B1.5.6-B1.5.8), done by the host ---- */
static bool mem_rw(armcore_t *c, uint32_t addr, uint8_t *buf, uint32_t n, bool write)
{
    const armimage_mcu_t *m = c->mcu;
    if (addr < m->sram_base || (uint64_t)addr + n > (uint64_t)m->sram_base + m->sram_bytes) return false; /* a frame lives in SRAM */
    if (write) memcpy(c->sram + (addr - m->sram_base), buf, n);
    else memcpy(buf, c->sram + (addr - m->sram_base), n);
    return true;
}

/* IPSR written, then APSR_NZCV once more: unicorn's translator otherwise keeps the old mode (platform facts) */
static void set_ipsr(armcore_t *c, uint32_t ipsr, uint32_t apsr)
{
    set_reg(c, UC_ARM_REG_IPSR, ipsr);
    set_reg(c, UC_ARM_REG_APSR, apsr);
    set_reg(c, UC_ARM_REG_APSR_NZCV, apsr);
}

static bool vector(armcore_t *c, unsigned exc, uint32_t *pc)
{
    char m[120];
    uint32_t at = c->cm.vtor + 4u * exc;
    const uint8_t *p = host(c, at, 4);
    if (!p) return snprintf(m, sizeof m, "HardFault: vector %u at 0x%08x is outside flash and SRAM (VTOR 0x%08x)", exc, at, c->cm.vtor),
                  fault(c, c->pc, 0, HFSR_VECTTBL, m), false;
    *pc = rd32(p);
    if (!(*pc & 1u))
        return snprintf(m, sizeof m, "HardFault: vector %u (0x%08x) has no Thumb bit: UsageFault INVSTATE", exc, *pc),
               fault(c, c->pc, 0x20000u, HFSR_FORCED, m),
               false;
    return true;
}

static const char *exc_name(unsigned exc)
{
    static const char *const names[] = { "", "Reset", "NMI", "HardFault", "MemManage", "BusFault", "UsageFault" };
    return exc < 7 ? names[exc] : "exception";
}

/* S0-S15 (as D0-D7: S2n the low word of Dn) and FPSCR into or out of an extended frame f at 0x20 and 0x60 (B1.5.7). */
static void fp_save(armcore_t *c, uint8_t *f)
{
    static const int rd[] = { UC_ARM_REG_D0, UC_ARM_REG_D1, UC_ARM_REG_D2, UC_ARM_REG_D3, UC_ARM_REG_D4, UC_ARM_REG_D5,
                              UC_ARM_REG_D6, UC_ARM_REG_D7, UC_ARM_REG_FPSCR };
    uint64_t d[8] = { 0 };
    uint32_t fpscr = 0;
    void *p[9];
    for (int i = 0; i < 8; i++) p[i] = &d[i];
    p[8] = &fpscr;
    uc_reg_read_batch(c->uc, (int *)rd, p, 9);
    for (int i = 0; i < 8; i++) wr32(f + 32 + 8 * i, (uint32_t)d[i]), wr32(f + 36 + 8 * i, (uint32_t)(d[i] >> 32));
    wr32(f + 0x60, fpscr), wr32(f + 0x64, 0);
}

static void fp_load(armcore_t *c, const uint8_t *f)
{
    for (int i = 0; i < 8; i++) {
        uint64_t d = (uint64_t)rd32(f + 36 + 8 * i) << 32 | rd32(f + 32 + 8 * i);
        uc_reg_write(c->uc, UC_ARM_REG_D0 + i, &d);
    }
    set_reg(c, UC_ARM_REG_FPSCR, rd32(f + 0x60));
}

/* Exception exc taken with ret the address to return to: the frame pushed (the extended one when CONTROL.FPCA on an
 * FPU: its S0-S15 and FPSCR saved at entry, see fp_save), LR = EXC_RETURN, the handler's PC. */
static void enter(armcore_t *c, unsigned exc, uint32_t ret)
{
    static const int rd[] = { UC_ARM_REG_R0, UC_ARM_REG_R1, UC_ARM_REG_R2, UC_ARM_REG_R3, UC_ARM_REG_R12, UC_ARM_REG_LR,
                              UC_ARM_REG_IPSR, UC_ARM_REG_CONTROL, UC_ARM_REG_APSR, UC_ARM_REG_PSP, UC_ARM_REG_MSP };
    uint32_t v[11], handler_pc;
    regs_read(c, rd, v, 11);
    uint32_t ipsr = v[6] & 0x1FFu, ctrl = v[7], apsr = v[8];
    bool psp = !ipsr && (ctrl & CONTROL_SPSEL), fp = c->mcu->fpu && (ctrl & CONTROL_FPCA);
    uint32_t sp = psp ? v[9] : v[10], xpsr = (apsr & 0xF80F0000u) | XPSR_T | ipsr, size = fp ? FP_FRAME_BYTES : BASIC_FRAME_BYTES;
    if ((fp || (c->cm.ccr & CCR_STKALIGN)) && (sp & 4u)) sp -= 4, xpsr |= XPSR_ALIGN; /* an extended frame is always aligned */
    sp -= size;
    uint8_t f[FP_FRAME_BYTES];
    for (int i = 0; i < 6; i++) wr32(f + 4 * i, v[i]);
    wr32(f + 24, ret), wr32(f + 28, xpsr);
    if (fp) fp_save(c, f), c->cm.fpcar = sp + BASIC_FRAME_BYTES;
    if (exc >= EXC_HARDFAULT && exc <= EXC_USAGEFAULT) {
        char m[120];
        snprintf(m, sizeof m, "%s taken", exc_name(exc));
        crash(c, ret, m);
        return;
    }
    if (!mem_rw(c, sp, f, size, true)) {
        char m[120];
        snprintf(m, sizeof m, "HardFault: stacking for %s at SP 0x%08x outside SRAM (STKERR)", exc == EXC_SVCALL ? "SVCall" : "an exception", sp);
        fault(c, ret, 0x1000u, HFSR_FORCED, m); /* BFSR STKERR */
        return;
    }
    if (!vector(c, exc, &handler_pc)) return;
    if (psp) set_reg(c, UC_ARM_REG_PSP, sp);
    else set_reg(c, UC_ARM_REG_MSP, sp);
    if (psp || c->mcu->fpu) set_reg(c, UC_ARM_REG_CONTROL, ctrl & ~(CONTROL_SPSEL | CONTROL_FPCA)); /* B1.5.6: FPCA cleared */
    set_ipsr(c, exc, apsr);
    set_reg(c, UC_ARM_REG_LR, (ipsr ? 0xFFFFFFF1u : psp ? 0xFFFFFFFDu : 0xFFFFFFF9u) & ~(fp ? EXC_RETURN_BASIC : 0u));
    cortexm_take(&c->cm, exc);
    c->pc = handler_pc & ~1u;
    c->cyc += ARMCORE_EXC_ENTRY_CYCLES;
    c->st.exceptions++;
}

/* The frame popped per EXC_RETURN: to thread or handler mode, from MSP or PSP. */
static void unstack(armcore_t *c, uint32_t excret)
{
    bool psp = excret & 4u, thread = excret & 8u, fp = !(excret & EXC_RETURN_BASIC);
    uint32_t sp = reg(c, psp ? UC_ARM_REG_PSP : UC_ARM_REG_MSP), msp = reg(c, UC_ARM_REG_MSP), size = fp ? FP_FRAME_BYTES : BASIC_FRAME_BYTES;
    uint8_t f[FP_FRAME_BYTES];
    char m[120];
    if (!mem_rw(c, sp, f, size, false)) {
        snprintf(m, sizeof m, "HardFault: unstacking at SP 0x%08x outside SRAM (UNSTKERR)", sp);
        fault(c, c->pc, 0x800u, HFSR_FORCED, m);
        return;
    }
    uint32_t xpsr = rd32(f + 28), ret = rd32(f + 24), nsp = sp + size + ((xpsr & XPSR_ALIGN) ? 4u : 0u);
    if (!(xpsr & XPSR_T)) {
        snprintf(m, sizeof m, "HardFault: return to 0x%08x with the frame's Thumb bit clear (UsageFault INVSTATE)", ret);
        fault(c, ret, 0x20000u, HFSR_FORCED, m);
        return;
    }
    if (fp) fp_load(c, f);
    set_ipsr(c, thread ? 0 : (xpsr & 0x1FFu), xpsr);
    uint32_t ctrl = (reg(c, UC_ARM_REG_CONTROL) & ~CONTROL_FPCA) | (fp ? CONTROL_FPCA : 0u); /* B1.5.8: FPCA = NOT EXC_RETURN[4] */
    if (psp) {
        set_reg(c, UC_ARM_REG_MSP, msp);
        set_reg(c, UC_ARM_REG_CONTROL, ctrl | CONTROL_SPSEL);
        set_reg(c, UC_ARM_REG_PSP, nsp);
    } else {
        set_reg(c, UC_ARM_REG_MSP, nsp);
        if (c->mcu->fpu) set_reg(c, UC_ARM_REG_CONTROL, ctrl);
    }
    static const int wr[] = { UC_ARM_REG_R0, UC_ARM_REG_R1, UC_ARM_REG_R2, UC_ARM_REG_R3, UC_ARM_REG_R12, UC_ARM_REG_LR,
                              UC_ARM_REG_APSR, UC_ARM_REG_APSR_NZCV };
    uint32_t v[8];
    for (int i = 0; i < 6; i++) v[i] = rd32(f + 4 * i);
    v[6] = v[7] = xpsr;
    regs_write(c, wr, v, 8);
    c->pc = ret & ~1u;
    c->cyc += ARMCORE_EXC_EXIT_CYCLES;
}

/* bx to EXC_RETURN: the exception deactivated, then a tail-chain to a pending one or the frame popped. */
static void exc_return(armcore_t *c)
{
    uint32_t excret = reg(c, UC_ARM_REG_PC) | 1u, exc = reg(c, UC_ARM_REG_IPSR) & 0x1FFu;
    char m[120];
    uint32_t low = excret & 0xFu;
    bool fp_ok = c->mcu->fpu || (excret & EXC_RETURN_BASIC); /* an extended frame only with an FPU */
    if ((excret & 0xFFFFFFE0u) != 0xFFFFFFE0u || !fp_ok || (low != 1u && low != 9u && low != 0xDu) || cortexm_return(&c->cm, exc) != 0) {
        snprintf(m, sizeof m, "HardFault: exception return 0x%08x from exception %u (UsageFault INVPC)", excret, exc);
        fault(c, c->blk_addr, 0x40000u, HFSR_FORCED, m);
        return;
    }
    int group;
    unsigned next = cortexm_best(&c->cm, &group);
    if (next && group < exec_prio(c) && next != EXC_RESET) {
        uint32_t pc, apsr = reg(c, UC_ARM_REG_APSR);
        if (!vector(c, next, &pc)) return;
        if (c->mcu->fpu) set_reg(c, UC_ARM_REG_CONTROL, reg(c, UC_ARM_REG_CONTROL) & ~CONTROL_FPCA); /* a new handler: no FP context */
        set_ipsr(c, next, apsr);
        set_reg(c, UC_ARM_REG_LR, excret);
        cortexm_take(&c->cm, next);
        c->pc = pc & ~1u;
        c->cyc += ARMCORE_TAIL_CHAIN_CYCLES;
        c->st.exceptions++, c->st.tail_chains++;
        return;
    }
    unstack(c, excret);
}

/* ---- stops ---- */
static void on_stop_intr(armcore_t *c)
{
    char m[120];
    uint32_t pc = reg(c, UC_ARM_REG_PC);
    if (c->intno == EXC_RETURN_INTNO) { exc_return(c); return; }
    if (c->intno == 2) { /* SVC: PC is past it; SVCall at its priority or escalated to HardFault */
        c->pc = pc;
        if (cortexm_group(&c->cm, cortexm_prio(&c->cm, EXC_SVCALL)) < exec_prio(c)) {
            cortexm_pend(&c->cm, EXC_SVCALL);
            cortexm_best(&c->cm, NULL);
            enter(c, EXC_SVCALL, pc);
            return;
        }
        c->cm.hfsr |= 1u << 30;
        crash(c, pc - 2, "HardFault: SVC at or above the execution priority (escalated)");
        return;
    }
    static const char *const why[] = { [1] = "UsageFault UNDEFINSTR: an undefined instruction", [3] = "a prefetch abort",
        [4] = "a data abort", [7] = "a breakpoint (BKPT) with no debugger", [17] = "UsageFault NOCP: a coprocessor instruction",
        [18] = "UsageFault INVSTATE: Thumb bit clear", [22] = "UsageFault UNALIGNED: an unaligned access" };
    const char *w = c->intno >= 0 && c->intno < (int)(sizeof why / sizeof why[0]) && why[c->intno] ? why[c->intno] : "an exception unicorn raised";
    snprintf(m, sizeof m, "HardFault: %s (unicorn exception %d)", w, c->intno);
    /* UFSR UNDEFINSTR, INVSTATE, NOCP, UNALIGNED; BFSR IBUSERR (a fetch), PRECISERR (no address known); a BKPT: DEBUGEVT */
    uint32_t cfsr = c->intno == 1 ? 0x10000u : c->intno == 18 ? 0x20000u : c->intno == 17 ? 0x80000u : c->intno == 22 ? 0x1000000u
                  : c->intno == 3 ? 0x100u : c->intno == 4 ? 0x200u : 0u;
    fault(c, pc, cfsr, c->intno == 7 ? 1u << 31 : cfsr ? HFSR_FORCED : 0u, m);
}

/* emu_start returned on its own: WFI/WFE (the PC past it) or a memory fault. */
static void on_stop_none(armcore_t *c, uc_err e)
{
    char m[160];
    uint32_t pc = reg(c, UC_ARM_REG_PC);
    if (e == UC_ERR_INSN_INVALID) {
        c->cm.cfsr |= 0x10000u, c->cm.hfsr |= 1u << 30;
        crash(c, pc, "HardFault: UsageFault UNDEFINSTR: an undefined instruction");
        return;
    }
    if (e != UC_ERR_OK) {
        const char *what = c->bad_type == UC_MEM_FETCH_UNMAPPED || c->bad_type == UC_MEM_FETCH_PROT ? "fetching"
                         : c->bad_type == UC_MEM_WRITE_UNMAPPED || c->bad_type == UC_MEM_WRITE_PROT ? "writing" : "reading";
        bool fetch = c->bad_type == UC_MEM_FETCH_UNMAPPED || c->bad_type == UC_MEM_FETCH_PROT;
        if (!fetch) c->cm.bfar = c->bad_addr;
        snprintf(m, sizeof m, "HardFault: bus fault %s 0x%08x (%s)", what, c->bad_addr, uc_strerror(e));
        fault(c, pc, fetch ? 0x100u : 0x8200u, HFSR_FORCED, m); /* IBUSERR; PRECISERR with BFARVALID */
        return;
    }
    uint8_t h[4] = { 0 };
    uint16_t h1 = 0, h2 = 0;
    if (uc_mem_read(c->uc, pc - 4, h, 4) == UC_ERR_OK) h1 = (uint16_t)(h[2] | h[3] << 8), h2 = (uint16_t)(h[0] | h[1] << 8);
    bool wfx = h1 == 0xBF30u || h1 == 0xBF20u || (h2 == 0xF3AFu && (h1 == 0x8003u || h1 == 0x8002u));
    if (!wfx) {
        snprintf(m, sizeof m, "the emulation stopped at 0x%08x for no reason mmsim knows", pc);
        crash(c, pc, m);
        return;
    }
    c->pc = pc, c->sleeping = true;
    c->st.sleeps++;
}

/* Asleep: wake on an exception that would preempt were PRIMASK clear (B1.5.19), else skip to the next event or the target. */
static void sleep_step(armcore_t *c)
{
    c->now = c->cyc;
    clock_check(c);
    advance_due(c);
    int group;
    unsigned best = cortexm_best(&c->cm, &group);
    if ((best && group < cortexm_exec_prio(&c->cm, 0, reg(c, UC_ARM_REG_BASEPRI), reg(c, UC_ARM_REG_FAULTMASK))) || c->cm.reset_request) {
        c->sleeping = false;
        c->cm.attention = true;
        return;
    }
    uint64_t to = c->ev_next < c->target ? c->ev_next : c->target;
    if (c->no_idle_skip && to > c->cyc + 1) to = c->cyc + 1;
    c->st.idle_cycles += to - c->cyc;
    if (to > c->cyc + 1) c->st.idle_jumped += to - c->cyc - 1;
    c->cyc = to;
}

static const int loop_regs[17] = { UC_ARM_REG_R0, UC_ARM_REG_R1, UC_ARM_REG_R2, UC_ARM_REG_R3, UC_ARM_REG_R4, UC_ARM_REG_R5,
    UC_ARM_REG_R6, UC_ARM_REG_R7, UC_ARM_REG_R8, UC_ARM_REG_R9, UC_ARM_REG_R10, UC_ARM_REG_R11, UC_ARM_REG_R12, UC_ARM_REG_SP,
    UC_ARM_REG_LR, UC_ARM_REG_APSR, UC_ARM_REG_APSR_NZCV };

/* The registers and flags loop l writes back to their values at its head (c->saved). */
static void loop_restore(armcore_t *c, const loop_t *l)
{
    int r[17], n = 0;
    uint32_t v[17];
    for (int i = 0; i < 15; i++)
        if (l->written & (1u << i)) r[n] = loop_regs[i], v[n++] = c->saved[i];
    if (l->written & THUMB_NZCV) r[n] = UC_ARM_REG_APSR, v[n++] = c->saved[15], r[n] = UC_ARM_REG_APSR_NZCV, v[n++] = c->saved[15];
    if (n) regs_write(c, r, v, n);
}

/* Iteration j of loop c->skip from its head's saved state (c->saved, c->cm_saved) at cycle t0 + j x n:
 * PROBE_EXITS, PROBE_STAYS, or PROBE_AGAIN / PROBE_NEVER (give up now / for good). The state is restored after. */
static int probe(armcore_t *c, uint64_t t0, uint64_t j)
{
    c->probe = true, c->probe_res = PROBE_RUNNING, c->probe_idx = 0, c->cyc = t0 + j * c->skip->n;
    uc_err e = uc_emu_start(c->uc, c->skip->head | 1u, 0, 0, 0);
    c->probe = false;
    int r = e != UC_ERR_OK && c->probe_res == PROBE_RUNNING ? PROBE_NEVER : c->probe_res == PROBE_RUNNING ? PROBE_AGAIN : c->probe_res;
    loop_restore(c, c->skip);
    c->cm = c->cm_saved, c->cyc = t0;
    return r;
}

/* The first iteration in (0, k) that exits, k if none: LOOP_GRID probes spread over them, then a bisection
 * between the last that stays and the first that exits (the exit taken as monotone in time within one
 * interval of the grid: elapsed-time comparisons are); 0 if a probe gives up. */
static uint64_t first_exit(armcore_t *c, uint64_t t0, uint64_t k)
{
    uint64_t lo = 0, hi = k;
    for (uint64_t i = 1; i <= LOOP_GRID; i++) {
        uint64_t g = (k - 1) * i / LOOP_GRID;
        if (g <= lo) continue;
        int r = probe(c, t0, g);
        if (r < 0) return 0;
        if (r == PROBE_EXITS) { hi = g; break; }
        lo = g;
    }
    while (hi < k && hi - lo > 1) {
        uint64_t mid = lo + (hi - lo) / 2;
        int r = probe(c, t0, mid);
        if (r < 0) return 0;
        if (r == PROBE_EXITS) hi = mid;
        else lo = mid;
    }
    return hi;
}

/* Stopped at the head of loop c->skip: jump to the start of the iteration before the first that exits,
 * or before the last whole one ahead of the next event or the target; then run on from there. */
static void skip_loop(armcore_t *c)
{
    loop_t *l = c->skip;
    uint64_t t0 = c->cyc, end = c->ev_next < c->target ? c->ev_next : c->target, k = (end - t0) / l->n, m = 0;
    c->pc = l->head;
    regs_read(c, loop_regs, c->saved, 16);
    c->cm_saved = c->cm, c->probe_timed = false;
    int r = probe(c, t0, 0);
    if (r == PROBE_STAYS && c->probe_timed && l->bits) r = PROBE_NEVER; /* e.g. a CYCCNT bit tested: exits come and go */
    if (r == PROBE_STAYS) m = c->probe_timed ? first_exit(c, t0, k) : k; /* untimed: the same outcome until the next event */
    if (r == PROBE_NEVER) l->verdict = LOOP_NEVER;
    if (m >= 2) {
        c->cyc = t0 + (m - 1) * l->n;
        c->st.loop_skips++, c->st.loop_cycles += (m - 1) * l->n;
    }
    l->retry_at = t0 + (m + 1) * l->n;
}

/* The first k = target - cycle instructions of the block at stop_addr, through an exit there (its cached translation dropped before and after). */
static void run_split(armcore_t *c)
{
    uint64_t k = c->split_to - c->cyc;
    c->pc = c->stop_addr;
    c->brk_hit = c->split_to == c->brk_cyc;
    if (k == 0) {
        if (c->stop_mid) c->resume_mid = c->stop_addr; /* still a remainder when it resumes */
        return;
    }
    uint32_t until = insn_addr(c, c->stop_addr, (uint32_t)k);
    uc_ctl_remove_cache(c->uc, c->stop_addr, until + 4);
    c->partial = true, c->stop = STOP_NONE, c->bad_type = -1;
    uc_err e = uc_emu_start(c->uc, c->stop_addr | 1u, until, 0, 0);
    flash_fix(c);
    c->partial = false;
    uc_ctl_remove_cache(c->uc, c->stop_addr, until + 4);
    if (c->crashed) return;
    if (e != UC_ERR_OK) { on_stop_none(c, e); return; }
    uint32_t pc = reg(c, UC_ARM_REG_PC);
    if (pc != until) {
        char m[120];
        snprintf(m, sizeof m, "a stop inside the block at 0x%08x ended at 0x%08x, not 0x%08x", c->stop_addr, pc, until);
        crash(c, pc, m);
        return;
    }
    c->cyc += k, c->pc = until, c->resume_mid = until;
    c->st.splits++;
}

/* ---- reset and the run ---- */
static void core_reset(armcore_t *c)
{
    c->cm.now = c->cyc;
    for (int i = 0; i < c->nreg; i++)
        if (c->reg[i].ops->reset) c->reg[i].ops->reset(c->reg[i].self);
    c->cm.reset_request = false;
    set_ipsr(c, 0, 0);
    set_reg(c, UC_ARM_REG_CONTROL, 0);
    set_reg(c, UC_ARM_REG_PRIMASK, 0), set_reg(c, UC_ARM_REG_BASEPRI, 0), set_reg(c, UC_ARM_REG_FAULTMASK, 0);
    set_reg(c, UC_ARM_REG_MSP, rd32(c->flash) & ~3u);
    set_reg(c, UC_ARM_REG_LR, 0xFFFFFFFFu);
    c->pc = rd32(c->flash + 4) & ~1u;
    c->sleeping = false, c->resume_mid = NO_ADDR, c->cm.attention = true, c->all_dirty = true;
}

static void run_once(armcore_t *c)
{
    c->stop = STOP_NONE, c->intno = -1, c->bad_type = -1;
    c->st.starts++, c->rec_gen++;
    uc_err e = uc_emu_start(c->uc, c->pc | 1u, 0, 0, 0);
    flash_fix(c);
    switch (c->stop) {
    case STOP_TAKE:
        c->pc = c->stop_addr;
        if (c->take == EXC_RESET) core_reset(c);
        else enter(c, c->take, c->stop_addr);
        break;
    case STOP_SPLIT: run_split(c); break;
    case STOP_SKIP: skip_loop(c); break;
    case STOP_RECUR: c->pc = c->stop_addr, c->cyc = c->rec_land; break;
    case STOP_INTR: on_stop_intr(c); break;
    case STOP_FAULT: break;
    default: on_stop_none(c, e); break;
    }
}

static int run(armcore_t *c)
{
    if (c->halted) c->halted = false, c->brk_skip = c->pc;
    c->all_dirty = true; /* the host may have changed a model since the last run (a byte queued, an encoder's edges) */
    while (!c->crashed && c->cyc < c->target) {
        bool slept = c->sleeping;
        if (c->sleeping) sleep_step(c);
        else run_once(c);
        if (!c->crashed && (c->brk_hit || (c->cyc >= c->halt_at && !slept && !c->sleeping))) { /* a step over WFI ends after it wakes */
            c->halted = true, c->brk_hit = false, c->halt_at = NO_TIME;
            return ARMCORE_HALTED;
        }
    }
    return c->crashed;
}

int armcore_run_to(armcore_t *c, uint64_t target)
{
    c->target = target, c->target_ps = NO_TIME;
    return run(c);
}

int armcore_run_until_ps(armcore_t *c, uint64_t t_ps)
{
    c->now = c->cyc;
    clock_check(c);
    c->target_ps = t_ps, c->target = cycle_at(c, t_ps);
    int rc = run(c);
    c->target_ps = NO_TIME;
    return rc;
}

static bool map_memories(armcore_t *c, char *err, size_t errn)
{
    const armimage_mcu_t *m = c->mcu;
    uc_err e = uc_mem_map_ptr(c->uc, m->flash_base, m->flash_bytes, UC_PROT_READ | UC_PROT_EXEC, c->flash);
    if (!e) e = uc_mem_map_ptr(c->uc, 0, m->flash_bytes, UC_PROT_READ | UC_PROT_EXEC, c->flash); /* BOOT0 = 0: flash at 0 */
    if (!e) e = uc_mem_map_ptr(c->uc, m->sram_base, m->sram_bytes, UC_PROT_ALL, c->sram);
    if (!e) e = uc_mmio_map(c->uc, PERIPH_BASE, PERIPH_BYTES, on_periph_read, c, on_periph_write, c);
    if (!e) e = uc_mmio_map(c->uc, CORTEXM_PPB_BASE, CORTEXM_PPB_BYTES, on_ppb_read, c, on_ppb_write, c);
    if (!e) e = uc_mmio_map(c->uc, SRAM_BB_BASE, BB_ALIAS_BYTES, on_sram_bb_read, c, on_sram_bb_write, c);
    if (!e && m->fsize_addr) e = uc_mmio_map(c->uc, sig_page(m), SIG_PAGE_BYTES, on_sig_read, c, on_sig_write, c);
    uc_hook h;
    if (!e) e = uc_hook_add(c->uc, &h, UC_HOOK_BLOCK, (void *)on_block, c, 1, 0);
    if (!e) e = uc_hook_add(c->uc, &h, UC_HOOK_INTR, (void *)on_intr, c, 1, 0);
    if (!e) e = uc_hook_add(c->uc, &h, UC_HOOK_MEM_INVALID, (void *)on_bad_mem, c, 1, 0);
    if (e) snprintf(err, errn, "mmsim: unicorn: %s", uc_strerror(e));
    return e == UC_ERR_OK;
}

static int by_base(const void *a, const void *b)
{
    const mmio_region_t *x = a, *y = b;
    return x->base < y->base ? -1 : x->base > y->base;
}

armcore_t *armcore_new(const armcore_cfg_t *cfg, char *err, size_t errn)
{
    const armimage_mcu_t *m = cfg->image->mcu;
    if (ucdl_load(err, errn) != 0) return NULL; /* libunicorn missing: an external failure (exit 3) */
    if (cfg->nregions < 0 || cfg->nregions > ARMCORE_REGIONS_MAX)
        return snprintf(err, errn, "mmsim: %d peripheral regions (at most %d)", cfg->nregions, ARMCORE_REGIONS_MAX), NULL;
    armcore_t *c = calloc(1, sizeof *c);
    if (c) c->flash = malloc(m->flash_bytes), c->sram = calloc(1, m->sram_bytes), c->rec_sram = malloc(m->sram_bytes);
    if (!c || !c->flash || !c->sram || !c->rec_sram) return snprintf(err, errn, "mmsim: out of memory"), armcore_free(c), NULL;
    memcpy(c->flash, cfg->image->flash, m->flash_bytes);
    c->mcu = m, c->clocks = cfg->clocks, c->verbose = cfg->verbose, c->no_idle_skip = cfg->no_idle_skip;
    c->links = cfg->reports_links, c->all_dirty = true;
    c->flash_write = cfg->flash_write, c->flash_ctx = cfg->flash_ctx;
    c->hclk = cfg->clocks && cfg->clocks->hclk ? cfg->clocks->hclk : cfg->hclk_hz;
    c->target_ps = NO_TIME, c->resume_mid = NO_ADDR, c->never_head = NO_ADDR, c->rec_head = NO_ADDR;
    c->halt_at = NO_TIME, c->brk_cyc = NO_TIME, c->brk_skip = NO_ADDR;
    cortexm_init(&c->cm, m->nirq, m->prio_bits, m->cpuid);
    cortexm_set_fpu(&c->cm, m->fpu != 0);
    if (cfg->nregions) memcpy(c->reg, cfg->regions, sizeof *c->reg * (size_t)cfg->nregions);
    c->reg[cfg->nregions] = (mmio_region_t){ CORTEXM_PPB_BASE, CORTEXM_PPB_BYTES, &cortexm_ops, &c->cm };
    c->nreg = cfg->nregions + 1;
    qsort(c->reg, (size_t)c->nreg, sizeof *c->reg, by_base);
    uc_err e = uc_open(UC_ARCH_ARM, UC_MODE_THUMB, &c->uc);
    if (!e) e = uc_ctl_set_cpu_model(c->uc, m->core == ARMCORE_M4 ? UC_CPU_ARM_CORTEX_M4 : UC_CPU_ARM_CORTEX_M3);
    if (e) return snprintf(err, errn, "mmsim: unicorn: %s", uc_strerror(e)), armcore_free(c), NULL;
    if (!c->hclk) return snprintf(err, errn, "mmsim: no core clock"), armcore_free(c), NULL;
    if (!map_memories(c, err, errn)) return armcore_free(c), NULL;
    core_reset(c);
    return c;
}

void armcore_free(armcore_t *c)
{
    if (!c) return;
    if (c->uc) uc_close(c->uc);
    free(c->flash);
    free(c->sram);
    free(c->rec_sram);
    free(c);
}

uint64_t armcore_cycles(const armcore_t *c) { return c->cyc; }
uint64_t armcore_time_ps(const armcore_t *c) { return time_at(c, c->cyc); }
mmio_irq_t armcore_irq(armcore_t *c) { return (mmio_irq_t){ cortexm_set_irq, &c->cm }; }
mmio_bus_t armcore_bus(armcore_t *c) { return (mmio_bus_t){ dma_read, dma_write, c }; }
cortexm_t *armcore_cortexm(armcore_t *c) { return &c->cm; }
uint8_t *armcore_flash(armcore_t *c) { return c->flash; }
void armcore_flash_changed(armcore_t *c, uint32_t addr, uint32_t bytes)
{
    uc_ctl_remove_cache(c->uc, addr, (uint64_t)addr + bytes);
    if (addr >= c->mcu->flash_base) uc_ctl_remove_cache(c->uc, addr - c->mcu->flash_base, (uint64_t)addr - c->mcu->flash_base + bytes);
}
void armcore_touch(armcore_t *c, uint32_t addr)
{
    const mmio_region_t *r = region_at(c, addr);
    if (r) touched(c, r);
}
void armcore_touch_all(armcore_t *c) { c->all_dirty = true; }
void armcore_set_links(armcore_t *c, bool reported) { c->links = reported, c->all_dirty = true; }
int armcore_crashed(const armcore_t *c, uint32_t *pc, const char **cause)
{
    if (!c->crashed) return 0;
    if (pc) *pc = c->crash_pc;
    if (cause) *cause = c->cause;
    return 1;
}
uint32_t armcore_reg(armcore_t *c, int r) { return r == UC_ARM_REG_PC ? c->pc : reg(c, r); }
int armcore_read(armcore_t *c, uint32_t addr, void *buf, size_t n)
{
    const uint8_t *p = n <= UINT32_MAX ? host(c, addr, (uint32_t)n) : NULL;
    if (!p) return -1;
    memcpy(buf, p, n);
    return 0;
}
const armcore_unmodeled_t *armcore_unmodeled(const armcore_t *c, int *n) { *n = c->nunm; return c->unm; }
armcore_stats_t armcore_stats(const armcore_t *c) { return c->st; }

/* ---- the debugger's hooks ---- */
int armcore_set_breaks(armcore_t *c, const uint32_t *addr, int n)
{
    if (n < 0 || n > ARMCORE_BREAKS_MAX) return -1;
    for (int i = 0; i < n; i++) c->brk[i] = addr[i] & ~1u;
    c->nbrk = n;
    if (!c->halted) c->brk_skip = NO_ADDR; /* stopped between runs (not at a halt): no breakpoint is being resumed from */
    return 0;
}
void armcore_halt_at(armcore_t *c, uint64_t cycle) { c->halt_at = cycle; }
int armcore_set_reg(armcore_t *c, int r, uint32_t v)
{
    if (r == UC_ARM_REG_PC) {
        if ((v & ~1u) != c->pc) c->pc = v & ~1u, c->resume_mid = NO_ADDR, c->sleeping = false;
        return 0;
    }
    return uc_reg_write(c->uc, r, &v) == UC_ERR_OK ? 0 : -1;
}
int armcore_write(armcore_t *c, uint32_t addr, const void *buf, size_t n)
{
    const armimage_mcu_t *m = c->mcu;
    if (addr < m->sram_base || n > m->sram_bytes || addr - m->sram_base > m->sram_bytes - n) return -1;
    memcpy(c->sram + (addr - m->sram_base), buf, n);
    return 0;
}

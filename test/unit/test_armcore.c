/* test_armcore.c - the Cortex-M core on libunicorn (sim/arm/armcore.c) and
 * its system peripherals (cortexm.c) running our own register-level
 * firmware (test/firmware/arm/coretest.c, built by the Makefile into
 * build/arm/coretest.elf), one scenario per test, checked against the
 * ARMv7-M ARM (DDI 0403E) and PM0056: preemption by priority (a pend
 * through NVIC ISPR, an interrupt raised by a peripheral at a cycle),
 * tail-chaining, PRIMASK, BASEPRI, priority grouping, SysTick's period and
 * COUNTFLAG, DWT CYCCNT, VTOR, SVCall and PendSV, SYSRESETREQ, the
 * bit-band aliases, unmodeled registers listed, faults ending the run with
 * the faulting PC; WFI skipping and any chunking giving the same state.
 * A fake peripheral at 0x40010000 stands for the MCU's (armtest.h). */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <cmocka.h>

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <unicorn/unicorn.h>

#include "arm/armcore.h"
#include "arm/armimage.h"
#include "../test/firmware/arm/armtest.h"

#define IMAGE "build/arm/coretest.elf"
#define FPU_IMAGE "build/arm/fputest.elf"
#define HSI_HZ 8000000u /* the STM32F1's clock out of reset (RM0008 7.2) */
#define SRAM_BYTES (20u << 10)

enum { PREEMPT = 1, PREEMPT_HW, TAILCHAIN, PRIMASK, BASEPRI, SYSTICK, COUNTFLAG, DWT, VTOR, WFI, FAULT_UNMAPPED, FAULT_PERIPH,
       UNDEF, SVC, UNMODELED, BITBAND, CLOCK, CHURN, RESET, PRIGROUP_SUB, PRIGROUP_NONE, SPIN, STORM, PSP,
       IDLE_CYCCNT, IDLE_TICK, IDLE_COUNTFLAG, IDLE_BENCH, IDLE_BITS, IDLE_RECUR, IDLE_COUNT, IDLE_MASKED };

typedef struct {
    uint32_t scenario, scratch;
    mmio_irq_t irq;
    uint64_t now, fire_at, hclk_cycle;
    mmio_clocks_t clocks;
} fake_t;

static mmio_status_t fake_read(void *self, uint32_t off, unsigned size, uint32_t *v)
{
    fake_t *f = self;
    if (off == 0x00) { *v = f->scenario; return MMIO_OK; }
    if (off == 0x18) { *v = f->scratch; return MMIO_OK; }
    return off == 0x14 ? MMIO_BUS_FAULT : MMIO_UNMODELED;
}

static mmio_status_t fake_write(void *self, uint32_t off, unsigned size, uint32_t v)
{
    fake_t *f = self;
    switch (off) {
    case 0x04: f->irq.set(f->irq.ctx, v, true); return MMIO_OK;
    case 0x08: f->irq.set(f->irq.ctx, v, false); return MMIO_OK;
    case 0x0C: f->fire_at = f->now + v; return MMIO_OK;
    case 0x10: f->clocks.hclk = v, f->hclk_cycle = f->now; return MMIO_OK;
    case 0x14: return MMIO_BUS_FAULT;
    case 0x18: f->scratch = v; return MMIO_OK;
    default: return MMIO_UNMODELED;
    }
}

static void fake_advance(void *self, uint64_t now)
{
    fake_t *f = self;
    f->now = now;
    if (f->fire_at <= now) f->fire_at = MMIO_NEVER, f->irq.set(f->irq.ctx, 2, true);
}

static uint64_t fake_next(void *self) { return ((fake_t *)self)->fire_at; }
static const mmio_ops_t fake_ops = { "FAKE", fake_read, fake_write, fake_advance, fake_next, NULL };

typedef struct {
    armimage_t img;
    fake_t fake;
    armcore_t *core;
} rig_t;

static rig_t *rig_image(const char *image, const char *mcu, uint32_t scenario, bool no_skip)
{
    rig_t *r = calloc(1, sizeof *r);
    char err[300];
    assert_non_null(r);
    if (armimage_read(image, armimage_mcu(mcu), &r->img, err, sizeof err) != 0) fail_msg("%s (make %s)", err, image);
    r->fake.scenario = scenario, r->fake.fire_at = MMIO_NEVER, r->fake.clocks.hclk = HSI_HZ;
    mmio_region_t reg = { FAKE_BASE, 0x400, &fake_ops, &r->fake };
    armcore_cfg_t cfg = { .image = &r->img, .regions = &reg, .nregions = 1, .clocks = &r->fake.clocks, .hclk_hz = HSI_HZ,
                          .no_idle_skip = no_skip };
    r->core = armcore_new(&cfg, err, sizeof err);
    if (!r->core) fail_msg("%s", err);
    r->fake.irq = armcore_irq(r->core);
    return r;
}

static rig_t *rig_new(uint32_t scenario, bool no_skip) { return rig_image(IMAGE, "stm32f103x8", scenario, no_skip); }

static void rig_free(rig_t *r)
{
    armcore_free(r->core);
    armimage_free(&r->img);
    free(r);
}

static mailbox_t mailbox(rig_t *r)
{
    mailbox_t mb;
    assert_int_equal(armcore_read(r->core, 0x20000000u, &mb, sizeof mb), 0);
    return mb;
}

static void no_crash(rig_t *r)
{
    uint32_t pc;
    const char *cause;
    if (armcore_crashed(r->core, &pc, &cause)) fail_msg("crashed at 0x%08x: %s", pc, cause);
}

/* Run the scenario to cycles; its log must be want (n words). */
static rig_t *run_log(uint32_t scenario, uint64_t cycles, const uint32_t *want, uint32_t n)
{
    rig_t *r = rig_new(scenario, false);
    armcore_run_to(r->core, cycles);
    no_crash(r);
    mailbox_t mb = mailbox(r);
    assert_int_equal(mb.done, 1);
    for (uint32_t i = 0; i < n && i < mb.nlog; i++)
        if (mb.log[i] != want[i]) fail_msg("scenario %u: event %u is 0x%x, want 0x%x", scenario, i, mb.log[i], want[i]);
    assert_int_equal(mb.nlog, n);
    return r;
}

#define EV(a, b) ((uint32_t)(a) << 8 | (uint32_t)(b))

/* libunicorn missing: one line naming it, no core (run first: the library stays loaded once it is). */
static void test_no_libunicorn(void **state)
{
    armimage_t img;
    char err[300] = "";
    if (armimage_read(IMAGE, armimage_mcu("stm32f103x8"), &img, err, sizeof err) != 0) fail_msg("%s", err);
    armcore_cfg_t cfg = { .image = &img, .hclk_hz = HSI_HZ };
    setenv("MMSIM_UNICORN", "/nonexistent/libunicorn.so.2", 1);
    armcore_t *c = armcore_new(&cfg, err, sizeof err);
    unsetenv("MMSIM_UNICORN");
    assert_null(c);
    if (!strstr(err, "libunicorn.so.2") || strchr(err, '\n')) fail_msg("the error: %s", err);
    armimage_free(&img);
}

static void test_preempt_ispr(void **state)
{
    const uint32_t want[] = { EV('S', '1'), EV('I', '0'), EV('S', '2') };
    rig_free(run_log(PREEMPT, 20000, want, 3));
}

static void test_preempt_peripheral(void **state)
{
    const uint32_t want[] = { EV('S', '1'), EV('I', '2'), EV('S', '2') };
    rig_free(run_log(PREEMPT_HW, 20000, want, 3));
}

static void test_tail_chain(void **state)
{
    const uint32_t want[] = { EV('I', '0'), EV('I', '1'), 'M' };
    rig_t *r = run_log(TAILCHAIN, 20000, want, 3);
    assert_true(armcore_stats(r->core).tail_chains >= 1);
    rig_free(r);
}

static void test_primask(void **state)
{
    const uint32_t want[] = { EV('I', '0'), 'M' };
    rig_t *r = run_log(PRIMASK, 20000, want, 2);
    mailbox_t mb = mailbox(r);
    assert_int_equal(mb.v[0], 0); /* nothing taken while masked */
    assert_int_equal(mb.v[1], 1); /* IRQ0 pending in ISPR meanwhile */
    rig_free(r);
}

static void test_basepri(void **state)
{
    const uint32_t want[] = { EV('I', '1'), EV('M', '1'), EV('I', '0'), EV('M', '2') };
    rig_free(run_log(BASEPRI, 20000, want, 4));
}

static void test_prigroup(void **state)
{
    const uint32_t sub[] = { EV('I', '0'), EV('I', 'b'), EV('I', '1'), 'M' };  /* same group: no preemption */
    const uint32_t none[] = { EV('I', '0'), EV('I', '1'), EV('I', 'b'), 'M' }; /* 0x40 preempts 0x60 */
    rig_free(run_log(PRIGROUP_SUB, 20000, sub, 4));
    rig_free(run_log(PRIGROUP_NONE, 20000, none, 4));
}

static void test_systick_period(void **state)
{
    rig_t *r = run_log(SYSTICK, 20000, NULL, 0);
    mailbox_t mb = mailbox(r);
    for (int i = 1; i < 5; i++) assert_int_equal(mb.v[i] - mb.v[i - 1], 100); /* RVR + 1 cycles (B3.3.1) */
    assert_int_equal(mb.v[14], 0x411FC231u);                                   /* CPUID (PM0056 4.4.1) */
    rig_free(r);
}

static void test_countflag(void **state)
{
    rig_t *r = run_log(COUNTFLAG, 20000, NULL, 0);
    mailbox_t mb = mailbox(r);
    assert_true(mb.v[0] & (1u << 16));    /* set at the wrap */
    assert_false(mb.v[1] & (1u << 16));   /* cleared by the read */
    int64_t d = (int64_t)(mb.v[3] - mb.v[2]) - 400; /* (RVR + 1) x 8 cycles at HCLK/8, within a poll loop */
    if (d < -12 || d > 12) fail_msg("COUNTFLAG %u cycles apart, want 400", mb.v[3] - mb.v[2]);
    rig_free(r);
}

static void test_dwt(void **state)
{
    rig_t *r = run_log(DWT, 20000, NULL, 0);
    mailbox_t mb = mailbox(r);
    assert_int_equal(mb.v[0], 0);  /* DEMCR.TRCENA clear: CYCCNT stands */
    assert_int_equal(mb.v[1], 12); /* ldr, 10 nops, b: the second ldr's block starts 12 cycles later */
    rig_free(r);
}

static void test_vtor(void **state)
{
    const uint32_t want[] = { 'A' };
    rig_t *r = run_log(VTOR, 20000, want, 1);
    mailbox_t mb = mailbox(r);
    assert_true(mb.v[0] >= 0x20000000u && (mb.v[0] & 0xFFu) == 0);
    rig_free(r);
}

static void test_svc_pendsv(void **state)
{
    const uint32_t want[] = { 'V', 'v', 'P', 'M' }; /* PendSV (0xF0) waits for SVCall (0x80), then tail-chains */
    rig_free(run_log(SVC, 20000, want, 4));
}

static void test_process_stack(void **state)
{
    const uint32_t want[] = { 'V' };
    rig_t *r = run_log(PSP, 20000, want, 1);
    mailbox_t mb = mailbox(r);
    assert_int_equal(mb.v[2], 0xFFFFFFFDu); /* EXC_RETURN: thread mode, PSP (B1.5.8) */
    assert_true(mb.v[3] > 0x20004000u);      /* the handler on the main stack */
    assert_int_equal(mb.v[0], 2);            /* CONTROL.SPSEL back after the return */
    assert_true(mb.v[1] <= mb.v[4] && mb.v[4] - mb.v[1] < 64); /* thread code's SP: the process stack, the frame popped */
    assert_int_equal(mb.v[5], 0x4444u);
    rig_free(r);
}

static void test_reset_request(void **state)
{
    const uint32_t want[] = { 'R' };
    rig_free(run_log(RESET, 20000, want, 1));
}

static void test_bitband(void **state)
{
    rig_t *r = run_log(BITBAND, 20000, NULL, 0);
    mailbox_t mb = mailbox(r);
    assert_int_equal(mb.v[0], 8);
    assert_int_equal(mb.v[1], 1);
    assert_int_equal(mb.v[2], 0x20);
    rig_free(r);
}

static void test_unmodeled(void **state)
{
    rig_t *r = run_log(UNMODELED, 20000, NULL, 0);
    int n, seen = 0;
    const armcore_unmodeled_t *u = armcore_unmodeled(r->core, &n);
    for (int i = 0; i < n; i++) {
        if (u[i].addr == 0x40007000u && u[i].reads == 1 && !strcmp(u[i].region, "")) seen |= 1;
        if (u[i].addr == 0xE000EDF0u && u[i].writes == 1 && !strcmp(u[i].region, "PPB")) seen |= 2;
    }
    assert_int_equal(seen, 3);
    rig_free(r);
}

static void crash_at(uint32_t scenario, const char *want)
{
    rig_t *r = rig_new(scenario, false);
    uint32_t pc;
    const char *cause;
    assert_int_equal(armcore_run_to(r->core, 20000), 1);
    assert_int_equal(armcore_crashed(r->core, &pc, &cause), 1);
    mailbox_t mb = mailbox(r);
    /* the PC: the faulting instruction's (an exception unicorn raises) or its translated block's start (a bad access) */
    if (pc > mb.v[0] || mb.v[0] - pc > 16 || !strstr(cause, want)) fail_msg("crash at 0x%08x (%s), want 0x%08x (%s)", pc, cause, mb.v[0], want);
    assert_int_equal(armcore_run_to(r->core, 40000), 1); /* never run again */
    rig_free(r);
}

static void test_faults(void **state)
{
    crash_at(FAULT_UNMAPPED, "0x60000000");
    crash_at(FAULT_PERIPH, "0x40010014");
    crash_at(UNDEF, "UNDEFINSTR");
    /* the fault status decoded (B3.2.15-16) and the PC a HardFault handler would read from the frame */
    crash_at(FAULT_UNMAPPED, "CFSR 0x00008200: PRECISERR BFARVALID (BFAR 0x60000000), HFSR 0x40000000: FORCED; stacked PC 0x0800");
    crash_at(FAULT_PERIPH, "CFSR 0x00008200: PRECISERR BFARVALID (BFAR 0x40010014), HFSR 0x40000000: FORCED; stacked PC 0x0800");
    crash_at(UNDEF, "CFSR 0x00010000: UNDEFINSTR, HFSR 0x40000000: FORCED; stacked PC 0x0800");
}

static void test_clock_switch(void **state)
{
    rig_t *r = run_log(CLOCK, 20000, NULL, 0);
    uint64_t c = armcore_cycles(r->core), s = r->fake.hclk_cycle;
    assert_true(s > 100 && s < c);
    assert_int_equal(armcore_time_ps(r->core), s * 125000u + (c - s) * 1000000000000ull / 72000000u);
    rig_free(r);
}

/* The state a determinism test compares: cycles, registers, SRAM. */
static void snapshot(rig_t *r, uint8_t *out)
{
    static const int regs[] = { UC_ARM_REG_R0, UC_ARM_REG_R1, UC_ARM_REG_R2, UC_ARM_REG_R3, UC_ARM_REG_R4, UC_ARM_REG_R5,
        UC_ARM_REG_R6, UC_ARM_REG_R7, UC_ARM_REG_R8, UC_ARM_REG_R12, UC_ARM_REG_MSP, UC_ARM_REG_PC, UC_ARM_REG_IPSR };
    uint64_t c = armcore_cycles(r->core);
    memcpy(out, &c, 8);
    for (size_t i = 0; i < sizeof regs / sizeof regs[0]; i++) {
        uint32_t v = armcore_reg(r->core, regs[i]);
        memcpy(out + 8 + 4 * i, &v, 4);
    }
    assert_int_equal(armcore_read(r->core, 0x20000000u, out + 64, SRAM_BYTES), 0);
}

static void test_wfi_skip_same_state(void **state)
{
    static uint8_t a[64 + SRAM_BYTES], b[64 + SRAM_BYTES];
    rig_t *r = rig_new(WFI, false), *q = rig_new(WFI, true);
    armcore_run_to(r->core, 80000), armcore_run_to(q->core, 80000);
    no_crash(r), no_crash(q);
    mailbox_t mb = mailbox(r);
    assert_int_equal(mb.done, 1);
    for (int i = 1; i < 15; i++) assert_int_equal(mb.v[i] - mb.v[i - 1], 1000); /* v[15]: main's own read */
    assert_true(armcore_stats(r->core).idle_cycles > 40000);
    snapshot(r, a), snapshot(q, b);
    assert_memory_equal(a, b, sizeof a);
    rig_free(r), rig_free(q);
}

/* Idle loops jumped over (armcore.c, "idle loops"): at several targets (some inside a wait) and in random
 * chunks, the same cycles, registers and SRAM as running every iteration; and the skips did happen. */
static void idle_same_state(uint32_t scenario, uint64_t end, uint32_t nv, bool skips)
{
    static uint8_t a[64 + SRAM_BYTES], b[64 + SRAM_BYTES];
    const uint64_t stops[] = { 3001, 40000, 77777, 120003, end };
    rig_t *r = rig_new(scenario, false), *q = rig_new(scenario, true), *k = rig_new(scenario, false);
    uint32_t x = 777;
    for (size_t i = 0; i < sizeof stops / sizeof stops[0]; i++) {
        if (stops[i] > end) continue;
        armcore_run_to(r->core, stops[i]), armcore_run_to(q->core, stops[i]);
        for (uint64_t t = armcore_cycles(k->core); t < stops[i];) {
            x = x * 1103515245u + 12345u;
            t += 1 + (x >> 16) % 20000;
            armcore_run_to(k->core, t < stops[i] ? t : stops[i]);
        }
        no_crash(r), no_crash(q), no_crash(k);
        snapshot(r, a), snapshot(q, b);
        if (memcmp(a, b, sizeof a)) fail_msg("scenario %u at cycle %llu: skipping changed the state", scenario, (unsigned long long)stops[i]);
        snapshot(k, b);
        if (memcmp(a, b, sizeof a)) fail_msg("scenario %u at cycle %llu: skipping in chunks changed the state", scenario, (unsigned long long)stops[i]);
    }
    mailbox_t mb = mailbox(r);
    assert_int_equal(mb.done, 1);
    for (uint32_t i = 1; i < nv; i++) assert_true(mb.v[i] > mb.v[i - 1]);
    armcore_stats_t st = armcore_stats(r->core);
    if (!skips) assert_int_equal(st.loop_skips, 0);
    else if (st.loop_skips < nv || st.loop_cycles + st.idle_cycles < end / 2)
        fail_msg("scenario %u: %llu skips, %llu cycles skipped of %llu", scenario, (unsigned long long)st.loop_skips,
                 (unsigned long long)(st.loop_cycles + st.idle_cycles), (unsigned long long)end);
    assert_int_equal(armcore_stats(q->core).loop_skips, 0);
    rig_free(r), rig_free(q), rig_free(k);
}

static void test_idle_cyccnt(void **state) { idle_same_state(IDLE_CYCCNT, 160000, 5, true); }
static void test_idle_hal_delay(void **state) { idle_same_state(IDLE_TICK, 60000, 8, true); }
static void test_idle_countflag(void **state) { idle_same_state(IDLE_COUNTFLAG, 180000, 4, true); }
static void test_idle_bits(void **state) { idle_same_state(IDLE_BITS, 60000, 6, false); } /* not skipped: the same state */
/* armcore.c "recurring states": a wait calling a function that pushes, pops and stores is jumped over
 * (by recurrences, the short-loop skipper cannot); one counting in RAM is not. */
static void test_idle_recur(void **state)
{
    idle_same_state(IDLE_RECUR, 300000, 5, true);
    rig_t *r = rig_new(IDLE_RECUR, false);
    armcore_run_to(r->core, 300000);
    armcore_stats_t st = armcore_stats(r->core);
    if (st.recur_skips < 20 || st.recur_cycles < 150000)
        fail_msg("%llu recurrences jumped, %llu cycles", (unsigned long long)st.recur_skips, (unsigned long long)st.recur_cycles);
    rig_free(r);
}
static void test_idle_count(void **state) { idle_same_state(IDLE_COUNT, 100000, 4, false); }
static void test_idle_masked(void **state) { idle_same_state(IDLE_MASKED, 300000, 5, true); } /* SysTick pending at a CPSIE: never jumped past */

static void test_chunking_same_state(void **state)
{
    static uint8_t a[64 + SRAM_BYTES], b[64 + SRAM_BYTES];
    const uint64_t end = 3000000;
    rig_t *r = rig_new(CHURN, false), *q = rig_new(CHURN, false);
    armcore_run_to(r->core, end);
    uint32_t x = 12345;
    for (uint64_t t = 0; t < end;) {
        x = x * 1103515245u + 12345u;
        t += 1 + (x >> 16) % 3000;
        armcore_run_to(q->core, t < end ? t : end);
    }
    no_crash(r), no_crash(q);
    assert_true(mailbox(r).v[1] > 1000); /* SysTick and the peripheral's interrupts kept coming */
    assert_true(armcore_stats(q->core).splits > 100);
    snapshot(r, a), snapshot(q, b);
    assert_memory_equal(a, b, sizeof a);
    rig_free(r), rig_free(q);
}

/* The M4F's FP context (fputest.c): thread S0-S15 and FPSCR survive IRQ0, whose own survive IRQ1 preempting it (B1.5.7). */
static void test_fpu_extended_frame(void **state)
{
    rig_t *r = rig_image(FPU_IMAGE, "stm32f405xg", 1, false);
    armcore_run_to(r->core, 20000);
    no_crash(r);
    mailbox_t mb = mailbox(r);
    assert_int_equal(mb.done, 1);
    assert_int_equal(mb.v[15], 0xC0000000u);         /* FPCCR at reset: ASPEN, LSPEN */
    assert_int_equal(mb.v[14], 0x00F00000u);         /* CPACR: CP10 and CP11 as written */
    assert_int_equal(mb.v[0] & 4u, 4u);               /* CONTROL.FPCA after the thread's first FP instruction */
    assert_int_equal(mb.v[2] & 4u, 0u);               /* cleared on entry */
    assert_int_equal(mb.v[3], 0xFFFFFFE9u);           /* EXC_RETURN: thread, MSP, extended frame */
    assert_true(mb.v[6] >= mb.v[9] + 0x20u && mb.v[6] < mb.v[9] + 0x60u && !(mb.v[6] & 7u)); /* FPCAR: in the frame above the handler's SP */
    assert_int_equal(mb.v[12], 0x3F800000u);          /* at FPCAR: the thread's S0 */
    assert_int_equal(mb.v[13], 0x03C00000u);          /* at FPCAR + 0x40: its FPSCR */
    assert_int_equal(mb.v[4] & 4u, 4u);               /* the handler's own FP use sets it again */
    assert_int_equal(mb.v[5], 0xFFFFFFE1u);           /* IRQ1 preempting it: handler, extended frame */
    for (uint32_t i = 0; i < 16; i++) {
        uint32_t want_irq0 = 0xC0000001u + i;
        if (mb.log[16 + i] != want_irq0) fail_msg("IRQ0's S%u is 0x%08x after IRQ1, want 0x%08x", i, mb.log[16 + i], want_irq0);
    }
    static const uint32_t thread_vals[16] = { 0x3F800000, 0x40000000, 0x40400000, 0x40800000, 0x40A00000, 0x40C00000, 0x40E00000,
        0x41000000, 0x41100000, 0x41200000, 0x41300000, 0x41400000, 0x41500000, 0x41600000, 0x41700000, 0x41800000 };
    for (uint32_t i = 0; i < 16; i++)
        if (mb.log[i] != thread_vals[i]) fail_msg("thread S%u is 0x%08x after the interrupts, want 0x%08x", i, mb.log[i], thread_vals[i]);
    assert_int_equal(mb.v[10], 0x00800000u);          /* IRQ0's FPSCR after IRQ1 */
    assert_int_equal(mb.v[8], 0x03C00000u);           /* the thread's FPSCR */
    assert_int_equal(mb.v[1] & 4u, 4u);               /* FPCA back after the return (NOT EXC_RETURN[4]) */
    rig_free(r);
    r = rig_image(FPU_IMAGE, "stm32f405xg", 2, false); /* no FP instruction before the interrupt: the basic frame */
    armcore_run_to(r->core, 20000);
    no_crash(r);
    mb = mailbox(r);
    assert_int_equal(mb.v[3], 0xFFFFFFF9u);
    assert_int_equal(mb.v[1] & 4u, 0u);
    rig_free(r);
    armimage_t img; /* the hard-float image on an MCU without an FPU: refused before unicorn sees it */
    char err[300] = "";
    assert_int_not_equal(armimage_read(FPU_IMAGE, armimage_mcu("stm32f103x8"), &img, err, sizeof err), 0);
    if (!strstr(err, "FPU") && !strstr(err, "hard-float")) fail_msg("the error: %s", err);
}

/* The debugger's halts are invisible: single steps (armcore_halt_at) through
 * the first cycles, then breakpoints at 64 of the addresses stepped through
 * (main's loop and the interrupt handlers), each hit resumed, end in the
 * state of the run without them; a breakpoint halts with the PC at its address. */
static void test_debug_halts_same_state(void **state)
{
    static uint8_t a[64 + SRAM_BYTES], b[64 + SRAM_BYTES];
    const uint64_t end = 300000;
    rig_t *r = rig_new(CHURN, false), *q = rig_new(CHURN, false);
    armcore_run_to(r->core, end);
    uint32_t brk[ARMCORE_BREAKS_MAX];
    int nbrk = 0, steps = 0, hits = 0;
    while (armcore_cycles(q->core) < 30000) {
        armcore_halt_at(q->core, armcore_cycles(q->core) + 1);
        assert_int_equal(armcore_run_to(q->core, end), ARMCORE_HALTED);
        uint32_t pc = armcore_reg(q->core, UC_ARM_REG_PC);
        int i = 0;
        while (i < nbrk && brk[i] != pc) i++;
        if (i == nbrk && nbrk < ARMCORE_BREAKS_MAX) brk[nbrk++] = pc;
        steps++;
    }
    assert_int_equal(armcore_set_breaks(q->core, brk, nbrk), 0);
    int rc;
    while ((rc = armcore_run_to(q->core, end)) == ARMCORE_HALTED) {
        uint32_t pc = armcore_reg(q->core, UC_ARM_REG_PC);
        int i = 0;
        while (i < nbrk && brk[i] != pc) i++;
        if (i == nbrk) fail_msg("halted at 0x%08x, not at a breakpoint", pc);
        if (++hits > 2000000) fail_msg("halted %d times by 300,000 cycles: a resumed breakpoint taken again", hits);
    }
    assert_int_equal(rc, 0);
    no_crash(r), no_crash(q);
    print_message("debug halts: %d steps, %d breakpoints, %d hits\n", steps, nbrk, hits);
    assert_true(steps > 1000 && nbrk == ARMCORE_BREAKS_MAX && hits > 10000);
    print_message("debug halts: %u interrupts\n", mailbox(r).v[1]);
    assert_true(mailbox(r).v[1] > 100); /* interrupts kept coming */
    snapshot(r, a), snapshot(q, b);
    assert_memory_equal(a, b, sizeof a);
    rig_free(r), rig_free(q);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_no_libunicorn), cmocka_unit_test(test_preempt_ispr), cmocka_unit_test(test_preempt_peripheral), cmocka_unit_test(test_tail_chain),
        cmocka_unit_test(test_primask), cmocka_unit_test(test_basepri), cmocka_unit_test(test_prigroup),
        cmocka_unit_test(test_systick_period), cmocka_unit_test(test_countflag), cmocka_unit_test(test_dwt),
        cmocka_unit_test(test_vtor), cmocka_unit_test(test_svc_pendsv), cmocka_unit_test(test_process_stack), cmocka_unit_test(test_reset_request),
        cmocka_unit_test(test_bitband), cmocka_unit_test(test_unmodeled), cmocka_unit_test(test_faults),
        cmocka_unit_test(test_clock_switch), cmocka_unit_test(test_fpu_extended_frame), cmocka_unit_test(test_idle_cyccnt),
        cmocka_unit_test(test_idle_hal_delay), cmocka_unit_test(test_idle_countflag), cmocka_unit_test(test_idle_bits), cmocka_unit_test(test_idle_recur), cmocka_unit_test(test_idle_count), cmocka_unit_test(test_idle_masked), cmocka_unit_test(test_wfi_skip_same_state), cmocka_unit_test(test_chunking_same_state),
        cmocka_unit_test(test_debug_halts_same_state),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}

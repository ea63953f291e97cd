/* cortexm.c - NVIC, SCB, SysTick and DWT CYCCNT (see cortexm.h). */
#include "cortexm.h"

#include <stdio.h>
#include <string.h>

#define TRCENA_BIT (1u << 24)          /* DEMCR: DWT and ITM enabled (ARMv7-M C1.6.5) */
#define DWT_CTRL_RESET 0x40000000u     /* NUMCOMP 4 comparators (Cortex-M3 TRM r1p1 8.3) */
#define CCR_RESET 0x00000200u          /* PM0056 4.4.7: STKALIGN set */
#define AIRCR_VECTKEY 0x05FAu          /* written in [31:16] */
#define AIRCR_VECTKEYSTAT 0xFA05u      /* read in [31:16] */
#define FPCCR_RESET 0xC0000000u        /* ASPEN, LSPEN: automatic and lazy FP state preservation (B3.2.20) */
#define FPCCR_WRITABLE 0xC000017Bu     /* ASPEN, LSPEN, MONRDY, BFRDY, MMRDY, HFRDY, THREAD, USER, LSPACT */
#define CPACR_CP10_CP11 0x00F00000u    /* the FPU's access fields (B3.2.20); the other coprocessors are absent: RAZ/WI */
#define MVFR0_M4F 0x10110021u          /* Cortex-M4 TRM r0p1 chapter 7, FPU register summary: single precision, divide, square root, 16 D registers */
#define MVFR1_M4F 0x11000011u
#define ST_ENABLE 1u
#define ST_TICKINT 2u
#define ST_CLKSOURCE 4u
#define ST_COUNTFLAG (1u << 16)
#define ST_RVR_MASK 0x00FFFFFFu
enum { ICSR_PENDSTCLR = 1u << 25, ICSR_PENDSTSET = 1u << 26, ICSR_PENDSVCLR = 1u << 27, ICSR_PENDSVSET = 1u << 28,
       ICSR_NMIPENDSET = 1u << 31 };

static void set_pending(cortexm_t *cm, unsigned exc, bool on)
{
    if (cm->pending[exc] == on) return;
    cm->pending[exc] = on;
    cm->npending += on ? 1u : (unsigned)-1;
    cm->attention = true;
}

void cortexm_init(cortexm_t *cm, unsigned nirq, unsigned prio_bits, uint32_t cpuid)
{
    memset(cm, 0, sizeof *cm);
    cm->nirq = nirq > CORTEXM_IRQ_MAX ? CORTEXM_IRQ_MAX : nirq;
    cm->prio_mask = (uint8_t)(0xFFu << (8u - prio_bits));
    cm->cpuid = cpuid;
    cortexm_ops.reset(cm);
}

static void reset(void *self)
{
    cortexm_t *cm = self;
    unsigned nirq = cm->nirq;
    uint8_t mask = cm->prio_mask;
    uint32_t cpuid = cm->cpuid;
    uint64_t now = cm->now;
    bool fpu = cm->fpu;
    memset(cm, 0, sizeof *cm);
    cm->nirq = nirq, cm->prio_mask = mask, cm->cpuid = cpuid, cm->now = now, cm->fpu = fpu;
    cm->fpccr = fpu ? FPCCR_RESET : 0u;
    cm->ccr = CCR_RESET, cm->dwt_ctrl = DWT_CTRL_RESET;
    cm->st_at = cm->cyc_at = now;
    for (unsigned e = EXC_NMI; e <= EXC_SYSTICK; e++) cm->enabled[e] = true;
    cm->enabled[EXC_MEMMANAGE] = cm->enabled[EXC_BUSFAULT] = cm->enabled[EXC_USAGEFAULT] = false;
    cm->attention = true;
}

void cortexm_set_fpu(cortexm_t *cm, bool fpu)
{
    cm->fpu = fpu;
    cm->fpccr = fpu ? FPCCR_RESET : 0u;
}

void cortexm_pend(cortexm_t *cm, unsigned exc)
{
    if (exc < 16u + cm->nirq) set_pending(cm, exc, true);
}

void cortexm_set_irq(void *ctx, unsigned irq, bool level)
{
    cortexm_t *cm = ctx;
    if (irq >= cm->nirq) return;
    cm->line[EXC_IRQ0 + irq] = level;
    if (level && !cm->active[EXC_IRQ0 + irq]) set_pending(cm, EXC_IRQ0 + irq, true);
}

int cortexm_prio(const cortexm_t *cm, unsigned exc)
{
    if (exc == EXC_RESET) return -3;
    if (exc == EXC_NMI) return -2;
    if (exc == EXC_HARDFAULT) return -1;
    return cm->prio[exc];
}

int cortexm_group(const cortexm_t *cm, int prio)
{
    if (prio < 0) return prio;
    return prio & (int)(0xFFu << (cm->prigroup + 1u)) & 0xFF; /* B1.5.4: PRIGROUP bits of subpriority */
}

int cortexm_exec_prio(const cortexm_t *cm, uint32_t primask, uint32_t basepri, uint32_t faultmask)
{
    int p = 256;
    for (unsigned e = 1; e < 16u + cm->nirq; e++)
        if (cm->active[e] && cortexm_group(cm, cortexm_prio(cm, e)) < p) p = cortexm_group(cm, cortexm_prio(cm, e));
    if ((basepri & 0xFFu) && cortexm_group(cm, (int)(basepri & 0xFFu)) < p) p = cortexm_group(cm, (int)(basepri & 0xFFu));
    if ((primask & 1u) && p > 0) p = 0;
    if ((faultmask & 1u) && p > -1) p = -1;
    return p;
}

unsigned cortexm_best(const cortexm_t *cm, int *group)
{
    unsigned best = 0;
    int bp = 0;
    if (cm->npending == 0) return 0;
    for (unsigned e = 1; e < 16u + cm->nirq; e++) {
        if (!cm->pending[e] || !cm->enabled[e]) continue;
        int p = cortexm_prio(cm, e);
        if (!best || cortexm_group(cm, p) < cortexm_group(cm, bp) || (cortexm_group(cm, p) == cortexm_group(cm, bp) && p < bp))
            best = e, bp = p;
    }
    if (best && group) *group = cortexm_group(cm, bp);
    return best;
}

void cortexm_take(cortexm_t *cm, unsigned exc)
{
    set_pending(cm, exc, false);
    cm->active[exc] = true;
    cm->attention = true;
}

int cortexm_return(cortexm_t *cm, unsigned exc)
{
    if (exc == 0 || exc >= CORTEXM_EXC_MAX || !cm->active[exc]) return -1;
    cm->active[exc] = false;
    if (cm->line[exc]) set_pending(cm, exc, true); /* a level still high pends again (B3.4.1) */
    cm->attention = true;
    return 0;
}

unsigned cortexm_nactive(const cortexm_t *cm)
{
    unsigned n = 0;
    for (unsigned e = 1; e < 16u + cm->nirq; e++) n += cm->active[e];
    return n;
}

/* ---- SysTick (ARMv7-M B3.3) ---- */
static uint64_t st_div(const cortexm_t *cm) { return (cm->st_csr & ST_CLKSOURCE) ? 1u : CORTEXM_SYSTICK_EXT_DIV; }

static void st_wrap(cortexm_t *cm)
{
    cm->st_csr |= ST_COUNTFLAG;
    if (cm->st_csr & ST_TICKINT) set_pending(cm, EXC_SYSTICK, true);
}

/* t ticks of the counter: down to 0 (COUNTFLAG, the exception), then RVR reloaded on the next tick */
static void st_ticks(cortexm_t *cm, uint64_t t)
{
    uint64_t v = cm->st_cvr;
    if (v > 0 && t < v) { cm->st_cvr = (uint32_t)(v - t); return; }
    if (v > 0) t -= v, cm->st_cvr = 0, st_wrap(cm);
    uint64_t r = cm->st_rvr;
    if (t == 0 || r == 0) return; /* RVR 0: the counter stays at 0 */
    uint64_t rem = t % (r + 1);
    if (t / (r + 1)) st_wrap(cm);
    cm->st_cvr = rem == 0 ? 0 : (uint32_t)(r + 1 - rem);
}

static void advance(void *self, uint64_t now)
{
    cortexm_t *cm = self;
    if (now <= cm->now) return;
    if (cm->st_csr & ST_ENABLE) st_ticks(cm, now / st_div(cm) - cm->st_at / st_div(cm));
    cm->st_at = cm->now = now;
}

static uint64_t next_event(void *self)
{
    cortexm_t *cm = self;
    if (!(cm->st_csr & ST_ENABLE)) return MMIO_NEVER;
    uint64_t k = cm->st_cvr ? cm->st_cvr : (cm->st_rvr ? cm->st_rvr + 1u : 0);
    if (!k) return MMIO_NEVER;
    uint64_t div = st_div(cm);
    return (cm->st_at / div + k) * div;
}

/* ---- DWT CYCCNT (ARMv7-M C1.8.8) ---- */
static bool dwt_counting(const cortexm_t *cm) { return (cm->dwt_ctrl & 1u) && (cm->demcr & TRCENA_BIT); }
static uint32_t cyccnt(const cortexm_t *cm) { return cm->cyc_base + (dwt_counting(cm) ? (uint32_t)(cm->now - cm->cyc_at) : 0u); }
static void dwt_fold(cortexm_t *cm) { cm->cyc_base = cyccnt(cm), cm->cyc_at = cm->now; }

/* ---- registers ---- */
static uint32_t shcsr_read(const cortexm_t *cm)
{
    static const struct { unsigned exc, bit; } act[] = { { EXC_MEMMANAGE, 0 }, { EXC_BUSFAULT, 1 }, { EXC_USAGEFAULT, 3 },
        { EXC_SVCALL, 7 }, { EXC_DEBUGMON, 8 }, { EXC_PENDSV, 10 }, { EXC_SYSTICK, 11 } };
    uint32_t v = cm->shcsr & (7u << 16);
    for (size_t i = 0; i < sizeof act / sizeof act[0]; i++) v |= (uint32_t)cm->active[act[i].exc] << act[i].bit;
    v |= (uint32_t)cm->pending[EXC_USAGEFAULT] << 12 | (uint32_t)cm->pending[EXC_MEMMANAGE] << 13 |
         (uint32_t)cm->pending[EXC_BUSFAULT] << 14 | (uint32_t)cm->pending[EXC_SVCALL] << 15;
    return v;
}

static uint32_t icsr_read(const cortexm_t *cm)
{
    unsigned top = 0, nact = 0;
    for (unsigned e = 1; e < 16u + cm->nirq; e++)
        if (cm->active[e]) nact++, top = e; /* VECTACTIVE: IPSR; the core keeps the last taken highest, so the highest number is a stand-in */
    unsigned pend = cortexm_best(cm, NULL);
    bool isr = false;
    for (unsigned e = EXC_IRQ0; e < 16u + cm->nirq; e++) isr |= cm->pending[e];
    return top | (uint32_t)(nact <= 1) << 11 | (uint32_t)pend << 12 | (uint32_t)isr << 22 |
           (uint32_t)cm->pending[EXC_SYSTICK] << 26 | (uint32_t)cm->pending[EXC_PENDSV] << 28 | (uint32_t)cm->pending[EXC_NMI] << 31;
}

/* the 32 IRQs of bank n as a bit mask of one of the state arrays */
static uint32_t bank(const cortexm_t *cm, const bool *a, unsigned n)
{
    uint32_t v = 0;
    for (unsigned i = 0; i < 32; i++)
        if (n * 32 + i < cm->nirq && a[EXC_IRQ0 + n * 32 + i]) v |= 1u << i;
    return v;
}

static mmio_status_t nvic_read(cortexm_t *cm, uint32_t off, uint32_t *v)
{
    unsigned n = (off & 0x7Fu) / 4;
    if (n >= (cm->nirq + 31) / 32) { *v = 0; return MMIO_OK; } /* banks past the implemented lines read as zero */
    switch (off & ~0x7Fu) {
    case 0xE100: case 0xE180: *v = bank(cm, cm->enabled, n); return MMIO_OK;
    case 0xE200: case 0xE280: *v = bank(cm, cm->pending, n); return MMIO_OK;
    case 0xE300: *v = bank(cm, cm->active, n); return MMIO_OK;
    default: return MMIO_UNMODELED;
    }
}

static mmio_status_t nvic_write(cortexm_t *cm, uint32_t off, uint32_t v)
{
    unsigned n = (off & 0x7Fu) / 4;
    uint32_t base = off & ~0x7Fu;
    if (base == 0xE300) return MMIO_OK; /* IABR is read-only */
    for (unsigned i = 0; i < 32; i++) {
        unsigned e = EXC_IRQ0 + n * 32 + i;
        if (!(v >> i & 1u) || n * 32 + i >= cm->nirq) continue;
        if (base == 0xE100) cm->enabled[e] = true;
        else if (base == 0xE180) cm->enabled[e] = false;
        else if (base == 0xE200) set_pending(cm, e, true);
        else if (base == 0xE280 && !cm->line[e]) set_pending(cm, e, false); /* a level still high stays pending */
        else if (base != 0xE280) return MMIO_UNMODELED;
    }
    cm->attention = true;
    return MMIO_OK;
}

/* priority byte i of a byte-lane register: IPR (IRQ i) at 0xE400, SHPR1-3 (exceptions 4-15) at 0xED18 */
static uint8_t *prio_byte(cortexm_t *cm, uint32_t off)
{
    if (off >= 0xE400 && off < 0xE400 + cm->nirq) return &cm->prio[EXC_IRQ0 + (off - 0xE400)];
    if (off >= 0xED18 && off < 0xED24) return &cm->prio[4 + (off - 0xED18)];
    return NULL;
}

static bool is_prio(const cortexm_t *cm, uint32_t off) { return (off >= 0xE400 && off < 0xE4F0) || (off >= 0xED18 && off < 0xED24); }

/* The FPU's registers (B3.2.20, Cortex-M4 TRM 7.3); without an FPU they are not there. */
static mmio_status_t fpu_read(const cortexm_t *cm, uint32_t off, uint32_t *v)
{
    if (!cm->fpu) return MMIO_UNMODELED;
    switch (off) {
    case 0xED88: *v = cm->cpacr; return MMIO_OK;
    case 0xEF34: *v = cm->fpccr; return MMIO_OK;
    case 0xEF38: *v = cm->fpcar; return MMIO_OK;
    case 0xEF3C: *v = cm->fpdscr; return MMIO_OK;
    case 0xEF40: *v = MVFR0_M4F; return MMIO_OK;
    case 0xEF44: *v = MVFR1_M4F; return MMIO_OK;
    default: return MMIO_UNMODELED;
    }
}

static mmio_status_t fpu_write(cortexm_t *cm, uint32_t off, uint32_t v)
{
    if (!cm->fpu) return MMIO_UNMODELED;
    switch (off) {
    case 0xED88: cm->cpacr = v & CPACR_CP10_CP11; return MMIO_OK;
    case 0xEF34: cm->fpccr = v & FPCCR_WRITABLE; return MMIO_OK;
    case 0xEF38: cm->fpcar = v & ~7u; return MMIO_OK;
    case 0xEF3C: cm->fpdscr = v & 0x07C00000u; return MMIO_OK; /* AHP, DN, FZ, RMode */
    case 0xEF40: case 0xEF44: return MMIO_OK;                  /* MVFR0/1 are read-only */
    default: return MMIO_UNMODELED;
    }
}

static bool is_fpu_reg(uint32_t off) { return off == 0xED88 || (off >= 0xEF34 && off <= 0xEF44); }

static mmio_status_t scb_read(cortexm_t *cm, uint32_t off, uint32_t *v)
{
    if (is_fpu_reg(off)) return fpu_read(cm, off, v);
    switch (off) {
    case 0xE004: *v = (cm->nirq + 31) / 32 - 1; return MMIO_OK; /* ICTR INTLINESNUM */
    case 0xE008: *v = cm->actlr; return MMIO_OK;
    case 0xE010: *v = cm->st_csr; cm->st_csr &= ~ST_COUNTFLAG; return MMIO_OK; /* COUNTFLAG clears on read */
    case 0xE014: *v = cm->st_rvr; return MMIO_OK;
    case 0xE018: *v = cm->st_cvr; return MMIO_OK;
    case 0xE01C: *v = CORTEXM_SYSTICK_CALIB; return MMIO_OK;
    case 0xED00: *v = cm->cpuid; return MMIO_OK;
    case 0xED04: *v = icsr_read(cm); return MMIO_OK;
    case 0xED08: *v = cm->vtor; return MMIO_OK;
    case 0xED0C: *v = AIRCR_VECTKEYSTAT << 16 | cm->prigroup << 8; return MMIO_OK;
    case 0xED10: *v = cm->scr; return MMIO_OK;
    case 0xED14: *v = cm->ccr; return MMIO_OK;
    case 0xED24: *v = shcsr_read(cm); return MMIO_OK;
    case 0xED28: *v = cm->cfsr; return MMIO_OK;
    case 0xED2C: *v = cm->hfsr; return MMIO_OK;
    case 0xED34: *v = cm->mmfar; return MMIO_OK;
    case 0xED38: *v = cm->bfar; return MMIO_OK;
    case 0xEDFC: *v = cm->demcr; return MMIO_OK;
    case 0x1000: *v = cm->dwt_ctrl; return MMIO_OK;
    case 0x1004: *v = cyccnt(cm); return MMIO_OK;
    default: return off >= 0xE100 && off < 0xE380 ? nvic_read(cm, off, v) : MMIO_UNMODELED;
    }
}

static mmio_status_t icsr_write(cortexm_t *cm, uint32_t v)
{
    if (v & ICSR_NMIPENDSET) set_pending(cm, EXC_NMI, true);
    if (v & ICSR_PENDSVSET) set_pending(cm, EXC_PENDSV, true);
    else if (v & ICSR_PENDSVCLR) set_pending(cm, EXC_PENDSV, false);
    if (v & ICSR_PENDSTSET) set_pending(cm, EXC_SYSTICK, true);
    else if (v & ICSR_PENDSTCLR) set_pending(cm, EXC_SYSTICK, false);
    return MMIO_OK;
}

static mmio_status_t aircr_write(cortexm_t *cm, uint32_t v)
{
    if (v >> 16 != AIRCR_VECTKEY) return MMIO_OK; /* a write without the key is ignored (B3.2.6) */
    cm->prigroup = v >> 8 & 7u;
    if (v & 4u) cm->reset_request = true; /* SYSRESETREQ */
    if (v & 3u) return MMIO_UNMODELED;    /* VECTRESET, VECTCLRACTIVE: debug only */
    cm->attention = true;
    return MMIO_OK;
}

static mmio_status_t systick_write(cortexm_t *cm, uint32_t off, uint32_t v)
{
    if (off == 0xE010) {
        bool was = cm->st_csr & ST_ENABLE;
        cm->st_csr = (cm->st_csr & ST_COUNTFLAG) | (v & (ST_ENABLE | ST_TICKINT | ST_CLKSOURCE));
        if (!was && (v & ST_ENABLE)) cm->st_at = cm->now;
    } else if (off == 0xE014) {
        cm->st_rvr = v & ST_RVR_MASK;
    } else if (off == 0xE018) {
        cm->st_cvr = 0, cm->st_csr &= ~ST_COUNTFLAG; /* any write clears the counter and COUNTFLAG */
    } else {
        return MMIO_OK; /* CALIB is read-only */
    }
    cm->attention = true;
    return MMIO_OK;
}

static mmio_status_t scb_write(cortexm_t *cm, uint32_t off, uint32_t v)
{
    if (is_fpu_reg(off)) return fpu_write(cm, off, v);
    switch (off) {
    case 0xE008: cm->actlr = v & 7u; return MMIO_OK;
    case 0xE010: case 0xE014: case 0xE018: case 0xE01C: return systick_write(cm, off, v);
    case 0xED04: return icsr_write(cm, v);
    case 0xED08: cm->vtor = v & 0x3FFFFF80u; return MMIO_OK; /* TBLOFF [29:7] (B3.2.5) */
    case 0xED0C: return aircr_write(cm, v);
    case 0xED10: cm->scr = v & 0x16u; return MMIO_OK;
    case 0xED14: cm->ccr = v & 0x31Bu; return MMIO_OK;
    case 0xED24:
        cm->shcsr = v & (7u << 16);
        cm->enabled[EXC_MEMMANAGE] = v >> 16 & 1u, cm->enabled[EXC_BUSFAULT] = v >> 17 & 1u, cm->enabled[EXC_USAGEFAULT] = v >> 18 & 1u;
        cm->attention = true;
        return MMIO_OK;
    case 0xED28: cm->cfsr &= ~v; return MMIO_OK; /* write one to clear */
    case 0xED2C: cm->hfsr &= ~v; return MMIO_OK;
    case 0xED34: cm->mmfar = v; return MMIO_OK;
    case 0xED38: cm->bfar = v; return MMIO_OK;
    case 0xEDFC: dwt_fold(cm); cm->demcr = v & 0x010F07F1u; return MMIO_OK;
    case 0xEF00: if ((v & 0x1FFu) < cm->nirq) set_pending(cm, EXC_IRQ0 + (v & 0x1FFu), true); return MMIO_OK; /* STIR */
    case 0x1000: dwt_fold(cm); cm->dwt_ctrl = (cm->dwt_ctrl & 0xF0000000u) | (v & 1u); return (v & ~0xF0000001u) ? MMIO_UNMODELED : MMIO_OK;
    case 0x1004: cm->cyc_base = v, cm->cyc_at = cm->now; return MMIO_OK;
    default: return off >= 0xE100 && off < 0xE380 ? nvic_write(cm, off, v) : MMIO_UNMODELED;
    }
}

static mmio_status_t ppb_read(void *self, uint32_t off, unsigned size, uint32_t *value)
{
    cortexm_t *cm = self;
    if (is_prio(cm, off)) { /* byte, halfword or word over priority bytes */
        uint32_t v = 0;
        for (unsigned i = 0; i < size; i++) {
            uint8_t *p = prio_byte(cm, off + i);
            v |= (uint32_t)(p ? *p : 0u) << (8 * i);
        }
        *value = v;
        return MMIO_OK;
    }
    if (size != 4 || (off & 3u)) return MMIO_UNMODELED; /* the rest are word registers (B3.2.1) */
    return scb_read(cm, off, value);
}

static mmio_status_t ppb_write(void *self, uint32_t off, unsigned size, uint32_t value)
{
    cortexm_t *cm = self;
    if (is_prio(cm, off)) {
        for (unsigned i = 0; i < size; i++) {
            uint8_t *p = prio_byte(cm, off + i);
            if (p) *p = (uint8_t)(value >> (8 * i)) & cm->prio_mask;
        }
        cm->attention = true;
        return MMIO_OK;
    }
    if (size != 4 || (off & 3u)) return MMIO_UNMODELED;
    return scb_write(cm, off, value);
}

const mmio_ops_t cortexm_ops = {
    .name = "PPB", .read = ppb_read, .write = ppb_write, .advance = advance, .next_event = next_event, .reset = reset,
};

/* The set bits of v named by names[0..32) (NULL: reserved) appended to out at *at. */
static void bit_names(uint32_t v, const char *const *names, char *out, size_t n, size_t *at)
{
    for (int b = 0; b < 32; b++) {
        if (!(v & (1u << b)) || !names[b] || *at >= n) continue;
        int k = snprintf(out + *at, n - *at, " %s", names[b]);
        *at += k > 0 ? (size_t)k : 0u;
    }
}

void cortexm_fault_text(const cortexm_t *cm, char *out, size_t n)
{
    /* CFSR = UFSR:BFSR:MMFSR (B3.2.15); HFSR (B3.2.16) */
    static const char *const cfsr[32] = { [0] = "IACCVIOL", [1] = "DACCVIOL", [3] = "MUNSTKERR", [4] = "MSTKERR", [5] = "MLSPERR",
        [7] = "MMARVALID", [8] = "IBUSERR", [9] = "PRECISERR", [10] = "IMPRECISERR", [11] = "UNSTKERR", [12] = "STKERR",
        [13] = "LSPERR", [15] = "BFARVALID", [16] = "UNDEFINSTR", [17] = "INVSTATE", [18] = "INVPC", [19] = "NOCP",
        [24] = "UNALIGNED", [25] = "DIVBYZERO" };
    static const char *const hfsr[32] = { [1] = "VECTTBL", [30] = "FORCED", [31] = "DEBUGEVT" };
    size_t at = 0;
    int k = snprintf(out, n, "CFSR 0x%08x:", cm->cfsr);
    at = k > 0 ? (size_t)k : 0u;
    bit_names(cm->cfsr, cfsr, out, n, &at);
    if ((cm->cfsr & 0x80u) && at < n) at += (size_t)snprintf(out + at, n - at, " (MMFAR 0x%08x)", cm->mmfar);
    if ((cm->cfsr & 0x8000u) && at < n) at += (size_t)snprintf(out + at, n - at, " (BFAR 0x%08x)", cm->bfar);
    if (at < n) at += (size_t)snprintf(out + at, n - at, ", HFSR 0x%08x:", cm->hfsr);
    bit_names(cm->hfsr, hfsr, out, n, &at);
}

/* stm32f4_flash.c - STM32F4 flash interface: RM0090 rev 19 section 3 (3.4
 * ACR: LATENCY, PRFTEN, ICEN, DCEN, ICRST, DCRST; 3.5.1 unlock: KEY1
 * 0x45670123 then KEY2 0xCDEF89AB, a wrong sequence a bus error and CR
 * locked until reset; 3.5.3 sector erase SER/SNB/STRT and mass erase MER;
 * 3.5.4 programming with PG and PSIZE: a write of another size sets PGPERR,
 * a misaligned one PGAERR, a write without PG PGSERR, none of them
 * programming; programming only clears bits ("successive write operations
 * are possible ... when changing bits from 1 to 0"); 3.7 interrupts EOP
 * with EOPIE, errors with ERRIE; 3.8 registers) and RM0383 rev 3 section 3.
 * BSY lasts the F405/407 datasheet's typical times (DS8626 rev 9, table
 * "Flash memory programming": tprog 16 us per write; tERASE16KB 400/300/250
 * ms, tERASE64KB 1200/700/550 ms, tERASE128KB 2/1.3/1 s, tME 16/11/8 s at
 * x8/x16/x32 parallelism; x64 taken as x32), at the HCLK of the start.
 * An erase's 0xFF appear when BSY falls.
 * Modeled also: the ACR read back (the wait states themselves are the
 * core's, which counts none), OPTCR read as its erased reset value.
 * Not modeled (MMIO_UNMODELED): option byte programming (OPTKEYR, OPTCR
 * writes), the OTP area. Stated limits: the core's stall on a flash
 * access while BSY is not modeled; the array is written at once and read
 * back at once. */
#include "arm/stm32f4_flash.h"

#include <string.h>

#include "arm/stm32f1_clk.h"
#include "arm/stm32f4_reg.h"

enum { ACR = 0x00, KEYR = 0x04, OPTKEYR = 0x08, SR = 0x0C, CR = 0x10, OPTCR = 0x14 };
#define KEY1 0x45670123u
#define KEY2 0xCDEF89ABu
#define ACR_ICRST (1u << 11)
#define ACR_DCRST (1u << 12)
#define SR_EOP    (1u << 0)
#define SR_OPERR  (1u << 1)
#define SR_WRPERR (1u << 4)
#define SR_PGAERR (1u << 5)
#define SR_PGPERR (1u << 6)
#define SR_PGSERR (1u << 7)
#define SR_BSY    (1u << 16)
#define SR_FLAGS  0x000001F3u /* EOP, OPERR, WRPERR, PGAERR, PGPERR, PGSERR, RDERR: rc_w1 */
#define SR_ERRORS (SR_OPERR | SR_WRPERR | SR_PGAERR | SR_PGPERR | SR_PGSERR)
#define CR_PG     (1u << 0)
#define CR_SER    (1u << 1)
#define CR_MER    (1u << 2)
#define CR_SNB_SHIFT 3
#define CR_PSIZE_SHIFT 8
#define CR_STRT   (1u << 16)
#define CR_EOPIE  (1u << 24)
#define CR_ERRIE  (1u << 25)
#define CR_LOCK   (1u << 31)
#define CR_MASK   0x030103FFu
#define OPTCR_RESET 0x0FFFAAEDu /* RM0090 3.8.7, RM0383 3.8.6 */

/* DS8626 "Flash memory programming", typical, by parallelism x8, x16, x32. */
#define TPROG_US 16u
static const uint32_t erase_ms[3][3] = { { 400, 300, 250 }, { 1200, 700, 550 }, { 2000, 1300, 1000 } };
static const uint32_t mass_erase_ms[3] = { 16000, 11000, 8000 };

bool stm32f4_flash_sector(const stm32f4_flash_t *f, unsigned n, uint32_t *off, uint32_t *len)
{
    uint32_t o = n < 4 ? n * 0x4000u : n == 4 ? 0x10000u : 0x20000u * (n - 4);
    uint32_t l = n < 4 ? 0x4000u : n == 4 ? 0x10000u : 0x20000u;
    if (n >= STM32F4_FLASH_SECTORS || o + l > f->size) return false;
    *off = o;
    *len = l;
    return true;
}

static void update_irq(stm32f4_flash_t *f)
{
    bool lv = ((f->sr & SR_EOP) && (f->cr & CR_EOPIE)) || ((f->sr & SR_ERRORS) && (f->cr & CR_ERRIE));
    if (lv == f->irq_level) return;
    f->irq_level = lv;
    if (f->irq.set) f->irq.set(f->irq.ctx, STM32F4_FLASH_IRQ, lv);
}

static uint64_t ms_cycles(const stm32f4_flash_t *f, uint64_t us)
{
    return stm32_ticks_to_cycles(us, f->clk->hclk, 1000000u);
}

static unsigned parallelism(const stm32f4_flash_t *f)
{
    unsigned p = (f->cr >> CR_PSIZE_SHIFT) & 3u;
    return p > 2 ? 2 : p;
}

static void busy_for(stm32f4_flash_t *f, uint64_t us)
{
    uint64_t from = f->busy_until > f->now ? f->busy_until : f->now;
    f->busy_until = stm32_at(from, ms_cycles(f, us));
    f->sr |= SR_BSY;
    f->eop_due = f->cr & CR_EOPIE;
}

static void flash_advance(void *self, uint64_t now)
{
    stm32f4_flash_t *f = self;
    if (now > f->now) f->now = now;
    if (!(f->sr & SR_BSY) || f->now < f->busy_until) return;
    f->sr &= ~SR_BSY;
    if (f->erase_len) { memset(f->mem + f->erase_off, 0xFF, f->erase_len); f->erase_len = 0; }
    if (f->eop_due) f->sr |= SR_EOP;
    f->eop_due = false;
    update_irq(f);
}

static uint64_t flash_next_event(void *self)
{
    const stm32f4_flash_t *f = self;
    return (f->sr & SR_BSY) ? f->busy_until : MMIO_NEVER;
}

/* STRT: a sector or mass erase (RM0090 3.5.3). */
static mmio_status_t start_erase(stm32f4_flash_t *f)
{
    bool ser = f->cr & CR_SER, mer = f->cr & CR_MER;
    unsigned p = parallelism(f);
    if (ser == mer) { f->sr |= SR_PGSERR; return MMIO_OK; } /* neither, or both: nothing erased */
    if (mer) {
        f->erase_off = 0;
        f->erase_len = f->size;
        for (uint32_t o, l, n = 0; stm32f4_flash_sector(f, n, &o, &l); n++) f->sectors_erased++;
        busy_for(f, 1000u * mass_erase_ms[p]);
        return MMIO_OK;
    }
    unsigned snb = (f->cr >> CR_SNB_SHIFT) & 0xFu;
    uint32_t off, len;
    if (!stm32f4_flash_sector(f, snb, &off, &len)) return MMIO_UNMODELED; /* no such sector on this part */
    f->erase_off = off;
    f->erase_len = len;
    f->sectors_erased++;
    busy_for(f, 1000u * erase_ms[snb < 4 ? 0 : snb == 4 ? 1 : 2][p]);
    return MMIO_OK;
}

mmio_status_t stm32f4_flash_mem_write(stm32f4_flash_t *f, uint32_t off, unsigned size, uint32_t value)
{
    flash_advance(f, f->now);
    uint32_t err = 0;
    if (!(f->cr & CR_PG) || (f->cr & CR_LOCK)) err = SR_PGSERR;
    else if (size != 1u << ((f->cr >> CR_PSIZE_SHIFT) & 3u)) err = SR_PGPERR;
    else if ((off & (size - 1)) || off + size > f->size) err = SR_PGAERR;
    if (err) {
        f->sr |= err;
        update_irq(f);
        return MMIO_OK;
    }
    for (unsigned i = 0; i < size; i++) f->mem[off + i] &= (uint8_t)(value >> (8 * i)); /* 1 -> 0 only */
    f->programmed++;
    busy_for(f, TPROG_US);
    return MMIO_OK;
}

static bool valid(uint32_t off) { return off <= OPTCR; }

static uint32_t peek(const stm32f4_flash_t *f, uint32_t off)
{
    switch (off) {
    case ACR: return f->acr;
    case SR: return f->sr;
    case CR: return f->cr;
    case OPTCR: return f->optcr;
    default: return 0; /* KEYR, OPTKEYR: write-only */
    }
}

static mmio_status_t flash_read(void *self, uint32_t off, unsigned size, uint32_t *value)
{
    stm32f4_flash_t *f = self;
    if (!stm32_access_ok(off, size) || !valid(off & ~3u)) return MMIO_UNMODELED;
    *value = stm32_read_lanes(peek(f, off & ~3u), off, size);
    return MMIO_OK;
}

static mmio_status_t write_keyr(stm32f4_flash_t *f, uint32_t v)
{
    if (f->locked_out || !(f->cr & CR_LOCK)) { f->locked_out = true; f->cr |= CR_LOCK; return MMIO_BUS_FAULT; }
    if (f->key_step == 0 && v == KEY1) { f->key_step = 1; return MMIO_OK; }
    if (f->key_step == 1 && v == KEY2) { f->key_step = 0; f->cr &= ~CR_LOCK; return MMIO_OK; }
    f->locked_out = true; /* RM0090 3.5.1: a wrong sequence locks CR until the next reset */
    return MMIO_BUS_FAULT;
}

static mmio_status_t write_cr(stm32f4_flash_t *f, uint32_t v)
{
    if (f->cr & CR_LOCK) return MMIO_OK; /* locked: the write is ignored */
    f->cr = (v & CR_MASK) | (v & CR_LOCK);
    mmio_status_t st = MMIO_OK;
    if (v & CR_STRT) st = (f->sr & SR_BSY) ? MMIO_OK : start_erase(f);
    f->cr &= ~CR_STRT; /* cleared as the operation starts (reads 0 once BSY falls) */
    update_irq(f);
    return st;
}

static mmio_status_t flash_write(void *self, uint32_t off, unsigned size, uint32_t value)
{
    stm32f4_flash_t *f = self;
    if (!stm32_access_ok(off, size) || !valid(off & ~3u)) return MMIO_UNMODELED;
    uint32_t w = off & ~3u, v = stm32f4_merge(peek(f, w), off, size, value);
    switch (w) {
    case ACR: {
        uint32_t lat = f->part == STM32F4_F405 ? 0x7u : 0xFu;
        f->acr = v & (lat | 0x700u); /* ICRST/DCRST act at once and read 0 */
        return MMIO_OK;
    }
    case KEYR: return write_keyr(f, value);
    case SR:
        f->sr &= ~(stm32f4_lane_value(off, size, value) & SR_FLAGS);
        update_irq(f);
        return MMIO_OK;
    case CR: return write_cr(f, v);
    default: return MMIO_UNMODELED; /* OPTKEYR, OPTCR: option bytes */
    }
}

static void flash_reset(void *self)
{
    stm32f4_flash_t *f = self;
    f->acr = f->sr = 0;
    f->cr = CR_LOCK; /* RM0090 3.8.5: reset 0x8000 0000 */
    f->optcr = OPTCR_RESET;
    f->key_step = 0;
    f->locked_out = false;
    f->busy_until = 0;
    f->erase_len = 0;
    f->eop_due = false;
    update_irq(f);
}

const mmio_ops_t stm32f4_flash_ops = { "FLASH", flash_read, flash_write, flash_advance, flash_next_event,
                                       flash_reset };

void stm32f4_flash_init(stm32f4_flash_t *f, stm32f4_part_t part, uint8_t *mem, uint32_t size,
                        const mmio_clocks_t *clk, mmio_irq_t irq)
{
    *f = (stm32f4_flash_t){ 0 };
    f->part = part;
    f->mem = mem;
    f->size = size;
    f->clk = clk;
    f->irq = irq;
    flash_reset(f);
}

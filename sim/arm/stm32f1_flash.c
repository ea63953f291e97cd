/* stm32f1_flash.c - the STM32F1's flash interface (stm32f1_flash.h):
 * RM0008 3.3.3, PM0075 2.3 (operations) and 3 (registers). */
#include "arm/stm32f1_flash.h"

#include <string.h>

#include "arm/stm32f1_reg.h"
#include "io/memfile.h"

/* FLASH_ACR (RM0008 3.3.3, PM0075 3.1) */
#define ACR_WMASK 0x1Fu        /* LATENCY 2:0, HLFCYA 3, PRFTBE 4 */
#define ACR_PRFTBE (1u << 4)
#define ACR_PRFTBS (1u << 5)
#define ACR_RESET 0x30u
/* FLASH_KEYR (PM0075 3.2) */
#define KEY1 0x45670123u
#define KEY2 0xCDEF89ABu
/* FLASH_SR (PM0075 3.4) */
#define SR_BSY (1u << 0)
#define SR_PGERR (1u << 2)
#define SR_WRPRTERR (1u << 4)
#define SR_EOP (1u << 5)
#define SR_W1C (SR_PGERR | SR_WRPRTERR | SR_EOP)
/* FLASH_CR (PM0075 3.5) */
#define CR_PG (1u << 0)
#define CR_PER (1u << 1)
#define CR_MER (1u << 2)
#define CR_OPTPG (1u << 4)
#define CR_OPTER (1u << 5)
#define CR_STRT (1u << 6)
#define CR_LOCK (1u << 7)
#define CR_ERRIE (1u << 10)
#define CR_EOPIE (1u << 12)
#define CR_WMASK (CR_PG | CR_PER | CR_MER | CR_OPTPG | CR_OPTER | CR_STRT | CR_ERRIE | CR_EOPIE)
#define CR_RESET 0x80u
/* the option bytes as erased: OBR (RDPRT 0, user options all 1), WRPR all 1 (PM0075 3.7, 3.8) */
#define OBR_ERASED 0x03FFFFFCu
#define WRPR_ERASED 0xFFFFFFFFu

/* Operation times, ns (DS5319 section 5.3, 'Flash memory characteristics'):
 * tprog 52.5 us typical (a half-word); tERASE and tME 20-40 ms, no
 * typical given: the middle, 30 ms. */
#define PROG_NS 52500u
#define ERASE_NS 30000000u

static void update_irq(stm32f1_flash_t *f)
{
    int on = ((f->cr & CR_EOPIE) && (f->sr & SR_EOP)) || ((f->cr & CR_ERRIE) && (f->sr & (SR_PGERR | SR_WRPRTERR)));
    if (f->irq.set) f->irq.set(f->irq.ctx, STM32F1_FLASH_IRQ, on);
}

/* BSY for ns from now, or from the end of the operation under way. */
static void busy_for(stm32f1_flash_t *f, uint64_t ns)
{
    uint64_t from = f->busy_until > f->now ? f->busy_until : f->now;
    f->busy_until = from + stm32f1_cycles_for(ns, 1000000000u, f->clk->hclk);
    f->sr |= SR_BSY;
}

static void flash_advance(void *self, uint64_t now)
{
    stm32f1_flash_t *f = self;
    if (now < f->now) return;
    f->now = now;
    if ((f->sr & SR_BSY) && now >= f->busy_until) {
        f->sr = (f->sr & ~SR_BSY) | SR_EOP; /* PM0075 3.4: EOP at the end of a program or erase */
        f->cr &= ~CR_STRT;                  /* STRT falls with BSY */
        update_irq(f);
    }
}

static uint64_t flash_next_event(void *self)
{
    const stm32f1_flash_t *f = self;
    return (f->sr & SR_BSY) ? f->busy_until : MMIO_NEVER;
}

static void flash_reset(void *self)
{
    stm32f1_flash_t *f = self;
    f->acr = ACR_RESET, f->sr = 0, f->cr = CR_RESET, f->ar = 0;
    f->key1_seen = f->locked_out = 0;
    f->busy_until = f->now;
    update_irq(f);
}

void stm32f1_flash_init(stm32f1_flash_t *f, uint8_t *mem, uint32_t size, uint32_t page, const mmio_clocks_t *clk,
                        mmio_irq_t irq)
{
    memset(f, 0, sizeof *f);
    f->mem = mem, f->size = size, f->page = page ? page : STM32F1_FLASH_PAGE_MD;
    f->clk = clk, f->irq = irq;
    flash_reset(f);
}

/* PM0075 2.3.2: KEY1 then KEY2 unlocks CR; any other sequence is a bus
 * error and locks the FPEC until the next reset. */
static mmio_status_t write_keyr(stm32f1_flash_t *f, uint32_t v, unsigned size)
{
    if (!f->locked_out && size == 4) {
        if (!f->key1_seen && v == KEY1 && (f->cr & CR_LOCK)) return f->key1_seen = 1, MMIO_OK;
        if (f->key1_seen && v == KEY2) return f->key1_seen = 0, f->cr &= ~CR_LOCK, MMIO_OK;
    }
    f->locked_out = 1, f->key1_seen = 0, f->cr |= CR_LOCK;
    return MMIO_BUS_FAULT;
}

/* STRT with PER: the page holding AR; with MER: all of it (PM0075 2.3.4, 2.3.5). */
static void start_erase(stm32f1_flash_t *f)
{
    if (f->cr & CR_MER) {
        memset(f->mem, 0xFF, f->size);
        f->erased += f->size / f->page, f->changed = 1;
    } else {
        uint32_t off = f->ar - STM32F1_FLASH_BASE;
        if (f->ar >= STM32F1_FLASH_BASE && off < f->size) {
            memset(f->mem + off / f->page * f->page, 0xFF, f->page);
            f->erased++, f->changed = 1;
        } /* an address outside the flash erases nothing (the chip's answer is not documented) */
    }
    busy_for(f, ERASE_NS);
}

static mmio_status_t write_cr(stm32f1_flash_t *f, uint32_t v, uint32_t mask)
{
    if (f->cr & CR_LOCK) return MMIO_OK; /* CR is write-protected while locked (PM0075 3.5) */
    uint32_t old = f->cr;
    f->cr = stm32f1_reg_merge(f->cr, v, mask, CR_WMASK & ~CR_STRT);
    if (v & mask & CR_LOCK) f->cr |= CR_LOCK; /* LOCK: set by software only */
    mmio_status_t st = (f->cr & (CR_OPTPG | CR_OPTER)) ? MMIO_UNMODELED : MMIO_OK;
    if ((v & mask & CR_STRT) && !(old & CR_STRT) && (f->cr & (CR_PER | CR_MER))) {
        f->cr |= CR_STRT;
        start_erase(f);
    }
    update_irq(f);
    return st;
}

static mmio_status_t flash_write(void *self, uint32_t off, unsigned size, uint32_t value)
{
    stm32f1_flash_t *f = self;
    uint32_t v = stm32f1_reg_wvalue(off, size, value), m = stm32f1_reg_mask(off, size);
    switch (stm32f1_reg_word(off)) {
    case 0x00: f->acr = stm32f1_reg_merge(f->acr, v, m, ACR_WMASK); break;
    case 0x04: return write_keyr(f, value, size);
    case 0x0C:
        f->sr &= ~(v & m & SR_W1C);
        update_irq(f);
        break;
    case 0x10: return write_cr(f, v, m);
    case 0x14: f->ar = stm32f1_reg_merge(f->ar, v, m, 0xFFFFFFFFu); break;
    default: return MMIO_UNMODELED; /* OPTKEYR: option bytes; OBR, WRPR read-only */
    }
    f->acr = (f->acr & ~ACR_PRFTBS) | ((f->acr & ACR_PRFTBE) ? ACR_PRFTBS : 0); /* the buffer follows its enable */
    return MMIO_OK;
}

static mmio_status_t flash_read(void *self, uint32_t off, unsigned size, uint32_t *value)
{
    const stm32f1_flash_t *f = self;
    uint32_t reg;
    switch (stm32f1_reg_word(off)) {
    case 0x00: reg = f->acr; break;
    case 0x04: reg = 0; break; /* KEYR: write-only, reads 0 */
    case 0x0C: reg = f->sr; break;
    case 0x10: reg = f->cr; break;
    case 0x14: reg = f->ar; break;
    case 0x1C: reg = OBR_ERASED; break;
    case 0x20: reg = WRPR_ERASED; break;
    default: return MMIO_UNMODELED; /* OPTKEYR */
    }
    *value = stm32f1_reg_rvalue(off, size, reg);
    return MMIO_OK;
}

const mmio_ops_t stm32f1_flash_ops = {
    .name = "FLASH", .read = flash_read, .write = flash_write,
    .advance = flash_advance, .next_event = flash_next_event, .reset = flash_reset,
};

/* PM0075 2.3.3: a half-word at a time into an erased location (0xFFFF);
 * 0x0000 may be written over anything; otherwise PGERR and nothing
 * written. */
mmio_status_t stm32f1_flash_mem_write(stm32f1_flash_t *f, uint32_t off, unsigned size, uint32_t value)
{
    if (!(f->cr & CR_PG) || (f->cr & CR_LOCK)) return MMIO_UNMODELED; /* dropped, reported */
    if (size != 2 || (off & 1u) || off + 2 > f->size) return MMIO_BUS_FAULT;
    uint16_t hw = (uint16_t)value, old = (uint16_t)(f->mem[off] | f->mem[off + 1] << 8);
    f->ar = STM32F1_FLASH_BASE + off;
    if (old != 0xFFFFu && hw != 0) {
        f->sr |= SR_PGERR;
    } else {
        f->mem[off] = (uint8_t)hw, f->mem[off + 1] = (uint8_t)(hw >> 8);
        f->programmed++, f->changed = 1;
        busy_for(f, PROG_NS);
    }
    update_irq(f);
    return MMIO_OK;
}

int stm32f1_flash_load(stm32f1_flash_t *f, const char *path, const char *what, char *err, size_t errn)
{
    if (memfile_load(path, f->mem, f->size, 0xFF, what, err, errn) != 0) return -1;
    f->changed = 0;
    return 0;
}

int stm32f1_flash_save(const stm32f1_flash_t *f, const char *path, char *err, size_t errn)
{
    return memfile_save(path, f->mem, f->size, err, errn);
}

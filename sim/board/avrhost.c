/* avrhost.c - one AVR core in simavr (see avrhost.h). */
#include "avrhost.h"

#include <errno.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include <simavr/avr_ioport.h>
#include <simavr/avr_uart.h>
#include <simavr/sim_avr.h>
#include <simavr/sim_cycle_timers.h>
#include <simavr/sim_elf.h>
#include <simavr/sim_io.h>
#include <simavr/sim_irq.h>

#include "image_mcu.h"
#include "io/infile.h"

static elf_firmware_t fw; /* the ELF between avrhost_read and avrhost_put (large: off the stack) */

/* simavr's messages: errors kept for our one-line messages (the last one),
 * never printed by simavr itself; the rest dropped */
static char last_log[200];
/* simavr's avr_sadly_crashed said its name (its log line) since the last
 * run: with gdb's stub on it halts the core (cpu_Stopped) instead of
 * cpu_Crashed, to wait for gdb; the host ends the run as without gdb */
static int sadly_crashed;

static void quiet_logger(avr_t *avr, const int level, const char *fmt, va_list ap)
{
    (void)avr;
    if (level > LOG_ERROR) return;
    vsnprintf(last_log, sizeof last_log, fmt, ap);
    size_t n = strlen(last_log);
    while (n > 0 && (last_log[n - 1] == '\n' || last_log[n - 1] == '\r')) last_log[--n] = '\0';
    if (!strcmp(last_log, "avr_sadly_crashed")) sadly_crashed = 1;
}

static void log_install(void) { avr_global_logger_set(quiet_logger); }
static void log_clear(void) { last_log[0] = '\0'; }
/* ": MESSAGE" if simavr said something since log_clear, else "" (to append to an error line) */
static const char *log_sep(void) { return last_log[0] ? ": " : ""; }

/* The host's stop: a cycle timer that does nothing. simavr runs
 * instructions in a batch (avr_run_one loops while the cycles left before
 * the next cycle timer, run_cycle_count, exceed the instruction's; no
 * interrupt pending; the core running) and ends the batch at the first
 * instruction boundary at or past the next timer's cycle. Without this
 * timer a batch would run past the step; with it, the AVR stops at the
 * same boundary as running one instruction per avr_run call. */
static avr_cycle_count_t on_stop(avr_t *avr, avr_cycle_count_t when, void *param)
{
    (void)avr, (void)when, (void)param;
    return 0;
}

/* The core's sleep callback: the host never sleeps (time is cycles, not the
 * wall clock). A sleeping core jumps how_long cycles, to its next cycle
 * timer; the jump is made as long as simavr makes it without the host's
 * stop and with its own level check (extint_level.h): to the next other
 * timer, or simavr's 1000 cycles when none, or 1 cycle while simavr's check
 * would run, so a sleeping firmware wakes at the cycle it wakes at in
 * simavr alone. */
static void no_sleep(avr_t *avr, avr_cycle_count_t how_long)
{
    avr_cycle_timer_slot_p t = avr->cycle_timers.timer;
    while (t && t->timer == on_stop) t = t->next;
    avr_cycle_count_t plain = extint_level_sleep(avr, t ? t->when - avr->cycle : AVRHOST_NO_TIMER_SLEEP_CYCLES);
    avr->cycle += plain - how_long; /* modulo 2^64: a shorter jump too; simavr adds 1 + how_long after this call */
}

/* e_flags' AVR architecture arch (0: none) that of the MCU want, where image_mcu_arch knows it */
static int check_arch(const char *path, unsigned arch, const char *want, const char *board, char *err, size_t errn)
{
    unsigned need = image_mcu_arch(want);
    if (!arch || !need || arch == need) return 0;
    if (board)
        return snprintf(err, errn, "%s: built for another MCU (AVR architecture avr%u; the board %s has an %s: avr%u)", path,
                        arch, board, want, need), -1;
    return snprintf(err, errn, "%s: built for another MCU (AVR architecture avr%u; --avr runs an %s: avr%u; see --mcu)", path,
                    arch, want, need), -1;
}

/* the ELF checked by our reader, its MCU matched, then read by simavr with the tags that would act dropped */
static int read_elf(avrhost_image_t *img, const char *path, const char *want_mcu, const char *board, char *err, size_t errn)
{
    image_elf_t ie;
    if (image_check_elf(path, AVRHOST_IMAGE_MAX_BYTES, &ie, err, errn) != 0) return -1;
    const char *want = want_mcu ? want_mcu : ie.mcu[0] ? ie.mcu : AVRHOST_DEFAULT_MCU;
    if (check_arch(path, ie.arch, want, board, err, errn) != 0) return -1;
    if (ie.mcu[0] && strcmp(ie.mcu, want))
        return board ? snprintf(err, errn, "%s: built for the %s; the board %s has an %s", path, ie.mcu, board, want)
                     : snprintf(err, errn, "%s: built for the %s; --mcu says %s", path, ie.mcu, want), -1;
    memset(&fw, 0, sizeof fw);
    log_clear();
    if (elf_read_firmware(path, &fw) != 0 || fw.flashsize == 0)
        return snprintf(err, errn, "%s: not an AVR ELF image%s%s", path, log_sep(), last_log), -1;
    /* an image never makes the simulator write a file or take commands: no VCD trace, command or console register */
    fw.tracename[0] = '\0';
    fw.tracecount = 0;
    fw.traceperiod = 0;
    fw.command_register_addr = 0;
    fw.console_register_addr = 0;
    snprintf(img->mcu, sizeof img->mcu, "%s", ie.mcu);
    img->f_cpu = ie.f_cpu;
    return 0;
}

int avrhost_read(avrhost_image_t *img, const char *path, int hex_ok, const char *want_mcu, const char *board, char *err,
                 size_t errn)
{
    memset(img, 0, sizeof *img);
    log_install(); /* simavr's messages about the file: ours, not printed */
    size_t n = strlen(path);
    if (access(path, R_OK) != 0) return snprintf(err, errn, "%s: cannot read: %s", path, strerror(errno)), -1;
    FILE *f = infile_open(path, AVRHOST_IMAGE_MAX_BYTES, NULL, err, errn); /* a FIFO would hang the open */
    if (!f) return -1;
    uint8_t h[4] = { 0 }; /* the ELF magic */
    size_t got = fread(h, 1, sizeof h, f);
    fclose(f);
    if (hex_ok && n > 4 && !strcmp(path + n - 4, ".hex")) {
        img->hex = 1;
        return image_read_hex(path, AVRHOST_IMAGE_MAX_BYTES, &img->bytes, err, errn);
    }
    if (got < sizeof h || memcmp(h, "\x7f" "ELF", 4) != 0)
        return snprintf(err, errn, "%s: not an AVR ELF image%s", path, hex_ok ? " (or a .hex file)" : ""), -1;
    return read_elf(img, path, want_mcu, board, err, errn);
}

/* An IO module of ours in the core's list: its reset hook counts the
 * watchdog's resets (simavr resets the core inside avr_run only for the
 * watchdog; the host's resets come between runs), and a write hook on the
 * stack pointer's high byte catches the stack leaving SRAM. */
struct avrhost_watch_t {
    avr_io_t io;
    avrhost_t *h;
    uint8_t sph_bad[256]; /* per SPH value: the stack outside SRAM (see on_sph) */
};

static void on_reset(avr_io_t *io)
{
    avrhost_t *h = ((struct avrhost_watch_t *)io)->h;
    uint64_t now = h->avr->cycle, second = h->avr->frequency; /* cycles of one second */
    h->init_sp_known = 0; /* a reset: the start-up code's stack setup runs again, as it should */
    if (!h->running) h->restarts_in_row = 0;
    if (!h->running) {
        h->wdt_in_row = 0;
        return;
    }
    h->wdt_resets++;
    h->wdt_in_row = h->wdt_in_row > 0 && now - h->wdt_last_cycle <= second ? h->wdt_in_row + 1u : 1u;
    h->wdt_last_cycle = now;
    if (h->wdt_in_row >= AVRHOST_WDT_LOOP_RESETS && !h->crash) {
        h->crash = "watchdog_reset_loop";
        h->crash_pc = h->avr->pc;
        h->avr->state = cpu_Crashed; /* avr_run returns; the core is not run again */
    }
}

/* The instruction at flash byte address pc is `out SPH, Rr` (1011 111r rrrr 1110, datasheet's instruction set). */
static int is_out_sph(const avr_t *avr, uint32_t pc)
{
    if (pc + 1u > avr->flashend) return 0;
    unsigned op = avr->flash[pc] | (unsigned)avr->flash[pc + 1u] << 8;
    return (op & 0xFE0Fu) == 0xBE0Eu;
}

/* SPH set to RAMEND's high byte by the instruction at pc: the first such
 * `out` after a reset is the start-up code's; the same instruction again
 * without a reset between is the program started over by a jump to 0.
 * AVRHOST_WDT_LOOP_RESETS of those in a row, each within a second of the
 * last, end the run as a reset loop. */
static void on_sp_init(avrhost_t *h, avr_t *avr, uint8_t v)
{
    if (v != (uint8_t)(avr->ramend >> 8)) return;
    if (!h->init_sp_known) {
        if (is_out_sph(avr, avr->pc)) h->init_sp_known = 1, h->init_sp_pc = avr->pc;
        return;
    }
    if (avr->pc != h->init_sp_pc) return;
    uint64_t now = avr->cycle, second = avr->frequency;
    h->restarts++;
    h->restarts_in_row = h->restarts_in_row > 0 && now - h->restart_last_cycle <= second ? h->restarts_in_row + 1u : 1u;
    h->restart_last_cycle = now;
    if (h->restarts_in_row >= AVRHOST_WDT_LOOP_RESETS && !h->crash) {
        h->crash = "reset_loop";
        h->crash_pc = avr->pc;
        avr->state = cpu_Crashed; /* avr_run returns after this instruction */
    }
}

/* SPH written through simavr's IO write hooks: the firmware's out and sts,
 * and every push, pop, call and return (simavr sets SP through the same
 * path): the stack pointer checked against SRAM before the next
 * instruction can push. The check is a table by SPH value (sph_guard), as
 * this runs a few million times a simulated second. */
static void on_sph(avr_t *avr, avr_io_addr_t addr, uint8_t v, void *param)
{
    avrhost_t *h = param;
    avr->data[addr] = v;
    on_sp_init(h, avr, v);
    if (h->watch->sph_bad[v] && !h->crash) {
        h->crash = "stack_overflow";
        h->crash_pc = avr->pc;
        h->crash_sp = (uint32_t)v << 8 | avr->data[R_SPL];
        avr->state = cpu_Crashed; /* avr_run returns after this instruction */
    }
}

/* Which SPH values put the stack outside SRAM. Where SRAM starts on a
 * 256-byte boundary (ATmega88/168/328/2560) the high byte decides alone;
 * elsewhere only a high byte that no low byte can make valid counts
 * (between the two writes of an out pair SP holds the new SPH with the old
 * SPL). */
static void sph_guard(avrhost_t *h)
{
    uint32_t lo = h->avr->ioend + 1u, hi = h->avr->ramend;
    for (uint32_t v = 0; v < 256; v++) {
        int low = (lo & 0xFFu) == 0 ? (v << 8) < lo : ((v << 8) | 0xFFu) < lo;
        h->watch->sph_bad[v] = low || (v << 8) > hi;
    }
}

static int watch_install(avrhost_t *h, char *err, size_t errn)
{
    h->watch = calloc(1, sizeof *h->watch);
    if (!h->watch) return snprintf(err, errn, "out of memory"), -1;
    h->watch->h = h;
    h->watch->io.kind = "mmsim-watch";
    h->watch->io.reset = on_reset;
    avr_register_io(h->avr, &h->watch->io);
    sph_guard(h);
    avr_register_io_write(h->avr, R_SPH, on_sph, h);
    return 0;
}

int avrhost_make(avrhost_t *h, const char *mcu, const char *who, char *err, size_t errn)
{
    log_install();
    h->avr = avr_make_mcu_by_name(mcu);
    if (!h->avr) return snprintf(err, errn, "%s: simavr does not know the MCU '%s'", who, mcu), -1;
    avr_init(h->avr);
    h->avr->log = LOG_NONE;
    return watch_install(h, err, errn);
}

/* the HEX bytes our reader parsed into the core's flash, run by run */
static int put_hex(avrhost_t *h, avrhost_image_t *img, const char *path, const char *mcu, char *err, size_t errn)
{
    image_hex_t *x = &img->bytes;
    int rc = 0;
    if (x->end > h->avr->flashend + 1u) {
        snprintf(err, errn, "%s: bytes up to 0x%X: larger than the %s's flash (%u bytes)", path, x->end - 1u, mcu,
                 h->avr->flashend + 1u);
        rc = -1;
    }
    char why[300];
    if (rc == 0 && image_mcu_check(x->flash, x->end, mcu, why, sizeof why) != 0)
        rc = -1, snprintf(err, errn, "%s: %s", path, why);
    for (int i = 0; i < x->nchunks && rc == 0; i++)
        avr_loadcode(h->avr, x->flash + x->chunks[i].base, x->chunks[i].size, x->chunks[i].base);
    image_hex_free(x);
    return rc;
}

/* the ELF's code and data within the flash, its variables within the SRAM, its .eeprom within the EEPROM */
static int check_elf_sizes(const avrhost_t *h, const char *path, const char *mcu, char *err, size_t errn)
{
    const struct avr_t *avr = h->avr;
    uint64_t code = (uint64_t)fw.flashbase + fw.flashsize, vars = (uint64_t)fw.datasize + fw.bsssize;
    if (code > avr->flashend + 1u)
        return snprintf(err, errn, "%s: %llu bytes of code: larger than the %s's flash (%u bytes): built for another MCU?",
                        path, (unsigned long long)code, mcu, avr->flashend + 1u), -1;
    if (vars > (uint64_t)avr->ramend - avr->ioend)
        return snprintf(err, errn, "%s: %llu bytes of variables (.data and .bss): more than the %s's SRAM (%u bytes)", path,
                        (unsigned long long)vars, mcu, avr->ramend - avr->ioend), -1;
    if (fw.eesize > avr->e2end + 1u)
        return snprintf(err, errn, "%s: %u bytes of .eeprom: more than the %s's EEPROM (%u bytes)", path, fw.eesize, mcu,
                        avr->e2end + 1u), -1;
    char why[300];
    if (fw.flash && fw.flashbase == 0 && image_mcu_check(fw.flash, fw.flashsize, mcu, why, sizeof why) != 0)
        return snprintf(err, errn, "%s: %s", path, why), -1;
    return 0;
}

int avrhost_put(avrhost_t *h, avrhost_image_t *img, const char *path, const char *mcu, uint32_t f_cpu, double step_s,
                char *err, size_t errn)
{
    if (f_cpu < AVRHOST_F_CPU_MIN_HZ || f_cpu > AVRHOST_F_CPU_MAX_HZ || (img->f_cpu && img->f_cpu != f_cpu)) {
        if (img->hex) image_hex_free(&img->bytes);
        if (img->f_cpu && img->f_cpu != f_cpu)
            return snprintf(err, errn, "%s: built for a %u Hz clock (.mmcu), run at %u Hz", path, img->f_cpu, f_cpu), -1;
        return snprintf(err, errn, "%s: a clock of %u Hz (an AVR runs at 1 to 32 MHz)", path, f_cpu), -1;
    }
    if (img->hex) {
        if (put_hex(h, img, path, mcu, err, errn) != 0) return -1;
    } else {
        if (check_elf_sizes(h, path, mcu, err, errn) != 0) return -1;
        snprintf(fw.mmcu, sizeof fw.mmcu, "%s", mcu);
        fw.frequency = f_cpu;
        avr_load_firmware(h->avr, &fw);
    }
    h->avr->frequency = f_cpu;
    h->avr->sleep = no_sleep;
    /* MMSIM_SIMAVR_LEVEL=1 leaves INT0/INT1's level check to simavr (every
     * cycle while a pin is low): test/cli/cli_board.sh compares the two */
    const char *lvl = getenv("MMSIM_SIMAVR_LEVEL");
    if (!lvl || strcmp(lvl, "1") != 0) extint_level_init(&h->lvl, h->avr);
    h->cycles_per_step = (uint64_t)llround((double)f_cpu * step_s);
    h->target = h->avr->cycle;
    return 0;
}

void avrhost_feed(avrhost_t *h)
{
    while (h->in_len > 0 && !h->xoff) {
        uint8_t c = h->in[h->in_head];
        h->in_head = (h->in_head + 1) % AVRHOST_IN_MAX;
        h->in_len--;
        if (h->uart && !avr_regbit_get(h->avr, h->uart->rxen)) { /* simavr ignores it too; counted apart */
            h->bytes_dropped++;
            continue;
        }
        h->bytes_in++;
        avr_raise_irq(h->uart_in, c); /* may raise XOFF at once */
    }
}

size_t avrhost_room(const avrhost_t *h) { return AVRHOST_IN_MAX - h->in_len; }

void avrhost_queue(avrhost_t *h, const uint8_t *bytes, size_t n)
{
    for (size_t i = 0; i < n && h->in_len < AVRHOST_IN_MAX; i++) h->in[(h->in_head + h->in_len++) % AVRHOST_IN_MAX] = bytes[i];
}

static void on_out(struct avr_irq_t *irq, uint32_t value, void *param)
{
    avrhost_t *h = param;
    (void)irq;
    h->sink(h->sink_ctx, (uint8_t)value);
}

static void on_xon(struct avr_irq_t *irq, uint32_t value, void *param)
{
    avrhost_t *h = param;
    (void)irq, (void)value;
    h->xoff = 0;
    avrhost_feed(h);
}

static void on_xoff(struct avr_irq_t *irq, uint32_t value, void *param)
{
    avrhost_t *h = param;
    (void)irq, (void)value;
    h->xoff = 1;
}

void avrhost_uart_flags(avrhost_t *h)
{
    uint32_t flags = 0; /* simavr would print UART lines itself, and usleep while the AVR polls the UART */
    avr_ioctl(h->avr, AVR_IOCTL_UART_GET_FLAGS('0'), &flags);
    flags &= ~(uint32_t)(AVR_UART_FLAG_STDIO | AVR_UART_FLAG_POLL_SLEEP);
    avr_ioctl(h->avr, AVR_IOCTL_UART_SET_FLAGS('0'), &flags);
}

int avrhost_uart_open(avrhost_t *h, avrhost_sink_fn *sink, void *ctx, const char *who, char *err, size_t errn)
{
    h->sink = sink;
    h->sink_ctx = ctx;
    avrhost_uart_flags(h);
    h->uart_in = avr_io_getirq(h->avr, AVR_IOCTL_UART_GETIRQ('0'), UART_IRQ_INPUT);
    avr_irq_t *out = avr_io_getirq(h->avr, AVR_IOCTL_UART_GETIRQ('0'), UART_IRQ_OUTPUT);
    avr_irq_t *xon = avr_io_getirq(h->avr, AVR_IOCTL_UART_GETIRQ('0'), UART_IRQ_OUT_XON);
    avr_irq_t *xoff = avr_io_getirq(h->avr, AVR_IOCTL_UART_GETIRQ('0'), UART_IRQ_OUT_XOFF);
    if (!h->uart_in || !out || !xon || !xoff)
        return snprintf(err, errn, "%s%sthe MCU '%s' has no UART0 in simavr", who ? who : "", who ? ": " : "", h->avr->mmcu), -1;
    for (avr_io_t *io = h->avr->io_port; io; io = io->next)
        if (!strcmp(io->kind, "uart") && ((avr_uart_t *)io)->name == '0') h->uart = (avr_uart_t *)io;
    avr_irq_register_notify(out, on_out, h);
    avr_irq_register_notify(xon, on_xon, h);
    avr_irq_register_notify(xoff, on_xoff, h);
    return 0;
}

/* The crash's cause when simavr stopped the core on its own. cpu_Done:
 * asleep with interrupts off. cpu_Crashed with the PC past the flash (now,
 * or at the batch's start: pc_was) or back at 0: simavr's check for a bad
 * jump (a PC past the program's code, or a jump to 0 after the start) has
 * stopped it; inside a batch of instructions the jump's target is not
 * known, so the PC is 0 then. Anything else: simavr's own reason. */
static void crash_cause(avrhost_t *h, int state, uint32_t pc_was)
{
    if (h->crash) return;
    h->crash_pc = h->avr->pc;
    if (state == cpu_Done) h->crash = "sleep_with_interrupts_off";
    else if (h->avr->pc > h->avr->flashend || h->avr->pc == 0) h->crash = "bad_jump";
    else if (pc_was > h->avr->flashend) h->crash = "bad_jump", h->crash_pc = pc_was;
    else h->crash = "crashed";
}

/* The stack pointer outside SRAM after a run, whole: where SRAM does not
 * start on a 256-byte boundary the SPH hook lets pass a high byte that
 * only some low bytes make valid; the next push would write into the IO
 * registers, then past simavr's data array. */
static void sp_check(avrhost_t *h)
{
    const avr_t *avr = h->avr;
    uint32_t sp = (uint32_t)avr->data[R_SPH] << 8 | avr->data[R_SPL];
    if (h->crash || (sp >= avr->ioend + 1u && sp <= avr->ramend)) return;
    h->crash = "stack_overflow";
    h->crash_pc = avr->pc;
    h->crash_sp = sp;
}

/* The PC at a word 0xFFFF after a run: erased flash (a reserved opcode; simavr would run through it). */
static void erased_check(avrhost_t *h)
{
    const avr_t *avr = h->avr;
    if (h->crash || avr->pc + 1u > avr->flashend || avr->flash[avr->pc] != 0xFFu || avr->flash[avr->pc + 1u] != 0xFFu)
        return;
    h->crash = "erased_flash";
    h->crash_pc = avr->pc;
}

static int crash_line(const avrhost_t *h, char *err, size_t errn)
{
    char detail[260] = "";
    if (!strcmp(h->crash, "stack_overflow"))
        snprintf(detail, sizeof detail, " (SP 0x%04X outside SRAM 0x%04X..0x%04X)", h->crash_sp, h->avr->ioend + 1u,
                 h->avr->ramend);
    else if (!strcmp(h->crash, "bad_jump"))
        snprintf(detail, sizeof detail, " (the program counter left the program: past its code, flash ending at 0x%04X, or to 0)",
                 h->avr->flashend);
    else if (!strcmp(h->crash, "watchdog_reset_loop"))
        snprintf(detail, sizeof detail, " (%u watchdog resets in a row)", h->wdt_in_row);
    else if (!strcmp(h->crash, "reset_loop"))
        snprintf(detail, sizeof detail,
                 " (the program started over %u times in a row without a reset: a jump to 0, as avr-libc's "
                 "__bad_interrupt makes for an enabled interrupt without a handler)", h->restarts_in_row);
    else if (!strcmp(h->crash, "erased_flash"))
        snprintf(detail, sizeof detail, " (the opcode 0xFFFF, erased flash: a jump or call past the program)");
    else if (last_log[0]) snprintf(detail, sizeof detail, " (simavr: %s)", last_log);
    return snprintf(err, errn, "firmware crashed at cycle %llu, PC 0x%04X: %s%s", (unsigned long long)h->avr->cycle,
                    h->crash_pc, h->crash, detail), -1;
}

int avrhost_gdb(avrhost_t *h, unsigned port, char *err, size_t errn)
{
    void (*keep)(avr_t *, avr_cycle_count_t) = h->avr->sleep;
    if (avrgdb_start(&h->stub, h->avr, port, err, errn) != 0) return -1;
    h->avr->sleep = keep; /* the stub's sleep waits on its socket in wall time; ours jumps the cycles */
    h->gdb = 1;
    sadly_crashed = 0;
    return 0;
}

/* One call into the core. With gdb's stub on: halted, it serves gdb (the
 * caller's cycle stays, so nothing else advances); else it runs (one
 * instruction while gdb is attached), and a crash simavr halted for gdb
 * ends the firmware as it does without gdb. */
static int run_once(avrhost_t *h)
{
    avr_t *avr = h->avr;
    if (h->gdb && avr->state == cpu_Stopped && !sadly_crashed) {
        avrgdb_wait(&h->stub, avr);
        return avr->state;
    }
    h->running = 1;
    int state = h->gdb ? avrgdb_run(&h->stub, avr) : avr_run(avr);
    h->running = 0;
    if (h->gdb && sadly_crashed) state = avr->state = cpu_Crashed;
    return state;
}

int avrhost_run_to(avrhost_t *h, uint64_t until, char *err, size_t errn)
{
    if (h->crash) return crash_line(h, err, errn);
    avr_t *avr = h->avr;
    if (avr->cycle >= until) return 0;
    /* a reset (avr_reset) sets it back to 1; 1 while gdb is attached: simavr checks breakpoints between avr_run calls */
    avr->run_cycle_limit = h->gdb && avrgdb_attached(&h->stub, avr) ? 1 : AVRHOST_BATCH_MAX_CYCLES;
    avr_cycle_timer_register(avr, until - avr->cycle, on_stop, h);
    while (avr->cycle < until) {
        uint32_t pc_was = avr->pc;
        int state = run_once(h);
        sp_check(h);
        erased_check(h);
        if (h->crash || state == cpu_Done || state == cpu_Crashed) {
            avr_cycle_timer_cancel(avr, on_stop, h);
            crash_cause(h, state, pc_was);
            return crash_line(h, err, errn);
        }
    }
    avr_cycle_timer_cancel(avr, on_stop, h); /* still there if a sleep jumped past it */
    return 0;
}

void avrhost_close(avrhost_t *h)
{
    if (h->avr && h->gdb) avrgdb_stop(h->avr); /* its sockets closed: a gdb still attached sees the connection close */
    h->gdb = 0;
    if (h->avr) avr_terminate(h->avr);
    free(h->watch); /* after the core, whose IO list held it */
    h->watch = NULL;
}

avr_irq_t *avrhost_pin_irq(avr_t *avr, char port, unsigned bit) { return avr_io_getirq(avr, AVR_IOCTL_IOPORT_GETIRQ(port), (int)bit); }

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
#include <simavr/sim_elf.h>
#include <simavr/sim_io.h>
#include <simavr/sim_irq.h>

#include "io/infile.h"

static elf_firmware_t fw; /* the ELF between avrhost_read and avrhost_put (large: off the stack) */

/* simavr's messages: errors kept for our one-line messages (the last one),
 * never printed by simavr itself; the rest dropped */
static char last_log[200];

static void quiet_logger(avr_t *avr, const int level, const char *fmt, va_list ap)
{
    (void)avr;
    if (level > LOG_ERROR) return;
    vsnprintf(last_log, sizeof last_log, fmt, ap);
    size_t n = strlen(last_log);
    while (n > 0 && (last_log[n - 1] == '\n' || last_log[n - 1] == '\r')) last_log[--n] = '\0';
}

static void log_install(void) { avr_global_logger_set(quiet_logger); }
static void log_clear(void) { last_log[0] = '\0'; }
/* ": MESSAGE" if simavr said something since log_clear, else "" (to append to an error line) */
static const char *log_sep(void) { return last_log[0] ? ": " : ""; }

/* the core's sleep callback: the host never sleeps (time is cycles, not the wall clock) */
static void no_sleep(avr_t *avr, avr_cycle_count_t how_long) { (void)avr, (void)how_long; }

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

int avrhost_make(avrhost_t *h, const char *mcu, const char *who, char *err, size_t errn)
{
    log_install();
    h->avr = avr_make_mcu_by_name(mcu);
    if (!h->avr) return snprintf(err, errn, "%s: simavr does not know the MCU '%s'", who, mcu), -1;
    avr_init(h->avr);
    h->avr->log = LOG_NONE;
    return 0;
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
    avr_irq_register_notify(out, on_out, h);
    avr_irq_register_notify(xon, on_xon, h);
    avr_irq_register_notify(xoff, on_xoff, h);
    return 0;
}

int avrhost_run_to(avrhost_t *h, uint64_t until, char *err, size_t errn)
{
    while (h->avr->cycle < until) {
        int state = avr_run(h->avr);
        if (state == cpu_Done || state == cpu_Crashed)
            return snprintf(err, errn, "AVR %s at cycle %llu%s%s", state == cpu_Crashed ? "crashed" : "halted",
                            (unsigned long long)h->avr->cycle, log_sep(), last_log), -1;
    }
    return 0;
}

void avrhost_close(avrhost_t *h)
{
    if (h->avr) avr_terminate(h->avr);
}

avr_irq_t *avrhost_pin_irq(avr_t *avr, char port, unsigned bit) { return avr_io_getirq(avr, AVR_IOCTL_IOPORT_GETIRQ(port), (int)bit); }

/* pil.c - an AVR in simavr on the simulator's serial link (see pil.h). */
#include "pil.h"

#include <errno.h>
#include <fcntl.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <string.h>
#include <sys/socket.h>
#include <unistd.h>

#include <simavr/avr_uart.h>
#include <simavr/sim_avr.h>
#include <simavr/sim_elf.h>
#include <simavr/sim_io.h>
#include <simavr/sim_irq.h>

#include "avrlog.h"
#include "io/infile.h"


static void feed(pil_t *p)
{
    while (p->in_len > 0 && !p->xoff) {
        uint8_t b = p->in[p->in_head];
        p->in_head = (p->in_head + 1) % PIL_IN_MAX;
        p->in_len--;
        p->bytes_in++;
        avr_raise_irq(p->uart_in, b); /* may raise XOFF at once */
    }
}

static void on_out(struct avr_irq_t *irq, uint32_t value, void *param)
{
    pil_t *p = param;
    uint8_t b = (uint8_t)value;
    (void)irq;
    if (write(p->fd, &b, 1) == 1) p->bytes_out++; /* the socket holds ~200 kB: the link drains it at the baud */
}

static void on_xon(struct avr_irq_t *irq, uint32_t value, void *param)
{
    pil_t *p = param;
    (void)irq;
    (void)value;
    p->xoff = 0;
    feed(p);
}

static void on_xoff(struct avr_irq_t *irq, uint32_t value, void *param)
{
    pil_t *p = param;
    (void)irq;
    (void)value;
    p->xoff = 1;
}

int pil_open(pil_t *p, const char *elf, const char *mcu, uint32_t f_cpu, double step_s, int *link_fd, char *err,
             size_t errn)
{
    memset(p, 0, sizeof *p);
    p->fd = -1;
    avrlog_install();
    if (access(elf, R_OK) != 0) {
        snprintf(err, errn, "%s: cannot read: %s", elf, strerror(errno));
        return -1;
    }
    uint8_t h[20] = { 0 }; /* ELF magic and e_machine 83 = AVR: simavr prints its own errors otherwise */
    FILE *f = infile_open(elf, PIL_ELF_MAX_BYTES, NULL, err, errn); /* a FIFO would hang the open */
    if (!f) return -1;
    size_t got = f ? fread(h, 1, sizeof h, f) : 0;
    if (f) fclose(f);
    if (got < sizeof h || memcmp(h, "\x7f" "ELF", 4) != 0 || h[18] != 83 || h[19] != 0) {
        snprintf(err, errn, "%s: not an AVR ELF image", elf);
        return -1;
    }
    static elf_firmware_t fw; /* large: keep it off the stack */
    memset(&fw, 0, sizeof fw);
    avrlog_clear();
    if (elf_read_firmware(elf, &fw) != 0 || fw.flashsize == 0) {
        snprintf(err, errn, "%s: not an AVR ELF image%s%s", elf, avrlog_sep(), avrlog_last());
        return -1;
    }
    snprintf(p->mcu, sizeof p->mcu, "%s", mcu ? mcu : fw.mmcu[0] ? fw.mmcu : "atmega328p");
    p->f_cpu = f_cpu ? f_cpu : fw.frequency ? fw.frequency : 16000000u;
    p->avr = avr_make_mcu_by_name(p->mcu);
    if (!p->avr) {
        snprintf(err, errn, "%s: simavr does not know the MCU '%s'", elf, p->mcu);
        return -1;
    }
    avr_init(p->avr);
    p->avr->log = LOG_NONE;
    snprintf(fw.mmcu, sizeof fw.mmcu, "%s", p->mcu);
    fw.frequency = p->f_cpu;
    avr_load_firmware(p->avr, &fw);
    p->avr->frequency = p->f_cpu;
    p->avr->sleep = avrlog_no_sleep;
    for (uint32_t a = p->avr->ioend + 1u; a <= p->avr->ramend; a++) p->avr->data[a] = PIL_PAINT; /* for pil_stack */

    uint32_t flags = 0; /* simavr would print UART lines itself, and usleep while the AVR polls the UART */
    avr_ioctl(p->avr, AVR_IOCTL_UART_GET_FLAGS('0'), &flags);
    flags &= ~(uint32_t)(AVR_UART_FLAG_STDIO | AVR_UART_FLAG_POLL_SLEEP);
    avr_ioctl(p->avr, AVR_IOCTL_UART_SET_FLAGS('0'), &flags);
    p->uart_in = avr_io_getirq(p->avr, AVR_IOCTL_UART_GETIRQ('0'), UART_IRQ_INPUT);
    avr_irq_t *out = avr_io_getirq(p->avr, AVR_IOCTL_UART_GETIRQ('0'), UART_IRQ_OUTPUT);
    avr_irq_t *xon = avr_io_getirq(p->avr, AVR_IOCTL_UART_GETIRQ('0'), UART_IRQ_OUT_XON);
    avr_irq_t *xoff = avr_io_getirq(p->avr, AVR_IOCTL_UART_GETIRQ('0'), UART_IRQ_OUT_XOFF);
    if (!p->uart_in || !out || !xon || !xoff) {
        snprintf(err, errn, "%s: the MCU '%s' has no UART0 in simavr", elf, p->mcu);
        avr_terminate(p->avr);
        p->avr = NULL;
        return -1;
    }
    avr_irq_register_notify(out, on_out, p);
    avr_irq_register_notify(xon, on_xon, p);
    avr_irq_register_notify(xoff, on_xoff, p);

    int sv[2];
    if (socketpair(AF_UNIX, SOCK_STREAM | SOCK_CLOEXEC, 0, sv) != 0) {
        snprintf(err, errn, "cannot make the serial line: %s", strerror(errno));
        avr_terminate(p->avr);
        p->avr = NULL;
        return -1;
    }
    fcntl(sv[0], F_SETFL, O_NONBLOCK);
    fcntl(sv[1], F_SETFL, O_NONBLOCK);
    p->fd = sv[1];
    *link_fd = sv[0];
    p->cycles_per_step = (uint64_t)llround((double)p->f_cpu * step_s);
    p->target = p->avr->cycle;
    return 0;
}

int pil_step(pil_t *p, char *err, size_t errn)
{
    /* bytes the link sent this step wait for the receive FIFO */
    for (;;) {
        size_t room = PIL_IN_MAX - p->in_len;
        if (room == 0) break;
        size_t tail = (p->in_head + p->in_len) % PIL_IN_MAX;
        size_t n = PIL_IN_MAX - tail < room ? PIL_IN_MAX - tail : room;
        ssize_t k = read(p->fd, p->in + tail, n);
        if (k <= 0) break;
        p->in_len += (size_t)k;
    }
    feed(p);
    p->target += p->cycles_per_step;
    while (p->avr->cycle < p->target) {
        int state = avr_run(p->avr);
        if (state == cpu_Done || state == cpu_Crashed) {
            snprintf(err, errn, "AVR %s at cycle %llu%s%s", state == cpu_Crashed ? "crashed" : "halted",
                     (unsigned long long)p->avr->cycle, avrlog_sep(), avrlog_last());
            return -1;
        }
    }
    p->cycles = p->avr->cycle;
    return 0;
}

void pil_stack(const pil_t *p, uint32_t *stack_max, uint32_t *free_min)
{
    /* up from the start of SRAM: .data and .bss are written at reset, the
     * first 16 untouched bytes start the gap; the first touched byte above
     * it is the deepest the stack went (scanning down from the top would
     * stop early at untouched holes inside stack frames) */
    const uint8_t *d = p->avr->data;
    uint32_t lo = p->avr->ioend + 1u, top = p->avr->ramend, a = lo;
    while (a + 16u <= top) {
        uint32_t k = 0;
        while (k < 16u && d[a + k] == PIL_PAINT) k++;
        if (k == 16u) break;
        a += k + 1u;
    }
    uint32_t gap = a;
    while (a <= top && d[a] == PIL_PAINT) a++;
    *free_min = a - gap;
    *stack_max = top + 1u - a;
}

void pil_close(pil_t *p)
{
    /* simavr has no call that frees a whole core: p->avr stays pointing at
     * it (reachable, not a leak) and the process ends soon after */
    if (p->avr) avr_terminate(p->avr);
    if (p->fd >= 0) close(p->fd);
    p->fd = -1;
}

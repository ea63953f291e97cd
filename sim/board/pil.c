/* pil.c - an AVR in simavr on the simulator's serial link (see pil.h). */
#include "pil.h"

#include <errno.h>
#include <fcntl.h>
#include <stdio.h>
#include <string.h>
#include <sys/socket.h>
#include <unistd.h>

#include <simavr/sim_avr.h>


/* UART0's sink: each byte the firmware sends onto the socket */
static void to_link(void *ctx, uint8_t b)
{
    pil_t *p = ctx;
    if (write(p->fd, &b, 1) == 1) p->bytes_out++; /* the socket holds ~200 kB: the link drains it at the baud */
}

static int open_fail(pil_t *p)
{
    avrhost_close(&p->host);
    p->host.avr = NULL;
    return -1;
}

int pil_open(pil_t *p, const char *elf, const char *mcu, uint32_t f_cpu, double step_s, int *link_fd, char *err,
             size_t errn)
{
    memset(p, 0, sizeof *p);
    p->fd = -1;
    avrhost_image_t img;
    if (avrhost_read(&img, elf, 0, mcu, NULL, err, errn) != 0) return -2;
    snprintf(p->mcu, sizeof p->mcu, "%s", mcu ? mcu : img.mcu[0] ? img.mcu : AVRHOST_DEFAULT_MCU);
    p->f_cpu = f_cpu ? f_cpu : img.f_cpu ? img.f_cpu : 16000000u;
    if (avrhost_make(&p->host, p->mcu, elf, err, errn) != 0) return -2;
    if (avrhost_put(&p->host, &img, elf, p->mcu, p->f_cpu, step_s, err, errn) != 0) return open_fail(p), -2;
    avr_t *avr = p->host.avr;
    for (uint32_t a = avr->ioend + 1u; a <= avr->ramend; a++) avr->data[a] = PIL_PAINT; /* for pil_stack */
    if (avrhost_uart_open(&p->host, to_link, p, elf, err, errn) != 0) return open_fail(p);
    int sv[2];
    if (socketpair(AF_UNIX, SOCK_STREAM | SOCK_CLOEXEC, 0, sv) != 0) {
        snprintf(err, errn, "cannot make the serial line: %s", strerror(errno));
        return open_fail(p);
    }
    fcntl(sv[0], F_SETFL, O_NONBLOCK);
    fcntl(sv[1], F_SETFL, O_NONBLOCK);
    p->fd = sv[1];
    *link_fd = sv[0];
    return 0;
}

int pil_step(pil_t *p, char *err, size_t errn)
{
    /* bytes the link sent this step wait for the receive FIFO */
    uint8_t buf[AVRHOST_IN_MAX];
    for (;;) {
        size_t room = avrhost_room(&p->host);
        if (room == 0) break;
        ssize_t k = read(p->fd, buf, room);
        if (k <= 0) break;
        avrhost_queue(&p->host, buf, (size_t)k);
    }
    avrhost_feed(&p->host);
    p->host.target += p->host.cycles_per_step;
    int rc = avrhost_run_to(&p->host, p->host.target, err, errn);
    p->bytes_in = p->host.bytes_in;
    p->bytes_dropped = p->host.bytes_dropped;
    if (rc != 0) return -1;
    p->cycles = p->host.avr->cycle;
    return 0;
}

void pil_stack(const pil_t *p, uint32_t *stack_max, uint32_t *free_min)
{
    /* up from the start of SRAM: .data and .bss are written at reset, the
     * first 16 untouched bytes start the gap; the first touched byte above
     * it is the deepest the stack went (scanning down from the top would
     * stop early at untouched holes inside stack frames) */
    const avr_t *avr = p->host.avr;
    const uint8_t *d = avr->data;
    uint32_t lo = avr->ioend + 1u, top = avr->ramend, a = lo;
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
    /* simavr has no call that frees a whole core: p->host.avr stays pointing at
     * it (reachable, not a leak) and the process ends soon after */
    avrhost_close(&p->host);
    if (p->fd >= 0) close(p->fd);
    p->fd = -1;
}

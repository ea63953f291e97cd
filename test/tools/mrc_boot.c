/* mrc_boot - boots an AVR image (an ATmega328P at 16 MHz, as on the Arduino
 * Nano) in simavr, for test/cli/cli_mazerunner.sh: runs it for SECONDS of
 * simulated time and prints everything it writes on UART0 to stdout, at
 * whatever baud it set. T=TEXT arguments type TEXT and a newline on UART0 at
 * simulated second T (in order). No board: the pins and the ADC read what
 * simavr gives by default. At the end one line on stderr: the baud the
 * firmware set, the cycles run, bytes out and in; simavr's warnings and
 * errors go to stderr as "simavr: ..." lines, each kind once. VCC, AVCC
 * and AREF are 5 V, as on a Nano powered from its 5 V regulator.
 *
 *   mrc_boot FIRMWARE.elf SECONDS [T=TEXT ...]
 *
 * Exit 0; 2 for bad arguments or an image simavr cannot load; 1 if the AVR
 * crashed or halted. */
#include <stdarg.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <simavr/avr_uart.h>
#include <simavr/sim_avr.h>
#include <simavr/sim_elf.h>
#include <simavr/sim_io.h>
#include <simavr/sim_irq.h>

#define F_CPU_HZ 16000000u
#define MAX_SENDS 16
#define IN_MAX 4096

static struct {
    avr_irq_t *uart_in;
    int xoff;
    char in[IN_MAX]; /* typed bytes waiting for the receiver */
    size_t in_len, in_head;
    unsigned long bytes_out, bytes_in;
} u;

/* simavr's warnings and errors, each distinct one printed once (a firmware
 * may trigger one on every ADC conversion); repeats counted for the end */
#define LOG_KINDS 16
static char log_seen[LOG_KINDS][160];
static unsigned long log_count[LOG_KINDS];

static void logger(avr_t *avr, const int level, const char *fmt, va_list ap)
{
    (void)avr;
    if (level > LOG_WARNING) return;
    char m[160];
    vsnprintf(m, sizeof m, fmt, ap);
    size_t n = strlen(m);
    while (n > 0 && (m[n - 1] == '\n' || m[n - 1] == '\r')) m[--n] = '\0';
    for (int i = 0; i < LOG_KINDS; i++) {
        if (log_count[i] == 0) {
            snprintf(log_seen[i], sizeof log_seen[i], "%s", m);
            log_count[i] = 1;
            fprintf(stderr, "simavr: %s\n", m);
            return;
        }
        if (strcmp(log_seen[i], m) == 0) {
            log_count[i]++;
            return;
        }
    }
    fprintf(stderr, "simavr: %s\n", m);
}

static void no_sleep(avr_t *avr, avr_cycle_count_t how_long)
{
    (void)avr;
    (void)how_long;
}

static void feed(void)
{
    while (u.in_len > 0 && !u.xoff) {
        uint8_t b = (uint8_t)u.in[u.in_head];
        u.in_head = (u.in_head + 1) % IN_MAX;
        u.in_len--;
        u.bytes_in++;
        avr_raise_irq(u.uart_in, b); /* may raise XOFF at once */
    }
}

static void on_out(struct avr_irq_t *irq, uint32_t value, void *param)
{
    (void)irq;
    (void)param;
    putchar((int)(value & 0xff));
    u.bytes_out++;
}

static void on_xon(struct avr_irq_t *irq, uint32_t value, void *param)
{
    (void)irq;
    (void)value;
    (void)param;
    u.xoff = 0;
    feed();
}

static void on_xoff(struct avr_irq_t *irq, uint32_t value, void *param)
{
    (void)irq;
    (void)value;
    (void)param;
    u.xoff = 1;
}

static void type(const char *text)
{
    size_t n = strlen(text);
    for (size_t i = 0; i <= n && u.in_len < IN_MAX; i++) {
        u.in[(u.in_head + u.in_len) % IN_MAX] = i < n ? text[i] : '\n';
        u.in_len++;
    }
    feed();
}

int main(int argc, char **argv)
{
    if (argc < 3) {
        fprintf(stderr, "usage: mrc_boot FIRMWARE.elf SECONDS [T=TEXT ...]\n");
        return 2;
    }
    char *end;
    double seconds = strtod(argv[2], &end);
    if (*end || !(seconds > 0 && seconds <= 3600)) {
        fprintf(stderr, "mrc_boot: SECONDS: expected a number in (0, 3600], got '%s'\n", argv[2]);
        return 2;
    }
    double send_t[MAX_SENDS];
    const char *send_text[MAX_SENDS];
    int sends = 0;
    for (int i = 3; i < argc; i++) {
        double t = strtod(argv[i], &end);
        if (*end != '=' || !(t >= 0) || sends == MAX_SENDS || (sends > 0 && t < send_t[sends - 1])) {
            fprintf(stderr, "mrc_boot: expected T=TEXT with T in order (at most %d), got '%s'\n", MAX_SENDS, argv[i]);
            return 2;
        }
        send_t[sends] = t;
        send_text[sends++] = end + 1;
    }

    avr_global_logger_set(logger);
    static elf_firmware_t fw; /* large: keep it off the stack */
    if (elf_read_firmware(argv[1], &fw) != 0 || fw.flashsize == 0) {
        fprintf(stderr, "mrc_boot: %s: not an AVR ELF image simavr can load\n", argv[1]);
        return 2;
    }
    avr_t *avr = avr_make_mcu_by_name("atmega328p");
    if (!avr) {
        fprintf(stderr, "mrc_boot: simavr has no atmega328p\n");
        return 2;
    }
    avr_init(avr);
    snprintf(fw.mmcu, sizeof fw.mmcu, "atmega328p");
    fw.frequency = F_CPU_HZ;
    avr_load_firmware(avr, &fw);
    avr->frequency = F_CPU_HZ;
    avr->sleep = no_sleep; /* time is cycles, not the host's clock */
    avr->vcc = avr->avcc = avr->aref = 5000; /* mV: the Nano on 5 V (the ADC warns on every conversion without AVCC) */

    uint32_t flags = 0; /* simavr would print UART lines itself, and usleep while the AVR polls */
    avr_ioctl(avr, AVR_IOCTL_UART_GET_FLAGS('0'), &flags);
    flags &= ~(uint32_t)(AVR_UART_FLAG_STDIO | AVR_UART_FLAG_POLL_SLEEP);
    avr_ioctl(avr, AVR_IOCTL_UART_SET_FLAGS('0'), &flags);
    u.uart_in = avr_io_getirq(avr, AVR_IOCTL_UART_GETIRQ('0'), UART_IRQ_INPUT);
    avr_irq_register_notify(avr_io_getirq(avr, AVR_IOCTL_UART_GETIRQ('0'), UART_IRQ_OUTPUT), on_out, NULL);
    avr_irq_register_notify(avr_io_getirq(avr, AVR_IOCTL_UART_GETIRQ('0'), UART_IRQ_OUT_XON), on_xon, NULL);
    avr_irq_register_notify(avr_io_getirq(avr, AVR_IOCTL_UART_GETIRQ('0'), UART_IRQ_OUT_XOFF), on_xoff, NULL);

    avr_cycle_count_t stop = (avr_cycle_count_t)(seconds * F_CPU_HZ);
    int next = 0, rc = 0;
    while (avr->cycle < stop) {
        if (next < sends && avr->cycle >= (avr_cycle_count_t)(send_t[next] * F_CPU_HZ)) type(send_text[next++]);
        int state = avr_run(avr);
        if (state == cpu_Done || state == cpu_Crashed) {
            fprintf(stderr, "mrc_boot: AVR %s at cycle %llu\n", state == cpu_Crashed ? "crashed" : "halted",
                    (unsigned long long)avr->cycle);
            rc = 1;
            break;
        }
    }
    fflush(stdout);
    /* the baud from the registers as the firmware left them (ATmega328P:
     * UCSR0A 0xC0 with U2X0 bit 1, UBRR0L 0xC4, UBRR0H 0xC5) */
    unsigned ubrr = avr->data[0xC4] | (unsigned)(avr->data[0xC5] & 0x0f) << 8;
    unsigned div = (avr->data[0xC0] & 0x02) ? 8u : 16u;
    fprintf(stderr, "mrc_boot: UART0 at %.0f baud (UBRR0 %u, %s speed), %llu cycles, %lu bytes out, %lu in\n",
            (double)F_CPU_HZ / (div * (ubrr + 1.0)), ubrr, div == 8 ? "double" : "normal",
            (unsigned long long)avr->cycle, u.bytes_out, u.bytes_in);
    for (int i = 0; i < LOG_KINDS && log_count[i] > 0; i++)
        if (log_count[i] > 1) fprintf(stderr, "simavr: '%s' %lu times in all\n", log_seen[i], log_count[i]);
    avr_terminate(avr);
    return rc;
}

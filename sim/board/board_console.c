/* board_console.c - what a person sees and types: UART0 (every byte the
 * firmware sends is kept as the console and echoed live with --verbose;
 * typed text waits for the receiver, respecting its XON/XOFF), the LEDs
 * (level changes counted), the emitter pins (their level kept for the ADC)
 * and the interrupts (each vector's services counted). */
#include "board_int.h"

#include <stdlib.h>
#include <string.h>

#include <simavr/avr_ioport.h>
#include <simavr/avr_uart.h>
#include <simavr/sim_avr.h>
#include <simavr/sim_interrupts.h>
#include <simavr/sim_io.h>
#include <simavr/sim_irq.h>

void board_console_feed(board_t *b)
{
    while (b->in_len > 0 && !b->xoff) {
        uint8_t c = b->in[b->in_head];
        b->in_head = (b->in_head + 1) % BOARD_IN_MAX;
        b->in_len--;
        b->st.uart_bytes_in++;
        avr_raise_irq(b->uart_in, c); /* may raise XOFF at once */
    }
}

static void on_out(struct avr_irq_t *irq, uint32_t value, void *param)
{
    board_t *b = param;
    char c = (char)value;
    (void)irq;
    b->st.uart_bytes_out++;
    if (b->con_len + 1 < BOARD_CONSOLE_MAX) {
        b->con[b->con_len++] = c;
        b->con[b->con_len] = '\0';
    } else b->st.console_dropped++;
    if (b->echo) {
        fputc(c, b->echo);
        if (c == '\n') fflush(b->echo);
    }
}

static void on_xon(struct avr_irq_t *irq, uint32_t value, void *param)
{
    board_t *b = param;
    (void)irq, (void)value;
    b->xoff = 0;
    board_console_feed(b);
}

static void on_xoff(struct avr_irq_t *irq, uint32_t value, void *param)
{
    board_t *b = param;
    (void)irq, (void)value;
    b->xoff = 1;
}

static void on_led(struct avr_irq_t *irq, uint32_t value, void *param)
{
    board_t *b = param;
    for (int i = 0; i < b->spec.nleds; i++)
        if (irq == board_pin_irq(b, b->spec.led_pin[i]) && b->led_level[i] != (int)(value & 1u)) {
            b->led_level[i] = (int)(value & 1u);
            b->st.led_changes[i]++;
        }
}

static void on_emitter(struct avr_irq_t *irq, uint32_t value, void *param)
{
    board_t *b = param;
    for (int i = 0; i < b->spec.nemitters; i++)
        if (irq == board_pin_irq(b, b->spec.emitter_pin[i])) b->emitter_level[i] = (int)(value & 1u);
}

static void on_vector(struct avr_irq_t *irq, uint32_t value, void *param)
{
    board_t *b = param;
    avr_int_table_p t = &b->avr->interrupts;
    if (!value) return; /* 1 when serviced, 0 at its RETI */
    for (int i = 0; i < t->vector_count; i++)
        if (&t->vector[i]->irq[AVR_INT_IRQ_RUNNING] == irq && t->vector[i]->vector < BOARD_VECTORS_MAX)
            b->st.interrupts[t->vector[i]->vector]++;
}

void board_uart_flags(board_t *b)
{
    uint32_t flags = 0; /* simavr would print UART lines itself, and usleep while the AVR polls the UART */
    avr_ioctl(b->avr, AVR_IOCTL_UART_GET_FLAGS('0'), &flags);
    flags &= ~(uint32_t)(AVR_UART_FLAG_STDIO | AVR_UART_FLAG_POLL_SLEEP);
    avr_ioctl(b->avr, AVR_IOCTL_UART_SET_FLAGS('0'), &flags);
}

int board_console_init(board_t *b, char *err, size_t errn)
{
    b->con = malloc(BOARD_CONSOLE_MAX);
    if (!b->con) {
        snprintf(err, errn, "out of memory");
        return -1;
    }
    b->con[0] = '\0';
    board_uart_flags(b);
    b->uart_in = avr_io_getirq(b->avr, AVR_IOCTL_UART_GETIRQ('0'), UART_IRQ_INPUT);
    avr_irq_t *out = avr_io_getirq(b->avr, AVR_IOCTL_UART_GETIRQ('0'), UART_IRQ_OUTPUT);
    avr_irq_t *xon = avr_io_getirq(b->avr, AVR_IOCTL_UART_GETIRQ('0'), UART_IRQ_OUT_XON);
    avr_irq_t *xoff = avr_io_getirq(b->avr, AVR_IOCTL_UART_GETIRQ('0'), UART_IRQ_OUT_XOFF);
    if (!b->uart_in || !out || !xon || !xoff) {
        snprintf(err, errn, "the MCU '%s' has no UART0 in simavr", b->spec.mcu);
        return -1;
    }
    avr_irq_register_notify(out, on_out, b);
    avr_irq_register_notify(xon, on_xon, b);
    avr_irq_register_notify(xoff, on_xoff, b);
    for (int i = 0; i < b->spec.nleds; i++) avr_irq_register_notify(board_pin_irq(b, b->spec.led_pin[i]), on_led, b);
    for (int i = 0; i < b->spec.nemitters; i++) avr_irq_register_notify(board_pin_irq(b, b->spec.emitter_pin[i]), on_emitter, b);
    avr_int_table_p t = &b->avr->interrupts;
    for (int i = 0; i < t->vector_count; i++) avr_irq_register_notify(&t->vector[i]->irq[AVR_INT_IRQ_RUNNING], on_vector, b);
    return 0;
}

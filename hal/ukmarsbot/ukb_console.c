/* ukb_console.c - UART0 for hal_log and the board's one-letter commands.
 *
 * Out: a ring of UKB_TX_RING bytes emptied by the data-register-empty
 * interrupt. hal_log and hal_log_P never wait (hal.h: a backend must not
 * block longer than queueing takes, and the firmware may log from fw_tick):
 * a line that does not fit whole is dropped and counted. The board's own
 * replies (ukb_console_printf_P) are written from the main loop only and
 * wait for room. In: a small ring filled by the receive interrupt. */
#include "ukb_console.h"

#include <stdarg.h>
#include <stdio.h>
#include <string.h>
#include <avr/interrupt.h>
#include <avr/pgmspace.h>
#include <util/atomic.h>

#include "hal.h"
#include "ukb_board.h"

#define UKB_TX_RING 64 /* bytes: a power of two; 5.6 ms of output at 115200 */
/* a line, bytes without the NUL: with its CR LF it fits the empty ring
 * (the firmware's hal_log lines are at most HAL_LOG_MAX = 50) */
#define UKB_LINE_MAX (UKB_TX_RING - 3)
#define UKB_RX_RING 8   /* bytes: a power of two (commands are one letter) */

static volatile uint8_t tx_buf[UKB_TX_RING], tx_head, tx_tail;
static volatile uint8_t rx_buf[UKB_RX_RING], rx_head, rx_tail;
static volatile uint16_t dropped;

void ukb_console_init(void)
{
    /* U2X: UBRR = F_CPU / (8 * baud) - 1 = 16.4 -> 16, 115200 within 2.1 %
     * (ATmega328P datasheet, "Examples of Baud Rate Setting", 16 MHz) */
    UCSR0A = _BV(U2X0);
    UBRR0 = (uint16_t)((F_CPU + 4UL * UKB_CONSOLE_BAUD) / (8UL * UKB_CONSOLE_BAUD) - 1UL);
    UCSR0C = _BV(UCSZ01) | _BV(UCSZ00); /* 8 data bits, no parity, 1 stop bit */
    UCSR0B = _BV(RXEN0) | _BV(TXEN0) | _BV(RXCIE0);
}

ISR(USART_RX_vect)
{
    uint8_t c = UDR0, next = (uint8_t)((rx_head + 1) & (UKB_RX_RING - 1));
    if (next != rx_tail) {
        rx_buf[rx_head] = c;
        rx_head = next;
    }
}

ISR(USART_UDRE_vect)
{
    if (tx_head == tx_tail) {
        UCSR0B &= (uint8_t)~_BV(UDRIE0);
        return;
    }
    UDR0 = tx_buf[tx_tail];
    tx_tail = (uint8_t)((tx_tail + 1) & (UKB_TX_RING - 1));
}

int ukb_console_getc(void)
{
    int c = -1;
    ATOMIC_BLOCK(ATOMIC_RESTORESTATE) {
        if (rx_head != rx_tail) {
            c = rx_buf[rx_tail];
            rx_tail = (uint8_t)((rx_tail + 1) & (UKB_RX_RING - 1));
        }
    }
    return c;
}

static uint8_t tx_free(void)
{
    return (uint8_t)((tx_tail - tx_head - 1) & (UKB_TX_RING - 1));
}

/* Queues a line and CR LF if all of it fits now; 0 if it did not. */
static uint8_t queue_line(const char *s, uint8_t in_flash)
{
    uint8_t ok = 0;
    ATOMIC_BLOCK(ATOMIC_RESTORESTATE) {
        uint8_t n = (uint8_t)((in_flash ? strnlen_P(s, UKB_LINE_MAX) : strnlen(s, UKB_LINE_MAX)) + 2);
        if (n <= tx_free()) {
            for (uint8_t i = 0; i < n; i++) {
                char c = i + 2 == n ? '\r' : i + 1 == n ? '\n' : in_flash ? (char)pgm_read_byte(s + i) : s[i];
                tx_buf[tx_head] = (uint8_t)c;
                tx_head = (uint8_t)((tx_head + 1) & (UKB_TX_RING - 1));
            }
            UCSR0B |= _BV(UDRIE0);
            ok = 1;
        }
    }
    return ok;
}

void hal_log(const char *line)
{
    if (!queue_line(line, 0)) dropped++;
}

void hal_log_P(const char *line) /* a PSTR() line */
{
    if (!queue_line(line, 1)) dropped++;
}

uint16_t ukb_console_dropped(void)
{
    uint16_t n;
    ATOMIC_BLOCK(ATOMIC_RESTORESTATE) { n = dropped; }
    return n;
}

void ukb_console_printf_P(const char *fmt, ...)
{
    char line[UKB_LINE_MAX + 1];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf_P(line, sizeof line, fmt, ap);
    va_end(ap);
    while (!queue_line(line, 0)) {} /* the transmit interrupt makes room */
}

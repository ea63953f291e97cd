/* avr_wire.c - the wire codec's shared vectors checked on the ATmega328P
 * (16-bit int, avr-gcc). Run in simavr by test/cli/cli_hil.sh. Prints one line
 * on UART0 and stops the CPU (simavr then exits). */
#include <avr/io.h>
#include <avr/interrupt.h>
#include <avr/sleep.h>
#include <stdio.h>

#include "wire_vectors.h"

static void put(char c)
{
    while (!(UCSR0A & (1 << UDRE0))) {}
    UDR0 = (uint8_t)c;
}

int main(void)
{
    UCSR0A = 1 << U2X0;
    UBRR0 = 1; /* 1,000,000 baud at 16 MHz with U2X */
    UCSR0B = 1 << TXEN0;
    const char *first;
    unsigned bad = wire_vectors_check(&first);
    char line[64];
    snprintf(line, sizeof line, "wire vectors: %u failed%s%s\n", bad, bad ? ", first " : "", bad ? first : "");
    for (const char *p = line; *p; p++) put(*p);
    while (!(UCSR0A & (1 << TXC0))) {}
    cli();
    sleep_cpu();
    for (;;) {}
}

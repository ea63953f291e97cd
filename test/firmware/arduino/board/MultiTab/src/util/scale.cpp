// scale.cpp - see scale.h
#include "scale.h"

#include <avr/pgmspace.h>

long scale_percent(long value, int percent) { return value * percent / 100; }

int unused_mode() { return 0; }

// 2 x 20,000 bytes (more than the Nano's flash leaves; an AVR object is at
// most 32,767 bytes) of a counting pattern
#define TABLE_BYTES 20000u
#define R10(i) (uint8_t)(i), (uint8_t)(i + 1), (uint8_t)(i + 2), (uint8_t)(i + 3), (uint8_t)(i + 4), \
    (uint8_t)(i + 5), (uint8_t)(i + 6), (uint8_t)(i + 7), (uint8_t)(i + 8), (uint8_t)(i + 9)
#define R100(i) R10(i), R10(i + 10), R10(i + 20), R10(i + 30), R10(i + 40), R10(i + 50), R10(i + 60), \
    R10(i + 70), R10(i + 80), R10(i + 90)
#define R1000(i) R100(i), R100(i + 100), R100(i + 200), R100(i + 300), R100(i + 400), R100(i + 500), \
    R100(i + 600), R100(i + 700), R100(i + 800), R100(i + 900)
#define R10000(i) R1000(i), R1000(i + 1000), R1000(i + 2000), R1000(i + 3000), R1000(i + 4000), \
    R1000(i + 5000), R1000(i + 6000), R1000(i + 7000), R1000(i + 8000), R1000(i + 9000)
static const uint8_t TABLE_A[TABLE_BYTES] PROGMEM = { R10000(0), R10000(1) };
static const uint8_t TABLE_B[TABLE_BYTES] PROGMEM = { R10000(2), R10000(3) };

uint8_t table_byte(unsigned i)
{
    i %= 2 * TABLE_BYTES;
    return i < TABLE_BYTES ? pgm_read_byte(&TABLE_A[i]) : pgm_read_byte(&TABLE_B[i - TABLE_BYTES]);
}

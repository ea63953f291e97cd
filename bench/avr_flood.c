/* avr_flood.c - AVR side of the flood benchmark: REPS full heading-aware
 * floods of a blank 16x16 map (unknown walls open: the mouse's first and
 * largest flood), then sleep with interrupts off so simavr stops. The host
 * side (bench/simavr_cycles.c) counts the cycles. */
#include <avr/interrupt.h>
#include <avr/sleep.h>

#include "flood.h"

#ifndef REPS
#define REPS 10
#endif

static maze_t m;
static flood_t f;
volatile uint16_t sink;
volatile uint8_t reps = REPS; /* volatile: REPS 0 must not fold the loop away */

int main(void)
{
    maze_init(&m, 16, 16);
    flood_target_goal(&f, &m);
    for (uint8_t i = 0; i < reps; i++)
        sink = flood_run(&f, &m, m.start, m.start_heading, FLOOD_UNKNOWN_OPEN | FLOOD_FULL);
    cli();
    sleep_mode();
    return 0;
}

/* extint_level.h - INT0/INT1 in their "low level" mode (EICRA's reset
 * value) with the behaviour simavr gives them, at the cost of edge mode.
 *
 * What simavr (1.6) does: while an INTn pin is low in level mode, a cycle
 * timer checks it at every instruction boundary ("strict level trigger",
 * on after every reset) and raises the interrupt again whenever the global
 * interrupt flag is set and the INTn flag (EIFR) is clear and not pending.
 * That timer keeps simavr from batching instructions, and the board rests
 * the encoder pins low, so a firmware that never touches EICRA runs ~3x
 * slower than one in edge mode.
 *
 * What is done instead: simavr's check is turned off and the same check
 * runs as our own cycle timer, at the same boundaries, but only while it
 * can change something. While the INTn flag is set or pending the check
 * raises nothing, and the flag only clears through a write to EIFR or the
 * interrupt being serviced: the check sleeps then and wakes at those two
 * events (and ends, as simavr's does, when the pin goes high or EICRA
 * leaves level mode). What the firmware sees (the flag, each interrupt and
 * its cycle) is what simavr's own check gives; a firmware that leaves the
 * interrupt disabled pays one check per falling edge. */
#ifndef EXTINT_LEVEL_H
#define EXTINT_LEVEL_H

#include <stdint.h>

struct avr_t;
struct avr_extint_t;
struct extint_level_s;

#define EXTINT_LEVEL_MAX 2 /* INT0 and INT1: the ATmega328P's level-capable external interrupts */

typedef struct {
    struct extint_level_s *x;
    int no;    /* INTn */
    int alive; /* simavr's check would still run: the pin went low in level mode and stayed so */
} extint_level_in_t;

typedef struct extint_level_s {
    struct avr_t *avr;
    struct avr_extint_t *ext; /* NULL: the MCU has no external interrupts in simavr */
    extint_level_in_t in[EXTINT_LEVEL_MAX];
} extint_level_t;

/* Take over the level check of avr's INT0/INT1 (after the image is loaded). */
void extint_level_init(extint_level_t *x, struct avr_t *avr);
/* The AVR cycles a sleeping avr would sleep with simavr's own check: 1
 * while that check would run but ours sleeps (simavr's is due each
 * cycle), else plain (the cycles to its next timer). */
uint64_t extint_level_sleep(struct avr_t *avr, uint64_t plain);

#endif

/* board_switch.h - the switches part: four DIP switches and a button on
 * a resistor ladder into one ADC channel, set by a person's hands; the
 * ladder's voltage is the part's output IRQ, which board.c connects to
 * board_adc's. */
#ifndef BOARD_SWITCH_H
#define BOARD_SWITCH_H

#include "board.h"

struct avr_t;
struct avr_irq_t;

typedef struct {
    const board_spec_t *spec;     /* the ladder's resistors, VCC */
    unsigned switches;            /* 0..15, bit k: switch k+1 on */
    int button;                   /* 1: held down */
    struct avr_irq_t *out;        /* the part's output: the ladder's voltage in mV, rounded up to the mV as the ADC takes an input, raised on each change */
} board_switches_t;

/* All off, the output made in avr's IRQ pool (board.c connects it). */
void board_switches_init(board_switches_t *s, struct avr_t *avr, const board_spec_t *spec);
/* The hands: the switches (0..15) and the button, raised on the output. */
void board_switches_set(board_switches_t *s, unsigned switches, int button);
/* The ladder's voltage now, V. */
double board_switches_volts(const board_switches_t *s);

#endif

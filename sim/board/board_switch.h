/* board_switch.h - the switches part: four DIP switches and a button on
 * a resistor ladder into one ADC channel, set by a person's hands. */
#ifndef BOARD_SWITCH_H
#define BOARD_SWITCH_H

#include "board.h"

typedef struct {
    const board_spec_t *spec;     /* the ladder's resistors, VCC */
    unsigned switches;            /* 0..15, bit k: switch k+1 on */
    int button;                   /* 1: held down */
} board_switches_t;

void board_switches_init(board_switches_t *s, const board_spec_t *spec);
/* The ladder's voltage now, V. */
double board_switches_volts(const board_switches_t *s);

#endif

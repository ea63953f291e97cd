/* analog.h - the voltages a board's ADC pins see from the robot's physics,
 * the same for every emulated board (the AVR's sim/board/board_adc.c and
 * the STM32's sim/arm/armboard.c): an IR detector's output for the
 * emitters as they are lit now (the robot file's [ir.*] model, sim.h
 * sim_ir_read, whose counts are its ADC's reading of full scale), and the
 * battery's supply (after its series diode) through a divider. */
#ifndef WORLD_ANALOG_H
#define WORLD_ANALOG_H

#include "world/sim.h"

/* IR sensor i's reading now as millivolts at an ADC of full scale
 * full_scale_v that reads full_counts at it (1023 for a 10-bit ADC):
 * counts x full_scale_v x 1000 / full_counts. */
double analog_ir_mv(sim_state_t *s, unsigned i, double full_scale_v, double full_counts);
/* IR sensor i's own ADC's full-scale count (2^adc_bits - 1, [ir.*] adc_bits). */
double analog_ir_full_counts(const sim_state_t *s, unsigned i);
/* The supply (sim_supply_v) through a divider of r_top_ohm over r_bottom_ohm, V. */
double analog_divider_v(const sim_state_t *s, double r_top_ohm, double r_bottom_ohm);

#endif

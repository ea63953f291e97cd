/* board_adc.h - the analogue front end part: what each ADC channel sees
 * when a conversion starts (an IR detector with the emitters as their pins
 * are, the switch ladder, the battery through its divider). */
#ifndef BOARD_ADC_H
#define BOARD_ADC_H

#include <stddef.h>
#include <stdint.h>

#include "board.h"

struct avr_t;
struct avr_irq_t;
struct avr_adc_t;

/* The part's inputs (its IRQs, made in the AVR's pool): the switch
 * ladder's voltage in mV (board_switch's output) and each emitter pin's
 * level, in the board file's [emitter.*] order (board_led's outputs). */
#define BOARD_ADC_EMITTERS 8 /* >= BOARD_LED_PINS_MAX */
enum { BOARD_ADC_IN_LADDER = 0, BOARD_ADC_IN_EMITTER = 1, BOARD_ADC_INPUTS = BOARD_ADC_IN_EMITTER + BOARD_ADC_EMITTERS };

typedef struct {
    struct avr_t *avr;
    const struct avr_adc_t *adc;
    const board_spec_t *spec;     /* VCC, the ladder's and the battery's channels, the emitters' groups */
    sim_state_t *sim;                   /* IR detectors, emitters, battery */
    struct avr_irq_t *input;      /* BOARD_ADC_INPUTS of them (BOARD_ADC_IN_*) */
    uint32_t ladder_mv;           /* the switch ladder's voltage, mV, as its input last said */
    int emitter_on[BOARD_ADC_EMITTERS]; /* each emitter pin's level, as its input last said */
    int ir_of_channel[BOARD_ADC_CHANNELS]; /* the IR sensor on each channel (-1: none) */
    struct avr_irq_t *in[BOARD_ADC_CHANNELS];
    board_stats_t *st;            /* adc_conversions */
    double held_mv;               /* the sample-and-hold capacitor: the last conversion's input, mV (0 at power-on) */
} board_adc_t;

/* Wire the part to avr's ADC; its inputs wait for board.c to connect the
 * other parts' outputs. 0, or -1 with one line in err (a robot IR channel
 * the board lacks, an MCU without an ADC in simavr). */
int board_adc_init(board_adc_t *a, struct avr_t *avr, const board_spec_t *spec, sim_state_t *sim, board_stats_t *st, char *err,
                   size_t errn);
/* 0, or -1 with a line in err: the firmware chose an auto-trigger simavr lacks. */
int board_adc_check(const board_adc_t *a, char *err, size_t errn);

#endif

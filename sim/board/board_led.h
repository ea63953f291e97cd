/* board_led.h - the LED part: output pins a person (LEDs) or the IR
 * detectors (emitters) see, each pin's level followed through its ioport
 * IRQ and given out again on the part's own output IRQ, one per pin, that
 * board.c connects to whatever sees it (the emitters to board_adc's). */
#ifndef BOARD_LED_H
#define BOARD_LED_H

#include <stdint.h>

#include "board.h"

struct avr_t;
struct avr_irq_t;

#define BOARD_LED_PINS_MAX 8 /* >= BOARD_LEDS_MAX and SIM_EMITTER_GROUPS */

typedef struct {
    int n;
    struct board_led_s {
        int level;                /* 1: the pin is high */
        uint32_t *changes;        /* counted level changes (NULL: not counted) */
        struct avr_irq_t *out;    /* the part's output: the level (0 or 1), raised as it changes */
    } led[BOARD_LED_PINS_MAX];
} board_leds_t;

/* Follow the n pins (at most BOARD_LED_PINS_MAX); changes (NULL: none): a
 * counter per pin. */
void board_leds_init(board_leds_t *l, struct avr_t *avr, const board_pin_t *pins, int n, uint32_t *changes);
/* Pin i's level now (0 for i out of range). */
int board_leds_level(const board_leds_t *l, int i);
/* Pin i's output IRQ (NULL for i out of range): its level as it changes. */
struct avr_irq_t *board_leds_irq(const board_leds_t *l, int i);
/* All levels low (a reset cleared the ports), raised on the outputs. */
void board_leds_clear(board_leds_t *l);

#endif

/* board_led.c - the LED part (board_led.h). */
#include "board_led.h"

#include <simavr/sim_avr.h>
#include <simavr/sim_irq.h>

#include "avrhost.h"

static void on_pin(struct avr_irq_t *irq, uint32_t value, void *param)
{
    struct board_led_s *led = param;
    (void)irq;
    if (led->level == (int)(value & 1u)) return;
    led->level = (int)(value & 1u);
    if (led->changes) (*led->changes)++;
}

void board_leds_init(board_leds_t *l, avr_t *avr, const board_pin_t *pins, int n, uint32_t *changes)
{
    l->n = n < BOARD_LED_PINS_MAX ? n : BOARD_LED_PINS_MAX;
    for (int i = 0; i < l->n; i++) {
        l->led[i].level = 0;
        l->led[i].changes = changes ? &changes[i] : NULL;
        avr_irq_register_notify(avrhost_pin_irq(avr, pins[i].port, pins[i].bit), on_pin, &l->led[i]);
    }
}

int board_leds_level(const board_leds_t *l, int i) { return i >= 0 && i < l->n ? l->led[i].level : 0; }

void board_leds_clear(board_leds_t *l)
{
    for (int i = 0; i < l->n; i++) l->led[i].level = 0;
}

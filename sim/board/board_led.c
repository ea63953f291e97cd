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
    avr_raise_irq(led->out, (uint32_t)led->level);
}

void board_leds_init(board_leds_t *l, avr_t *avr, const board_pin_t *pins, int n, uint32_t *changes)
{
    static const char *names[BOARD_LED_PINS_MAX] = { "led.level0", "led.level1", "led.level2", "led.level3",
                                                     "led.level4", "led.level5", "led.level6", "led.level7" };
    l->n = n < BOARD_LED_PINS_MAX ? n : BOARD_LED_PINS_MAX;
    avr_irq_t *out = l->n > 0 ? avr_alloc_irq(&avr->irq_pool, 0, (uint32_t)l->n, names) : NULL;
    for (int i = 0; i < l->n; i++) {
        l->led[i].level = 0;
        l->led[i].changes = changes ? &changes[i] : NULL;
        l->led[i].out = &out[i];
        avr_irq_register_notify(avrhost_pin_irq(avr, pins[i].port, pins[i].bit), on_pin, &l->led[i]);
    }
}

int board_leds_level(const board_leds_t *l, int i) { return i >= 0 && i < l->n ? l->led[i].level : 0; }

avr_irq_t *board_leds_irq(const board_leds_t *l, int i) { return i >= 0 && i < l->n ? l->led[i].out : NULL; }

void board_leds_clear(board_leds_t *l)
{
    for (int i = 0; i < l->n; i++) {
        l->led[i].level = 0;
        avr_raise_irq(l->led[i].out, 0);
    }
}

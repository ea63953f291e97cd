/* avr_main.c - links the firmware for the ATmega328P to measure its size
 * (make firmware-size). The HAL here is a stub: time from a counter, log
 * lines dropped. The real Arduino backend lives in hal/arduino. */
#include "explore.h"
#include "hal.h"

static explore_t mouse; /* the whole search state, in .bss */
static volatile uint32_t fake_us;

uint32_t hal_micros(void) { return fake_us; }
void hal_log(const char *line) { (void)line; }

int main(void)
{
    maze_t blank;
    maze_init(&blank, 16, 16);
    explore_init(&mouse, &blank);
    for (;;) {
        explore_sense(&mouse, 0);
        int d = explore_next(&mouse);
        if (d < 0) break;
        explore_moved(&mouse, (uint8_t)d);
        fake_us += 1000u;
    }
    return mouse.steps == 0;
}

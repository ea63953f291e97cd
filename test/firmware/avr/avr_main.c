/* avr_main.c - links the firmware for the ATmega328P to measure its size
 * (make firmware-size). The HAL here is a stub (no I/O): the real Arduino
 * backend lives in hal/arduino. A timer interrupt would call fw_tick. */
#include "hal.h"

static volatile uint32_t fake_us;
static volatile int16_t motor[2];

uint32_t hal_micros(void) { return fake_us; }
void hal_motor_set(int16_t left, int16_t right) { motor[0] = left; motor[1] = right; }
int32_t hal_encoder(uint8_t side) { return motor[side & 1]; }
void hal_encoder_reset(void) {}
void hal_tick_hold(void) {}
void hal_tick_release(void) {}
hal_distance_t hal_distance(uint8_t sensor) { hal_distance_t d = { (uint16_t)(100u + sensor), 0, 0 }; return d; }
void hal_log(const char *line) { (void)line; }
void hal_log_P(const char *line) { (void)line; }
uint8_t hal_maze(hal_maze_t *m) { (void)m; return 0; } /* none announced: the classic 16x16 */
void hal_belief(const struct maze_s *map, uint16_t cell, uint8_t heading, uint8_t state)
{
    (void)map; (void)cell; (void)heading; (void)state;
}

int main(void)
{
    fw_setup();
    for (;;) {
        fw_tick();
        fw_loop();
        fake_us += 1000u;
    }
}

/* avr_tick.c - AVR side of the control-tick benchmark: REPS calls of
 * motion_tick (odometry, two profiles, feed-forward + P control, all in
 * float) during a forward move, then sleep with interrupts off so simavr
 * stops; bench/simavr_cycles.c counts the cycles. */
#include <avr/interrupt.h>
#include <avr/sleep.h>

#include "hal.h"
#include "motion.h"

#ifndef REPS
#define REPS 100
#endif

static motion_t mo;
static volatile int32_t counts;
volatile uint16_t reps = REPS; /* volatile: REPS 0 must not fold the loop away */

uint32_t hal_micros(void) { return 0; }
void hal_motor_set(int16_t left, int16_t right) { counts += (left + right) / 256; }
int32_t hal_encoder(uint8_t side) { return counts + side; }
void hal_encoder_reset(void) {}
hal_distance_t hal_distance(uint8_t sensor) { hal_distance_t d = { (uint16_t)(60u + sensor), 0 }; return d; }
void hal_log(const char *line) { (void)line; }
void hal_log_P(const char *line) { (void)line; }
uint8_t hal_maze(hal_maze_t *m) { (void)m; return 0; } /* none announced: the classic 16x16 */
void hal_belief(const struct maze_s *map, uint16_t cell, uint8_t heading, uint8_t state)
{
    (void)map; (void)cell; (void)heading; (void)state;
}
void fw_setup(void) {}
void fw_tick(void) {}
void fw_loop(void) {}

int main(void)
{
    motion_init(&mo);
    motion_forward(&mo, 1000.0f, 700.0f, 0.0f);
    for (uint16_t i = 0; i < reps; i++) motion_tick(&mo, 0.001f);
    cli();
    sleep_mode();
    return 0;
}

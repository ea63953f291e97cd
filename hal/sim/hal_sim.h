/* hal_sim.h - the simulator backend of hal/hal.h (host, in-process).
 * Attach a running simulation and the HAL reads its encoders and ToF
 * readings, sets its motor commands and reports its time. */
#ifndef HAL_SIM_H
#define HAL_SIM_H

#include <stdint.h>
#include <stdio.h>

struct sim_s;

/* Serve the HAL from this simulation (NULL detaches). */
void hal_sim_attach(struct sim_s *s);
/* Without an attached simulation (grid mode): the time hal_micros reports. */
void hal_sim_set_time_us(uint64_t t_us);
/* Where hal_log lines go: a stream (NULL = dropped, the default). */
void hal_sim_set_log(FILE *out);

/* The mouse's last hal_belief report (a copy): returns 1 and fills the
 * non-NULL outputs, or 0 if none since the last attach. */
int hal_sim_belief(const struct maze_s **map, uint16_t *cell, uint8_t *heading, uint8_t *state);

#endif

/* hal_sim.h - the simulator backend of hal/hal.h (host, in-process). */
#ifndef HAL_SIM_H
#define HAL_SIM_H

#include <stdint.h>
#include <stdio.h>

/* Set the simulation time that hal_micros reports (microseconds). */
void hal_sim_set_time_us(uint64_t t_us);
/* Where hal_log lines go: a stream (NULL = dropped, the default). */
void hal_sim_set_log(FILE *out);

#endif

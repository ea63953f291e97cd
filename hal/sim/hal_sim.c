/* hal_sim.c - hal/hal.h for the simulator: time is simulation time, set by
 * the simulator as it steps; log lines go to a stream the simulator picks. */
#include "hal.h"
#include "hal_sim.h"

static uint64_t sim_time_us;
static FILE *log_out;

void hal_sim_set_time_us(uint64_t t_us) { sim_time_us = t_us; }
void hal_sim_set_log(FILE *out) { log_out = out; }

uint32_t hal_micros(void) { return (uint32_t)sim_time_us; }

void hal_log(const char *line)
{
    if (log_out) fprintf(log_out, "%s\n", line);
}

/* hal_sim.c - hal/hal.h for the simulator: time is simulation time; motors,
 * encoders and ToF readings are the attached simulation's. */
#include "hal.h"
#include "hal_sim.h"

#include <math.h>

#include "world/sim.h"

static sim_state_t *sim;
static FILE *log_out;
static int32_t encoder_zero[2];
static sim_belief_t belief;
static hal_maze_t announced;   /* hal_maze's answer */
static uint8_t announced_ok;   /* whether there is one */

void hal_sim_attach(struct sim_state_s *s)
{
    sim = s;
    encoder_zero[0] = encoder_zero[1] = 0;
    belief.seq = 0;
}
void hal_sim_set_log(FILE *out) { log_out = out; }

void hal_sim_set_maze(const struct maze_s *m)
{
    announced_ok = 0;
    if (!m) return;
    hal_maze_t a = { m->width, m->height, maze_x(m, m->start), maze_y(m, m->start), m->start_heading,
                     m->width, m->height, 0, 0 };
    for (uint16_t c = 0; c < maze_cells(m); c++) {
        if (!maze_is_goal(m, (maze_cell_t)c)) continue;
        uint8_t x = maze_x(m, (maze_cell_t)c), y = maze_y(m, (maze_cell_t)c);
        if (x < a.goal_x0) a.goal_x0 = x;
        if (y < a.goal_y0) a.goal_y0 = y;
        if (x > a.goal_x1) a.goal_x1 = x;
        if (y > a.goal_y1) a.goal_y1 = y;
    }
    announced = a;
    announced_ok = a.goal_x0 <= a.goal_x1; /* a maze without a goal announces nothing */
}

uint8_t hal_maze(hal_maze_t *m)
{
    if (announced_ok) *m = announced;
    return announced_ok;
}

/* fw_tick and fw_loop run in turn (sim/contest/run_firmware.c): nothing to hold */
void hal_tick_hold(void) {}
void hal_tick_release(void) {}

uint32_t hal_micros(void)
{
    if (sim) return (uint32_t)(sim->step * (uint64_t)llround(sim->model->cfg->sim.step_s * 1e6));
    return 0; /* no simulation attached: time stands at 0 */
}

void hal_motor_set(int16_t left, int16_t right)
{
    if (!sim) return;
    sim->cmd[WORLD_LEFT] = left;
    sim->cmd[WORLD_RIGHT] = right;
}

int32_t hal_encoder(uint8_t side)
{
    return sim ? sim->encoder[side & 1].count - encoder_zero[side & 1] : 0;
}

void hal_encoder_reset(void)
{
    if (!sim) return;
    encoder_zero[0] = sim->encoder[0].count;
    encoder_zero[1] = sim->encoder[1].count;
}

hal_distance_t hal_distance(uint8_t sensor)
{
    hal_distance_t d = { 0, 1, 0 };
    if (!sim || sensor >= HAL_TOF_COUNT) return d;
    const tof_reading_t *r = &sim->tof_last[sensor];
    d.mm = (uint16_t)lround(r->dist_m * 1000.0);
    d.timeout = (uint8_t)r->timeout;
    d.seq = (uint8_t)sim->tof_count[sensor];
    return d;
}

void hal_log(const char *line)
{
    if (log_out) fprintf(log_out, "%s\n", line);
}

void hal_belief(const struct maze_s *map, uint16_t cell, uint8_t heading, uint8_t state)
{
    /* a copy for the contest's observers (hal_sim_belief); the simulation never reads it */
    belief.seq++;
    belief.t_us = sim ? sim->step * (uint64_t)llround(sim->model->cfg->sim.step_s * 1e6) : 0;
    belief.map = *map;
    belief.cell = cell;
    belief.heading = heading;
    belief.state = state;
}

const sim_belief_t *hal_sim_belief(void) { return &belief; }

uint8_t hal_ir_count(void) { return sim ? (uint8_t)sim_ir_count(sim) : 0; }
void hal_emitter(uint8_t group, uint8_t on)
{
    if (sim) sim_emitter_set(sim, group, on);
}
static uint8_t ir_seq;
uint16_t hal_ir_raw(uint8_t sensor)
{
    if (!sim) return 0;
    ir_seq++;
    return (uint16_t)sim_ir_read(sim, sensor);
}
uint8_t hal_ir_seq(void) { return ir_seq; }
uint8_t hal_gyro_present(void) { return sim ? (uint8_t)sim_has_gyro(sim) : 0; }
int32_t hal_gyro_mdps(void) { return sim ? (int32_t)lround(sim_gyro_rad_s(sim) * 180.0 / M_PI * 1000.0) : 0; }
uint16_t hal_battery_mv(void)
{
    double v = sim ? sim_battery_v(sim) * 1000.0 : 0;
    return (uint16_t)(v < 0 ? 0 : v > 65535 ? 65535 : lround(v));
}

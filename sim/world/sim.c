/* sim.c - the contest loop around the world (see sim.h). */
#include "sim.h"

#include <math.h>

static double start_heading(uint8_t d)
{
    static const double a[4] = { M_PI / 2, 0.0, -M_PI / 2, M_PI };
    return a[d & 3];
}

/* This robot's asymmetries: the configured ones plus the per-seed
 * variation's draws (config [variation]; one stream, drawn in this order). */
static void vary(simcfg_t *c, uint64_t seed)
{
    rng_t r;
    rng_init(&r, seed, RNG_STREAM_VARIATION);
    double g[5];
    for (int i = 0; i < 5; i++) g[i] = rng_gauss(&r);
    c->wheel_d_diff_m += c->wheel_d_sigma_m * g[0];
    c->motor_k_diff_pct += c->motor_k_sigma_pct * g[1];
    c->tyre_mu_diff += c->tyre_mu_sigma * g[2];
    c->com_x_m += c->com_sigma_m * g[3];
    c->com_y_m += c->com_sigma_m * g[4];
}

int sim_init(sim_t *s, const simcfg_t *cfg, const maze_t *m, uint64_t seed)
{
    simcfg_t robot = *cfg;
    const simcfg_t *c = &robot;
    vary(&robot, seed);
    double cell = c->cell_m;
    s->cfg = robot;
    s->maze = m;
    s->seed = seed;
    s->world = world_create(c, m, (maze_x(m, m->start) + 0.5) * cell, (maze_y(m, m->start) + 0.5) * cell,
                            start_heading(m->start_heading));
    if (!s->world) return -1;
    double counts_per_rev = c->encoder_ppr * c->gear_ratio;
    uint64_t period = (uint64_t)llround(c->tof_period_s / c->step_s);
    if (period == 0) period = 1;
    for (int i = 0; i < 2; i++) {
        /* right minus left, in per cent of the mean */
        motor_init(&s->motor[i], c, 1.0 + (i == WORLD_LEFT ? -0.005 : 0.005) * c->motor_k_diff_pct);
        encoder_init(&s->encoder[i], counts_per_rev, world_wheel_angle(s->world, i));
        s->cmd[i] = 0;
    }
    for (int i = 0; i < WORLD_TOF_COUNT; i++) {
        tof_init(&s->tof[i], c, seed, (unsigned)i);
        s->tof_last[i].dist_m = c->tof_range_m;
        s->tof_last[i].timeout = 1;
        s->tof_true_m[i] = -1;
        s->tof_next_step[i] = (uint64_t)i * period / WORLD_TOF_COUNT; /* staggered */
        s->tof_count[i] = 0;
    }
    s->tof_enabled = 1;
    s->diverged = 0;
    race_init(&s->race, m, cell, c->time_limit_s);
    s->step = 0;
    return 0;
}

void sim_free(sim_t *s)
{
    world_destroy(s->world);
    s->world = NULL;
}

double sim_time_s(const sim_t *s) { return (double)s->step * s->cfg.step_s; }

void sim_step(sim_t *s)
{
    double dt = s->cfg.step_s;
    if (s->diverged) return;
    motor_drive_t d[2];
    for (int i = 0; i < 2; i++) d[i] = motor_drive(&s->motor[i], s->cmd[i], world_wheel_rate(s->world, i), dt);
    world_step(s->world, d);
    s->step++;
    if (!world_sane(s->world)) {
        s->diverged = 1;
        return;
    }
    for (int i = 0; i < 2; i++) motor_after(&s->motor[i], &d[i], world_wheel_rate(s->world, i), dt);
    for (int i = 0; i < 2; i++) encoder_update(&s->encoder[i], world_wheel_angle(s->world, i));
    uint64_t period = (uint64_t)llround(s->cfg.tof_period_s / dt);
    if (period == 0) period = 1;
    for (int i = 0; i < WORLD_TOF_COUNT; i++) {
        if (s->step < s->tof_next_step[i]) continue;
        s->tof_next_step[i] += period;
        if (!s->tof_enabled) continue;
        /* rays only when a sensor updates: 3 rays per 30 ms, not per step */
        s->tof_true_m[i] = world_tof_ray(s->world, i, s->cfg.tof_range_m);
        s->tof_last[i] = tof_measure(&s->tof[i], s->tof_true_m[i]);
        s->tof_count[i]++;
    }
    double x, y, h;
    world_pose(s->world, &x, &y, &h);
    race_update(&s->race, sim_time_s(s), x, y);
}

/* stubs until the robot file's components are wired in (issue 17) */
int sim_ir_count(const sim_t *s) { (void)s; return 0; }
void sim_emitter_set(sim_t *s, unsigned group, int on) { (void)s; (void)group; (void)on; }
int sim_emitter(const sim_t *s, unsigned group) { (void)s; (void)group; return 0; }
unsigned sim_ir_read(sim_t *s, unsigned i) { (void)s; (void)i; return 0; }
int sim_has_gyro(const sim_t *s) { (void)s; return 0; }
double sim_gyro_rad_s(const sim_t *s) { (void)s; return 0; }
double sim_battery_v(const sim_t *s) { return s->cfg.battery_v; }

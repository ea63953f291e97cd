/* sim.c - the contest loop around the world (see sim.h). */
#include "sim.h"

#include <math.h>

static double start_heading(uint8_t d)
{
    static const double a[4] = { M_PI / 2, 0.0, -M_PI / 2, M_PI };
    return a[d & 3];
}

int sim_init(sim_t *s, const simcfg_t *c, const maze_t *m, uint64_t seed)
{
    double cell = c->cell_m;
    s->cfg = *c;
    s->maze = m;
    s->seed = seed;
    s->world = world_create(c, m, (maze_x(m, m->start) + 0.5) * cell, (maze_y(m, m->start) + 0.5) * cell,
                            start_heading(m->start_heading));
    if (!s->world) return -1;
    double counts_per_rev = c->encoder_ppr * c->gear_ratio;
    uint64_t period = (uint64_t)llround(c->tof_period_s / c->step_s);
    if (period == 0) period = 1;
    for (int i = 0; i < 2; i++) {
        motor_init(&s->motor[i], c);
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

/* The motors' torques over one ODE step. motor_step's torque is
 * damping * (free speed - w), explicit in the wheel speed w of the step
 * before. Damping up to J/(2*dt) stays explicit, J the inertia the torque
 * turns (a free wheel then settles without overshoot): all of it for the
 * default robot. The rest goes to ODE as an implicit damper towards the
 * free speed, on the speed at the end of the step: stable for any motor. */
static void step_motors(sim_t *s, double dt)
{
    double torque[2], damping[2], free[2];
    double explicit_max = 0.5 * world_hinge_inertia(s->world) / dt; /* N*m*s/rad */
    for (int i = 0; i < 2; i++) {
        double all = motor_damping(&s->motor[i], s->cmd[i], dt);
        free[i] = motor_free_speed(&s->motor[i], s->cmd[i], dt);
        torque[i] = motor_step(&s->motor[i], s->cmd[i], world_wheel_rate(s->world, i), dt);
        damping[i] = fmax(0.0, all - explicit_max);
        if (damping[i] > 0) torque[i] *= explicit_max / all; /* the explicit share */
    }
    world_step_motors(s->world, torque, damping, free);
    for (int i = 0; i < 2; i++)
        if (damping[i] > 0)
            motor_set_torque(&s->motor[i], s->cmd[i], torque[i] + damping[i] * (free[i] - world_wheel_rate(s->world, i)));
}

void sim_step(sim_t *s)
{
    double dt = s->cfg.step_s;
    if (s->diverged) return;
    step_motors(s, dt);
    s->step++;
    if (!world_sane(s->world)) {
        s->diverged = 1;
        return;
    }
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

/* driver.c - scripted path following on the true pose (see driver.h). */
#include "driver.h"

#include <math.h>

#define ARRIVE_M 0.015      /* a waypoint is reached within 15 mm */
#define TURN_IN_PLACE 0.35  /* rad: above this heading error, turn on the spot */
#define CRUISE_M_S 0.7      /* speed on straights */
#define DECEL_G 0.5         /* brake at half the sliding friction's limit */

static solve_path_t best;

void driver_init(driver_t *d, const truemaze_t *m, const sim_model_t *md, int runs)
{
    const simcfg_t *c = md->cfg;
    double wheel_r_m = (md->wheel_r_m[WORLD_LEFT] + md->wheel_r_m[WORLD_RIGHT]) / 2; /* the wheels' mean */
    /* m/s per command step at no load: V/1023 / Kt * wheel radius */
    d->v_per_cmd = motor_free_speed(&c->robot.drive[0], battery_spec_full_v(&c->robot.battery)) / 1023.0 * wheel_r_m;
    double cell_m = c->world.cell_m;
    d->decel_m_s2 = fmin(2.0, DECEL_G * c->robot.tyre_mu_dynamic * 9.81);
    d->n = 0;
    d->idx = 1;
    d->vref = 0;
    d->dir = 1;
    d->runs_left = runs;
    d->done = 0;
    d->reachable = solve_best(m, &best) == 0;
    if (!d->reachable) {
        d->done = 1;
        return;
    }
    /* keep the first cell, every corner and the last cell */
    for (uint16_t i = 0; i < best.len; i++) {
        if (i > 0 && i + 1 < best.len) {
            int ax = truemaze_x(m, best.path[i]) - truemaze_x(m, best.path[i - 1]);
            int ay = truemaze_y(m, best.path[i]) - truemaze_y(m, best.path[i - 1]);
            int bx = truemaze_x(m, best.path[i + 1]) - truemaze_x(m, best.path[i]);
            int by = truemaze_y(m, best.path[i + 1]) - truemaze_y(m, best.path[i]);
            if (ax == bx && ay == by) continue;
        }
        d->wx[d->n] = (truemaze_x(m, best.path[i]) + 0.5) * cell_m;
        d->wy[d->n] = (truemaze_y(m, best.path[i]) + 0.5) * cell_m;
        d->n++;
    }
}

static double clamp(double v, double lo, double hi) { return v < lo ? lo : v > hi ? hi : v; }

void driver_update(driver_t *d, sim_state_t *s)
{
    double x, y, h, v, om;
    if (d->done || d->n < 2) {
        s->cmd[0] = s->cmd[1] = 0;
        d->done = 1;
        return;
    }
    world_pose(s->world, &x, &y, &h);
    world_velocity(s->world, &v, &om);
    double dx = d->wx[d->idx] - x, dy = d->wy[d->idx] - y, dist = hypot(dx, dy);
    if (dist < ARRIVE_M) {
        int end = d->dir > 0 ? d->n - 1 : 0;
        if (d->idx == end) {
            if (d->dir > 0) d->runs_left--;
            if (d->dir < 0 && d->runs_left <= 0) {
                d->done = 1;
                s->cmd[0] = s->cmd[1] = 0;
                return;
            }
            d->dir = -d->dir;
        }
        d->idx += d->dir;
        dx = d->wx[d->idx] - x;
        dy = d->wy[d->idx] - y;
        dist = hypot(dx, dy);
    }
    double e = remainder(atan2(dy, dx) - h, 2 * M_PI);
    double fwd = 0, turn;
    if (fabs(e) > TURN_IN_PLACE) {
        /* on the spot, yaw rate damped; gentler on slippery tyres */
        double lim = 450 * fmin(1.0, s->model->cfg->robot.tyre_mu_dynamic);
        turn = clamp(900 * e - 60 * om, -lim, lim);
        d->vref = 0;
    } else {
        /* speed reference: cruise, braking into each corner at DECEL_M_S2;
         * feed-forward from the motor's no-load speed plus a speed loop */
        double vref = fmin(CRUISE_M_S, sqrt(2 * d->decel_m_s2 * dist));
        /* and accelerate no harder than we brake, or the tyres spin */
        vref = fmin(vref, d->vref + d->decel_m_s2 * s->model->cfg->sim.step_s);
        d->vref = vref;
        fwd = clamp(vref / d->v_per_cmd + 3000 * (vref - v), -1023, 1023);
        turn = clamp(1200 * e - 40 * om, -300, 300);
    }
    s->cmd[WORLD_LEFT] = (int)lround(clamp(fwd - turn, -1023, 1023));
    s->cmd[WORLD_RIGHT] = (int)lround(clamp(fwd + turn, -1023, 1023));
}

/* bench.c - the validation benches (bench.h): an open field or a
 * corridor of cells, step counts, the voltage step and its first-order
 * fit, and the table a check is added to. */
#include "validate/bench.h"

#include <math.h>

#include "world/robot.h"
#include "world/world.h"
#include "world/sensors/ir.h"
#include "world/sensors/sensor.h"

bench_t bench; /* one at a time; truemaze_t and sim_state_t are large */

void bench_field(truemaze_t *m, uint8_t w, uint8_t h, uint8_t sx)
{
    truemaze_init(m, w, h);
    for (uint8_t y = 0; y < h; y++)
        for (uint8_t x = 0; x < w; x++) {
            truemaze_cell_t c = truemaze_cell(m, x, y);
            if (x + 1 < w) truemaze_set_wall(m, c, TRUEMAZE_EAST, 0);
            if (y + 1 < h) truemaze_set_wall(m, c, TRUEMAZE_NORTH, 0);
        }
    m->start = truemaze_cell(m, sx, 0);
    m->start_heading = TRUEMAZE_NORTH;
}

void bench_corridor(truemaze_t *m, uint8_t n)
{
    truemaze_init(m, n, 1);
    for (uint8_t x = 0; x + 1 < n; x++) truemaze_set_wall(m, truemaze_cell(m, x, 0), TRUEMAZE_EAST, 0);
    m->start = truemaze_cell(m, 0, 0);
    m->start_heading = TRUEMAZE_EAST;
}

int bench_init(const simcfg_t *c)
{
    sim_model_build(&bench.model, c, 1);
    return sim_init(&bench.sim, &bench.model, &bench.maze, 1);
}

long bench_steps(const simcfg_t *c, double seconds) { return lround(seconds / c->sim.step_s); }

int bench_volt_cmd(const sim_state_t *s, double v_volt)
{
    double b = sim_battery_v(s);
    long cmd = b > 0 ? lround(v_volt / b * MOTOR_CMD_MAX) : 0;
    return (int)(cmd > MOTOR_CMD_MAX ? MOTOR_CMD_MAX : cmd < -MOTOR_CMD_MAX ? -MOTOR_CMD_MAX : cmd);
}

/* The squared residual of the fit with time constant tau; *vss its best
 * steady speed. */
static double step_residual(const double *t, const double *x, long n, double tau, double *vss)
{
    double gg = 0, gx = 0, xx = 0;
    for (long i = 0; i < n; i++) {
        double g = t[i] - tau * (1 - exp(-t[i] / tau));
        gg += g * g, gx += g * x[i], xx += x[i] * x[i];
    }
    *vss = gg > 0 ? gx / gg : 0;
    return xx - 2 * *vss * gx + *vss * *vss * gg;
}

bench_step_t bench_step_fit(const double *t_s, const double *x, long n)
{
    bench_step_t r = { 0, 0 };
    if (n < 2) return r;
    const double gr = (sqrt(5) - 1) / 2;
    double lo = 1e-3, hi = t_s[n - 1] > 2e-3 ? t_s[n - 1] : 2e-3, v;
    double a = hi - gr * (hi - lo), b = lo + gr * (hi - lo);
    double fa = step_residual(t_s, x, n, a, &v), fb = step_residual(t_s, x, n, b, &v);
    for (int k = 0; k < 60; k++) {
        if (fa < fb) {
            hi = b, b = a, fb = fa;
            a = hi - gr * (hi - lo);
            fa = step_residual(t_s, x, n, a, &v);
        } else {
            lo = a, a = b, fa = fb;
            b = lo + gr * (hi - lo);
            fb = step_residual(t_s, x, n, b, &v);
        }
    }
    r.tm_s = 0.5 * (lo + hi);
    step_residual(t_s, x, n, r.tm_s, &r.steady);
    return r;
}

#define STEP_S 1.2       /* s: motorlab's step length */
#define STEP_MAX 48000   /* samples: 1.2 s at 25 us */

bench_step_t bench_voltage_step(const simcfg_t *c, double v_volt, int rot)
{
    static double t[STEP_MAX], x[STEP_MAX];
    bench_step_t r = { 0, 0 };
    bench_field(&bench.maze, 10, 10, 4);
    sim_state_t *s = &bench.sim;
    if (bench_init(c) != 0) return r;
    const sim_model_t *md = s->model; /* the robot as simulated: each wheel's radius with the seed's asymmetry */
    if (rot) world_place(s->world, 4.5 * md->arena.cell_m, 4.5 * md->arena.cell_m, M_PI / 2, NULL); /* the field's middle */
    long n = lround(STEP_S / md->step_s);
    if (n > STEP_MAX) n = STEP_MAX;
    double dist = 0;
    for (long i = 0; i < n; i++) {
        s->cmd[WORLD_LEFT] = bench_volt_cmd(s, rot ? -v_volt : v_volt);
        s->cmd[WORLD_RIGHT] = bench_volt_cmd(s, v_volt);
        sim_step(md, s);
        double vl = world_wheel_rate(s->world, WORLD_LEFT) * md->wheel_r_m[WORLD_LEFT];
        double vr = world_wheel_rate(s->world, WORLD_RIGHT) * md->wheel_r_m[WORLD_RIGHT];
        dist += (rot ? (vr - vl) / (2 * md->chassis.wheel_x_m) : (vr + vl) / 2) * md->step_s;
        t[i] = (i + 1) * md->step_s, x[i] = dist;
    }
    sim_free(s);
    return bench_step_fit(t, x, n);
}

void bench_add(validate_check_t *v, int *n, const char *name, double expected, double measured, const char *unit,
                double tol_pct, int bound, const char *source)
{
    validate_check_t *k = &v[(*n)++];
    k->name = name;
    k->expected = expected;
    k->measured = measured;
    k->unit = unit;
    k->tolerance_pct = tol_pct;
    k->bound = bound;
    k->source = source;
    k->kind = VALIDATE_PREDICTED;
    if (bound == VALIDATE_NEAR) k->pass = fabs(measured - expected) <= tol_pct / 100.0 * fabs(expected);
    else if (bound == VALIDATE_MAX) k->pass = measured <= expected;
    else k->pass = 1;
}

void bench_fit(validate_check_t *v, int *n, const char *name, double expected, double measured, const char *unit,
               const char *source)
{
    bench_add(v, n, name, expected, measured, unit, 0, VALIDATE_REPORT, source);
    v[*n - 1].kind = VALIDATE_FITTED;
}

/* Sensor i's mean lit-minus-dark over 64 samples, the robot where it is. */
double bench_lit_minus_dark(sim_state_t *s, unsigned i)
{
    const robot_part_t *p = &s->model->part[sensor_of_kind(s->model, "ir", i)];
    unsigned g = (unsigned)((const ir_part_spec_t *)p->spec)->emitter;
    double sum = 0;
    for (int k = 0; k < 64; k++) {
        sim_emitter_set(s, g, 0);
        double dark = sim_ir_read(s, i);
        sim_emitter_set(s, g, 1);
        sum += sim_ir_read(s, i) - dark;
    }
    sim_emitter_set(s, g, 0);
    return sum / 64;
}

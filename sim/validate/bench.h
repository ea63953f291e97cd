/* bench.h - the validation benches, shared by validate.c (motor, world,
 * ToF) and validate_robot.c (the robot file's measured figures, IR, gyro).
 * Private to sim/validate. */
#ifndef VALIDATE_BENCH_H
#define VALIDATE_BENCH_H

#include "validate.h"
#include "maze/truemaze.h"
#include "world/sim.h"

typedef struct {
    truemaze_t maze;
    sim_model_t model;
    sim_state_t sim;
} bench_t;

extern bench_t bench; /* one at a time; truemaze_t and sim_state_t are large */

/* An open field w x h cells (outer walls only), the robot in cell (sx, 0)
 * facing north. */
void bench_field(truemaze_t *m, uint8_t w, uint8_t h, uint8_t sx);
/* A corridor of n cells running east, the robot in its first facing east. */
void bench_corridor(truemaze_t *m, uint8_t n);
/* bench.sim made for config c on bench.maze (the model built with seed 1
 * into bench.model): 0, or -1 if ODE could not be set up. */
int bench_init(const simcfg_t *c);
/* Physics steps in `seconds`. */
long bench_steps(const simcfg_t *c, double seconds);
/* The motor command for v_volt with the battery as it is now. */
int bench_volt_cmd(const sim_state_t *s, double v_volt);
/* A first-order step response fitted to a distance log by least squares:
 * x(t) = vss (t - tau (1 - e^(-t/tau))), vss linear given tau, tau by
 * golden-section search over [1 ms, the log's length]. The same fit as
 * tools/mmfit's step_figures (on the distance: robust to count
 * quantisation), so a figure mmfit fits is the figure --validate reads. */
typedef struct {
    double steady, tm_s; /* steady speed (units of x per s) and the time constant (s) */
} bench_step_t;
bench_step_t bench_step_fit(const double *t_s, const double *x, long n);
/* From rest in an open field, v_volt on both motors (rot: -v left, +v
 * right, a spin counter-clockwise) for 1.2 s, as ukmars' motorlab steps a
 * motor, at c's step: the steady speed (m/s, or rad/s turning over the
 * track) and time constant, fitted to the distance (or angle) the encoders
 * measure, as the robot measures it (wheel turns x its calibrated wheel
 * radius; turning over its track, mazerunner-core's MOUSE_RADIUS). */
bench_step_t bench_voltage_step(const simcfg_t *c, double v_volt, int rot);
/* Append a predicted check to v (at *n): graded as its bound says
 * (validate.h); source names the data the model was not built from. */
/* IR sensor i's (the robot file's i-th [ir.*]) mean lit-minus-dark reading
 * over 64 samples, its emitter group lit and dark in turn, the robot where
 * it is. */
double bench_lit_minus_dark(sim_state_t *s, unsigned i);
void bench_add(validate_check_t *v, int *n, const char *name, double expected, double measured, const char *unit,
         double tol_pct, int bound, const char *source);
/* Append a fitted figure: the model was built from `expected` (source
 * names the data); reported, never graded. */
void bench_fit(validate_check_t *v, int *n, const char *name, double expected, double measured, const char *unit,
               const char *source);
/* The robot file's checks: its [measured.*] figures and IR calibration
 * readings reproduced, its IR sensors and gyro against their models'
 * analytic values (validate_robot.c). Returns the new count. */
int validate_robot_checks(const simcfg_t *c, validate_check_t *v, int n);
/* Where a one-cell stop at the example firmware's acceleration ends against
 * the encoders (stop.c). Returns the new count. */
int validate_stop_checks(const simcfg_t *c, validate_check_t *v, int n);

#endif

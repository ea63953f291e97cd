/* stop.c - where a stop ends against the encoders (see bench.h): one-cell
 * moves driven on the robot's own encoders, and how far the body truly
 * went along its heading against the distance its encoders report.
 *
 * What it predicts. A tyre that rolls without slipping turns its wheel by
 * the distance over the rolling radius, and the encoder counts that turn
 * relative to the chassis; once the robot is at rest on the floor again
 * (its chassis level, as it started) the chassis' travel is the wheels'
 * turn times their radius, whatever it pitched in between. A stop at the
 * example firmware's 3 m/s^2 asks 0.31 of the tyres' grip (tyre_mu 1.0 in
 * the shipped robot files), well inside the friction cone: the prediction
 * is 0. The bar allows what the model itself counts as gripping: a tyre
 * keeps its static friction up to the robot file's tyre_slip_m_s of slip
 * (5 mm/s), so a tyre creeping at that through a whole stop (v / a, 0.13 s)
 * runs 0.67 mm past its wheel's turn; and the encoders' whole counts: each
 * reads its wheel's turn truncated (encoder.c keeps the remainder), so
 * their mean is within one count, spread over the moves. A wheel that
 * leaves the floor or slides in the stop shows as more: the paper robot
 * tips about 85 mrad nose down in each stop, and a spin form that hands
 * the chassis the motor's whole torque lifts a wheel 0.25 mm off the floor
 * and ends 1.3 mm a move past its encoders (docs/BENCHMARKS.md). */
#include "bench.h"

#include <math.h>

#include "world/motor.h"
#include "world/world.h"

#define STOP_MOVE_M 0.180    /* m: one cell (the maze's 180 mm pitch) */
#define STOP_ACCEL_M_S2 3.0  /* m/s^2: firmware/robot_config.h RC_ACCEL_MM_S2 and RC_RUN_ACCEL_MM_S2, 3000 mm/s^2 */
#define STOP_PEAK_M_S 0.4    /* m/s: under the 481 mm/s up to which the paper robot's motor gives 3 m/s^2 (robot_config.h) */
#define STOP_MOVES 4         /* moves from rest to rest: a bias adds up over them, the encoders' last count does not */
#define STOP_REST_S 0.3      /* s: at rest after each move */
#define STOP_SETTLE_S 0.5    /* s: the loop holds the last move's end this long before the pose is read */
#define STOP_KP_V_M 500.0    /* V per m of a wheel's position error: the loop holds the end within the gearbox's stiction */
#define STOP_KD_V_S_M 2.0    /* V per m/s of a wheel's speed error: damps the loop */

/* The trapezoid's target distance (m), speed (m/s) and acceleration
 * (m/s^2) t_s into a move. */
static void profile(double t_s, double *p_m, double *v_m_s, double *a_m_s2)
{
    const double a = STOP_ACCEL_M_S2, vp = STOP_PEAK_M_S, tr = vp / a;
    const double tc = (STOP_MOVE_M - vp * tr) / vp, te = 2 * tr + tc; /* ramp, cruise and move times, s */
    if (t_s < tr) *p_m = 0.5 * a * t_s * t_s, *v_m_s = a * t_s, *a_m_s2 = a;
    else if (t_s < tr + tc) *p_m = 0.5 * vp * tr + vp * (t_s - tr), *v_m_s = vp, *a_m_s2 = 0;
    else if (t_s < te) {
        double u = te - t_s;
        *p_m = STOP_MOVE_M - 0.5 * a * u * u, *v_m_s = a * u, *a_m_s2 = -a;
    } else *p_m = STOP_MOVE_M, *v_m_s = 0, *a_m_s2 = 0;
}

/* The voltage that drives wheel w at v_m_s with a_m_s2 (the motor's
 * back-EMF, its friction and half the robot's mass accelerated) and
 * corrects its encoder distance d_m towards p_m. */
static double wheel_volts(const simcfg_t *c, const sim_state_t *s, int w, double p_m, double v_m_s, double a_m_s2, double d_m)
{
    const drive_spec_t *d = &c->robot.drive[w];
    double r, ke, eta, rw = s->model->wheel_r_m[w];
    motor_constants(d, &r, &ke, &eta);
    double m_kg = c->robot.body_mass_kg + 2 * c->robot.wheel_mass_kg + c->robot.caster_mass_kg;
    double i_a = 0.5 * m_kg * a_m_s2 * rw / (d->gear_ratio * eta * ke) + (v_m_s > 0 ? d->no_load_a : 0);
    double ff = ke * d->gear_ratio * v_m_s / rw + r * i_a;
    double vw = world_wheel_rate(s->world, w) * rw; /* the wheel's speed relative to the chassis, as its encoder sees it */
    return ff + STOP_KP_V_M * (p_m - d_m) + STOP_KD_V_S_M * (v_m_s - vw);
}

/* From rest in an open field, STOP_MOVES one-cell trapezoids, each from
 * rest to rest, driven on the encoders, the last held STOP_SETTLE_S: the
 * body's true travel along its start heading less the encoders' mean
 * distance, mm per move; *count_mm one count (the wheels' mean). */
static double stop_past_odometry_mm(const simcfg_t *c, double *count_mm)
{
    bench_field(&bench.maze, 3, STOP_MOVES + 2, 1);
    sim_state_t *s = &bench.sim;
    *count_mm = 0;
    if (bench_init(c) != 0) return 1e9;
    double mm_per_count[2], x0, y0, h0, x, y, h;
    for (int w = 0; w < 2; w++) /* the wheel's own radius: a robot calibrated by pushing it (counts_500mm) */
        mm_per_count[w] = 2 * M_PI * s->model->wheel_r_m[w] * 1000 / (c->robot.drive[w].encoder_ppr * c->robot.drive[w].gear_ratio);
    *count_mm = 0.5 * (mm_per_count[0] + mm_per_count[1]);
    world_pose(s->world, &x0, &y0, &h0);
    int32_t e0[2] = { s->encoder[0].count, s->encoder[1].count };
    double move_s = STOP_PEAK_M_S / STOP_ACCEL_M_S2 + STOP_MOVE_M / STOP_PEAK_M_S + STOP_REST_S; /* a move and its rest */
    long n = bench_steps(c, STOP_MOVES * move_s + STOP_SETTLE_S);
    for (long i = 0; i < n; i++) {
        double t_s = (double)i * c->sim.step_s, p, v, a;
        int k = (int)(t_s / move_s);
        if (k >= STOP_MOVES) k = STOP_MOVES - 1;
        profile(t_s - k * move_s, &p, &v, &a);
        for (int w = 0; w < 2; w++) {
            double d_m = (s->encoder[w].count - e0[w]) * mm_per_count[w] / 1000;
            s->cmd[w] = bench_volt_cmd(s, wheel_volts(c, s, w, p + k * STOP_MOVE_M, v, a, d_m));
        }
        sim_step(s->model, s);
    }
    world_pose(s->world, &x, &y, &h);
    double along_mm = ((x - x0) * cos(h0) + (y - y0) * sin(h0)) * 1000;
    double enc_mm = 0.5 * ((s->encoder[0].count - e0[0]) * mm_per_count[0] + (s->encoder[1].count - e0[1]) * mm_per_count[1]);
    sim_free(s);
    return (along_mm - enc_mm) / STOP_MOVES;
}

int validate_stop_checks(const simcfg_t *c, validate_check_t *v, int n)
{
    double count_mm, past_mm = stop_past_odometry_mm(c, &count_mm);
    double creep_mm = c->robot.tyre_slip_m_s * STOP_PEAK_M_S / STOP_ACCEL_M_S2 * 1000; /* a stop's slip at the grip limit */
    bench_add(v, &n, "stop_past_odometry", creep_mm + count_mm / STOP_MOVES, fabs(past_mm), "mm", 0, VALIDATE_MAX,
        "physical requirement: one-cell moves at 3 m/s^2 (firmware/robot_config.h RC_ACCEL_MM_S2) driven on the encoders "
        "end where they say: |the true travel along the heading less their mean distance| at rest, per move (4 moves of "
        "180 mm at 0.4 m/s); 0 for rolling tyres, the bar tyre_slip_m_s through a stop (v/a) + one count / 4 moves");
    return n;
}

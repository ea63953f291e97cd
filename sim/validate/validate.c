/* validate.c - the validation scenarios (see validate.h). Each builds its
 * bench, runs the simulator's own step (sim_step: motors, ODE, encoders,
 * sensors) and measures what a lab would. */
#include "validate.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#include "validate/bench.h"
#include "world/motor.h"
#include "world/sim.h"

#define RPM_PER_RAD_S (60.0 / (2.0 * M_PI))
#define KGMM_PER_NM (1.0 / 9.80665e-3)
#define NM_PER_KGCM 0.0980665
#define DATASHEET "Pololu micro metal gearmotors datasheet Rev 2.0 (May 2018), 30:1 LP 6V"
#define ROBOT_MOTOR "the robot file's [motor.left] figures at rated_v"

static sim_state_t *open_bench(const simcfg_t *c, int lift, int lock)
{
    if (lift || lock) bench_field(&bench.maze, 3, 3, 1);
    if (bench_init(c) != 0) return NULL;
    if (lift) world_lift(bench.sim.world, lock);
    return &bench.sim;
}

static void run_steps(sim_state_t *s, long n)
{
    for (long i = 0; i < n; i++) sim_step(s->model, s);
}

/* ---- the motor on the bench (robot lifted) ---- */

typedef struct {
    double rpm, current_a, torque_nm;
} operating_t;

/* The lifted robot at full command, each wheel braked by load_nm against
 * its motion, after settle_s: the left wheel's speed and current. */
static operating_t loaded(const simcfg_t *c, double load_nm, double settle_s)
{
    operating_t op = { 0, 0, 0 };
    sim_state_t *s = open_bench(c, 1, 0);
    if (!s) return op;
    s->cmd[0] = s->cmd[1] = MOTOR_CMD_MAX;
    for (long i = 0; i < bench_steps(c, settle_s); i++) {
        world_brake(s->world, load_nm);
        sim_step(s->model, s);
    }
    op.rpm = world_wheel_rate(s->world, WORLD_LEFT) * RPM_PER_RAD_S;
    op.current_a = s->motor[WORLD_LEFT].i_a;
    op.torque_nm = load_nm;
    sim_free(s);
    return op;
}

/* The wheels locked to the lifted chassis, full command, for t_s. */
static operating_t stalled(const simcfg_t *c, double t_s)
{
    operating_t op = { 0, 0, 0 };
    sim_state_t *s = open_bench(c, 1, 1);
    if (!s) return op;
    s->cmd[0] = s->cmd[1] = MOTOR_CMD_MAX;
    run_steps(s, bench_steps(c, t_s));
    op.current_a = s->motor[WORLD_LEFT].i_a;
    op.torque_nm = s->motor[WORLD_LEFT].torque_nm;
    sim_free(s);
    return op;
}

/* The continuous equations of the configured motor and wheel (motor.h),
 * integrated by RK4 at 0.1 us from rest at full command: the wheel's speed
 * at t_s (rad/s), and the current (A). */
static double reference_response(const simcfg_t *c, double t_s, double *current_a)
{
    const drive_spec_t *d = &c->robot.drive[0];
    double r, ke, eta, n = d->gear_ratio, v = battery_spec_full_v(&c->robot.battery);
    motor_constants(&c->robot.drive[0], &r, &ke, &eta);
    sim_model_t md; /* the bench's robot (open_bench's seed), for its left wheel's radius */
    sim_model_build(&md, c, 1);
    double rw = md.wheel_r_m[WORLD_LEFT];
    double j = 0.5 * c->robot.wheel_mass_kg * rw * rw + c->robot.drive[0].rotor_inertia_kgm2 * n * n; /* the wheel's axle inertia */
    double i = 0, w = 0, h = 1e-7;
    long k = lround(t_s / h);
    for (long s = 0; s < k; s++) {
        double di[4], dw[4], ii = i, ww = w;
        for (int q = 0; q < 4; q++) {
            di[q] = (v - r * ii - ke * n * ww) / c->robot.drive[0].l_h;
            double drive = n * eta * ke * (ii - motor_friction_a(d->no_load_a, d->friction_load_a, ii));
            dw[q] = (ww > 0 || drive > 0) ? drive / j : 0; /* stiction holds it until the drive beats the friction */
            double f = q < 2 ? 0.5 * h : h;
            if (q < 3) {
                ii = i + f * di[q];
                ww = w + f * dw[q];
            }
        }
        i += h / 6 * (di[0] + 2 * di[1] + 2 * di[2] + di[3]);
        w += h / 6 * (dw[0] + 2 * dw[1] + 2 * dw[2] + dw[3]);
    }
    *current_a = i;
    return w;
}

static double lifted_speed_at(const simcfg_t *c, double t_s)
{
    sim_state_t *s = open_bench(c, 1, 0);
    if (!s) return 0;
    s->cmd[0] = s->cmd[1] = MOTOR_CMD_MAX;
    run_steps(s, bench_steps(c, t_s));
    double w = world_wheel_rate(s->world, WORLD_LEFT);
    sim_free(s);
    return w;
}

/* Encoder counts over ten wheel turns of the lifted robot, per turn. */
static double counts_per_rev(const simcfg_t *c)
{
    sim_state_t *s = open_bench(c, 1, 0);
    if (!s) return 0;
    s->cmd[0] = s->cmd[1] = 300;
    double turned = 0, last = world_wheel_angle(s->world, WORLD_LEFT);
    int32_t c0 = s->encoder[WORLD_LEFT].count;
    while (turned < 20 * M_PI && s->step < 1000000) {
        sim_step(s->model, s);
        double a = world_wheel_angle(s->world, WORLD_LEFT);
        turned += remainder(a - last, 2 * M_PI);
        last = a;
    }
    double cpr = (s->encoder[WORLD_LEFT].count - c0) / (turned / (2 * M_PI));
    sim_free(s);
    return cpr;
}

/* ---- the robot on the floor ---- */

/* Idle in the start cell for minutes: the body centre's drift, mm/min. */
static double creep_mm_per_min(const simcfg_t *c, double minutes)
{
    bench_field(&bench.maze, 3, 3, 1);
    sim_state_t *s = open_bench(c, 0, 0);
    if (!s) return 1e9;
    double x0, y0, h, x, y;
    run_steps(s, bench_steps(c, 1.0)); /* settle on the floor */
    world_pose(s->world, &x0, &y0, &h);
    run_steps(s, bench_steps(c, 60.0 * minutes));
    world_pose(s->world, &x, &y, &h);
    sim_free(s);
    return hypot(x - x0, y - y0) * 1000.0 / minutes;
}

/* Full command straight ahead across an open field for 4 m: how far the
 * body centre ends up sideways of the start line, mm. */
static double veer_mm_4m(const simcfg_t *c)
{
    bench_field(&bench.maze, 32, 32, 16);
    sim_state_t *s = open_bench(c, 0, 0);
    if (!s) return 1e9;
    double x0, y0, h, x, y;
    world_pose(s->world, &x0, &y0, &h);
    s->cmd[0] = s->cmd[1] = MOTOR_CMD_MAX;
    do {
        sim_step(s->model, s);
        world_pose(s->world, &x, &y, &h);
    } while (y - y0 < 4.0 && s->step < 100000);
    sim_free(s);
    return fabs(x - x0) * 1000.0;
}

/* The robot in a corridor facing its end wall with the front sensor true_m
 * from it, for seconds: the valid readings' mean and standard deviation,
 * how many were valid and how many timeouts. */
typedef struct {
    double mean, sd;
    long n, timeouts;
} tof_stats_t;

/* The robot's forward-looking ToF sensor (yaw 0): its index among its
 * ToF sensors, or -1. */
static int front_tof(const simcfg_t *c)
{
    for (unsigned i = 0; i < WORLD_TOF_COUNT; i++) {
        int k = robot_part_of_kind(c, "tof", i);
        if (k >= 0 && c->robot.part[k].yaw_deg == 0) return (int)i;
    }
    return -1;
}

static const tof_spec_t *tof_spec(const simcfg_t *c, int i)
{
    return (const tof_spec_t *)c->robot.part[robot_part_of_kind(c, "tof", (unsigned)i)].spec;
}

/* The robot with its front ToF sensor as one ray (fov 0) and noise cv_or_keep
 * (< 0: the robot file's): the ranging along its axis, which a cone in a
 * corridor would mix with the side walls. One bench at a time. */
static const simcfg_t *one_ray(const simcfg_t *c, double cv_or_keep)
{
    static simcfg_t b;
    b = *c;
    tof_spec_t *ts = (tof_spec_t *)b.robot.part[robot_part_of_kind(c, "tof", (unsigned)front_tof(c))].spec;
    ts->fov_rad = 0.0;
    if (cv_or_keep >= 0.0) ts->cv = cv_or_keep;
    return &b;
}

static tof_stats_t tof_facing(const simcfg_t *cfg, double true_m, double seconds)
{
    tof_stats_t st = { 0, 0, 0, 0 };
    const simcfg_t *c = one_ray(cfg, -1.0);
    int f = front_tof(c);
    double sensor_y = c->robot.part[robot_part_of_kind(c, "tof", (unsigned)f)].y_m;
    bench_corridor(&bench.maze, 16);
    sim_state_t *s = open_bench(c, 0, 0);
    if (!s) return st;
    double face = 16 * c->world.cell_m - c->world.wall_thick_m / 2;
    world_place(s->world, face - sensor_y - true_m, 0.5 * c->world.cell_m, 0.0, NULL);
    double sum = 0, sum2 = 0;
    uint32_t seen = s->tof_count[f];
    for (long i = 0; i < bench_steps(c, seconds); i++) {
        sim_step(s->model, s);
        if (s->tof_count[f] == seen) continue;
        seen = s->tof_count[f];
        tof_reading_t r = s->tof_last[f];
        if (r.timeout) {
            st.timeouts++;
            continue;
        }
        sum += r.dist_m;
        sum2 += r.dist_m * r.dist_m;
        st.n++;
    }
    if (st.n > 1) {
        st.mean = sum / st.n;
        st.sd = sqrt(fmax(0, (sum2 - sum * sum / st.n) / (st.n - 1)));
    }
    sim_free(s);
    return st;
}

/* The front ToF sensor's first noise-free reading with the end wall of a
 * 16-cell corridor ahead_m ahead of it (the robot on the corridor's centre
 * line), m; -1 = a timeout. */
static double tof_corridor_reading(const simcfg_t *c, double ahead_m)
{
    static simcfg_t b;
    b = *c;
    int f = front_tof(c), k = robot_part_of_kind(c, "tof", (unsigned)f);
    ((tof_spec_t *)b.robot.part[k].spec)->cv = 0.0;
    bench_corridor(&bench.maze, 16);
    sim_state_t *s = open_bench(&b, 0, 0);
    if (!s) return -1;
    double face = 16 * c->world.cell_m - c->world.wall_thick_m / 2;
    world_place(s->world, face - c->robot.part[k].y_m - ahead_m, 0.5 * c->world.cell_m, 0.0, NULL);
    uint32_t seen = s->tof_count[f];
    for (long i = 0; i < bench_steps(c, 1.0) && s->tof_count[f] == seen; i++) sim_step(s->model, s);
    double d = s->tof_last[f].timeout ? -1.0 : s->tof_last[f].dist_m;
    sim_free(s);
    return d;
}

/* The end wall's distance ahead beyond which the front ToF's cone reaches
 * the corridor's side walls first (its reading falls short of the end
 * wall by more than 1 mm), m, by bisection to 0.5 mm between 0.1 and 1 m. */
static double tof_side_wall_onset_m(const simcfg_t *c)
{
    double lo = 0.1, hi = 1.0;
    while (hi - lo > 0.0005) {
        double mid = 0.5 * (lo + hi), d = tof_corridor_reading(c, mid);
        if (d >= 0.0 && d < mid - 0.001) hi = mid;
        else lo = mid;
    }
    return 0.5 * (lo + hi);
}

/* Full command into the end wall of a corridor for 3 s: how far the body's
 * front got past the wall's face at most, mm (0 = never). */
static double tunnelling_mm(const simcfg_t *c)
{
    bench_corridor(&bench.maze, 3);
    sim_state_t *s = open_bench(c, 0, 0);
    if (!s) return 1e9;
    double face = 3 * c->world.cell_m - c->world.wall_thick_m / 2, worst = 0;
    s->cmd[0] = s->cmd[1] = MOTOR_CMD_MAX;
    for (long i = 0; i < bench_steps(c, 3.0); i++) {
        sim_step(s->model, s);
        for (int k = 0; k < 8; k++) { /* the body's corners: a robot that pitches leads with an edge */
            double p[3] = { (k & 1 ? 0.5 : -0.5) * c->robot.body_w_m, (k & 2 ? 0.5 : -0.5) * c->robot.body_l_m,
                            c->robot.body_clearance_m + (k & 4 ? c->robot.body_h_m : 0) }, q[3];
            world_body_point(s->world, p, q);
            worst = fmax(worst, q[0] - face);
        }
    }
    sim_free(s);
    return worst * 1000.0;
}

/* ---- the table ---- */

/* The Pololu 30:1 LP 6V of the paper robot (its datasheet's other figures
 * are checked only for it). */
static int pololu_30_lp(const drive_spec_t *d)
{
    return d->rated_v == 6 && d->no_load_rpm == 450 && d->stall_a == 0.36 && d->stall_torque_nm == 0.028439;
}

/* The best of f over the brake torque in [0, hi] (golden section on the
 * simulator's own response; f is unimodal there): its operating point. */
typedef double (*figure_fn)(const simcfg_t *c, operating_t op);

static operating_t best_load(const simcfg_t *c, double hi, figure_fn f)
{
    const double g = 0.5 * (sqrt(5.0) - 1);
    double a = 0, b = hi, x1 = b - g * (b - a), x2 = a + g * (b - a);
    operating_t o1 = loaded(c, x1, 1.0), o2 = loaded(c, x2, 1.0);
    for (int i = 0; i < 24; i++) {
        if (f(c, o1) > f(c, o2)) {
            b = x2, x2 = x1, o2 = o1, x1 = b - g * (b - a);
            o1 = loaded(c, x1, 1.0);
        } else {
            a = x1, x1 = x2, o1 = o2, x2 = a + g * (b - a);
            o2 = loaded(c, x2, 1.0);
        }
    }
    return f(c, o1) > f(c, o2) ? o1 : o2;
}

static double output_w(const simcfg_t *c, operating_t op) { return op.torque_nm * op.rpm / RPM_PER_RAD_S; }

static double efficiency(const simcfg_t *c, operating_t op)
{
    double in_w = battery_spec_full_v(&c->robot.battery) * op.current_a;
    return in_w > 0 ? output_w(c, op) / in_w : 0;
}

/* The rest of the Pololu 30:1 LP 6V's published curve (its datasheet p.1),
 * the peaks found by sweeping the brake on the lifted robot. The motor is
 * built from no load and stall, and the loss model's one further parameter
 * (friction_load_a, bench/fit_motor_losses.py) from the maximum power 0.31 W
 * (fitted: reported); the maximum-efficiency point (320 rpm, 0.66 kg*mm,
 * 0.11 A, 0.22 W out: 33.3 % of 6 V x 0.11 A) is predicted. */
static int pololu_predictions(const simcfg_t *c, validate_check_t *v, int n)
{
    const double tol_pct = 5; /* the loss model predicts the published curve within 5 % */
    operating_t pe = best_load(c, c->robot.drive[0].stall_torque_nm, efficiency);
    bench_add(v, &n, "max_efficiency_speed", 320, pe.rpm, "rpm", tol_pct, VALIDATE_NEAR,
              DATASHEET " p.1, max efficiency 320 rpm: the simulated peak, the brake swept (not used by the fit)");
    bench_add(v, &n, "max_efficiency_current", 0.11, pe.current_a, "A", tol_pct, VALIDATE_NEAR,
              DATASHEET " p.1, max efficiency 0.11 A: the simulated peak, the brake swept (not used by the fit)");
    bench_add(v, &n, "max_efficiency", 0.22 / (6 * 0.11) * 100, efficiency(c, pe) * 100, "%", tol_pct, VALIDATE_NEAR,
              DATASHEET " p.1: 0.22 W out at 6 V x 0.11 A = 33.3 %; the simulated peak (not used by the fit)");
    bench_add(v, &n, "max_efficiency_torque", 0.66, pe.torque_nm * KGMM_PER_NM, "kg*mm", tol_pct, VALIDATE_NEAR,
              DATASHEET " p.1, max efficiency at 0.66 kg*mm: the simulated peak's load (not used by the fit; a flat peak)");
    operating_t mid = loaded(c, 0.66 / KGMM_PER_NM, 1.0);
    bench_add(v, &n, "mid_torque_current", 0.11, mid.current_a, "A", tol_pct, VALIDATE_NEAR,
              DATASHEET " p.1: 0.11 A at 0.66 kg*mm, the wheel braked there (not used by the fit)");
    operating_t mp = best_load(c, c->robot.drive[0].stall_torque_nm, output_w);
    bench_fit(v, &n, "max_power", 0.31, output_w(c, mp), "W",
              DATASHEET " p.1: max power 0.31 W; friction_load_a is fitted to it (bench/fit_motor_losses.py)");
    return n;
}

/* The Pimoroni (Kingly Gear JL-12FN20) 6 V gearmotors of UKMARSBOT: their
 * sheets' figures that the robot files' motors were not built from
 * (bench/fit_ukmarsbot.py: R from the 20:1 sheet's no-load and load points,
 * Ke from ORION's FWD_KM or the 20:1 sheet's no-load speed, the no-load
 * current from BIAS_FF). */
#define UKB_DOCS "ukmarsbot docs/speed-performance.md l.13: Pimoroni 6 V motors, \"a stall current of around 0.8 Amp\""
static int pimoroni_predictions(const simcfg_t *c, operating_t nl, operating_t st, validate_check_t *v, int n)
{
    const drive_spec_t *d = &c->robot.drive[0];
    if (d->rated_v != 6 || (fabs(d->gear_ratio - 11.4) > 0.01 && fabs(d->gear_ratio - 19.55) > 0.01)) return n;
    int eleven = fabs(d->gear_ratio - 11.4) <= 0.01;
    if (!eleven) { /* the 20:1 sheet's load point: R was built from it */
        operating_t lp = loaded(c, 0.05 * NM_PER_KGCM, 1.0);
        bench_fit(v, &n, "sheet_load_point_speed", 826, lp.rpm, "rpm",
                  "pimoroni-gearmotor-20-1.pdf: 826 rpm at 0.05 kg.cm, 6 V (the motor's R is fitted to it)");
        bench_fit(v, &n, "sheet_load_point_current", 0.22, lp.current_a, "A",
                  "pimoroni-gearmotor-20-1.pdf: 0.22 A at 0.05 kg.cm, 6 V (the motor's R is fitted to it, with the "
                  "sheet's 0.08 A no-load current)");
    }
    bench_add(v, &n, "stall_current_ukmars_docs", 0.8, st.current_a, "A", 10, VALIDATE_NEAR,
              UKB_DOCS " (not used by the fit: R came from the 20:1 sheet's no-load and load points)");
    if (eleven)
        bench_add(v, &n, "sheet_no_load_speed", 1950, nl.rpm, "rpm", 10, VALIDATE_NEAR,
                  "pimoroni-gearmotor-11-1.pdf: no load 1950 rpm +-10 % at 6 V (not used by the fit: Ke came from ORION's "
                  "FWD_KM and ROT_KM, slower per volt)");
    bench_add(v, &n, "sheet_no_load_current", 0.08, nl.current_a, "A", 10, VALIDATE_NEAR,
              eleven ? "pimoroni-gearmotor-11-1.pdf: no load 0.08 A at 6 V (not used by the fit: no_load_a came from ORION's "
                       "BIAS_FF 0.34 V)"
                     : "pimoroni-gearmotor-20-1.pdf: no load 0.08 A at 6 V (not used by the fit: no_load_a came from OSMIUM's "
                       "BIAS_FF 0.121 V)");
    return n;
}

static int motor_checks(const simcfg_t *c, validate_check_t *v, int n)
{
    const drive_spec_t *d = &c->robot.drive[0];
    operating_t nl = loaded(c, 0, 3.0), st = stalled(c, 1.0), first = stalled(c, c->sim.step_s);
    int pololu = pololu_30_lp(d);
    bench_fit(v, &n, "no_load_speed", d->no_load_rpm, nl.rpm, "rpm",
              pololu ? DATASHEET " p.1: no load 450 rpm (the motor is built from it)"
                     : ROBOT_MOTOR ": no_load_rpm (the motor is built from it)");
    bench_fit(v, &n, "no_load_current", d->no_load_a, nl.current_a, "A",
              pololu ? DATASHEET " p.1: no load 0.02 A (the motor is built from it)"
                     : ROBOT_MOTOR ": no_load_a (the motor is built from it)");
    bench_fit(v, &n, "stall_torque", d->stall_torque_nm, st.torque_nm, "N*m",
              pololu ? DATASHEET " p.1: stall 2.9 kg*mm (the motor is built from it)"
                     : ROBOT_MOTOR ": stall_torque_nm (the motor is built from it)");
    bench_fit(v, &n, "stall_current", d->stall_a, st.current_a, "A",
              pololu ? DATASHEET " p.1: stall 0.36 A (the motor is built from it)"
                     : ROBOT_MOTOR ": stall_a (the motor is built from it)");
    double r = d->rated_v / d->stall_a;
    bench_add(v, &n, "first_step_current", battery_spec_full_v(&c->robot.battery) / r * (1 - exp(-c->sim.step_s * r / d->l_h)),
        first.current_a, "A", 2, VALIDATE_NEAR,
        "analytic: V/R*(1 - exp(-t*R/L)) one step after stall, an independent solution of the motor's circuit");
    n = pimoroni_predictions(c, nl, st, v, n);
    return pololu ? pololu_predictions(c, v, n) : n;
}

/* The lifted wheel's speed after a full-command step, against the
 * reference at 1, 2 and 5 ms. A time that is not a whole number of steps is
 * sampled at the first step after it and named by that time (a 2 ms step:
 * step_response_2ms, then step_response_6ms), and a time met twice is
 * checked once, so each check compares the simulation and the reference
 * at the same instant. */
static int response_checks(const simcfg_t *c, validate_check_t *v, int n)
{
    const drive_spec_t *d = &c->robot.drive[0];
    static const double at_s[] = { 0.001, 0.002, 0.005 };
    static char names[3][32]; /* the check table keeps the name's pointer: one validate_run's table at a time */
    double h = c->sim.step_s, last_s = 0;
    for (int k = 0; k < 3; k++) {
        double steps = ceil(at_s[k] / h - 1e-9), t_s = fabs(steps * h - at_s[k]) < 1e-12 ? at_s[k] : steps * h;
        if (t_s <= last_s) continue;
        last_s = t_s;
        snprintf(names[k], sizeof names[k], "step_response_%gms", t_s * 1e3);
        double i_ref, w_ref = reference_response(c, t_s, &i_ref);
        bench_add(v, &n, names[k], w_ref, lifted_speed_at(c, t_s), "rad/s", 2, VALIDATE_NEAR,
            "analytic: the motor's L-R circuit and the wheel's inertia (rotor reflected), RK4 at 0.1 us: an independent "
            "solution of the same equations");
    }
    bench_fit(v, &n, "encoder_counts_per_rev", d->encoder_ppr * d->gear_ratio, counts_per_rev(c), "counts",
              "the robot file's encoder_ppr x gear_ratio (the encoder is built from them)");
    return n;
}

/* The cone (predicted: the datasheet's field of view and the maze's
 * geometry, not fitted to anything): on a 168 mm corridor's centre line,
 * with h = (cell - wall) / 2 to either side wall, a cone of full angle fov
 * meets the side walls h / tan(fov / 2) ahead (0.379 m at 25 deg), at a
 * slant distance of h / sin(fov / 2) (0.388 m): the nearest surface in the
 * cone is the side wall, and the reading falls short of the end wall, once
 * the end wall is farther than that. */
static int tof_cone_check(const simcfg_t *c, validate_check_t *v, int n)
{
    const tof_spec_t *ts = tof_spec(c, front_tof(c));
    if (ts->fov_rad <= 0.0) return n;
    double half_w = 0.5 * (c->world.cell_m - c->world.wall_thick_m);
    bench_add(v, &n, "tof_cone_side_wall_onset", half_w / sin(0.5 * ts->fov_rad), tof_side_wall_onset_m(c), "m", 1,
        VALIDATE_NEAR, "predicted (data: VL53L0X datasheet DocID029104, 25 deg field of view; the maze's 180 mm cell, "
        "12 mm wall): the end-wall distance beyond which the cone sees a corridor's side walls first");
    return n;
}

/* The front ToF sensor's spread (sd / mean, one ray) with its timing
 * budget budget_s and the noise the model gives that budget, over
 * `readings` readings of a wall at 98 % of 1.2 m (ST's distance for its
 * accuracy figures) or of the sensor's range if that is shorter. */
static double tof_spread_at(const simcfg_t *c, double budget_s, double readings)
{
    static simcfg_t b;
    b = *c;
    tof_spec_t *ts = (tof_spec_t *)b.robot.part[robot_part_of_kind(c, "tof", (unsigned)front_tof(c))].spec;
    ts->period_s = budget_s;
    ts->cv = tof_cv_at(budget_s);
    tof_stats_t st = tof_facing(&b, 0.98 * fmin(1.2, ts->range_m), readings * budget_s);
    return st.mean > 0 ? st.sd / st.mean : 0;
}

/* Predicted (the accuracy at budgets the model was not built from): the
 * model's noise is 4 % at 33 ms (Table 12) scaled by sqrt(33 ms / budget)
 * (tof_cv_at), and DocID029104 states three more figures for the same
 * white target: Table 12's 66 ms column and Table 13's high speed and high
 * accuracy profiles. Graded only for a sensor whose noise is the model's
 * (a robot file's own cv, e.g. the paper's 0.05, is not). The datasheet
 * gives whole percents, so the bars are 10 %. */
static int tof_budget_checks(const simcfg_t *c, validate_check_t *v, int n)
{
    const tof_spec_t *ts = tof_spec(c, front_tof(c));
    if (fabs(ts->cv - tof_cv_at(ts->period_s)) > 1e-12) return n;
    bench_add(v, &n, "tof_sigma_66ms", 0.03, tof_spread_at(c, 0.066, 3000), "1", 10, VALIDATE_NEAR,
        "predicted (data: VL53L0X datasheet DocID029104 Table 12, white 88 % target at 120 cm indoors, 66 ms budget: 3 % "
        "as one standard deviation; the model: 4 % at 33 ms x sqrt(33 / 66)), 3000 readings");
    bench_add(v, &n, "tof_sigma_high_speed", 0.05, tof_spread_at(c, 0.020, 3000), "1", 10, VALIDATE_NEAR,
        "predicted (data: VL53L0X datasheet DocID029104 Table 13, high speed profile, 20 ms: accuracy +/- 5 %; the "
        "model: 4 % at 33 ms x sqrt(33 / 20)), 3000 readings");
    bench_add(v, &n, "tof_sigma_high_accuracy", 0.03, tof_spread_at(c, 0.200, 300), "1", 0, VALIDATE_MAX,
        "predicted (data: VL53L0X datasheet DocID029104 Table 13, high accuracy profile, 200 ms: accuracy < +/- 3 %; the "
        "model: 4 % at 33 ms x sqrt(33 / 200)), 300 readings");
    return n;
}

/* The ToF sensor's figures from its ranging profile (VL53L0X DocID029104
 * Tables 11-13), each reproduced by the model built from it: its noise at
 * the distance the datasheet states it for, and its timeout just beyond
 * its range. */
static int tof_fitted(const simcfg_t *c, validate_check_t *v, int n)
{
    const tof_spec_t *ts = tof_spec(c, front_tof(c));
    tof_stats_t edge = tof_facing(c, ts->range_m * 0.98, 60.0), beyond = tof_facing(c, ts->range_m * 1.02, 6.0);
    bench_fit(v, &n, "tof_noise_cv", ts->cv, edge.mean > 0 ? edge.sd / edge.mean : 0, "1",
              "the robot file's cv (unless given, VL53L0X datasheet DocID029104 Table 12's 4 % as one standard deviation "
              "at 33 ms x sqrt(33 ms / period)), reproduced with a wall at 0.98 x range over 60 s of readings (the sensor "
              "is built from it)");
    bench_fit(v, &n, "tof_timeout_beyond_range", 0, (double)beyond.n, "readings",
              "the robot file's range_mm (its ranging profile's: VL53L0X datasheet DocID029104 Tables 11 and 13, 1.2 m on "
              "a white target for the default profile): valid readings with a wall at 1.02 x range, all timeouts (the "
              "sensor is built from it)");
    return tof_cone_check(c, v, tof_budget_checks(c, v, n));
}

static int floor_checks(const simcfg_t *c, validate_check_t *v, int n)
{
    bench_add(v, &n, "rest_creep_mm_per_min", 0.1, creep_mm_per_min(c, 10.0), "mm/min", 0, VALIDATE_MAX,
        "physical requirement: a robot at rest stays at rest (10 minutes idle in the start cell)");
    bench_add(v, &n, "straight_veer_mm_4m", 2.0, veer_mm_4m(c), "mm", 0, VALIDATE_MAX,
        "physical requirement: a symmetric robot drives straight (full command, 4 m, sideways drift)");
    /* the soft contact gives way in proportion to the push per contact point: the paper robot's
     * flat face 0.39 mm, UKMARSBOT (tilted by the push, leading with an edge) 1.35 mm */
    bench_add(v, &n, "wall_no_tunnelling", 2.0, tunnelling_mm(c), "mm", 0, VALIDATE_MAX,
        "physical requirement: full command into a 12 mm wall, the body stops at its face (contact softness allows < 2 mm)");
    if (front_tof(c) < 0) return n;
    return tof_fitted(c, v, n);
}

/* The robot as a lab benches its motors and the physics: its motors on a
 * supply at their rated voltage (no battery sag, no H-bridge), and its
 * wheels alike (a symmetric robot must drive straight). The paper's robot
 * is that already. */
static simcfg_t bench_robot(const simcfg_t *c)
{
    simcfg_t b = *c;
    b.robot.battery.ocv_n = 1;
    b.robot.battery.ocv_v[0] = c->robot.drive[0].rated_v;
    b.robot.battery.r_ohm = 0;
    for (int i = 0; i < 2; i++) b.robot.drive[i].driver_r_ohm = 0;
    b.robot.wheel_left_d_m = b.robot.wheel_right_d_m = (c->robot.wheel_left_d_m + c->robot.wheel_right_d_m) / 2;
    return b;
}

int validate_run(const simcfg_t *c, validate_check_t *checks)
{
    static simcfg_t b; /* large */
    b = bench_robot(c);
    int n = motor_checks(&b, checks, 0);
    n = response_checks(&b, checks, n);
    n = floor_checks(&b, checks, n);
    n = validate_stop_checks(&b, checks, n);
    return validate_robot_checks(c, checks, n);
}

static const char *bound_name(int b) { return b == VALIDATE_NEAR ? "near" : b == VALIDATE_MAX ? "max" : "report"; }

static const char *kind_name(int k) { return k == VALIDATE_FITTED ? "fitted" : "predicted"; }

int validate_graded(const validate_check_t *k) { return k->kind == VALIDATE_PREDICTED && k->bound != VALIDATE_REPORT; }

validate_summary_t validate_summary(const validate_check_t *v, int n)
{
    validate_summary_t s = { 0, 0, 0, 0 };
    for (int i = 0; i < n; i++) {
        if (validate_graded(&v[i])) {
            s.graded++;
            s.passed += v[i].pass;
        } else if (v[i].kind == VALIDATE_FITTED) s.fitted++;
        else s.reported++;
    }
    return s;
}

void validate_print(const validate_check_t *v, int n, FILE *out)
{
    fprintf(out, "%-26s %-9s %12s %12s %-8s %9s %-4s %s\n", "check", "kind", "expected", "measured", "unit", "tolerance",
            "pass", "source");
    for (int i = 0; i < n; i++) {
        char tol[32];
        if (!validate_graded(&v[i])) snprintf(tol, sizeof tol, "-");
        else if (v[i].bound == VALIDATE_NEAR) snprintf(tol, sizeof tol, "%g %%", v[i].tolerance_pct);
        else snprintf(tol, sizeof tol, "at most");
        fprintf(out, "%-26s %-9s %12.6g %12.6g %-8s %9s %-4s %s\n", v[i].name, kind_name(v[i].kind), v[i].expected,
                v[i].measured, v[i].unit, tol, !validate_graded(&v[i]) ? "-" : v[i].pass ? "yes" : "NO", v[i].source);
    }
    validate_summary_t s = validate_summary(v, n);
    fprintf(out, "%d of %d predicted checks pass; %d fitted figures reported", s.passed, s.graded, s.fitted);
    if (s.reported) fprintf(out, "; %d prediction%s reported with no bar", s.reported, s.reported == 1 ? "" : "s");
    fprintf(out, "\n");
}

json_t *validate_json(const validate_check_t *v, int n)
{
    json_t *arr = json_array();
    for (int i = 0; i < n; i++) {
        int graded = validate_graded(&v[i]);
        json_t *k = json_pack("{s:s, s:s, s:f, s:f, s:s, s:o, s:s, s:o, s:s}", "name", v[i].name, "kind",
                              kind_name(v[i].kind), "expected", v[i].expected, "measured", v[i].measured, "unit",
                              v[i].unit, "tolerance_pct",
                              graded && v[i].bound == VALIDATE_NEAR ? json_real(v[i].tolerance_pct) : json_null(),
                              "source", v[i].source, "pass", graded ? json_boolean(v[i].pass) : json_null(), "bound",
                              bound_name(v[i].bound));
        json_array_append_new(arr, k);
    }
    validate_summary_t s = validate_summary(v, n);
    return json_pack("{s:o, s:i, s:i, s:i, s:i}", "checks", arr, "predicted", s.graded, "passed", s.passed, "fitted",
                     s.fitted, "reported", s.reported);
}

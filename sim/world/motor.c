/* motor.c - DC gearmotor models (see motor.h). */
#include "motor.h"

#include <math.h>

#define RPM_TO_RAD_S (2.0 * M_PI / 60.0)

double motor_friction_a(double no_load_a, double load_a, double i_a)
{
    if (load_a <= 0) return no_load_a;
    double x = fabs(i_a) - no_load_a; /* the current the load draws */
    return x > 0 ? no_load_a + load_a * (1.0 - exp(-x / (2.0 * load_a))) : no_load_a;
}

void motor_constants(const drive_spec_t *c, double *r_ohm, double *ke_v_s, double *eta)
{
    double r = c->rated_v / c->stall_a;
    double w_motor = c->no_load_rpm * RPM_TO_RAD_S * c->gear_ratio;
    double ke = (c->rated_v - r * c->no_load_a) / w_motor; /* free running, the friction is no_load_a */
    double i_f = motor_friction_a(c->no_load_a, c->friction_load_a, c->stall_a);
    *r_ohm = r;
    *ke_v_s = ke;
    *eta = c->stall_torque_nm / (c->gear_ratio * ke * (c->stall_a - i_f));
}

double motor_terminal_v(const motor_t *m) { return m->v_applied - (m->r_circuit_ohm - m->r_ohm) * m->i_a; }

double motor_free_speed(const drive_spec_t *c, double v_volt)
{
    double r, ke, eta;
    if (c->motor_model == MOTOR_MODEL_PAPER) return v_volt / (c->stall_torque_nm / c->stall_a);
    motor_constants(c, &r, &ke, &eta);
    double w = (fabs(v_volt) - r * c->no_load_a) / (ke * c->gear_ratio);
    return w > 0 ? copysign(w, v_volt) : 0.0;
}

void motor_init(motor_t *m, const drive_spec_t *c, double battery_v, double battery_r_ohm, double scale)
{
    m->model = c->motor_model;
    m->n = c->gear_ratio;
    m->l_h = c->l_h;
    m->battery_v = battery_v;
    m->battery_r_ohm = battery_r_ohm;
    if (m->model == MOTOR_MODEL_PAPER) { /* eq. 4-5: K and R from the stall figures, at the output shaft */
        m->r_ohm = c->rated_v / c->stall_a;
        m->ke_v_s = c->stall_torque_nm / c->stall_a / m->n * scale;
        m->eta = 1.0;
        m->i_friction_a = 0.0;
        m->friction_load_a = 0.0;
        m->r_ohm += c->driver_r_ohm;
    } else {
        motor_constants(c, &m->r_ohm, &m->ke_v_s, &m->eta);
        m->ke_v_s *= scale;
        m->i_friction_a = c->no_load_a;
        m->friction_load_a = c->friction_load_a;
        m->r_ohm += c->driver_r_ohm; /* the H-bridge's switches conduct the current in drive and in slow decay alike */
    }
    m->i_a = 0.0;
    m->v_applied = 0.0;
    m->r_circuit_ohm = m->r_ohm;
    m->torque_nm = 0.0;
    m->k_mean = 0.0;
    m->decay = 0.0;
    m->step_r_ohm = m->step_dt_s = -1.0; /* nothing cached yet */
    m->i_start_a = 0.0;
}

/* The H-bridge at duty d = cmd/1023 puts d*(V_oc - R_b*i_batt) on the motor,
 * and the battery delivers i_batt = d*i: the motor's circuit sees d*V_oc
 * through R + d^2*R_b. Both in the current's own step, so a large internal
 * resistance cannot make the sag oscillate. Sets v_applied to the open
 * circuit part and returns the circuit's resistance. */
static double drive_circuit(motor_t *m, int cmd)
{
    if (cmd > MOTOR_CMD_MAX) cmd = MOTOR_CMD_MAX;
    if (cmd < -MOTOR_CMD_MAX) cmd = -MOTOR_CMD_MAX;
    double duty = (double)cmd / MOTOR_CMD_MAX;
    m->v_applied = duty * m->battery_v;
    return m->r_ohm + duty * duty * m->battery_r_ohm;
}

motor_drive_t motor_drive(motor_t *m, int cmd, double w_rad_s, double dt_s)
{
    motor_drive_t d = { 0, 0, 0 };
    double kn = m->ke_v_s * m->n; /* at the output shaft */
    double r = drive_circuit(m, cmd);
    m->r_circuit_ohm = r;
    if (m->model == MOTOR_MODEL_PAPER) { /* eq. 3: backward difference with this step's start speed */
        double l_dt = m->l_h / dt_s;
        m->i_a = (m->v_applied - kn * w_rad_s + l_dt * m->i_a) / (r + l_dt);
        m->torque_nm = kn * m->i_a;
        d.t0_nm = m->torque_nm;
        return d;
    }
    if (r != m->step_r_ohm || dt_s != m->step_dt_s) { /* once per circuit and step (R_b = 0: once a run) */
        double x = dt_s * r / m->l_h;                 /* the step in L/R time constants */
        m->decay = exp(-x);                           /* the start current's share left at the end */
        m->k_mean = x > 1e-9 ? (1.0 - m->decay) / x : 1.0; /* its weight in the step's mean */
        m->step_r_ohm = r;
        m->step_dt_s = dt_s;
    }
    m->i_start_a = m->i_a;
    double g = m->n * m->eta * m->ke_v_s; /* output torque per ampere */
    /* mean current = (1-k)*(V - kn*w_mean)/R + k*i_start with the step's mean
     * speed w_mean = (w_start + w_end)/2 (trapezoidal: second order; the
     * end-speed half is the implicit damper) */
    double dmp = g * (1.0 - m->k_mean) * kn / r;
    d.t0_nm = g * ((1.0 - m->k_mean) * m->v_applied / r + m->k_mean * m->i_start_a) - 0.5 * dmp * w_rad_s;
    d.damping_nm_s = 0.5 * dmp;
    /* the friction at this step's mean current, its speed taken at the start
     * (the current settles in L/R, far within the step) */
    double i_step = (1.0 - m->k_mean) * (m->v_applied - kn * w_rad_s) / r + m->k_mean * m->i_start_a;
    d.friction_nm = g * motor_friction_a(m->i_friction_a, m->friction_load_a, i_step);
    return d;
}

void motor_after(motor_t *m, const motor_drive_t *d, double w_end_rad_s, double dt_s)
{
    if (m->model == MOTOR_MODEL_PAPER) return; /* motor_drive did it all */
    double r = m->r_circuit_ohm, kn = m->ke_v_s * m->n, i_ss = (m->v_applied - kn * w_end_rad_s) / r;
    (void)dt_s; /* the step's decay is motor_drive's */
    m->i_a = i_ss + (m->i_start_a - i_ss) * m->decay;
    /* the output torque: the drive less the gearbox's friction, which
     * opposes the motion, or at rest the motion the drive tends to cause */
    double drive = d->t0_nm - d->damping_nm_s * w_end_rad_s, f = d->friction_nm;
    double dir = fabs(w_end_rad_s) > 1e-9 ? w_end_rad_s : drive;
    m->torque_nm = dir > 0 ? drive - f : dir < 0 ? drive + f : drive;
    if (fabs(w_end_rad_s) <= 1e-9 && fabs(drive) < f) m->torque_nm = 0.0; /* held by stiction */
}

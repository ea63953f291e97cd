/* motor.c - implicit DC motor model (see motor.h). */
#include "motor.h"

#include <math.h>

void motor_init(motor_t *m, const simcfg_t *c)
{
    m->kt_nm_per_a = c->kt_nm_per_a;
    m->r_ohm = c->r_ohm;
    m->l_h = c->l_h;
    m->battery_v = c->battery_v;
    m->battery_r_ohm = c->battery_r_ohm;
    m->i_a = 0.0;
    m->v_applied = 0.0;
}

static double duty_of(int cmd)
{
    if (cmd > MOTOR_CMD_MAX) cmd = MOTOR_CMD_MAX;
    if (cmd < -MOTOR_CMD_MAX) cmd = -MOTOR_CMD_MAX;
    return (double)cmd / MOTOR_CMD_MAX;
}

/* The loop's resistance in ohm: winding, the battery's share (the battery
 * delivers duty * i on average through the H-bridge, so its internal
 * resistance appears as duty^2 * R_b) and the inductance's L/dt. */
static double loop_ohm(const motor_t *m, double duty, double dt_s)
{
    return m->r_ohm + duty * duty * m->battery_r_ohm + m->l_h / dt_s;
}

static void set_voltage(motor_t *m, double duty)
{
    m->v_applied = duty * (m->battery_v - m->battery_r_ohm * duty * m->i_a);
}

double motor_step(motor_t *m, int cmd, double w_rad_s, double dt_s)
{
    double duty = duty_of(cmd), l_dt = m->l_h / dt_s;
    m->i_a = (duty * m->battery_v - m->kt_nm_per_a * w_rad_s + l_dt * m->i_a) / loop_ohm(m, duty, dt_s);
    set_voltage(m, duty);
    return m->kt_nm_per_a * m->i_a;
}

double motor_damping(const motor_t *m, int cmd, double dt_s)
{
    return m->kt_nm_per_a * m->kt_nm_per_a / loop_ohm(m, duty_of(cmd), dt_s);
}

double motor_free_speed(const motor_t *m, int cmd, double dt_s)
{
    return (duty_of(cmd) * m->battery_v + m->l_h / dt_s * m->i_a) / m->kt_nm_per_a;
}

void motor_set_torque(motor_t *m, int cmd, double torque_nm)
{
    m->i_a = torque_nm / m->kt_nm_per_a;
    set_voltage(m, duty_of(cmd));
}

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

double motor_step(motor_t *m, int cmd, double w_rad_s, double dt_s)
{
    if (cmd > MOTOR_CMD_MAX) cmd = MOTOR_CMD_MAX;
    if (cmd < -MOTOR_CMD_MAX) cmd = -MOTOR_CMD_MAX;
    double duty = (double)cmd / MOTOR_CMD_MAX;
    /* the battery delivers duty * i on average through the H-bridge */
    double v_batt = m->battery_v - m->battery_r_ohm * fabs(duty * m->i_a);
    double l_dt = m->l_h / dt_s;
    m->v_applied = duty * v_batt;
    m->i_a = (m->v_applied - m->kt_nm_per_a * w_rad_s + l_dt * m->i_a) / (m->r_ohm + l_dt);
    return m->kt_nm_per_a * m->i_a;
}

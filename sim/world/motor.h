/* motor.h - DC gear motor, the paper's eq. 1-5 with the fixes of our issue.
 *
 * Electrical model, first-order backward difference (implicit) as the
 * paper's eq. 3, which is stable for any step although L/R = 60 us is far
 * shorter than the 1 ms physics step:
 *   i_t = (V - Kt*w + (L/dt)*i_{t-1}) / (R + L/dt),   T = Kt*i
 * Kt and w are referred to the gearbox output shaft (the wheel). The
 * simulator applies T to the wheel and -T to the chassis (the reaction
 * torque the paper's simulator forgot). Command: -1023..+1023 = -100..+100 %
 * of the battery voltage. Battery internal resistance sags the voltage by
 * the previous step's current (off by default). */
#ifndef MOTOR_H
#define MOTOR_H

#include <stdint.h>
#include "config.h"

#define MOTOR_CMD_MAX 1023

typedef struct {
    double kt_nm_per_a, r_ohm, l_h, battery_v, battery_r_ohm;
    double i_a;     /* armature current, A */
    double v_applied; /* last applied voltage, V */
} motor_t;

void motor_init(motor_t *m, const simcfg_t *c);
/* Advance by dt_s with command cmd (clamped to +-1023) and output-shaft
 * speed w_rad_s; returns the output-shaft torque in N*m. */
double motor_step(motor_t *m, int cmd, double w_rad_s, double dt_s);

#endif

/* motor.h - DC gear motor, the paper's eq. 1-5 with the fixes of our issue.
 *
 * Electrical model, first-order backward difference (implicit) as the
 * paper's eq. 3, which is stable for any step although L/R = 60 us is far
 * shorter than the 1 ms physics step:
 *   i_t = (V - Kt*w + (L/dt)*i_{t-1}) / (R + L/dt),   T = Kt*i
 * Kt and w are referred to the gearbox output shaft (the wheel). The
 * simulator applies T to the wheel and -T to the chassis (the reaction
 * torque the paper's simulator forgot). Command: -1023..+1023 = -100..+100 %
 * of the battery voltage. The battery's internal resistance R_b carries
 * the average battery current duty*i, so the motor sees duty^2*R_b in
 * series: the voltage sags under load and rises when the motor brakes
 * (off by default). In the same step as the current, so any R_b is
 * stable (it was the previous step's current: from R_b ~ 18 ohm on, the
 * sag overshot, oscillated and grew until ODE aborted, issue 15).
 *
 * The back-EMF brakes the wheel with -Kt^2/(R + L/dt) * w (motor_damping).
 * With w from the step before (explicit), a strong motor (large Kt, small
 * R) on a light or small wheel overshoots once damping*dt exceeds 2*J:
 * the wheel's speed oscillated, grew and ODE aborted (issue 15). sim.c
 * keeps the part up to J/(2*dt) explicit (all of it for the default
 * robot: 3.5e-4 N*m*s against 6.3e-4) and hands ODE the rest as an
 * implicit damper towards the free speed (world_step_motors). */
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
/* d(torque)/d(w) of motor_step's torque for this command: Kt^2 over the
 * loop's resistance, N*m*s/rad (> 0). */
double motor_damping(const motor_t *m, int cmd, double dt_s);
/* The output-shaft speed at which this step's torque is 0 (rad/s): the
 * torque is motor_damping * (free speed - w). */
double motor_free_speed(const motor_t *m, int cmd, double dt_s);
/* After a step whose torque ODE finished (implicit damping): the current
 * that gives torque_nm, and the voltage with it. */
void motor_set_torque(motor_t *m, int cmd, double torque_nm);

#endif

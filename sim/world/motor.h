/* motor.h - DC gearmotor and its drive, two models (config [motor] motor_model).
 *
 * datasheet (default): a DC motor whose constants come from the datasheet's
 * no-load and stall figures at the rated voltage V, with the gearbox's
 * efficiency and the no-load current as friction (motor shaft quantities,
 * N = gear ratio, w = output shaft speed):
 *   R   = V / i_stall                         armature resistance
 *   Ke  = (V - R*i_noload) / (N * w_noload)   back-EMF constant, V*s/rad
 *   Kt  = Ke                                  torque constant, N*m/A (SI)
 *   eta = T_stall / (N*Kt*(i_stall - i_f(i_stall)))  gearbox efficiency
 *   L di/dt = V*duty - R*i - Ke*N*w
 *   T_out   = N*eta*Kt*i - T_friction,  |T_friction| <= N*eta*Kt*i_f(i)
 * with the friction in amperes of motor current, F = friction_load_a:
 *   i_f(i) = i_noload + F*(1 - exp(-max(0, |i| - i_noload) / (2F)))
 * i_noload running free, rising by F once the motor carries a load (F = 0:
 * a constant friction). The rise's scale 2F is the model's: the friction
 * grows at most half as fast as the current at no load, so running free is
 * the one state a free motor settles to. It bends the curve as measured
 * gearmotors bend (Pololu's loaded figures lie on lines through the stall
 * extrapolation that miss the no-load point: the friction under load is
 * above the no-load current). F is fitted by bench/fit_motor_losses.py.
 * For the Pololu 30:1 LP 6V with F = 0: R 16.67 ohm, Ke 4.03 mV*s/rad, eta
 * 0.70 (F = 0.0273 A: eta 0.756); the no-load speed and current and the
 * stall torque and current come out exact either way (mmsim --validate).
 * The rotor's inertia, reflected through the gear (J*N^2), is part of the
 * wheel's (world.c).
 *
 * Coupling to the 1 ms physics step without bias: the current's time
 * constant L/R (60 us) is far below the step, so over a step the current is
 * solved exactly for the step's end speed: with k = (tau/h)(1 - e^(-h/tau)),
 * the step's mean current is (1-k)*i_ss(w) + k*i_start, affine in w. The
 * torque on the wheel is then T0 - D*w_end, and the physics applies the
 * damping part implicitly (a constraint row, world.c): no explicit lag of
 * the back-EMF behind the wheel. Friction is a stiction constraint, its
 * level i_f at the step's mean current with the start speed.
 *
 * paper: the paper's eq. 1-5 as its simulator ran them: T = K*i at the
 * output shaft with K = T_stall/i_stall, R = V/i_stall, the current by a
 * backward difference with the previous step's speed, no losses, no
 * rotor inertia (so its no-load speed is 61 % above the datasheet's).
 *
 * Command: -1023..+1023 = -100..+100 % of the battery voltage. The battery's
 * internal resistance R_b is in the motor's circuit as duty^2*R_b (the
 * H-bridge draws duty*i from the battery), solved with the current. */
#ifndef MOTOR_H
#define MOTOR_H

#include <stdint.h>
#include "config.h"

#define MOTOR_CMD_MAX 1023

typedef struct {
    int model;                 /* MOTOR_MODEL_* */
    double n;                  /* gear ratio */
    double r_ohm, l_h;
    double ke_v_s;             /* back-EMF constant at the motor shaft, V*s/rad (= Kt, N*m/A) */
    double eta;                /* gearbox efficiency, 1 = lossless */
    double i_friction_a;       /* no-load current: the friction in amperes of motor current */
    double friction_load_a;    /* the friction's rise under load, A (motor_friction_a) */
    double battery_v, battery_r_ohm;
    double i_a;                /* armature current at the end of the last step, A */
    double v_applied;          /* last open-circuit drive voltage, duty * battery_v, V */
    double r_circuit_ohm;      /* the circuit's resistance this step: R + duty^2 * R_b */
    double torque_nm;          /* output torque of the last step (friction excluded), N*m */
    /* this step's drive, set by motor_drive */
    double k_mean;             /* weight of the start current in the step's mean */
    double decay;              /* exp(-dt*R/L): the start current's share left at the step's end */
    double step_r_ohm, step_dt_s; /* the circuit and step k_mean and decay are for */
    double i_start_a;
} motor_t;

/* What the physics applies to a wheel during one step: the torque
 * t0_nm - damping_nm_s * w_end (w_end = the wheel's speed at the step's end,
 * rad/s, solved implicitly), and a Coulomb friction up to friction_nm that
 * holds the wheel at rest. */
typedef struct {
    double t0_nm, damping_nm_s, friction_nm;
} motor_drive_t;

/* scale: this motor's constant relative to the nominal (asymmetry), 1 = nominal */
void motor_init(motor_t *m, const drive_spec_t *c, double battery_v, double battery_r_ohm, double scale);
/* The drive for the next step with command cmd (clamped to +-1023), the
 * wheel's speed w_rad_s at the step's start and the step dt_s. */
motor_drive_t motor_drive(motor_t *m, int cmd, double w_rad_s, double dt_s);
/* After the step: the current at its end from the wheel's end speed. */
void motor_after(motor_t *m, const motor_drive_t *d, double w_end_rad_s, double dt_s);

/* The voltage on the motor's terminals after the last step (the battery's
 * sag taken off), V. */
double motor_terminal_v(const motor_t *m);

/* The output shaft's speed with no load at voltage v_volt, rad/s, of the
 * configured model (the scripted driver's feed-forward). */
double motor_free_speed(const drive_spec_t *c, double v_volt);

/* The friction in amperes of motor current at current i_a: no_load_a
 * running free, rising by load_a under load (the load-dependent friction
 * above); load_a 0: no_load_a at any current. */
double motor_friction_a(double no_load_a, double load_a, double i_a);

/* The datasheet model's constants from the config (motor shaft): R, Ke and
 * eta as above. */
void motor_constants(const drive_spec_t *c, double *r_ohm, double *ke_v_s, double *eta);

#endif

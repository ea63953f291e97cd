/* world_body.h - what the ODE world (world.c) and both forms of its wheels
 * (world_wheel_spin.c, world_wheel_hinge.c) use, on ODE's handles and the
 * model alone: the chassis' frame, its loose parts, axle torques and
 * motor rows. */
#ifndef WORLD_BODY_H
#define WORLD_BODY_H

#include <ode/ode.h>

#include "model.h"

/* Loose parts: geoms of no body (the body box, the wheel sides with spin
 * bodies), put where they stand on the chassis only when a wall or the
 * floor may be near, so that ODE's step does not move them each step. */
typedef struct {
    dGeomID geom[3];       /* the box, the left and the right wheel side; none with hinged wheels */
    double at[3][3];       /* each one's centre in the chassis' frame from its centre of mass, m */
    dMatrix3 rot[3];       /* and its orientation in the chassis' frame */
    int n;
} world_loose_t;

/* Robot-frame point -> world point for a robot at (x, y) facing heading. */
void world_frame_point(double x, double y, double heading, const double p[3], double out[3]);
/* Where wheel s's centre (0 left, 1 right) is in the chassis frame of
 * model m (its own radius above the floor). */
void world_wheel_point(const sim_model_t *m, int s, double p[3]);
/* Loose part k put where it stands on the chassis; geom g made the next
 * loose part, at at_m (the chassis' frame from its centre of mass) turned
 * by rot (NULL: not turned), and put in place. */
void world_loose_place(world_loose_t *l, dBodyID chassis, int k);
void world_loose_add(world_loose_t *l, dBodyID chassis, dGeomID g, const double at_m[3], const dReal *rot);
/* A torque t_nm about body b's own x axis. */
void world_axle_torque(dBodyID b, double t_nm);
/* An angular motor's parameter set to v where it differs from *was. */
void world_amotor_param(dJointID j, int param, double v, double *was);
/* The chassis' rate about its axle (its x), rad/s, + nose up. */
double world_pitch_rate(dBodyID chassis);

#endif

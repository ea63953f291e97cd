/* world_body.c - what the ODE world (world.c) and both forms of its
 * wheels (world_wheel_spin.c, world_wheel_hinge.c) use: the chassis' frame,
 * its loose parts, axle torques and motor rows (world_body.h). */
#include "world_body.h"

#include <math.h>

/* Robot-frame point -> world point for a robot at (x, y) facing heading. */
void world_frame_point(double x, double y, double heading, const double p[3], double out[3])
{
    double a = heading - M_PI / 2, ca = cos(a), sa = sin(a);
    out[0] = x + ca * p[0] - sa * p[1];
    out[1] = y + sa * p[0] + ca * p[1];
    out[2] = p[2];
}

/* Where wheel s's centre is in the chassis frame (its own radius above
 * the floor). */
void world_wheel_point(const sim_model_t *m, int s, double p[3])
{
    const sim_chassis_t *c = &m->chassis;
    p[0] = s == 0 ? -c->wheel_x_m : c->wheel_x_m; /* 0: the left wheel */
    p[1] = c->axle_y_m;
    p[2] = m->wheel_r_m[s];
}

/* Loose part k (the box or a wheel side) put where it stands on the
 * chassis. A loose part is a geom of no body, so that ODE's step does not
 * move it with the chassis each step: the box meets only walls and, with
 * the nose down, the floor; a wheel side only walls (world_step puts them
 * in place only where those may be near: clear_of_walls, box_floor). The
 * same arithmetic as ODE's for a geom offset on a body (position R p + c,
 * rotation R R_offset, each sum in ODE's order), so it stands exactly where
 * that geom would. */
void world_loose_place(world_loose_t *l, dBodyID chassis, int k)
{
    const dReal *R = dBodyGetRotation(chassis);
    const double *o = l->rot[k], *at = l->at[k];
    dVector3 p;
    dMatrix3 rot;
    dBodyGetRelPointPos(chassis, at[0], at[1], at[2], p);
    for (int i = 0; i < 3; i++) {
        for (int j = 0; j < 3; j++) rot[4 * i + j] = o[j] * R[4 * i] + o[4 + j] * R[4 * i + 1] + o[8 + j] * R[4 * i + 2];
        rot[4 * i + 3] = 0;
    }
    dGeomSetPosition(l->geom[k], p[0], p[1], p[2]);
    dGeomSetRotation(l->geom[k], rot);
}

/* Geom g made loose part number l->n, at at_m (the chassis' frame from
 * its centre of mass) turned by rot (NULL: not turned), and put in place. */
void world_loose_add(world_loose_t *l, dBodyID chassis, dGeomID g, const double at_m[3], const dReal *rot)
{
    int k = l->n++;
    l->geom[k] = g;
    for (int i = 0; i < 3; i++) l->at[k][i] = at_m[i];
    if (rot) {
        for (int i = 0; i < 12; i++) l->rot[k][i] = rot[i];
    } else {
        dRSetIdentity(l->rot[k]);
    }
    world_loose_place(l, chassis, k);
}

/* A torque t_nm about body b's own x axis (its rotation's first column):
 * dBodyAddRelTorque(b, t_nm, 0, 0) without the products by zero. */
void world_axle_torque(dBodyID b, double t_nm)
{
    const dReal *R = dBodyGetRotation(b);
    dBodyAddTorque(b, R[0] * t_nm, R[4] * t_nm, R[8] * t_nm);
}

/* An angular motor's parameter set to v only where it differs from *was,
 * what it was last set to (ODE keeps a parameter as set, so setting the
 * same value again changes nothing): most steps change only the motor's
 * target speed. A motor of no limits with no force (dParamFMax 0) gives
 * the solver no row: it is disabled then, so that ODE's step passes it by
 * (enabled again with a force). */
void world_amotor_param(dJointID j, int param, double v, double *was)
{
    if (*was == v) return;
    *was = v;
    dJointSetAMotorParam(j, param, v);
    if (param == dParamFMax && v > 0) dJointEnable(j);
    else if (param == dParamFMax) dJointDisable(j);
}

/* The chassis' rate about its axle (its x), rad/s, + nose up. */
double world_pitch_rate(dBodyID chassis)
{
    const dReal *om = dBodyGetAngularVel(chassis), *R = dBodyGetRotation(chassis);
    return om[0] * R[0] + om[1] * R[4] + om[2] * R[8];
}

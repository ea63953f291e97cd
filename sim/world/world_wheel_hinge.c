/* world_wheel_hinge.c - the wheels on hinges ([sim] wheels = hinge;
 * sim/world/README.md): each wheel a body on a hinge to the chassis, its
 * motor the hinge's motor row, its stiction an angular motor about the
 * axle. The wheel form's table (world_wheel_hinge, world_impl.h). */
#include "world_impl.h"

#include <math.h>

/* A wheel's orientation for a robot facing heading, turned by angle_rad
 * about its axle (positive = forward): a cylinder's axis is its z, turned
 * to point along the robot's x (NULL: as built). */
static void wheel_rotation(double heading, const double *angle_rad, dMatrix3 out)
{
    dMatrix3 rot, r2, r3, spin;
    dRFromAxisAndAngle(rot, 0, 0, 1, heading - M_PI / 2);
    dRFromAxisAndAngle(r2, 0, 1, 0, M_PI / 2);
    dMultiply0(angle_rad ? r3 : out, rot, r2, 3, 3, 3);
    if (!angle_rad) return;
    dRFromAxisAndAngle(spin, 0, 0, 1, -*angle_rad); /* hinge angles count the other way */
    dMultiply0(out, r3, spin, 3, 3, 3);
}

/* Hinged wheels ([sim] wheels = hinge). A wheel's body: a cylinder's mass (and the motor's rotor, reflected
 * through the gearbox as J * N^2) at its centre. */
static void hinge_wheel_body(world_t *w, int s, const double at_w[3], double heading)
{
    const sim_chassis_t *c = &w->model->chassis;
    dMass m;
    dMatrix3 r;
    w->wheel[s] = dBodyCreate(w->world);
    /* cylinder axis along z: the mass is set in the wheel frame */
    dMassSetCylinderTotal(&m, c->wheel_mass_kg, 3, w->model->wheel_r_m[s], c->wheel_w_m);
    if (w->model->rotor_j_kgm2[s] > 0) m.I[2 * 4 + 2] += w->model->rotor_j_kgm2[s];
    dBodySetMass(w->wheel[s], &m);
    /* No gyroscopic term on a wheel. ODE's implicit one damps a wheel that
     * spins while the chassis yaws by an amount that grows with the step
     * (an in-place spin ran 4 % slower at 2 ms than at 0.25 ms), and the
     * rotor reflected as J*N^2 would make the term N times the rotor's real
     * J*N*w*Omega. The real torque (wheel and rotor, about 4e-4 N*m in a
     * 20 rad/s spin) shifts about 5 mN between the tyres: left out. */
    dBodySetGyroscopicMode(w->wheel[s], 0);
    dBodySetPosition(w->wheel[s], at_w[0], at_w[1], at_w[2]);
    wheel_rotation(heading, NULL, r);
    dBodySetRotation(w->wheel[s], r);
}

/* A wheel's geoms. The tyre touches the floor as a sphere of the wheel's
 * radius: one contact on the wheel's centre plane, as a rounded tyre. A
 * flat cylinder touches with one rim edge or the other as the chassis
 * rolls a little, which moves the effective track between 88 and 104 mm
 * and makes in-place turns miss by up to 9 degrees. Against walls and
 * posts the wheel is its real cylinder. */
static void hinge_wheel_geoms(world_t *w, int s)
{
    double r = w->model->wheel_r_m[s];
    w->wheel_geom[s] = dCreateSphere(w->robot, r);
    dGeomSetBody(w->wheel_geom[s], w->wheel[s]);
    dGeomSetCategoryBits(w->wheel_geom[s], CAT_TYRE);
    dGeomSetCollideBits(w->wheel_geom[s], CAT_FLOOR);
    w->wheel_side[s] = dCreateCylinder(w->robot, r, w->model->chassis.wheel_w_m);
    dGeomSetBody(w->wheel_side[s], w->wheel[s]);
    dGeomSetCategoryBits(w->wheel_side[s], CAT_WHEEL_SIDE);
    dGeomSetCollideBits(w->wheel_side[s], CAT_STATIC);
}

/* A wheel's joints to the chassis: the hinge on the axle at anchor_w
 * (its motor row off until world_step drives it) and the gearbox's
 * stiction, an angular motor held at speed 0. */
static void hinge_wheel_joints(world_t *w, int s, const double anchor_w[3])
{
    const dReal *ax = dBodyGetRotation(w->chassis); /* robot x axis in the world: column 0 */
    w->hinge[s] = dJointCreateHinge(w->world, 0);
    dJointAttach(w->hinge[s], w->chassis, w->wheel[s]);
    dJointSetHingeAnchor(w->hinge[s], anchor_w[0], anchor_w[1], anchor_w[2]);
    dJointSetHingeAxis(w->hinge[s], ax[0], ax[4], ax[8]);
    dJointSetHingeParam(w->hinge[s], dParamFMax, 0);
    w->friction[s] = dJointCreateAMotor(w->world, 0);
    dJointAttach(w->friction[s], w->chassis, w->wheel[s]);
    dJointSetAMotorNumAxes(w->friction[s], 1);
    dJointSetAMotorAxis(w->friction[s], 0, 1, ax[0], ax[4], ax[8]); /* the axle: ODE takes it in the world's frame and keeps it in the chassis' */
    dJointSetAMotorParam(w->friction[s], dParamVel, 0);
    dJointSetAMotorParam(w->friction[s], dParamFMax, 0);
}

/* A wheel on its hinge is a body of its own: the chassis' mass is the body's and the casters'. */
static void chassis_mass(const world_t *w, dMass *mb)
{
    (void)w, (void)mb;
}

static void attach_box(world_t *w)
{
    dGeomSetBody(w->box, w->chassis);
    dGeomSetOffsetPosition(w->box, w->box_offset[0], w->box_offset[1], w->box_offset[2]);
}

/* Wheel s: its body where it stands on the chassis at (x_m, y_m) facing heading_rad, its geoms, its joints. */
static void build(world_t *w, int s, double x_m, double y_m, double heading_rad)
{
    double wp[3], ww[3];
    world_wheel_point(w->model, s, wp);
    world_frame_point(x_m, y_m, heading_rad, wp, ww);
    hinge_wheel_body(w, s, ww, heading_rad);
    hinge_wheel_geoms(w, s);
    hinge_wheel_joints(w, s, ww);
}

static double rate(const world_t *w, int s) { return dJointGetHingeAngleRate(w->hinge[s]); }
static double angle(const world_t *w, int s) { return dJointGetHingeAngle(w->hinge[s]); }

static void torque(world_t *w, int s, double t_nm)
{
    dJointAddHingeTorque(w->hinge[s], t_nm); /* +T on body1 (chassis), -T on body2 (wheel) */
}

static void motor_row(world_t *w, int s, double vel_rad_s, double fmax_nm, double cfm)
{
    dJointSetHingeParam(w->hinge[s], dParamVel, vel_rad_s);
    dJointSetHingeParam(w->hinge[s], dParamFMax, fmax_nm);
    dJointSetHingeParam(w->hinge[s], dParamCFM, cfm);
}

static void motor_off(world_t *w, int s) { dJointSetHingeParam(w->hinge[s], dParamFMax, 0); }

/* The hinge couples wheel and chassis itself: nothing more to hand over, nothing to do around an ODE step. */
static void couple(world_t *w, int s)
{
    (void)w, (void)s;
}

static void ode_step_nothing(world_t *w)
{
    (void)w;
}

static dBodyID contact_body(const world_t *w, dGeomID part, dGeomID other)
{
    (void)w, (void)part;
    return dGeomGetBody(other);
}

/* The tyre's point moves with the wheel's body: its speed is the contact's own, nothing to subtract. */
static void rim_vel(const world_t *w, int s, const dReal *p, dVector3 v)
{
    (void)w, (void)s, (void)p, (void)v;
}

/* An angular motor between chassis and wheel about the axle (its row holds
 * (w_chassis - w_wheel) . axis at its vel). */
static dJointID dyno_row(world_t *w, int s)
{
    dJointID j = dJointCreateAMotor(w->world, 0);
    dJointAttach(j, w->chassis, w->wheel[s]);
    dJointSetAMotorNumAxes(j, 1);
    dJointSetAMotorAxis(j, 0, 1, 1, 0, 0);
    return j;
}

static void hold_up(world_t *w, int s)
{
    const dReal *q = dBodyGetPosition(w->wheel[s]);
    dBodySetPosition(w->wheel[s], q[0], q[1], q[2] + WORLD_CARRY_M);
}

static void lock(world_t *w, int s)
{
    w->lock[s] = dJointCreateFixed(w->world, 0);
    dJointAttach(w->lock[s], w->chassis, w->wheel[s]);
    dJointSetFixed(w->lock[s]);
}

static void place(world_t *w, int s, double x_m, double y_m, double heading_rad, double angle_rad)
{
    double wp[3], ww[3];
    dMatrix3 r;
    world_wheel_point(w->model, s, wp);
    world_frame_point(x_m, y_m, heading_rad, wp, ww);
    wheel_rotation(heading_rad, &angle_rad, r);
    dBodySetPosition(w->wheel[s], ww[0], ww[1], ww[2]);
    dBodySetRotation(w->wheel[s], r);
    dBodySetLinearVel(w->wheel[s], 0, 0, 0);
    dBodySetAngularVel(w->wheel[s], 0, 0, 0);
}

static void set_speed(world_t *w, int s, double v_m_s)
{
    dVector3 f, x;
    dBodyVectorToWorld(w->chassis, 0, 1, 0, f);
    dBodyVectorToWorld(w->chassis, 1, 0, 0, x);
    double spin = -v_m_s / w->model->wheel_r_m[s]; /* rolling forward turns the wheel about -x */
    dBodySetLinearVel(w->wheel[s], v_m_s * f[0], v_m_s * f[1], 0);
    dBodySetAngularVel(w->wheel[s], spin * x[0], spin * x[1], spin * x[2]);
}

const world_wheels_t world_wheel_hinge = {
    .chassis_mass = chassis_mass,
    .attach_box = attach_box,
    .build = build,
    .rate = rate,
    .angle = angle,
    .torque = torque,
    .motor_row = motor_row,
    .motor_off = motor_off,
    .couple = couple,
    .before_ode = ode_step_nothing,
    .after_ode = ode_step_nothing,
    .contact_body = contact_body,
    .rim_vel = rim_vel,
    .dyno_row = dyno_row,
    .hold_up = hold_up,
    .lock = lock,
    .place = place,
    .set_speed = set_speed,
};

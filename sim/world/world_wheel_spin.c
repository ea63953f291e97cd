/* world_wheel_spin.c - the wheels as spin bodies ([sim] wheels = spin,
 * the default; sim/world/README.md): each wheel rides in the chassis (its
 * mass, and its inertia off the axle) and its spin relative to the chassis
 * is a body of its own, put on the wheel's centre with the chassis'
 * orientation before each ODE step. The wheel form's table
 * (world_wheel_spin, world_impl.h). */
#include "world_impl.h"

#include <math.h>

/* A spin body's mass (kg) and inertia off its axle (kg*m^2): so heavy that
 * the rows on it leave those freedoms still (1e6 against the robot's 0.1 kg) */
#define WORLD_SPIN_HEAVY 1e6

/* Spin bodies ([sim] wheels = spin). A wheel's spin body: a body that carries the wheel's spin about its
 * axle and nothing else. Its inertia about the axle is the wheel's
 * cylinder's and the motor's rotor, reflected through the gearbox as
 * J * N^2; its mass and its inertia about the other axes are so heavy that
 * the rows on it leave them still. world_step puts it on the wheel's centre
 * with the chassis' orientation before each ODE step; its angular velocity
 * along the chassis' x axis is the wheel's spin relative to the chassis
 * (+ rolling forward), as a hinge's rate. */
static void wheel_body(world_t *w, int s)
{
    const sim_chassis_t *c = &w->model->chassis;
    dMass m;
    double r = w->model->wheel_r_m[s], j = 0.5 * c->wheel_mass_kg * r * r;
    if (w->model->rotor_j_kgm2[s] > 0) j += w->model->rotor_j_kgm2[s];
    w->wheel[s] = dBodyCreate(w->world);
    dMassSetParameters(&m, WORLD_SPIN_HEAVY, 0, 0, 0, j, WORLD_SPIN_HEAVY, WORLD_SPIN_HEAVY, 0, 0, 0);
    w->spin_j[s] = j;
    w->wheel_j[s] = 0.5 * c->wheel_mass_kg * r * r;
    dBodySetMass(w->wheel[s], &m);
    dBodySetGravityMode(w->wheel[s], 0);
    /* No gyroscopic term on a wheel (its spin is relative to the chassis,
     * and ODE's implicit term damps a spinning wheel by an amount that
     * grows with the step); the real torque (wheel and rotor, about 4e-4
     * N*m in a 20 rad/s spin) shifts about 5 mN between the tyres: left out. */
    dBodySetGyroscopicMode(w->wheel[s], 0);
}

/* A wheel's geoms, on the chassis at the wheel's centre (their contacts
 * take the spin body as their second body: near_cb). The tyre touches the
 * floor as a sphere of the wheel's radius: one contact on the wheel's
 * centre plane, as a rounded tyre. A flat cylinder touches with one rim
 * edge or the other as the chassis rolls a little, which moves the
 * effective track between 88 and 104 mm and makes in-place turns miss by up
 * to 9 degrees. Against walls and posts the wheel is its real cylinder,
 * its axis along the axle. */
static void wheel_geoms(world_t *w, int s, const double at[3])
{
    double r = w->model->wheel_r_m[s];
    dMatrix3 axle;
    w->wheel_geom[s] = dCreateSphere(w->robot, r);
    dGeomSetBody(w->wheel_geom[s], w->chassis);
    dGeomSetOffsetPosition(w->wheel_geom[s], at[0] - w->com[0], at[1] - w->com[1], at[2] - w->com[2]);
    dGeomSetCategoryBits(w->wheel_geom[s], CAT_TYRE);
    dGeomSetCollideBits(w->wheel_geom[s], CAT_FLOOR);
    w->wheel_side[s] = dCreateCylinder(w->robot, r, w->model->chassis.wheel_w_m);
    const double side_at[3] = { at[0] - w->com[0], at[1] - w->com[1], at[2] - w->com[2] };
    dRFromAxisAndAngle(axle, 0, 1, 0, M_PI / 2); /* the cylinder's z to the chassis' x */
    dGeomSetCategoryBits(w->wheel_side[s], CAT_WHEEL_SIDE);
    dGeomSetCollideBits(w->wheel_side[s], CAT_STATIC);
    world_loose_add(&w->loose, w->chassis, w->wheel_side[s], side_at, axle);
}

/* An angular motor row on wheel s's spin body about its axle (the body's
 * x), against the world, off until set. */
static dJointID spin_row(world_t *w, int s)
{
    dJointID j = dJointCreateAMotor(w->world, 0);
    dVector3 x;
    dBodyVectorToWorld(w->wheel[s], 1, 0, 0, x); /* ODE takes the axis in the world's frame and keeps it in the body's */
    dJointAttach(j, w->wheel[s], 0);
    dJointSetAMotorNumAxes(j, 1);
    dJointSetAMotorAxis(j, 0, 1, x[0], x[1], x[2]);
    dJointSetAMotorParam(j, dParamFMax, 0);
    return j;
}

/* A wheel's rows: the motor's damper (off until world_step drives it) and
 * the gearbox's stiction, an angular motor held at speed 0. */
static void wheel_joints(world_t *w, int s)
{
    w->motor[s] = spin_row(w, s);
    w->friction[s] = spin_row(w, s);
    dJointSetAMotorParam(w->friction[s], dParamVel, 0);
}

/* Wheel s's spin rate relative to the chassis, rad/s, + forward. */
static double spin_rate(const world_t *w, int s)
{
    const dReal *om = dBodyGetAngularVel(w->wheel[s]), *R = dBodyGetRotation(w->wheel[s]);
    return om[0] * R[0] + om[1] * R[4] + om[2] * R[8];
}

/* Wheel s's spin body on the wheel's centre with the chassis' orientation,
 * spinning at rate_rad_s about the axle, its other freedoms at rest. */
static void spin_place(world_t *w, int s, double rate_rad_s)
{
    double wp[3];
    dVector3 at;
    const dReal *x = dBodyGetRotation(w->chassis); /* its x axis: x[0], x[4], x[8] */
    world_wheel_point(w->model, s, wp);
    dBodyGetRelPointPos(w->chassis, wp[0] - w->com[0], wp[1] - w->com[1], wp[2] - w->com[2], at);
    dBodySetPosition(w->wheel[s], at[0], at[1], at[2]);
    dBodySetQuaternion(w->wheel[s], dBodyGetQuaternion(w->chassis));
    dBodySetLinearVel(w->wheel[s], 0, 0, 0);
    dBodySetAngularVel(w->wheel[s], rate_rad_s * x[0], rate_rad_s * x[4], rate_rad_s * x[8]);
}

/* A torque t_nm about wheel s's axle between the chassis and the wheel
 * (+ turns the wheel forward). On the spin body only: the spin is relative
 * to the chassis, so a torque between the two acts on the spin alone; the
 * chassis feels the wheel through the tyre's force, which it takes at the
 * tyre's point, and through the wheel's own inertia (spin_advance). */
static void spin_torque(world_t *w, int s, double t_nm)
{
    world_axle_torque(w->wheel[s], t_nm);
}

/* After an ODE step: each wheel's angle advanced by its end spin (as ODE
 * moves a body by its end velocity), and the coupling of spin and chassis
 * for the next step. With s the spin relative to the chassis and p the
 * chassis' turn about the axle, a wheel of inertia Jw and its rotor (Jr,
 * gear ratio N) hold the kinetic energy Jw (s' + p')^2 / 2 + Jr (N s' + p')^2 / 2.
 * The spin body holds (Jw + N^2 Jr) s'^2 / 2; the chassis, Jw p'^2 / 2
 * (chassis_mass); the cross term (Jw + N Jr) s' p' becomes a torque of
 * Jw s'' on the chassis and Jw p'' on the spin, each a step late. That and
 * the tyre's force at the tyre's point are all the chassis takes from the
 * wheel: of the motor's torque, what spins the rotor (N^2 Jr s'', 14 times
 * the wheel's own inertia for the paper robot) reaches the chassis only as
 * the rotor's N Jr s'. N Jr is left out of the cross term: its sign is the
 * gear train's (each spur stage turns the rotor the other way), which the
 * robot files do not give, and it is under half of Jw for the paper robot
 * (6e-7 against 1.3e-6 kg*m^2). Handed J s'' instead (the motor's torque
 * as if it all reacted on the chassis), a braking robot would pitch nose
 * down harder and bounce a wheel off the floor as its nose meets it: the
 * example firmware's one-cell moves end 1.2 mm past its odometry, against
 * 0.0 mm so (docs/BENCHMARKS.md). */

/* An angle in rad wrapped into [-pi, pi] as remainder(a, 2 pi) does: for
 * |a| < 3 pi one subtraction or addition of 2 pi, exact by Sterbenz's lemma
 * (a and 2 pi within a factor of two), so the same double; beyond, remainder. */
static double wrap_angle(double a_rad)
{
    if (a_rad > M_PI && a_rad < 3 * M_PI) return a_rad - 2 * M_PI;
    if (a_rad < -M_PI && a_rad > -3 * M_PI) return a_rad + 2 * M_PI;
    if (a_rad >= -M_PI && a_rad <= M_PI) return a_rad;
    return remainder(a_rad, 2 * M_PI);
}

static void spin_advance(world_t *w)
{
    w->pitch_acc = (world_pitch_rate(w->chassis) - w->pitch_before) / w->h_s;
    for (int s = 0; s < 2; s++) {
        double rate = spin_rate(w, s);
        w->wheel_angle[s] = wrap_angle(w->wheel_angle[s] + rate * w->h_s);
        w->reaction_nm[s] = w->wheel_j[s] * (rate - w->spin_before[s]) / w->h_s;
    }
}

/* The wheels ride in the chassis, their inertia about the axle too
 * (spin_advance's note); their spin relative to it is the spin body's. */
static void chassis_mass(const world_t *w, dMass *mb)
{
    const sim_chassis_t *c = &w->model->chassis;
    dMass mc;
    for (int s = 0; s < 2; s++) {
        dMassSetCylinderTotal(&mc, c->wheel_mass_kg, 1, w->model->wheel_r_m[s], c->wheel_w_m);
        dMassTranslate(&mc, s == WORLD_LEFT ? -c->wheel_x_m : c->wheel_x_m, c->axle_y_m, w->model->wheel_r_m[s]);
        dMassAdd(mb, &mc);
    }
}

/* The body box is loose: a geom of no body, put on the chassis where a
 * wall or the floor may be near (world_loose_place). */
static void attach_box(world_t *w) { world_loose_add(&w->loose, w->chassis, w->box, w->box_offset, NULL); }

/* Wheel s: its geoms on the chassis, its spin body at rest, its rows. */
static void build(world_t *w, int s, double x_m, double y_m, double heading_rad)
{
    double wp[3];
    (void)x_m, (void)y_m, (void)heading_rad; /* the chassis, built already, places it */
    world_wheel_point(w->model, s, wp);
    wheel_geoms(w, s, wp);
    wheel_body(w, s);
    spin_place(w, s, 0);
    wheel_joints(w, s);
}

static double angle(const world_t *w, int s) { return w->wheel_angle[s]; }

/* The motor's damper: an angular motor row on the spin body. */
static void motor_row(world_t *w, int s, double vel_rad_s, double fmax_nm, double cfm)
{
    world_amotor_param(w->motor[s], dParamVel, vel_rad_s, &w->motor_set[s][0]);
    world_amotor_param(w->motor[s], dParamFMax, fmax_nm, &w->motor_set[s][1]);
    world_amotor_param(w->motor[s], dParamCFM, cfm, &w->motor_set[s][2]);
}

static void motor_off(world_t *w, int s) { world_amotor_param(w->motor[s], dParamFMax, 0, &w->motor_set[s][1]); }

/* The cross term of the kinetic energy, a step late (spin_advance's note):
 * the chassis takes the wheel's inertia times the spin's change, the spin
 * body that inertia times the chassis' pitch change. */
static void couple(world_t *w, int s)
{
    world_axle_torque(w->chassis, w->reaction_nm[s]);
    world_axle_torque(w->wheel[s], w->wheel_j[s] * w->pitch_acc);
}

/* Each spin body put on its wheel's centre as the chassis now stands,
 * spinning as it did; the spins and the chassis' pitch rate kept for
 * spin_advance. */
static void before_ode(world_t *w)
{
    for (int s = 0; s < 2; s++) {
        w->spin_before[s] = spin_rate(w, s);
        spin_place(w, s, w->spin_before[s]);
    }
    w->pitch_before = world_pitch_rate(w->chassis);
}

/* A wheel's contact holds the chassis against its spin body as its second
 * body: the relative speed at the point is the chassis' there less the
 * spin's rim speed, the wheel's own, and the contact's torque turns the
 * spin (the spin body's linear freedoms, too heavy to move, stand in for
 * the floor or wall). Any other part's, the other geom's body. */
static dBodyID contact_body(const world_t *w, dGeomID part, dGeomID other)
{
    for (int s = 0; s < 2; s++)
        if (part == w->wheel_geom[s] || part == w->wheel_side[s]) return w->wheel[s];
    return dGeomGetBody(other);
}

static void rim_vel(const world_t *w, int s, const dReal *p, dVector3 v) { dBodyGetPointVel(w->wheel[s], p[0], p[1], p[2], v); }

static void hold_up(world_t *w, int s) { spin_place(w, s, spin_rate(w, s)); }

/* Held at spin 0. */
static void lock(world_t *w, int s)
{
    w->lock[s] = spin_row(w, s);
    dJointSetAMotorParam(w->lock[s], dParamVel, 0);
    dJointSetAMotorParam(w->lock[s], dParamFMax, dInfinity);
}

static void place(world_t *w, int s, double x_m, double y_m, double heading_rad, double angle_rad)
{
    (void)x_m, (void)y_m, (void)heading_rad; /* the chassis, placed already, places it */
    w->wheel_angle[s] = remainder(angle_rad, 2 * M_PI);
    w->reaction_nm[s] = w->pitch_acc = 0; /* put down at rest: no coupling left from before */
    spin_place(w, s, 0);
}

static void set_speed(world_t *w, int s, double v_m_s) { spin_place(w, s, v_m_s / w->model->wheel_r_m[s]); /* rolling, + forward */ }

const world_wheels_t world_wheel_spin = {
    .chassis_mass = chassis_mass,
    .attach_box = attach_box,
    .build = build,
    .rate = spin_rate,
    .angle = angle,
    .torque = spin_torque,
    .motor_row = motor_row,
    .motor_off = motor_off,
    .couple = couple,
    .before_ode = before_ode,
    .after_ode = spin_advance,
    .contact_body = contact_body,
    .rim_vel = rim_vel,
    .dyno_row = spin_row,
    .hold_up = hold_up,
    .lock = lock,
    .place = place,
    .set_speed = set_speed,
};

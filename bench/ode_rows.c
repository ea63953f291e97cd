/* ode_rows.c - what ODE's exact step (dWorldStep) costs for the robot's
 * rows, and for a formulation with fewer: a two-wheeled robot on a floor,
 * its contacts made by hand (no collision detection, so only the solver is
 * counted), driven straight at a constant motor drive for STEPS steps of
 * 1 ms, in one of two forms:
 *
 *   hinge:  chassis + 2 wheel bodies on hinges (5 rows each) with the
 *           motor's damper row (1 each), each tyre a contact with two
 *           friction directions (3 rows), the caster frictionless (1 row):
 *           19 rows, as sim/world/world.c builds the paper robot.
 *   spin:   the wheels' mass in the chassis; each wheel's spin a body of
 *           its own that only the tyre contact and the motor row touch
 *           (its other five freedoms so heavy that the rows hardly move
 *           them, and reset each step to the wheel's centre and the
 *           chassis' axle): 2 x 3 + 2 + 1 = 9 rows.
 *
 * Prints the chassis' velocity, yaw rate and the left wheel's spin
 * relative to the chassis at the end, so the two forms' motion can be
 * compared; `turn` runs the
 * right wheel's motor at half speed. Run under callgrind with two step
 * counts to get instructions per step (docs/BENCHMARKS.md):
 *   valgrind --tool=callgrind build/ode_rows hinge|spin STEPS [turn]
 * The numbers are the paper robot's rounded (robots/paper.ini: 16 mm wheel
 * radius, 90 mm track, 55 mm caster offset); the motor is a damper toward
 * a speed (torque = D * (w_target - w)). */
#include <ode/ode.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define H_S 0.001          /* step, s */
#define R_M 0.016          /* wheel radius, m */
#define TRACK_M 0.09       /* wheel centres apart, m */
#define CASTER_X_M (-0.055) /* caster's offset behind the axle, m */
#define CASTER_R_M 0.005   /* caster sphere's radius, m */
#define BODY_KG 0.1        /* chassis, kg */
#define WHEEL_KG 0.01      /* each wheel, kg */
#define SPIN_KG_M2 5e-6    /* a wheel's spin inertia with its rotor reflected, kg*m^2 */
#define HEAVY 1e6          /* the spin body's other freedoms: kg and kg*m^2 */
#define D_NM_S 1e-4        /* the motor's damping, N*m*s */
#define W_TARGET_RAD_S 60  /* the motor's no-load speed, rad/s */
#define KP_N_M 5000        /* contact spring, N/m */
#define KD_N_S_M 10        /* contact damper, N*s/m */
#define MU 0.8             /* tyre friction coefficient */

static dWorldID world;
static dJointGroupID contacts;
static dBodyID chassis, wheel[2];
static dJointID motor[2];
static int spin_form;
static double target_rad_s[2] = { W_TARGET_RAD_S, W_TARGET_RAD_S }; /* left, right: the motors' speeds */

/* A contact at world point p (normal up, depth d) between a and b (b 0: the floor). */
static void contact(dBodyID a, dBodyID b, const dReal p[3], dReal d, double mu)
{
    dContact c;
    memset(&c, 0, sizeof c);
    c.geom.pos[0] = p[0], c.geom.pos[1] = p[1], c.geom.pos[2] = p[2];
    c.geom.normal[2] = 1;
    c.geom.depth = d;
    c.surface.mode = dContactSoftERP | dContactSoftCFM | (mu > 0 ? dContactApprox1 | dContactFDir1 : 0);
    c.surface.mu = mu;
    const dReal *R = dBodyGetRotation(chassis);
    c.fdir1[0] = R[0], c.fdir1[1] = R[4]; /* the chassis' forward axis, flat */
    c.surface.soft_erp = H_S * KP_N_M / (H_S * KP_N_M + KD_N_S_M);
    c.surface.soft_cfm = 1.0 / (H_S * KP_N_M + KD_N_S_M);
    dJointID j = dJointCreateContact(world, contacts, &c);
    dJointAttach(j, a, b);
}

/* Wheel s's centre in the world. */
static void wheel_centre(int s, dVector3 out)
{
    dBodyGetRelPointPos(chassis, 0, s ? -TRACK_M / 2 : TRACK_M / 2, 0, out);
}

static void build(void)
{
    dMass m;
    chassis = dBodyCreate(world);
    dMassSetBoxTotal(&m, BODY_KG, 0.1, 0.08, 0.02);
    for (int s = 0; s < 2 && spin_form; s++) { /* the wheels' mass and inertia ride in the chassis */
        dMass wm;
        dMassSetCylinderTotal(&wm, WHEEL_KG, 2, R_M, 0.008);
        dMassTranslate(&wm, 0, s ? -TRACK_M / 2 : TRACK_M / 2, 0);
        dMassAdd(&m, &wm);
    }
    dBodySetMass(chassis, &m);
    dBodySetPosition(chassis, 0, 0, R_M);
    for (int s = 0; s < 2; s++) {
        dVector3 c;
        wheel_centre(s, c);
        wheel[s] = dBodyCreate(world);
        dBodySetGyroscopicMode(wheel[s], 0);
        if (spin_form) {
            dMassSetParameters(&m, HEAVY, 0, 0, 0, HEAVY, SPIN_KG_M2, HEAVY, 0, 0, 0); /* spin about body y */
            dBodySetGravityMode(wheel[s], 0);
            motor[s] = dJointCreateAMotor(world, 0);
            dJointAttach(motor[s], wheel[s], 0);
            dJointSetAMotorNumAxes(motor[s], 1);
            dJointSetAMotorAxis(motor[s], 0, 1, 0, 1, 0); /* the spin body's own y: the axle */
        } else {
            dMassSetCylinderTotal(&m, WHEEL_KG, 2, R_M, 0.008);
            m.I[5] = SPIN_KG_M2; /* about y, the axle */
            motor[s] = dJointCreateHinge(world, 0);
        }
        dBodySetMass(wheel[s], &m);
        dBodySetPosition(wheel[s], c[0], c[1], c[2]);
        if (!spin_form) {
            dJointAttach(motor[s], chassis, wheel[s]);
            dJointSetHingeAnchor(motor[s], c[0], c[1], c[2]);
            dJointSetHingeAxis(motor[s], 0, 1, 0);
        }
    }
}

/* One step: the spin bodies put back on the axle, the contacts, the motor rows. */
static void step(void)
{
    for (int s = 0; s < 2; s++) {
        dVector3 c, p;
        wheel_centre(s, c);
        p[0] = c[0], p[1] = c[1], p[2] = c[2] - R_M;
        if (spin_form) {
            dVector3 ax;
            dReal rate = dBodyGetAngularVel(wheel[s])[0] * dBodyGetRotation(wheel[s])[1] +
                         dBodyGetAngularVel(wheel[s])[1] * dBodyGetRotation(wheel[s])[5] +
                         dBodyGetAngularVel(wheel[s])[2] * dBodyGetRotation(wheel[s])[9];
            dBodySetPosition(wheel[s], c[0], c[1], c[2]);
            dBodySetRotation(wheel[s], dBodyGetRotation(chassis));
            dBodyVectorToWorld(chassis, 0, 1, 0, ax);
            dBodySetLinearVel(wheel[s], 0, 0, 0);
            dBodySetAngularVel(wheel[s], rate * ax[0], rate * ax[1], rate * ax[2]);
            /* the spin body carries minus the wheel's spin (the contact's second body) */
            dJointSetAMotorParam(motor[s], dParamVel, -target_rad_s[s]);
            dJointSetAMotorParam(motor[s], dParamFMax, dInfinity);
            dJointSetAMotorParam(motor[s], dParamCFM, 1.0 / D_NM_S);
            contact(chassis, wheel[s], p, R_M - c[2], MU);
        } else {
            /* +w on the hinge's axis (y) rolls the wheel toward -x: the target is negative for forward */
            dJointSetHingeParam(motor[s], dParamVel, -target_rad_s[s]);
            dJointSetHingeParam(motor[s], dParamFMax, dInfinity);
            dJointSetHingeParam(motor[s], dParamCFM, 1.0 / D_NM_S);
            contact(wheel[s], 0, p, R_M - c[2], MU);
        }
    }
    dVector3 k;
    dBodyGetRelPointPos(chassis, CASTER_X_M, 0, CASTER_R_M - R_M, k);
    k[2] -= CASTER_R_M;
    contact(chassis, 0, k, -k[2], 0);
    dWorldStep(world, H_S);
    dJointGroupEmpty(contacts);
}

int main(int argc, char **argv)
{
    if (argc < 3 || argc > 4 || (strcmp(argv[1], "hinge") && strcmp(argv[1], "spin")) || (argc == 4 && strcmp(argv[3], "turn"))) {
        fprintf(stderr, "usage: ode_rows hinge|spin STEPS [turn]\n");
        return 2;
    }
    if (argc == 4) target_rad_s[1] = W_TARGET_RAD_S / 2; /* turn: the right wheel at half speed */
    spin_form = !strcmp(argv[1], "spin");
    long n = atol(argv[2]);
    dInitODE2(0);
    world = dWorldCreate();
    dWorldSetGravity(world, 0, 0, -9.81);
    dWorldSetCFM(world, 1e-6);
    dWorldSetERP(world, 0.4);
    contacts = dJointGroupCreate(0);
    build();
    for (long i = 0; i < n; i++) step();
    const dReal *v = dBodyGetLinearVel(chassis), *ws = dBodyGetAngularVel(wheel[0]);
    dVector3 ax;
    dBodyVectorToWorld(chassis, 0, 1, 0, ax);
    /* the left wheel's spin relative to the chassis, + rolling forward */
    double spin = spin_form ? -(ws[0] * ax[0] + ws[1] * ax[1] + ws[2] * ax[2]) : -dJointGetHingeAngleRate(motor[0]);
    printf("%s, %ld steps: chassis %.4f %.4f %.4f m/s, z %.5f m, yaw rate %.4f rad/s, left wheel spin %.3f rad/s\n", argv[1], n,
           v[0], v[1], v[2], dBodyGetPosition(chassis)[2], dBodyGetAngularVel(chassis)[2], spin);
    dJointGroupDestroy(contacts);
    dWorldDestroy(world);
    dCloseODE();
    return 0;
}

/* world.c - ODE scene and robot (see world.h). */
#include "world.h"
#include "wallgrid.h"

#include <math.h>
#include <stdarg.h>
#include <ode/ode.h>
#include <stdint.h>
#include <stdlib.h>

#define CAT_STATIC 1u
#define CAT_ROBOT 2u
#define CAT_RAY 4u
#define CAT_FLOOR 8u
#define CAT_TYRE 16u       /* wheel-floor contact sphere */
#define CAT_WHEEL_SIDE 32u /* wheel cylinder, against walls only */
/* ODE pairs two geoms when either one's category meets the other's collide
 * bits, so each kind that must not meet another has its own category */
#define MAX_CONTACTS 4
#define WORLD_PARTS 8 /* most geoms the robot has: body, two skids, two tyres, two wheel sides */
#define WORLD_CONTACT_STEP_S 0.00025 /* longest ODE step while the robot is near a wall, s */
#define WORLD_NEAR_M 0.001 /* margin beyond a step's travel for "near a wall", m */
/* Slowest a point of the robot may move for an impact to need the finer
 * steps, m/s: slower, a 2 ms step meets the wall at most 0.1 mm late, a
 * sixteenth of a 3 m/s impact's 1.6 mm depth; a robot resting against a
 * wall (the start cell's back wall) keeps the contest's step. */
#define WORLD_IMPACT_M_S 0.05
#define WORLD_TOUCH_SLACK_M 1e-6 /* "clear of walls" for the collision tree: a micrometre apart at least, m */
#define WORLD_STICTION_RAD_S 1.0 /* wheel speed below which the gearbox friction is a stiction row, rad/s */
/* A spin body's mass (kg) and inertia off its axle (kg*m^2): so heavy that
 * the rows on it leave those freedoms still (1e6 against the robot's 0.1 kg) */
#define WORLD_SPIN_HEAVY 1e6

struct world {
    const sim_model_t *model; /* the caller's: outlives the world */
    dWorldID world;
    dSpaceID top, statics, robot;
    dJointGroupID contacts;
    dGeomID floor, centre_post, box, caster, caster2, wheel_geom[2], wheel_side[2], ray;
    int spin;              /* [sim] wheels = spin: each wheel's spin a body of its own (wheel_body's note), else wheels on hinges */
    dBodyID chassis, wheel[2]; /* each wheel's body, or its spin body */
    dJointID hinge[2];     /* hinged wheels: each wheel's hinge (its motor row the motor's damper) */
    dJointID motor[2];     /* spin bodies: the motor's damper row on each (an angular motor) */
    dJointID friction[2];  /* the gearbox's stiction on each wheel (an angular motor, target speed 0) */
    double motor_set[2][3]; /* what drive_wheel last gave each spin body's motor row: its dParamVel (rad/s), dParamFMax (N*m), dParamCFM (rad/s per N*m); NaN: not yet */
    double friction_set[2]; /* what drive_wheel last gave each friction row's dParamFMax, N*m; NaN: not yet */
    double spin_j[2];      /* each spin body's inertia about its axle, kg*m^2 */
    double spin_before[2]; /* each wheel's spin before the ODE step in progress, rad/s */
    double wheel_j[2];     /* each wheel's own inertia about its axle (its cylinder's, no rotor), kg*m^2: what couples spin and chassis (spin_advance) */
    double reaction_nm[2]; /* wheel_j * the spin's change over the last ODE step / h, about the axle, N*m: the chassis takes it next (spin_advance) */
    double pitch_before;   /* the chassis' rate about its axle (its x) before the ODE step in progress, rad/s */
    double pitch_acc;      /* its change over the last ODE step / h, rad/s^2: wheel_j times it turns each spin body next (spin_advance) */
    double wheel_angle[2]; /* each wheel's angle about its axle, rad in (-pi, pi], + forward */
    dJointID lift, lock[2]; /* world_lift: chassis held above the floor, wheels locked */
    dGeomID *wall;          /* the maze's boxes (posts and walls), by wallgrid id */
    double (*wall_bounds)[4]; /* their floor bounds: min x, max x, min y, max y, m */
    int nwalls;
    wallgrid_t *grid;       /* the boxes by cell, for rays and contacts */
    double (*wall_aabb)[6]; /* each box's bounds as ODE has them (dGeomGetAABB), m */
    int *wall_rank;         /* each box's place in the collision tree's walk (maze_order) */
    int *near_ids;          /* room for every box: the candidates of one robot part */
    int ranked;             /* every box has its place: maze contacts by cell (else ODE's tree walk) */
    dGeomID part[WORLD_PARTS]; /* the robot's geoms in its space's order (ODE's), nparts of them */
    int nparts;
    /* With spin bodies the body box and the wheel sides are loose: geoms of no body, put where they stand on the chassis only when a wall or the floor may be near (place_part) */
    dGeomID loose[3];      /* the box, the left and the right wheel side; none with hinged wheels */
    double loose_at[3][3]; /* each one's centre in the chassis' frame from its centre of mass, m */
    dMatrix3 loose_rot[3]; /* and its orientation in the chassis' frame */
    int nloose;
    int box_low;           /* the box was last put where its bounds may reach the floor's: put it again before the next collision pass */
    int loose_placed;      /* the loose parts stand where the chassis now puts them (world_step clears it as the chassis moves) */
    double floor_top_m;    /* the top of the floor's bounds as ODE has them (dGeomGetAABB), m */
    double parts_box[2][3]; /* the box in the chassis' frame (from its centre of mass) that holds every part: low and high corner, m (parts_box) */
    int parts_boxed;       /* parts_box holds: every part rides on the chassis (not with hinged wheels) */
    dJointID hand_lin, hand_yaw; /* world_hand: a hand's grip on the chassis (made on first use) */
    double carry_pose[3];   /* world_carry: where it was lifted from (x m, y m, heading rad) */
    int carried;
    double box_offset[3];  /* chassis box centre in the chassis body frame */
    double com[3];         /* chassis centre of mass in the robot frame (world_place) */
    double reach_m;        /* a body corner's distance from the centre of mass in the floor's plane, m (sub_steps) */
    int touching, touched_last;
    int clear_now;         /* every part is clear of the walls (sub_steps: by a step's travel and a millimetre; world_step: by WORLD_TOUCH_SLACK_M), in the state before the next ODE step: near_cb skips the maze */
    unsigned collisions;
    unsigned step_kinds, episode_kinds; /* WORLD_CONTACT_* bits: this step's, this episode's */
    unsigned kind_count[WORLD_CONTACT_KINDS]; /* finished episodes by kind */
    double h_s;            /* the ODE step in progress (a sub-step near walls), s */
    double wall_depth_m;   /* deepest wall contact of the last world_step, m */
    double brake_nm;       /* world_brake's load for the next world_step, N*m */
};

static int ode_ready;

static dGeomID static_box(world_t *w, double x, double y, double lx, double ly)
{
    double h = w->model->arena.wall_height_m;
    dGeomID g = dCreateBox(w->statics, lx, ly, h);
    dGeomSetPosition(g, x, y, h / 2);
    dGeomSetCategoryBits(g, CAT_STATIC);
    dGeomSetCollideBits(g, CAT_ROBOT | CAT_RAY | CAT_WHEEL_SIDE);
    double *b = w->wall_bounds[w->nwalls];
    b[0] = x - lx / 2, b[1] = x + lx / 2, b[2] = y - ly / 2, b[3] = y + ly / 2;
    w->wall[w->nwalls++] = g;
    return g;
}

/* The maze's boxes, each filed in the cells it lies in (wallgrid). -1 when
 * out of memory. */
static int build_maze(world_t *w, const maze_t *m)
{
    const simcfg_world_t *a = &w->model->arena;
    size_t most = (size_t)(m->width + 1) * (size_t)(m->height + 1) * 3u; /* posts, and two walls a post at most */
    w->wall = malloc(sizeof *w->wall * most);
    w->wall_bounds = malloc(sizeof *w->wall_bounds * most);
    if (!w->wall || !w->wall_bounds) return -1;
    double cell = a->cell_m, post = a->post_m, thick = a->wall_thick_m;
    int cx = m->width % 2 == 0 ? m->width / 2 : -1, cy = m->height % 2 == 0 ? m->height / 2 : -1;
    for (int py = 0; py <= m->height; py++)
        for (int px = 0; px <= m->width; px++) {
            dGeomID g = static_box(w, px * cell, py * cell, post, post);
            if (px == cx && py == cy) w->centre_post = g;
        }
    for (uint8_t y = 0; y < m->height; y++)
        for (uint8_t x = 0; x < m->width; x++) {
            maze_cell_t c = maze_cell(m, x, y);
            /* each wall once: south and west of every cell, plus the outer north and east */
            if (!maze_passable(m, c, MAZE_SOUTH, 0)) static_box(w, (x + 0.5) * cell, y * cell, cell - post, thick);
            if (!maze_passable(m, c, MAZE_WEST, 0)) static_box(w, x * cell, (y + 0.5) * cell, thick, cell - post);
            if (y == m->height - 1 && !maze_passable(m, c, MAZE_NORTH, 0))
                static_box(w, (x + 0.5) * cell, (y + 1) * cell, cell - post, thick);
            if (x == m->width - 1 && !maze_passable(m, c, MAZE_EAST, 0))
                static_box(w, (x + 1) * cell, (y + 0.5) * cell, thick, cell - post);
        }
    w->grid = wallgrid_build(cell, m->width, m->height, w->nwalls, (const double (*)[4])w->wall_bounds);
    return w->grid ? 0 : -1;
}

/* maze_order's callback: the static box of the pair gets the next place. */
static void rank_cb(void *data, dGeomID a, dGeomID b)
{
    world_t *w = data;
    dGeomID g = dGeomGetCategoryBits(a) & CAT_STATIC ? a : b;
    int id = (int)(intptr_t)dGeomGetData(g);
    if (id >= 0 && id < w->nwalls && w->wall[id] == g && w->wall_rank[id] < 0) w->wall_rank[id] = w->ranked++;
}

/* The order in which ODE's collision tree meets the maze's boxes: its walk
 * goes through its blocks depth first, each block's boxes in the block's
 * order, so any walk meets the boxes it reaches in the order a walk over
 * the whole maze meets them. That walk is taken once here (a box over the
 * whole maze against the tree), so maze_collide can hand ODE's own pairs to
 * near_cb in ODE's order, and the contacts come out the same. Also each
 * box's bounds as ODE computes them. -1 when out of memory. */
static int maze_order(world_t *w)
{
    size_t n = (size_t)w->nwalls + 1;
    w->wall_aabb = malloc(sizeof *w->wall_aabb * n);
    w->wall_rank = malloc(sizeof *w->wall_rank * n);
    w->near_ids = malloc(sizeof *w->near_ids * n);
    if (!w->wall_aabb || !w->wall_rank || !w->near_ids) return -1;
    double lo[2] = { INFINITY, INFINITY }, hi[2] = { -INFINITY, -INFINITY }, top_m = 0;
    for (int i = 0; i < w->nwalls; i++) {
        dGeomSetData(w->wall[i], (void *)(intptr_t)i);
        w->wall_rank[i] = -1;
        dReal a[6];
        dGeomGetAABB(w->wall[i], a);
        for (int k = 0; k < 6; k++) w->wall_aabb[i][k] = a[k];
        for (int k = 0; k < 2; k++) lo[k] = fmin(lo[k], a[2 * k]), hi[k] = fmax(hi[k], a[2 * k + 1]);
        top_m = fmax(top_m, a[5]);
    }
    if (w->nwalls == 0) return 0;
    /* a box 1 m beyond the maze's bounds all round */
    dGeomID all = dCreateBox(0, hi[0] - lo[0] + 2, hi[1] - lo[1] + 2, top_m + 2);
    dGeomSetPosition(all, (lo[0] + hi[0]) / 2, (lo[1] + hi[1]) / 2, top_m / 2);
    dGeomSetCategoryBits(all, CAT_ROBOT);
    dGeomSetCollideBits(all, CAT_STATIC);
    w->ranked = 0;
    dSpaceCollide2(all, (dGeomID)w->statics, w, rank_cb);
    dGeomDestroy(all);
    w->ranked = w->ranked == w->nwalls;
    return 0;
}

/* Robot-frame point -> world point for a robot at (x, y) facing heading. */
static void frame_point(double x, double y, double heading, const double p[3], double out[3])
{
    double a = heading - M_PI / 2, ca = cos(a), sa = sin(a);
    out[0] = x + ca * p[0] - sa * p[1];
    out[1] = y + sa * p[0] + ca * p[1];
    out[2] = p[2];
}

/* The chassis' mass: the body box (its own yaw inertia if the robot file
 * gives one; its centre of mass where the model puts it) and the casters,
 * as spheres. com gets the combined centre of mass in the chassis frame
 * and mb is moved to it: ODE wants the centre of mass at the body's origin. */
static void chassis_mass(const world_t *w, dMass *mb, double com[3])
{
    const sim_chassis_t *c = &w->model->chassis;
    const double *bc = w->model->body_com_m;
    dMass mc;
    dMassSetBoxTotal(mb, c->body_mass_kg, c->body_w_m, c->body_l_m, c->body_h_m);
    if (c->body_yaw_inertia_kgm2 > 0) mb->I[2 * 4 + 2] = c->body_yaw_inertia_kgm2;
    dMassTranslate(mb, bc[0], bc[1], bc[2]);
    for (int k = 0; k < w->model->casters && k < 2; k++) {
        dMassSetSphereTotal(&mc, c->caster_mass_kg, c->caster_r_m);
        dMassTranslate(&mc, 0, c->caster_y_m[k], c->caster_r_m);
        dMassAdd(mb, &mc);
    }
    for (int s = 0; s < 2 && w->spin; s++) { /* spin bodies: the wheels ride in the chassis, their inertia about the axle too (spin_advance's note); their spin relative to it is the spin body's */
        dMassSetCylinderTotal(&mc, c->wheel_mass_kg, 1, w->model->wheel_r_m[s], c->wheel_w_m);
        dMassTranslate(&mc, s == WORLD_LEFT ? -c->wheel_x_m : c->wheel_x_m, c->axle_y_m, w->model->wheel_r_m[s]);
        dMassAdd(mb, &mc);
    }
    for (int k = 0; k < 3; k++) com[k] = mb->c[k];
    dMassTranslate(mb, -com[0], -com[1], -com[2]);
}

/* A skid: a sphere on the chassis at y_m along it, touching the floor. */
static dGeomID caster_geom(world_t *w, double y_m)
{
    double r = w->model->chassis.caster_r_m;
    dGeomID g = dCreateSphere(w->robot, r);
    dGeomSetBody(g, w->chassis);
    dGeomSetOffsetPosition(g, 0 - w->com[0], y_m - w->com[1], r - w->com[2]);
    dGeomSetCategoryBits(g, CAT_ROBOT);
    dGeomSetCollideBits(g, CAT_STATIC | CAT_FLOOR);
    return g;
}

/* Loose part k (the box or a wheel side) put where it stands on the
 * chassis. A loose part is a geom of no body, so that ODE's step does not
 * move it with the chassis each step: the box meets only walls and, with
 * the nose down, the floor; a wheel side only walls (world_step puts them
 * in place only where those may be near: clear_of_walls, box_floor). The
 * same arithmetic as ODE's for a geom offset on a body (position R p + c,
 * rotation R R_offset, each sum in ODE's order), so it stands exactly where
 * that geom would. */
static void place_part(world_t *w, int k)
{
    const dReal *R = dBodyGetRotation(w->chassis);
    const double *o = w->loose_rot[k], *at = w->loose_at[k];
    dVector3 p;
    dMatrix3 rot;
    dBodyGetRelPointPos(w->chassis, at[0], at[1], at[2], p);
    for (int i = 0; i < 3; i++) {
        for (int j = 0; j < 3; j++) rot[4 * i + j] = o[j] * R[4 * i] + o[4 + j] * R[4 * i + 1] + o[8 + j] * R[4 * i + 2];
        rot[4 * i + 3] = 0;
    }
    dGeomSetPosition(w->loose[k], p[0], p[1], p[2]);
    dGeomSetRotation(w->loose[k], rot);
}

/* Geom g made loose part number nloose, at at_m (the chassis' frame from
 * its centre of mass) turned by rot (NULL: not turned), and put in place. */
static void loosen(world_t *w, dGeomID g, const double at_m[3], const dReal *rot)
{
    int k = w->nloose++;
    w->loose[k] = g;
    for (int i = 0; i < 3; i++) w->loose_at[k][i] = at_m[i];
    if (rot) {
        for (int i = 0; i < 12; i++) w->loose_rot[k][i] = rot[i];
    } else {
        dRSetIdentity(w->loose_rot[k]);
    }
    place_part(w, k);
}

/* The chassis: one body at the combined centre of mass, the body box and
 * the casters as its geoms, offset from it. */
static void build_chassis(world_t *w, double x, double y, double heading)
{
    const sim_chassis_t *c = &w->model->chassis;
    double box_z = c->body_clearance_m + c->body_h_m / 2, com_w[3];
    dMass mb;
    dMatrix3 rot;
    chassis_mass(w, &mb, w->com);
    frame_point(x, y, heading, w->com, com_w);
    dRFromAxisAndAngle(rot, 0, 0, 1, heading - M_PI / 2);
    w->chassis = dBodyCreate(w->world);
    dBodySetMass(w->chassis, &mb);
    dBodySetPosition(w->chassis, com_w[0], com_w[1], com_w[2]);
    dBodySetRotation(w->chassis, rot);
    w->box_offset[0] = 0 - w->com[0];
    w->box_offset[1] = 0 - w->com[1];
    w->box_offset[2] = box_z - w->com[2];
    w->reach_m = 0.5 * hypot(c->body_w_m, c->body_l_m) + fabs(w->com[1]);

    w->box = dCreateBox(w->robot, c->body_w_m, c->body_l_m, c->body_h_m);
    dGeomSetCategoryBits(w->box, CAT_ROBOT);
    dGeomSetCollideBits(w->box, CAT_STATIC | CAT_FLOOR);
    if (w->spin) {
        loosen(w, w->box, w->box_offset, NULL);
    } else {
        dGeomSetBody(w->box, w->chassis);
        dGeomSetOffsetPosition(w->box, w->box_offset[0], w->box_offset[1], w->box_offset[2]);
    }
    w->caster = caster_geom(w, c->caster_y_m[0]);
    w->caster2 = w->model->casters > 1 ? caster_geom(w, c->caster_y_m[1]) : NULL;
}

/* Where wheel s's centre is in the chassis frame (its own radius above
 * the floor). */
static void wheel_point(const world_t *w, int s, double p[3])
{
    const sim_chassis_t *c = &w->model->chassis;
    p[0] = s == WORLD_LEFT ? -c->wheel_x_m : c->wheel_x_m;
    p[1] = c->axle_y_m;
    p[2] = w->model->wheel_r_m[s];
}

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
    loosen(w, w->wheel_side[s], side_at, axle);
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

/* A torque t_nm about body b's own x axis (its rotation's first column):
 * dBodyAddRelTorque(b, t_nm, 0, 0) without the products by zero. */
static void axle_torque(dBodyID b, double t_nm)
{
    const dReal *R = dBodyGetRotation(b);
    dBodyAddTorque(b, R[0] * t_nm, R[4] * t_nm, R[8] * t_nm);
}

/* Wheel s's spin body on the wheel's centre with the chassis' orientation,
 * spinning at rate_rad_s about the axle, its other freedoms at rest. */
static void spin_place(world_t *w, int s, double rate_rad_s)
{
    double wp[3];
    dVector3 at;
    const dReal *x = dBodyGetRotation(w->chassis); /* its x axis: x[0], x[4], x[8] */
    wheel_point(w, s, wp);
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
    axle_torque(w->wheel[s], t_nm);
}

/* Wheel s's spin rate relative to the chassis, rad/s, + forward (either form). */
static double wheel_rate(const world_t *w, int s) { return w->spin ? spin_rate(w, s) : dJointGetHingeAngleRate(w->hinge[s]); }

/* A torque t_nm between the chassis and wheel s about its axle, + turns the wheel forward (either form). */
static void wheel_torque(world_t *w, int s, double t_nm)
{
    if (w->spin) spin_torque(w, s, t_nm);
    else dJointAddHingeTorque(w->hinge[s], t_nm); /* +T on body1 (chassis), -T on body2 (wheel) */
}

/* An angular motor's parameter set to v only where it differs from *was,
 * what it was last set to (ODE keeps a parameter as set, so setting the
 * same value again changes nothing): most steps change only the motor's
 * target speed. A motor of no limits with no force (dParamFMax 0) gives
 * the solver no row: it is disabled then, so that ODE's step passes it by
 * (enabled again with a force). */
static void amotor_param(dJointID j, int param, double v, double *was)
{
    if (*was == v) return;
    *was = v;
    dJointSetAMotorParam(j, param, v);
    if (param == dParamFMax && v > 0) dJointEnable(j);
    else if (param == dParamFMax) dJointDisable(j);
}

/* Wheel s's motor row: toward vel_rad_s with at most fmax_nm, softness cfm (either form). */
static void motor_row(world_t *w, int s, double vel_rad_s, double fmax_nm, double cfm)
{
    if (w->spin) {
        amotor_param(w->motor[s], dParamVel, vel_rad_s, &w->motor_set[s][0]);
        amotor_param(w->motor[s], dParamFMax, fmax_nm, &w->motor_set[s][1]);
        amotor_param(w->motor[s], dParamCFM, cfm, &w->motor_set[s][2]);
    } else {
        dJointSetHingeParam(w->hinge[s], dParamVel, vel_rad_s);
        dJointSetHingeParam(w->hinge[s], dParamFMax, fmax_nm);
        dJointSetHingeParam(w->hinge[s], dParamCFM, cfm);
    }
}

/* parts_box: the box in the chassis' frame that holds every part, each
 * part taken as the box ODE bounds it by (a sphere's cube, a box, a
 * cylinder's box of 2r x 2r x its length), turned by the part's offset
 * rotation. 0 when a part rides on another body or is of another shape. */
static int parts_box(world_t *w)
{
    for (int k = 0; k < 3; k++) w->parts_box[0][k] = INFINITY, w->parts_box[1][k] = -INFINITY;
    for (int i = 0; i < w->nparts; i++) {
        dGeomID g = w->part[i];
        double half[3];
        int loose = -1;
        for (int k = 0; k < w->nloose; k++)
            if (g == w->loose[k]) loose = k;
        if (loose < 0 && dGeomGetBody(g) != w->chassis) return 0;
        if (dGeomGetClass(g) == dSphereClass) {
            half[0] = half[1] = half[2] = dGeomSphereGetRadius(g);
        } else if (dGeomGetClass(g) == dBoxClass) {
            dVector3 len;
            dGeomBoxGetLengths(g, len);
            for (int k = 0; k < 3; k++) half[k] = len[k] / 2;
        } else if (dGeomGetClass(g) == dCylinderClass) {
            dReal r, len;
            dGeomCylinderGetParams(g, &r, &len);
            half[0] = half[1] = r, half[2] = len / 2; /* its axis along its z */
        } else {
            return 0;
        }
        const dReal *o = loose >= 0 ? w->loose_at[loose] : dGeomGetOffsetPosition(g), *R = loose >= 0 ? w->loose_rot[loose] : dGeomGetOffsetRotation(g);
        for (int k = 0; k < 3; k++) {
            double e = fabs(R[4 * k]) * half[0] + fabs(R[4 * k + 1]) * half[1] + fabs(R[4 * k + 2]) * half[2];
            w->parts_box[0][k] = fmin(w->parts_box[0][k], o[k] - e);
            w->parts_box[1][k] = fmax(w->parts_box[1][k], o[k] + e);
        }
    }
    return 1;
}

/* The bounds on the floor (min x, max x, min y, max y, m) of the chassis'
 * parts_box as it stands, grown by e_m: they hold every part's bounds as
 * ODE computes them (the bounds of a turned box hold those of any box it
 * holds). */
static void parts_bounds(const world_t *w, double e_m, double r[4])
{
    const dReal *p = dBodyGetPosition(w->chassis), *R = dBodyGetRotation(w->chassis);
    double mid[3], half[3];
    for (int k = 0; k < 3; k++) mid[k] = (w->parts_box[0][k] + w->parts_box[1][k]) / 2, half[k] = (w->parts_box[1][k] - w->parts_box[0][k]) / 2;
    for (int i = 0; i < 2; i++) {
        const dReal *row = R + 4 * i;
        double c = p[i] + row[0] * mid[0] + row[1] * mid[1] + row[2] * mid[2];
        double ext = fabs(row[0]) * half[0] + fabs(row[1]) * half[1] + fabs(row[2]) * half[2] + e_m;
        r[2 * i] = c - ext;
        r[2 * i + 1] = c + ext;
    }
}

/* The robot for a body centre at (x, y) facing heading: the chassis, then
 * each wheel: on its hinge, or its geoms on the chassis, its spin body and
 * rows. */
static void build_robot(world_t *w, double x, double y, double heading)
{
    build_chassis(w, x, y, heading);
    for (int s = 0; s < 2; s++) {
        double wp[3], ww[3];
        wheel_point(w, s, wp);
        if (w->spin) {
            wheel_geoms(w, s, wp);
            wheel_body(w, s);
            spin_place(w, s, 0);
            wheel_joints(w, s);
            continue;
        }
        frame_point(x, y, heading, wp, ww);
        hinge_wheel_body(w, s, ww, heading);
        hinge_wheel_geoms(w, s);
        hinge_wheel_joints(w, s, ww);
    }
    int n = dSpaceGetNumGeoms(w->robot);
    w->nparts = n < WORLD_PARTS ? n : WORLD_PARTS; /* 7 at most: always all of them */
    for (int i = 0; i < w->nparts; i++) w->part[i] = dSpaceGetGeom(w->robot, i);
    w->parts_boxed = parts_box(w);
}

/* ODE's messages (not its errors): "LCP internal error, s <= 0" when the
 * exact solver meets a degenerate pivot, which it then steps past. They come
 * only from configs at their ranges' extremes (a 0.06 ohm motor: a damper row
 * of 1e4 N*m*s), never from the default robot; the run is checked by
 * world_sane instead of by text on stderr. */
static void ode_message(int num, const char *msg, va_list ap)
{
    (void)num;
    (void)msg;
    (void)ap;
}

world_t *world_create(const sim_model_t *model, const maze_t *m, double x_m, double y_m, double heading_rad)
{
    if (!ode_ready) {
        dSetMessageHandler(ode_message);
        if (!dInitODE2(0)) return NULL;
        ode_ready = 1;
    }
    world_t *w = calloc(1, sizeof *w);
    if (!w) return NULL;
    /* quickstep shuffles constraints with ODE's global PRNG: reseed it so
     * every world steps the same way, whatever ran before it */
    dRandSetSeed(1);
    const simcfg_world_t *c = &model->arena;
    w->model = model;
    w->spin = model->wheels == SIM_WHEELS_SPIN;
    w->world = dWorldCreate();
    dWorldSetGravity(w->world, 0, 0, -9.81);
    dWorldSetQuickStepNumIterations(w->world, model->solver_iterations);
    dWorldSetCFM(w->world, 1e-6); /* joints (hinges): near rigid */
    dWorldSetERP(w->world, 0.4);  /* joint drift corrected in ~2 steps */
    w->top = dSimpleSpaceCreate(0);
    double wx = m->width * c->cell_m, wy = m->height * c->cell_m, ext = fmax(wx, wy) + 0.1;
    dVector3 centre = { wx / 2, wy / 2, 0, 0 }, extents = { ext, ext, ext, 0 };
    w->statics = dQuadTreeSpaceCreate(w->top, centre, extents, 5);
    dGeomSetCategoryBits((dGeomID)w->statics, CAT_STATIC);
    dGeomSetCollideBits((dGeomID)w->statics, CAT_ROBOT | CAT_RAY | CAT_WHEEL_SIDE);
    w->robot = dSimpleSpaceCreate(w->top);
    dGeomSetCategoryBits((dGeomID)w->robot, CAT_ROBOT | CAT_TYRE | CAT_WHEEL_SIDE);
    dGeomSetCollideBits((dGeomID)w->robot, CAT_STATIC | CAT_FLOOR);
    w->floor = dCreatePlane(w->top, 0, 0, 1, 0);
    dGeomSetCategoryBits(w->floor, CAT_FLOOR);
    dGeomSetCollideBits(w->floor, CAT_ROBOT | CAT_TYRE);
    w->contacts = dJointGroupCreate(0);
    if (build_maze(w, m) != 0 || maze_order(w) != 0) {
        world_destroy(w);
        return NULL;
    }
    dReal floor_aabb[6];
    dGeomGetAABB(w->floor, floor_aabb);
    w->floor_top_m = floor_aabb[5];
    build_robot(w, x_m, y_m, heading_rad);
    for (int s = 0; s < 2; s++) {
        w->friction_set[s] = NAN;
        for (int k = 0; k < 3; k++) w->motor_set[s][k] = NAN;
    }
    w->ray = dCreateRay(0, 1.0);
    dGeomSetCategoryBits(w->ray, CAT_RAY);
    dGeomSetCollideBits(w->ray, CAT_STATIC);
    dGeomRaySetClosestHit(w->ray, 1);
    if (!c->centre_post) world_set_centre_post(w, 0);
    return w;
}

void world_destroy(world_t *w)
{
    if (!w) return;
    if (w->ray) dGeomDestroy(w->ray);
    wallgrid_free(w->grid);
    free(w->wall);
    free(w->wall_bounds);
    free(w->wall_aabb);
    free(w->wall_rank);
    free(w->near_ids);
    dJointGroupDestroy(w->contacts);
    dSpaceDestroy(w->top); /* and every geom in it */
    dWorldDestroy(w->world);
    free(w);
}

static int is_robot_part(const world_t *w, dGeomID g)
{
    return g == w->box || g == w->caster || (w->caster2 && g == w->caster2) || g == w->wheel_geom[0] || g == w->wheel_geom[1] || g == w->wheel_side[0] ||
           g == w->wheel_side[1];
}

/* Which part of the robot touches a wall at world point p: its body's
 * front or rear face (the rear gently, below WORLD_REAR_SOFT_M_S, or not),
 * else its side (the wheels' sides too). */
static unsigned contact_kind(const world_t *w, dGeomID a, const dReal *p)
{
    if (a != w->box) return a == w->caster || a == w->caster2 ? 1u << WORLD_CONTACT_FRONT : 1u << WORLD_CONTACT_SIDE;
    dVector3 q;
    dBodyGetPosRelPoint(w->chassis, p[0], p[1], p[2], q);
    double y = q[1] + w->com[1], half = w->model->chassis.body_l_m / 2, edge = 0.002; /* m */
    if (y > half - edge) return 1u << WORLD_CONTACT_FRONT;
    if (y >= -half + edge) return 1u << WORLD_CONTACT_SIDE;
    double v, om;
    world_velocity(w, &v, &om);
    return fabs(v) < WORLD_REAR_SOFT_M_S ? 1u << WORLD_CONTACT_REAR_SOFT : 1u << WORLD_CONTACT_REAR;
}

/* The body as the oriented box it is, not its bounds (a turning body's grow
 * by 40 %): whether it comes within margin_m of a wall or post. */
static int body_near(const world_t *w, double margin_m)
{
    const dReal *p = dGeomGetPosition(w->box), *R = dGeomGetRotation(w->box);
    dVector3 len;
    dGeomBoxGetLengths(w->box, len);
    const double c[3] = { p[0], p[1], p[2] }, half[3] = { len[0] / 2, len[1] / 2, len[2] / 2 };
    const double axis[3][3] = { { R[0], R[4], R[8] }, { R[1], R[5], R[9] }, { R[2], R[6], R[10] } };
    return wallgrid_any_box(w->grid, c, axis, half, 0, w->model->arena.wall_height_m, margin_m);
}

#define WORLD_BOX_SLACK_M 1e-6 /* parts_bounds and box_floor's lowest corner allow this much more, m: beyond any rounding of ODE's own bounds */
#define WORLD_UNION_SLACK_M 1e-9 /* the parts' joint bounds grown by this too, m: beyond any rounding of the finer tests */

/* Whether every part of the robot is more than margin_m from every wall
 * and post (wallgrid): first all the parts' bounds at once (the robot in
 * the open: one query), then the body as its oriented box and the other
 * parts by their bounds; the tyre spheres (which meet only the floor) only
 * with tyres. A "clear" is certain, so the maze's contacts are looked for
 * only where they may be. */
static int clear_of_walls(world_t *w, double margin_m, int tyres)
{
    if (w->parts_boxed) {
        /* the robot in the open: one query, no part's bounds computed (ODE's collision pass computes them) */
        double r[4];
        parts_bounds(w, margin_m + WORLD_UNION_SLACK_M + WORLD_BOX_SLACK_M, r);
        if (!wallgrid_any(w->grid, r)) return 1;
    }
    for (int k = 0; k < w->nloose && !w->loose_placed; k++) place_part(w, k);
    w->loose_placed = 1;
    dReal aabb[WORLD_PARTS][6];
    double all[4] = { INFINITY, -INFINITY, INFINITY, -INFINITY }, e = margin_m + WORLD_UNION_SLACK_M;
    int odd = 0;
    for (int i = 0; i < w->nparts; i++) {
        if (!tyres && !(dGeomGetCollideBits(w->part[i]) & CAT_STATIC)) continue;
        const dReal *a = aabb[i];
        dGeomGetAABB(w->part[i], aabb[i]);
        odd |= !(a[0] <= a[1] && a[2] <= a[3]); /* a NaN: left to the finer tests */
        if (a[0] - e < all[0]) all[0] = a[0] - e;
        if (a[1] + e > all[1]) all[1] = a[1] + e;
        if (a[2] - e < all[2]) all[2] = a[2] - e;
        if (a[3] + e > all[3]) all[3] = a[3] + e;
    }
    if (!odd && !wallgrid_any(w->grid, all)) return 1;
    for (int i = 0; i < w->nparts; i++) {
        if (!tyres && !(dGeomGetCollideBits(w->part[i]) & CAT_STATIC)) continue;
        if (w->part[i] == w->box) {
            if (body_near(w, margin_m)) return 0;
            continue;
        }
        const dReal *a = aabb[i];
        const double r[4] = { a[0] - margin_m, a[1] + margin_m, a[2] - margin_m, a[3] + margin_m };
        if (wallgrid_any(w->grid, r)) return 0;
    }
    return 1;
}

/* A contact's spring and damper (the robot part a, on a wall or the floor;
 * one of the pair's n contact points, each taking its share) as ODE's ERP
 * and CFM for the step in progress: ODE solves the contact
 * implicitly as a force kp*depth + kd*speed when ERP = h*kp/(h*kp + kd) and
 * CFM = 1/(h*kp + kd) (the ODE manual, "soft constraint and constraint
 * force mixing"), so the N/m and N*s/m hold at every step. */
static void soft_contact(const world_t *w, dGeomID a, int wall, int n, dContact *c)
{
    const simcfg_world_t *k = &w->model->arena;
    double kp = k->wall_kp_n_m, kd = k->wall_kd_n_s_m, h = w->h_s;
    if (!wall && (a == w->wheel_geom[0] || a == w->wheel_geom[1])) kp = k->tyre_kp_n_m, kd = k->tyre_kd_n_s_m;
    else if (!wall && (a == w->caster || a == w->caster2)) kp = k->caster_kp_n_m, kd = k->caster_kd_n_s_m;
    kp /= n, kd /= n;
    c->surface.soft_erp = h * kp / (h * kp + kd);
    c->surface.soft_cfm = 1.0 / (h * kp + kd);
}

static void near_cb(void *data, dGeomID a, dGeomID b);

/* The pairs ODE's dSpaceCollide2 of the robot's space and the maze's tree
 * would make, from the cells instead of the tree: for each robot part in
 * its space's order, the enabled boxes whose bounds meet the part's (ODE's
 * own bounds and its test, category bits as ODE pairs them: the tyre
 * spheres meet none), in the tree's order (maze_order). */
static void maze_collide(world_t *w)
{
    for (int i = 0; i < w->nparts; i++) {
        dGeomID g = w->part[i];
        if (!dGeomIsEnabled(g) || !((dGeomGetCategoryBits(g) & (CAT_ROBOT | CAT_RAY | CAT_WHEEL_SIDE)) || (dGeomGetCollideBits(g) & CAT_STATIC))) continue;
        dReal a[6];
        dGeomGetAABB(g, a);
        const double r[4] = { a[0], a[1], a[2], a[3] };
        int *id = w->near_ids, n = wallgrid_boxes(w->grid, r, id), m = 0;
        for (int k = 0; k < n; k++) {
            const double *b = w->wall_aabb[id[k]];
            if (!dGeomIsEnabled(w->wall[id[k]]) || a[0] > b[1] || a[1] < b[0] || a[2] > b[3] || a[3] < b[2] || a[4] > b[5] || a[5] < b[4]) continue;
            int v = id[k], j = m++;
            for (; j > 0 && w->wall_rank[id[j - 1]] > w->wall_rank[v]; j--) id[j] = id[j - 1];
            id[j] = v;
        }
        for (int k = 0; k < m; k++) near_cb(w, g, w->wall[id[k]]);
    }
}

static void near_cb(void *data, dGeomID a, dGeomID b)
{
    world_t *w = data;
    if (dGeomIsSpace(a) || dGeomIsSpace(b)) {
        int maze = a == (dGeomID)w->statics || b == (dGeomID)w->statics;
        if (!maze) dSpaceCollide2(a, b, data, near_cb);
        /* clear_now: world_step's finding just before this pass, the same state */
        else if (!w->clear_now) {
            /* ODE walks the smaller space's geoms against the other: the robot's, unless the maze has fewer boxes */
            if (w->ranked && w->nwalls > w->nparts) maze_collide(w);
            else dSpaceCollide2(a, b, data, near_cb);
        }
        return;
    }
    if (is_robot_part(w, b)) { dGeomID t = a; a = b; b = t; }
    if (!is_robot_part(w, a) || is_robot_part(w, b)) return;
    dContact c[MAX_CONTACTS];
    int n = dCollide(a, b, MAX_CONTACTS, &c[0].geom, sizeof(dContact));
    if (n <= 0) return;
    int wall = b != w->floor;
    if (wall) {
        w->touching = 1;
        w->step_kinds |= contact_kind(w, a, c[0].geom.pos);
        for (int i = 0; i < n; i++) w->wall_depth_m = fmax(w->wall_depth_m, c[i].geom.depth);
    }
    for (int i = 0; i < n; i++) {
        double mu = w->model->arena.body_wall_mu;
        if (a == w->caster || a == w->caster2) {
            mu = w->model->chassis.skid_mu; /* a skid slides: Coulomb friction */
        } else if (!wall && (a == w->wheel_geom[0] || a == w->wheel_geom[1])) {
            int side = a == w->wheel_geom[WORLD_LEFT] ? WORLD_LEFT : WORLD_RIGHT;
            dVector3 v, vs = { 0, 0, 0, 0 }; /* the tyre's point; with spin bodies the chassis' motion less the spin body's (below) */
            dBodyGetPointVel(dGeomGetBody(a), c[i].geom.pos[0], c[i].geom.pos[1], c[i].geom.pos[2], v);
            if (w->spin) dBodyGetPointVel(w->wheel[side], c[i].geom.pos[0], c[i].geom.pos[1], c[i].geom.pos[2], vs);
            double slip = hypot(v[0] - vs[0], v[1] - vs[1]);
            mu = slip > w->model->chassis.tyre_slip_m_s ? w->model->tyre_mu_dynamic[side] : w->model->tyre_mu[side];
        }
        c[i].surface.mode = dContactApprox1 | dContactSoftERP | dContactSoftCFM;
        if (!wall && (a == w->wheel_geom[0] || a == w->wheel_geom[1])) {
            /* align the friction pyramid with the wheel (rolling and
             * sideways), or its corners would make driving east and north
             * differ */
            const dReal *R = dBodyGetRotation(w->chassis); /* its y axis: R[1], R[5], R[9] */
            c[i].surface.mode |= dContactFDir1;
            c[i].fdir1[0] = R[1];
            c[i].fdir1[1] = R[5];
            c[i].fdir1[2] = 0;
        }
        c[i].surface.mu = mu;
        soft_contact(w, a, wall, n, &c[i]);
        dJointID j = dJointCreateContact(w->world, w->contacts, &c[i]);
        /* with spin bodies, a wheel's contact holds the chassis against its spin body
         * as its second body: the relative speed at the point is the
         * chassis' there less the spin's rim speed, the wheel's own, and
         * the contact's torque turns the spin (the spin body's linear
         * freedoms, too heavy to move, stand in for the floor or wall) */
        int ws = !w->spin ? -1 : a == w->wheel_geom[0] || a == w->wheel_side[0] ? 0 : a == w->wheel_geom[1] || a == w->wheel_side[1] ? 1 : -1;
        dBodyID b1 = dGeomGetBody(c[i].geom.g1); /* a loose part has none: it stands on the chassis (place_part) */
        dJointAttach(j, b1 ? b1 : w->chassis, ws >= 0 ? w->wheel[ws] : dGeomGetBody(c[i].geom.g2));
    }
}

/* A wheel's drive for the step: the constant torque explicitly; the part
 * that falls with the wheel's speed as the motor row, a damper toward
 * t0/D with damping D (ODE solves J*v = vel - cfm*lambda, so
 * lambda = (vel - v)/cfm: cfm = 1/D), implicit in the end speed; the
 * gearbox's friction as a motor held at speed 0 with at most that torque. */
static void drive_wheel(world_t *w, int s, const motor_drive_t *d)
{
    if (d->damping_nm_s > 0) {
        /* unbounded: the damper's torque is what it is, and the LCP solves it directly */
        motor_row(w, s, d->t0_nm / d->damping_nm_s, dInfinity, 1.0 / d->damping_nm_s);
    } else {
        if (w->spin) amotor_param(w->motor[s], dParamFMax, 0, &w->motor_set[s][1]);
        else dJointSetHingeParam(w->hinge[s], dParamFMax, 0);
        wheel_torque(w, s, d->t0_nm);
    }
    /* Moving, the friction is a torque against the motion: one step of it
     * cannot reverse a wheel turning faster than f*h/J (0.09 rad/s for the
     * default robot), so above WORLD_STICTION_RAD_S it is applied as such and
     * the solver has a row fewer. */
    double w_rad_s = wheel_rate(w, s);
    if (fabs(w_rad_s) > WORLD_STICTION_RAD_S) {
        amotor_param(w->friction[s], dParamFMax, 0, &w->friction_set[s]);
        wheel_torque(w, s, w_rad_s > 0 ? -d->friction_nm : d->friction_nm);
    } else {
        amotor_param(w->friction[s], dParamFMax, d->friction_nm, &w->friction_set[s]);
    }
    if (w->spin) {
        axle_torque(w->chassis, w->reaction_nm[s]);
        axle_torque(w->wheel[s], w->wheel_j[s] * w->pitch_acc);
    }
}

/* A contact episode over: counted once for each kind it had. */
static void end_episode(world_t *w)
{
    for (int k = 0; k < WORLD_CONTACT_KINDS; k++)
        if (w->episode_kinds & (1u << k)) w->kind_count[k]++;
    w->episode_kinds = 0;
}

void world_brake(world_t *w, double load_nm) { w->brake_nm = load_nm; }

/* world_brake's load against each wheel's motion, for one ODE step. */
static void brake_wheels(world_t *w)
{
    for (int s = 0; s < 2 && w->brake_nm != 0; s++) {
        double rate = wheel_rate(w, s);
        if (rate != 0) wheel_torque(w, s, rate > 0 ? -w->brake_nm : w->brake_nm); /* +T turns the wheel forward */
    }
}

/* A loose box put in place before the collision pass wherever its bounds
 * may reach the floor's (its lowest corner, by the chassis' pose, within
 * WORLD_BOX_SLACK_M of the floor's top), and once more after it was last
 * put there (its old bounds would still meet the floor's): elsewhere ODE's
 * pass finds it clear of the floor by its bounds, placed or not. */
static void box_floor(world_t *w)
{
    const dReal *p = dBodyGetPosition(w->chassis), *R = dBodyGetRotation(w->chassis);
    const double *o = w->box_offset;
    dVector3 len;
    dGeomBoxGetLengths(w->box, len);
    double low = p[2] + R[8] * o[0] + R[9] * o[1] + R[10] * o[2] - (fabs(R[8]) * len[0] + fabs(R[9]) * len[1] + fabs(R[10]) * len[2]) / 2;
    int near = !(low - WORLD_BOX_SLACK_M > w->floor_top_m); /* a NaN too */
    if ((near || w->box_low) && !w->loose_placed) place_part(w, 0);
    w->box_low = near;
}

/* How many ODE steps make this step: one in the open or at rest; moving
 * near a wall (within a step's travel of its fastest point) as many as keep
 * each at most WORLD_CONTACT_STEP_S, so a wall is met at most that much
 * travel late and its spring is integrated alike at every step. */
static int sub_steps(world_t *w, double h_s)
{
    if (h_s <= WORLD_CONTACT_STEP_S) return 1;
    const dReal *v = dBodyGetLinearVel(w->chassis), *om = dBodyGetAngularVel(w->chassis);
    double fastest = hypot(v[0], v[1]) + fabs(om[2]) * w->reach_m;
    if (fastest < WORLD_IMPACT_M_S) return 1;
    w->clear_now = clear_of_walls(w, fastest * h_s + WORLD_NEAR_M, 1);
    if (w->clear_now) return 1;
    return (int)ceil(h_s / WORLD_CONTACT_STEP_S - 1e-9);
}

/* The chassis' rate about its axle (its x), rad/s, + nose up. */
static double chassis_pitch_rate(const world_t *w)
{
    const dReal *om = dBodyGetAngularVel(w->chassis), *R = dBodyGetRotation(w->chassis);
    return om[0] * R[0] + om[1] * R[4] + om[2] * R[8];
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
    w->pitch_acc = (chassis_pitch_rate(w) - w->pitch_before) / w->h_s;
    for (int s = 0; s < 2; s++) {
        double rate = spin_rate(w, s);
        w->wheel_angle[s] = wrap_angle(w->wheel_angle[s] + rate * w->h_s);
        w->reaction_nm[s] = w->wheel_j[s] * (rate - w->spin_before[s]) / w->h_s;
    }
}

void world_step(world_t *w, const motor_drive_t drive[2])
{
    double h = w->model->step_s;
    w->loose_placed = 0; /* the chassis may have been moved since (world_place) */
    int n = sub_steps(w, h);
    w->touching = 0;
    w->step_kinds = 0;
    w->wall_depth_m = 0;
    w->h_s = h / n;
    for (int i = 0; i < n; i++) {
        for (int s = 0; s < 2 && w->spin; s++) {
            w->spin_before[s] = spin_rate(w, s);
            spin_place(w, s, w->spin_before[s]);
        }
        if (w->spin) w->pitch_before = chassis_pitch_rate(w);
        /* ODE clears the added torques after each of its steps */
        drive_wheel(w, WORLD_LEFT, &drive[WORLD_LEFT]);
        drive_wheel(w, WORLD_RIGHT, &drive[WORLD_RIGHT]);
        brake_wheels(w);
        /* before the collision pass, which may not move a geom (place_part) */
        if (!w->clear_now) w->clear_now = clear_of_walls(w, WORLD_TOUCH_SLACK_M, 0);
        if (w->nloose) box_floor(w);
        dSpaceCollide(w->top, w, near_cb);
        if (w->model->solver == SIM_SOLVER_EXACT) dWorldStep(w->world, w->h_s);
        else dWorldQuickStep(w->world, w->h_s);
        w->clear_now = w->loose_placed = 0;
        dJointGroupEmpty(w->contacts);
        if (w->spin) spin_advance(w);
    }
    w->brake_nm = 0;
    if (w->touching && !w->touched_last) w->collisions++;
    if (w->touching) w->episode_kinds |= w->step_kinds;
    else if (w->touched_last) end_episode(w);
    w->touched_last = w->touching;
}

double world_wall_depth(const world_t *w) { return w->wall_depth_m; }

unsigned world_contacts(const world_t *w, int kind)
{
    return w->kind_count[kind] + (w->touched_last && (w->episode_kinds & (1u << kind)) ? 1 : 0);
}

void world_dyno(world_t *w, double rate_rad_s)
{
    for (int s = 0; s < 2; s++) {
        dJointID j = w->spin ? spin_row(w, s) : dJointCreateAMotor(w->world, 0);
        if (!w->spin) {
            dJointAttach(j, w->chassis, w->wheel[s]);
            dJointSetAMotorNumAxes(j, 1);
            dJointSetAMotorAxis(j, 0, 1, 1, 0, 0);
        }
        /* its row holds the wheel's rate at vel ((w_chassis - w_wheel) . axis on a hinge) */
        dJointSetAMotorParam(j, dParamVel, rate_rad_s);
        dJointSetAMotorParam(j, dParamFMax, dInfinity);
    }
}

/* The chassis and wheels raised WORLD_CARRY_M and the chassis fixed to the world there. */
static void hold_up(world_t *w)
{
    const dReal *p = dBodyGetPosition(w->chassis);
    dBodySetPosition(w->chassis, p[0], p[1], p[2] + WORLD_CARRY_M);
    for (int s = 0; s < 2; s++) {
        if (w->spin) {
            spin_place(w, s, spin_rate(w, s));
            continue;
        }
        const dReal *q = dBodyGetPosition(w->wheel[s]);
        dBodySetPosition(w->wheel[s], q[0], q[1], q[2] + WORLD_CARRY_M);
    }
    w->lift = dJointCreateFixed(w->world, 0);
    dJointAttach(w->lift, w->chassis, 0);
    dJointSetFixed(w->lift);
}

void world_lift(world_t *w, int lock_wheels)
{
    hold_up(w);
    for (int s = 0; s < 2 && lock_wheels; s++) {
        if (w->spin) {
            w->lock[s] = spin_row(w, s); /* held at spin 0 */
            dJointSetAMotorParam(w->lock[s], dParamVel, 0);
            dJointSetAMotorParam(w->lock[s], dParamFMax, dInfinity);
            continue;
        }
        w->lock[s] = dJointCreateFixed(w->world, 0);
        dJointAttach(w->lock[s], w->chassis, w->wheel[s]);
        dJointSetFixed(w->lock[s]);
    }
}

void world_carry(world_t *w, int on)
{
    if (on == w->carried) return;
    if (on) {
        world_hand(w, 0, 0, 0);
        world_pose(w, &w->carry_pose[0], &w->carry_pose[1], &w->carry_pose[2]);
        hold_up(w);
    } else {
        dJointDestroy(w->lift);
        w->lift = 0;
        world_place(w, w->carry_pose[0], w->carry_pose[1], w->carry_pose[2], NULL);
    }
    w->carried = on;
}

int world_carried(const world_t *w) { return w->carried; }

/* The hand's grip: a linear motor on the chassis' centre of mass along the
 * world's x and y (its height free: it rests on its wheels) and an angular
 * motor about the world's z, each against the world. */
static void hand_make(world_t *w)
{
    w->hand_lin = dJointCreateLMotor(w->world, 0);
    dJointAttach(w->hand_lin, w->chassis, 0);
    dJointSetLMotorNumAxes(w->hand_lin, 2);
    dJointSetLMotorAxis(w->hand_lin, 0, 0, 1, 0, 0); /* rel 0: the world's axes */
    dJointSetLMotorAxis(w->hand_lin, 1, 0, 0, 1, 0);
    w->hand_yaw = dJointCreateAMotor(w->world, 0);
    dJointAttach(w->hand_yaw, w->chassis, 0);
    dJointSetAMotorNumAxes(w->hand_yaw, 1);
    dJointSetAMotorAxis(w->hand_yaw, 0, 0, 0, 0, 1);
}

void world_hand(world_t *w, int on, double v_m_s, double omega_rad_s)
{
    if (!w->hand_lin && !on) return;
    if (!w->hand_lin) hand_make(w);
    double f_n = on ? WORLD_HAND_FORCE_N : 0, t_nm = on ? WORLD_HAND_TORQUE_NM : 0;
    dVector3 fwd, axle;
    double r_w = (w->model->wheel_r_m[0] + w->model->wheel_r_m[1]) / 2;
    dBodyVectorToWorld(w->chassis, 0, 1, 0, fwd);
    /* the axle's middle, from the centre of mass (the body's origin) */
    dBodyGetRelPointPos(w->chassis, -w->com[0], w->model->chassis.axle_y_m - w->com[1], r_w - w->com[2], axle);
    const dReal *c = dBodyGetPosition(w->chassis);
    double n = hypot(fwd[0], fwd[1]), rx = c[0] - axle[0], ry = c[1] - axle[1];
    /* the centre of mass's velocity when the axle's middle goes v_m_s ahead and the chassis turns omega_rad_s */
    dJointSetLMotorParam(w->hand_lin, dParamVel, v_m_s * fwd[0] / n - omega_rad_s * ry);
    dJointSetLMotorParam(w->hand_lin, dParamVel2, v_m_s * fwd[1] / n + omega_rad_s * rx);
    dJointSetLMotorParam(w->hand_lin, dParamFMax, f_n);
    dJointSetLMotorParam(w->hand_lin, dParamFMax2, f_n);
    dJointSetAMotorParam(w->hand_yaw, dParamVel, omega_rad_s);
    dJointSetAMotorParam(w->hand_yaw, dParamFMax, t_nm);
}

void world_pose(const world_t *w, double *x_m, double *y_m, double *heading_rad)
{
    dVector3 p, f;
    dBodyGetRelPointPos(w->chassis, w->box_offset[0], w->box_offset[1], w->box_offset[2], p);
    dBodyVectorToWorld(w->chassis, 0, 1, 0, f);
    *x_m = p[0];
    *y_m = p[1];
    *heading_rad = atan2(f[1], f[0]);
}

void world_velocity(const world_t *w, double *v_m_s, double *omega_rad_s)
{
    const dReal *lv = dBodyGetLinearVel(w->chassis), *av = dBodyGetAngularVel(w->chassis);
    dVector3 f;
    dBodyVectorToWorld(w->chassis, 0, 1, 0, f);
    *v_m_s = lv[0] * f[0] + lv[1] * f[1];
    *omega_rad_s = av[2];
}

double world_body_z(const world_t *w)
{
    dVector3 p;
    dBodyGetRelPointPos(w->chassis, w->box_offset[0], w->box_offset[1], w->box_offset[2], p);
    return p[2];
}

double world_wheel_floor_gap(const world_t *w, int side)
{
    return dGeomGetPosition(w->wheel_geom[side])[2] - dGeomSphereGetRadius(w->wheel_geom[side]);
}

double world_wheel_angle(const world_t *w, int side) { return w->spin ? w->wheel_angle[side] : dJointGetHingeAngle(w->hinge[side]); }
double world_wheel_rate(const world_t *w, int side) { return wheel_rate(w, side); }

/* world_ray_normal: the nearest hit of one ray and its surface normal,
 * the ray tested exactly (ODE's ray-box) against the boxes along its path
 * (wallgrid). */
typedef struct {
    world_t *w;
    double best, normal[3], max_m;
} ray_hit_t;

static double ray_box(void *data, int id)
{
    ray_hit_t *h = data;
    dGeomID g = h->w->wall[id];
    dContactGeom cg;
    if (dGeomIsEnabled(g) && dCollide(h->w->ray, g, 1, &cg, sizeof cg) == 1 && (h->best < 0 || cg.depth < h->best)) {
        h->best = cg.depth;
        for (int k = 0; k < 3; k++) h->normal[k] = cg.normal[k];
    }
    return h->best < 0 ? INFINITY : h->best / h->max_m;
}

double world_ray_normal(world_t *w, const double pos_m[3], const double dir[3], double max_m, double normal[3])
{
    double n = sqrt(dir[0] * dir[0] + dir[1] * dir[1] + dir[2] * dir[2]);
    double u[3] = { dir[0] / n, dir[1] / n, dir[2] / n };
    ray_hit_t h = { w, -1, { 0, 0, 0 }, max_m };
    dGeomRaySetLength(w->ray, max_m);
    dGeomRaySet(w->ray, pos_m[0], pos_m[1], pos_m[2], u[0], u[1], u[2]);
    const double p[2] = { pos_m[0], pos_m[1] }, d[2] = { u[0] * max_m, u[1] * max_m };
    wallgrid_ray(w->grid, p, d, ray_box, &h);
    /* ODE's sign depends on the order of the pair: face the ray */
    double s = h.normal[0] * u[0] + h.normal[1] * u[1] + h.normal[2] * u[2] > 0 ? -1.0 : 1.0;
    for (int k = 0; k < 3; k++) normal[k] = s * h.normal[k];
    return h.best;
}

double world_ray(world_t *w, double x_m, double y_m, double z_m, double dir_rad, double max_m)
{
    const double pos[3] = { x_m, y_m, z_m }, dir[3] = { cos(dir_rad), sin(dir_rad), 0 };
    double normal[3];
    return world_ray_normal(w, pos, dir, max_m, normal);
}

void world_body_point(const world_t *w, const double p_m[3], double out_m[3])
{
    dVector3 q;
    /* the chassis frame's origin is the body's centre on the floor; ODE's is the centre of mass */
    dBodyGetRelPointPos(w->chassis, p_m[0] - w->com[0], p_m[1] - w->com[1], p_m[2] - w->com[2], q);
    for (int k = 0; k < 3; k++) out_m[k] = q[k];
}

void world_body_vector(const world_t *w, const double v[3], double out[3])
{
    dVector3 q;
    dBodyVectorToWorld(w->chassis, v[0], v[1], v[2], q);
    for (int k = 0; k < 3; k++) out[k] = q[k];
}

void world_place(world_t *w, double x_m, double y_m, double heading_rad, const double wheel_rad[2])
{
    dMatrix3 rot, r;
    double com_w[3], keep[2] = { world_wheel_angle(w, 0), world_wheel_angle(w, 1) };
    if (!wheel_rad) wheel_rad = keep;
    frame_point(x_m, y_m, heading_rad, w->com, com_w);
    dRFromAxisAndAngle(rot, 0, 0, 1, heading_rad - M_PI / 2);
    dBodySetPosition(w->chassis, com_w[0], com_w[1], com_w[2]);
    dBodySetRotation(w->chassis, rot);
    dBodySetLinearVel(w->chassis, 0, 0, 0);
    dBodySetAngularVel(w->chassis, 0, 0, 0);
    for (int s = 0; s < 2; s++) {
        double wp[3], ww[3];
        if (w->spin) {
            w->wheel_angle[s] = remainder(wheel_rad[s], 2 * M_PI);
            w->reaction_nm[s] = w->pitch_acc = 0; /* put down at rest: no coupling left from before */
            spin_place(w, s, 0);
            continue;
        }
        wheel_point(w, s, wp);
        frame_point(x_m, y_m, heading_rad, wp, ww);
        wheel_rotation(heading_rad, &wheel_rad[s], r);
        dBodySetPosition(w->wheel[s], ww[0], ww[1], ww[2]);
        dBodySetRotation(w->wheel[s], r);
        dBodySetLinearVel(w->wheel[s], 0, 0, 0);
        dBodySetAngularVel(w->wheel[s], 0, 0, 0);
    }
}

void world_set_speed(world_t *w, double v_m_s)
{
    dVector3 f, x;
    dBodyVectorToWorld(w->chassis, 0, 1, 0, f);
    dBodyVectorToWorld(w->chassis, 1, 0, 0, x);
    dBodySetLinearVel(w->chassis, v_m_s * f[0], v_m_s * f[1], 0);
    dBodySetAngularVel(w->chassis, 0, 0, 0);
    for (int s = 0; s < 2; s++) {
        if (w->spin) {
            spin_place(w, s, v_m_s / w->model->wheel_r_m[s]); /* rolling, + forward */
            continue;
        }
        double spin = -v_m_s / w->model->wheel_r_m[s]; /* rolling forward turns the wheel about -x */
        dBodySetLinearVel(w->wheel[s], v_m_s * f[0], v_m_s * f[1], 0);
        dBodySetAngularVel(w->wheel[s], spin * x[0], spin * x[1], spin * x[2]);
    }
}

unsigned world_collisions(const world_t *w) { return w->collisions; }

static int body_sane(dBodyID b)
{
    const dReal *p = dBodyGetPosition(b), *v = dBodyGetLinearVel(b), *a = dBodyGetAngularVel(b);
    for (int k = 0; k < 3; k++) /* written so that a NaN fails too */
        if (!(fabs(p[k]) < WORLD_SANE_M && fabs(v[k]) < WORLD_SANE_M_S && fabs(a[k]) < WORLD_SANE_RAD_S)) return 0;
    return 1;
}

int world_sane(const world_t *w)
{
    return body_sane(w->chassis) && body_sane(w->wheel[0]) && body_sane(w->wheel[1]);
}

void world_set_centre_post(world_t *w, int on)
{
    if (!w->centre_post) return;
    if (on) dGeomEnable(w->centre_post);
    else dGeomDisable(w->centre_post);
}

int world_has_centre_post(const world_t *w) { return w->centre_post && dGeomIsEnabled(w->centre_post); }

/* world.c - ODE scene and robot (see world.h). */
#include "world.h"

#include <math.h>
#include <ode/ode.h>
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

struct world {
    simcfg_t cfg;
    dWorldID world;
    dSpaceID top, statics, robot;
    dJointGroupID contacts;
    dGeomID floor, centre_post, box, caster, wheel_geom[2], wheel_side[2], ray;
    dBodyID chassis, wheel[2];
    dJointID hinge[2];
    double box_offset[3];  /* chassis box centre in the chassis body frame */
    double com[3];         /* chassis centre of mass in the robot frame (world_place) */
    double tof_pos[WORLD_TOF_COUNT][3], tof_dir[WORLD_TOF_COUNT];
    int touching, touched_last;
    unsigned collisions;
    double ray_best;
    double hinge_inertia; /* what a hinge torque turns (world_hinge_inertia), kg*m^2 */
};

static int ode_ready;

static dGeomID static_box(world_t *w, double x, double y, double lx, double ly)
{
    double h = w->cfg.wall_height_m;
    dGeomID g = dCreateBox(w->statics, lx, ly, h);
    dGeomSetPosition(g, x, y, h / 2);
    dGeomSetCategoryBits(g, CAT_STATIC);
    dGeomSetCollideBits(g, CAT_ROBOT | CAT_RAY | CAT_WHEEL_SIDE);
    return g;
}

static void build_maze(world_t *w, const maze_t *m)
{
    double cell = w->cfg.cell_m, post = w->cfg.post_m, thick = w->cfg.wall_thick_m;
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
}

/* Robot-frame point -> world point for a robot at (x, y) facing heading. */
static void frame_point(double x, double y, double heading, const double p[3], double out[3])
{
    double a = heading - M_PI / 2, ca = cos(a), sa = sin(a);
    out[0] = x + ca * p[0] - sa * p[1];
    out[1] = y + sa * p[0] + ca * p[1];
    out[2] = p[2];
}

static void build_robot(world_t *w, double x, double y, double heading)
{
    const simcfg_t *c = &w->cfg;
    double rw = c->wheel_d_m / 2;
    double box_p[3] = { 0, 0, c->body_clearance_m + c->body_h_m / 2 };
    double caster_p[3] = { 0, c->caster_y_m, c->caster_r_m };
    dMass mb, mc;
    dMatrix3 rot;

    /* chassis = box + caster sphere; ODE wants the centre of mass at the
     * body origin, so the body sits at the combined centre of mass and the
     * geoms are offset from it */
    dMassSetBoxTotal(&mb, c->body_mass_kg, c->body_w_m, c->body_l_m, c->body_h_m);
    dMassTranslate(&mb, box_p[0], box_p[1], box_p[2]);
    dMassSetSphereTotal(&mc, c->caster_mass_kg, c->caster_r_m);
    dMassTranslate(&mc, caster_p[0], caster_p[1], caster_p[2]);
    dMassAdd(&mb, &mc);
    double com[3] = { mb.c[0], mb.c[1], mb.c[2] }, com_w[3];
    dMassTranslate(&mb, -com[0], -com[1], -com[2]);
    frame_point(x, y, heading, com, com_w);
    dRFromAxisAndAngle(rot, 0, 0, 1, heading - M_PI / 2);
    w->chassis = dBodyCreate(w->world);
    dBodySetMass(w->chassis, &mb);
    dBodySetPosition(w->chassis, com_w[0], com_w[1], com_w[2]);
    dBodySetRotation(w->chassis, rot);
    for (int k = 0; k < 3; k++) w->box_offset[k] = box_p[k] - com[k];
    for (int k = 0; k < 3; k++) w->com[k] = com[k];

    w->box = dCreateBox(w->robot, c->body_w_m, c->body_l_m, c->body_h_m);
    dGeomSetBody(w->box, w->chassis);
    dGeomSetOffsetPosition(w->box, w->box_offset[0], w->box_offset[1], w->box_offset[2]);
    w->caster = dCreateSphere(w->robot, c->caster_r_m);
    dGeomSetBody(w->caster, w->chassis);
    dGeomSetOffsetPosition(w->caster, caster_p[0] - com[0], caster_p[1] - com[1], caster_p[2] - com[2]);

    for (int s = 0; s < 2; s++) {
        double wp[3] = { s == WORLD_LEFT ? -c->wheel_x_m : c->wheel_x_m, c->axle_y_m, rw }, ww[3];
        dMass m;
        dMatrix3 r2, r3;
        frame_point(x, y, heading, wp, ww);
        w->wheel[s] = dBodyCreate(w->world);
        /* cylinder axis along z: the mass is set in the wheel frame, then
         * the body is turned so that z points along the robot's x */
        dMassSetCylinderTotal(&m, c->wheel_mass_kg, 3, rw, c->wheel_w_m);
        if (c->rotor_inertia_kgm2 > 0) /* rotor inertia reflected through the gearbox: J * N^2 */
            m.I[2 * 4 + 2] += c->rotor_inertia_kgm2 * c->gear_ratio * c->gear_ratio;
        dBodySetMass(w->wheel[s], &m);
        /* a hinge torque turns the wheel one way and the chassis (pitch,
         * about the axle's direction; both wheels at once) the other */
        w->hinge_inertia = 1.0 / (1.0 / m.I[2 * 4 + 2] + 2.0 / mb.I[0]);
        dBodySetPosition(w->wheel[s], ww[0], ww[1], ww[2]);
        dRFromAxisAndAngle(r2, 0, 1, 0, M_PI / 2);
        dMultiply0(r3, rot, r2, 3, 3, 3);
        dBodySetRotation(w->wheel[s], r3);
        /* the tyre touches the floor as a sphere of the wheel's radius: one
         * contact on the wheel's centre plane, as a rounded tyre. A flat
         * cylinder touches with one rim edge or the other as the chassis
         * rolls a little, which moved the effective track between 88 and
         * 104 mm and made in-place turns miss by up to 9 degrees. The
         * wheel's mass and inertia stay those of a cylinder. */
        w->wheel_geom[s] = dCreateSphere(w->robot, rw);
        dGeomSetBody(w->wheel_geom[s], w->wheel[s]);
        /* ...but against walls and posts the wheel is its real cylinder */
        w->wheel_side[s] = dCreateCylinder(w->robot, rw, c->wheel_w_m);
        dGeomSetBody(w->wheel_side[s], w->wheel[s]);

        const dReal *ax = dBodyGetRotation(w->chassis); /* robot x axis in the world: column 0 */
        w->hinge[s] = dJointCreateHinge(w->world, 0);
        dJointAttach(w->hinge[s], w->chassis, w->wheel[s]);
        dJointSetHingeAnchor(w->hinge[s], ww[0], ww[1], ww[2]);
        dJointSetHingeAxis(w->hinge[s], ax[0], ax[4], ax[8]);
    }
    dGeomID parts[2] = { w->box, w->caster };
    for (int k = 0; k < 2; k++) {
        dGeomSetCategoryBits(parts[k], CAT_ROBOT);
        dGeomSetCollideBits(parts[k], CAT_STATIC | CAT_FLOOR);
    }
    for (int k = 0; k < 2; k++) {
        dGeomSetCategoryBits(w->wheel_geom[k], CAT_TYRE);
        dGeomSetCollideBits(w->wheel_geom[k], CAT_FLOOR);
        dGeomSetCategoryBits(w->wheel_side[k], CAT_WHEEL_SIDE);
        dGeomSetCollideBits(w->wheel_side[k], CAT_STATIC);
    }

    /* ToF sensors at the body's mid height, inside the body outline (a ray
     * starting inside a wall reports 0) */
    double zs = box_p[2], side = c->tof_side_angle_deg * M_PI / 180;
    double pos[3][3] = { { -c->tof_x_m, c->tof_y_m, zs }, { 0, c->tof_front_y_m, zs }, { c->tof_x_m, c->tof_y_m, zs } };
    double dir[3] = { M_PI / 2 + side, M_PI / 2, M_PI / 2 - side };
    for (int s = 0; s < WORLD_TOF_COUNT; s++) {
        for (int k = 0; k < 3; k++) w->tof_pos[s][k] = pos[s][k] - com[k];
        w->tof_dir[s] = dir[s];
    }
}

world_t *world_create(const simcfg_t *c, const maze_t *m, double x_m, double y_m, double heading_rad)
{
    if (!ode_ready) {
        if (!dInitODE2(0)) return NULL;
        ode_ready = 1;
    }
    world_t *w = calloc(1, sizeof *w);
    if (!w) return NULL;
    /* quickstep shuffles constraints with ODE's global PRNG: reseed it so
     * every world steps the same way, whatever ran before it */
    dRandSetSeed(1);
    w->cfg = *c;
    w->world = dWorldCreate();
    dWorldSetGravity(w->world, 0, 0, -9.81);
    dWorldSetQuickStepNumIterations(w->world, (int)c->solver_iterations);
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
    build_maze(w, m);
    build_robot(w, x_m, y_m, heading_rad);
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
    dGeomDestroy(w->ray);
    dJointGroupDestroy(w->contacts);
    dSpaceDestroy(w->top); /* and every geom in it */
    dWorldDestroy(w->world);
    free(w);
}

static int is_robot_part(const world_t *w, dGeomID g)
{
    return g == w->box || g == w->caster || g == w->wheel_geom[0] || g == w->wheel_geom[1] || g == w->wheel_side[0] ||
           g == w->wheel_side[1];
}

static void near_cb(void *data, dGeomID a, dGeomID b)
{
    world_t *w = data;
    if (dGeomIsSpace(a) || dGeomIsSpace(b)) {
        dSpaceCollide2(a, b, data, near_cb);
        return;
    }
    if (is_robot_part(w, b)) { dGeomID t = a; a = b; b = t; }
    if (!is_robot_part(w, a) || is_robot_part(w, b)) return;
    dContact c[MAX_CONTACTS];
    int n = dCollide(a, b, MAX_CONTACTS, &c[0].geom, sizeof(dContact));
    if (n <= 0) return;
    int wall = b != w->floor;
    if (wall) w->touching = 1;
    for (int i = 0; i < n; i++) {
        double mu = w->cfg.body_wall_mu;
        if (a == w->caster) {
            mu = 0.0; /* the paper's caster: frictionless */
        } else if (!wall && (a == w->wheel_geom[0] || a == w->wheel_geom[1])) {
            dVector3 v;
            dBodyGetPointVel(dGeomGetBody(a), c[i].geom.pos[0], c[i].geom.pos[1], c[i].geom.pos[2], v);
            double slip = hypot(v[0], v[1]);
            mu = slip > w->cfg.tyre_slip_m_s ? w->cfg.tyre_mu_dynamic : w->cfg.tyre_mu;
        }
        c[i].surface.mode = dContactApprox1 | dContactSoftERP | dContactSoftCFM;
        if (!wall && (a == w->wheel_geom[0] || a == w->wheel_geom[1])) {
            /* align the friction pyramid with the wheel (rolling and
             * sideways), or its corners would make driving east and north
             * differ */
            dVector3 f;
            dBodyVectorToWorld(w->chassis, 0, 1, 0, f);
            c[i].surface.mode |= dContactFDir1;
            c[i].fdir1[0] = f[0];
            c[i].fdir1[1] = f[1];
            c[i].fdir1[2] = 0;
        }
        c[i].surface.mu = mu;
        c[i].surface.soft_erp = w->cfg.contact_erp;
        c[i].surface.soft_cfm = w->cfg.contact_cfm;
        dJointID j = dJointCreateContact(w->world, w->contacts, &c[i]);
        dJointAttach(j, dGeomGetBody(c[i].geom.g1), dGeomGetBody(c[i].geom.g2));
    }
}

void world_step_motors(world_t *w, const double torque_nm[2], const double damping_nm_s[2], const double free_rad_s[2])
{
    for (int s = 0; s < 2; s++) {
        /* +T on body1 (chassis), -T on body2 (wheel): the wheel turns
         * forward and the chassis takes the reaction */
        dJointAddHingeTorque(w->hinge[s], torque_nm[s]);
        /* the damper as the hinge's motor row driving the rate to
         * free_rad_s with constraint force mixing 1/damping: ODE solves
         * J*v = vel - CFM*lambda, i.e. lambda = damping * (free - the
         * rate at the end of the step), implicitly, with the reaction on
         * the chassis, no force limit */
        int on = damping_nm_s[s] > 0;
        dJointSetHingeParam(w->hinge[s], dParamVel, on ? free_rad_s[s] : 0);
        dJointSetHingeParam(w->hinge[s], dParamFMax, on ? dInfinity : 0);
        if (on) dJointSetHingeParam(w->hinge[s], dParamCFM, 1.0 / damping_nm_s[s]);
    }
    w->touching = 0;
    dSpaceCollide(w->top, w, near_cb);
    dWorldQuickStep(w->world, w->cfg.step_s);
    dJointGroupEmpty(w->contacts);
    if (w->touching && !w->touched_last) w->collisions++;
    w->touched_last = w->touching;
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

double world_wheel_angle(const world_t *w, int side) { return dJointGetHingeAngle(w->hinge[side]); }
double world_wheel_rate(const world_t *w, int side) { return dJointGetHingeAngleRate(w->hinge[side]); }

static void ray_cb(void *data, dGeomID a, dGeomID b)
{
    world_t *w = data;
    if (dGeomIsSpace(a) || dGeomIsSpace(b)) {
        dSpaceCollide2(a, b, data, ray_cb);
        return;
    }
    dContactGeom cg;
    if (dCollide(a, b, 1, &cg, sizeof cg) == 1 && (w->ray_best < 0 || cg.depth < w->ray_best)) w->ray_best = cg.depth;
}

double world_ray(world_t *w, double x_m, double y_m, double z_m, double dir_rad, double max_m)
{
    dGeomRaySetLength(w->ray, max_m);
    dGeomRaySet(w->ray, x_m, y_m, z_m, cos(dir_rad), sin(dir_rad), 0);
    w->ray_best = -1;
    dSpaceCollide2(w->ray, (dGeomID)w->statics, w, ray_cb);
    return w->ray_best;
}

void world_tof_origin(const world_t *w, int s, double pos_m[3], double *dir_rad)
{
    dVector3 p, f;
    double a = w->tof_dir[s];
    dBodyGetRelPointPos(w->chassis, w->tof_pos[s][0], w->tof_pos[s][1], w->tof_pos[s][2], p);
    dBodyVectorToWorld(w->chassis, cos(a), sin(a), 0, f);
    for (int k = 0; k < 3; k++) pos_m[k] = p[k];
    *dir_rad = atan2(f[1], f[0]);
}

double world_tof_ray(world_t *w, int s, double max_m)
{
    double p[3], dir;
    world_tof_origin(w, s, p, &dir);
    return world_ray(w, p[0], p[1], p[2], dir, max_m);
}

void world_place(world_t *w, double x_m, double y_m, double heading_rad, const double wheel_rad[2])
{
    const simcfg_t *c = &w->cfg;
    dMatrix3 rot, r2, r3, spin, r4;
    double com_w[3], keep[2] = { world_wheel_angle(w, 0), world_wheel_angle(w, 1) };
    if (!wheel_rad) wheel_rad = keep;
    frame_point(x_m, y_m, heading_rad, w->com, com_w);
    dRFromAxisAndAngle(rot, 0, 0, 1, heading_rad - M_PI / 2);
    dBodySetPosition(w->chassis, com_w[0], com_w[1], com_w[2]);
    dBodySetRotation(w->chassis, rot);
    dBodySetLinearVel(w->chassis, 0, 0, 0);
    dBodySetAngularVel(w->chassis, 0, 0, 0);
    for (int s = 0; s < 2; s++) {
        double wp[3] = { s == WORLD_LEFT ? -c->wheel_x_m : c->wheel_x_m, c->axle_y_m, c->wheel_d_m / 2 }, ww[3];
        frame_point(x_m, y_m, heading_rad, wp, ww);
        /* as built (cylinder z along the robot's x), then turned about that axis */
        dRFromAxisAndAngle(r2, 0, 1, 0, M_PI / 2);
        dMultiply0(r3, rot, r2, 3, 3, 3);
        dRFromAxisAndAngle(spin, 0, 0, 1, -wheel_rad[s]); /* hinge angles count the other way */
        dMultiply0(r4, r3, spin, 3, 3, 3);
        dBodySetPosition(w->wheel[s], ww[0], ww[1], ww[2]);
        dBodySetRotation(w->wheel[s], r4);
        dBodySetLinearVel(w->wheel[s], 0, 0, 0);
        dBodySetAngularVel(w->wheel[s], 0, 0, 0);
    }
}

void world_step(world_t *w, double torque_left_nm, double torque_right_nm)
{
    const double t[2] = { torque_left_nm, torque_right_nm }, none[2] = { 0, 0 };
    world_step_motors(w, t, none, none);
}

double world_hinge_inertia(const world_t *w) { return w->hinge_inertia; }
int world_touching(const world_t *w) { return w->touched_last; }
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

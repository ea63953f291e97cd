/* world.c - ODE scene and robot (see world.h): the maze, the chassis,
 * contacts and the step. The wheels are the form's the model names
 * ([sim] wheels), each in its own file behind one table (world_impl.h:
 * world_wheel_spin.c, world_wheel_hinge.c). */
#include "world_impl.h"

#include <math.h>
#include <stdarg.h>
#include <stdint.h>
#include <stdlib.h>

#define MAX_CONTACTS 4
#define WORLD_CONTACT_STEP_S 0.00025 /* longest ODE step while the robot is near a wall, s */
#define WORLD_NEAR_M 0.001 /* margin beyond a step's travel for "near a wall", m */
/* Slowest a point of the robot may move for an impact to need the finer
 * steps, m/s: slower, a 2 ms step meets the wall at most 0.1 mm late, a
 * sixteenth of a 3 m/s impact's 1.6 mm depth; a robot resting against a
 * wall (the start cell's back wall) keeps the contest's step. */
#define WORLD_IMPACT_M_S 0.05
#define WORLD_TOUCH_SLACK_M 1e-6 /* "clear of walls" for the collision tree: a micrometre apart at least, m */
#define WORLD_STICTION_RAD_S 1.0 /* wheel speed below which the gearbox friction is a stiction row, rad/s */

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
static int build_maze(world_t *w, const truemaze_t *m)
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
            truemaze_cell_t c = truemaze_cell(m, x, y);
            /* each wall once: south and west of every cell, plus the outer north and east */
            if (!truemaze_open(m, c, TRUEMAZE_SOUTH)) static_box(w, (x + 0.5) * cell, y * cell, cell - post, thick);
            if (!truemaze_open(m, c, TRUEMAZE_WEST)) static_box(w, x * cell, (y + 0.5) * cell, thick, cell - post);
            if (y == m->height - 1 && !truemaze_open(m, c, TRUEMAZE_NORTH))
                static_box(w, (x + 0.5) * cell, (y + 1) * cell, cell - post, thick);
            if (x == m->width - 1 && !truemaze_open(m, c, TRUEMAZE_EAST))
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
    w->wheels->chassis_mass(w, mb); /* spin bodies: the wheels ride in the chassis */
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

/* The chassis: one body at the combined centre of mass, the body box and
 * the casters as its geoms, offset from it. */
static void build_chassis(world_t *w, double x, double y, double heading)
{
    const sim_chassis_t *c = &w->model->chassis;
    double box_z = c->body_clearance_m + c->body_h_m / 2, com_w[3];
    dMass mb;
    dMatrix3 rot;
    chassis_mass(w, &mb, w->com);
    world_frame_point(x, y, heading, w->com, com_w);
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
    w->wheels->attach_box(w);
    w->caster = caster_geom(w, c->caster_y_m[0]);
    w->caster2 = w->model->casters > 1 ? caster_geom(w, c->caster_y_m[1]) : NULL;
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
        for (int k = 0; k < w->loose.n; k++)
            if (g == w->loose.geom[k]) loose = k;
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
        const dReal *o = loose >= 0 ? w->loose.at[loose] : dGeomGetOffsetPosition(g), *R = loose >= 0 ? w->loose.rot[loose] : dGeomGetOffsetRotation(g);
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
    for (int s = 0; s < 2; s++) w->wheels->build(w, s, x, y, heading);
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

world_t *world_create(const sim_model_t *model, const truemaze_t *m, double x_m, double y_m, double heading_rad)
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
    w->wheels = model->wheels == SIM_WHEELS_SPIN ? &world_wheel_spin : &world_wheel_hinge;
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
    for (int k = 0; k < w->loose.n && !w->loose_placed; k++) world_loose_place(&w->loose, w->chassis, k);
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
            w->wheels->rim_vel(w, side, c[i].geom.pos, vs);
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
        /* the second body is the wheel form's (with spin bodies a wheel's contact holds the chassis against its spin body) */
        dBodyID b1 = dGeomGetBody(c[i].geom.g1); /* a loose part has none: it stands on the chassis (world_loose_place) */
        dJointAttach(j, b1 ? b1 : w->chassis, w->wheels->contact_body(w, a, c[i].geom.g2));
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
        w->wheels->motor_row(w, s, d->t0_nm / d->damping_nm_s, dInfinity, 1.0 / d->damping_nm_s);
    } else {
        w->wheels->motor_off(w, s);
        w->wheels->torque(w, s, d->t0_nm);
    }
    /* Moving, the friction is a torque against the motion: one step of it
     * cannot reverse a wheel turning faster than f*h/J (0.09 rad/s for the
     * default robot), so above WORLD_STICTION_RAD_S it is applied as such and
     * the solver has a row fewer. */
    double w_rad_s = w->wheels->rate(w, s);
    if (fabs(w_rad_s) > WORLD_STICTION_RAD_S) {
        world_amotor_param(w->friction[s], dParamFMax, 0, &w->friction_set[s]);
        w->wheels->torque(w, s, w_rad_s > 0 ? -d->friction_nm : d->friction_nm);
    } else {
        world_amotor_param(w->friction[s], dParamFMax, d->friction_nm, &w->friction_set[s]);
    }
    w->wheels->couple(w, s);
}

/* The chassis' body_drag_n_s_m, for one ODE step: a force against the
 * velocity of the axle's middle, applied on the floor under it, where the
 * tyres' traction meets it (higher up the two make a couple that pitches
 * a robot balanced over its axle onto a skid: the hinge form's straight
 * run then veered 0.2-0.4 m in 4). A spin in place leaves that point
 * still, so it loads a run and not a spin (the robot file's key says what
 * it stands for). */
static void drag_chassis(world_t *w)
{
    double c = w->model->chassis.body_drag_n_s_m;
    if (c <= 0) return;
    double x = -w->com[0], y = w->model->chassis.axle_y_m - w->com[1], z = -w->com[2]; /* from the centre of mass */
    dVector3 v;
    dBodyGetRelPointVel(w->chassis, x, y, z, v);
    dBodyAddForceAtRelPos(w->chassis, -c * v[0], -c * v[1], 0, x, y, z);
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
        double rate = w->wheels->rate(w, s);
        if (rate != 0) w->wheels->torque(w, s, rate > 0 ? -w->brake_nm : w->brake_nm); /* +T turns the wheel forward */
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
    if ((near || w->box_low) && !w->loose_placed) world_loose_place(&w->loose, w->chassis, 0);
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
        w->wheels->before_ode(w);
        /* ODE clears the added torques after each of its steps */
        drive_wheel(w, WORLD_LEFT, &drive[WORLD_LEFT]);
        drive_wheel(w, WORLD_RIGHT, &drive[WORLD_RIGHT]);
        brake_wheels(w);
        drag_chassis(w);
        /* before the collision pass, which may not move a geom (world_loose_place) */
        if (!w->clear_now) w->clear_now = clear_of_walls(w, WORLD_TOUCH_SLACK_M, 0);
        if (w->loose.n) box_floor(w);
        dSpaceCollide(w->top, w, near_cb);
        if (w->model->solver == SIM_SOLVER_EXACT) dWorldStep(w->world, w->h_s);
        else dWorldQuickStep(w->world, w->h_s);
        w->clear_now = w->loose_placed = 0;
        dJointGroupEmpty(w->contacts);
        w->wheels->after_ode(w);
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
        dJointID j = w->wheels->dyno_row(w, s);
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
    for (int s = 0; s < 2; s++) w->wheels->hold_up(w, s);
    w->lift = dJointCreateFixed(w->world, 0);
    dJointAttach(w->lift, w->chassis, 0);
    dJointSetFixed(w->lift);
}

void world_lift(world_t *w, int lock_wheels)
{
    hold_up(w);
    for (int s = 0; s < 2 && lock_wheels; s++) w->wheels->lock(w, s);
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

double world_wheel_angle(const world_t *w, int side) { return w->wheels->angle(w, side); }
double world_wheel_rate(const world_t *w, int side) { return w->wheels->rate(w, side); }

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

void world_cast(world_t *w, const sim_pose_t *at, int n, const double (*off)[3], double max_m, world_hit_t *hit)
{
    for (int i = 0; i < n; i++) {
        const double *o = off[i];
        world_hit_t *h = &hit[i];
        for (int k = 0; k < 3; k++) h->dir[k] = o[0] * at->axis[k] + o[1] * at->left[k] + o[2] * at->up[k];
        h->d_m = world_ray_normal(w, at->pos_m, h->dir, max_m, h->normal);
    }
}

void world_body_cast(world_t *w, const sim_pose_t *pose, int n, const double (*off)[3], double max_m, sim_pose_t *at,
                     world_hit_t *hit)
{
    world_body_point(w, pose->pos_m, at->pos_m);
    world_body_vector(w, pose->axis, at->axis);
    world_body_vector(w, pose->left, at->left);
    world_body_vector(w, pose->up, at->up);
    world_cast(w, at, n, off, max_m, hit);
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
    dMatrix3 rot;
    double com_w[3], keep[2] = { world_wheel_angle(w, 0), world_wheel_angle(w, 1) };
    if (!wheel_rad) wheel_rad = keep;
    world_frame_point(x_m, y_m, heading_rad, w->com, com_w);
    dRFromAxisAndAngle(rot, 0, 0, 1, heading_rad - M_PI / 2);
    dBodySetPosition(w->chassis, com_w[0], com_w[1], com_w[2]);
    dBodySetRotation(w->chassis, rot);
    dBodySetLinearVel(w->chassis, 0, 0, 0);
    dBodySetAngularVel(w->chassis, 0, 0, 0);
    for (int s = 0; s < 2; s++) w->wheels->place(w, s, x_m, y_m, heading_rad, wheel_rad[s]);
}

void world_set_speed(world_t *w, double v_m_s)
{
    dVector3 f;
    dBodyVectorToWorld(w->chassis, 0, 1, 0, f);
    dBodySetLinearVel(w->chassis, v_m_s * f[0], v_m_s * f[1], 0);
    dBodySetAngularVel(w->chassis, 0, 0, 0);
    for (int s = 0; s < 2; s++) w->wheels->set_speed(w, s, v_m_s);
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

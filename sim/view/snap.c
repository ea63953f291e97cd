/* snap.c - what the viewer draws of a run at one moment (see snap.h). */
#include "snap.h"

#include <math.h>
#include <string.h>

#include "world/sensors/ir.h"
#include "world/sensors/sensor.h"

static int is_ir(const simcfg_t *c, int i) { return !strcmp(c->robot.part[i].kind->name, "ir"); }

/* The IR sensor i's beam reach (its model's max_m). */
static double ir_max_m(const simcfg_t *c, int i) { return ((const ir_part_spec_t *)c->robot.part[i].spec)->model.max_m; }

void snap_from_sim(snap_t *out, const sim_state_t *s)
{
    const simcfg_t *c = s->model->cfg;
    memset(out, 0, sizeof *out);
    out->time_s = sim_time_s(s);
    world_pose(s->world, &out->x_m, &out->y_m, &out->heading_rad);
    double w_rad_s;
    world_velocity(s->world, &out->v_m_s, &w_rad_s);
    for (int k = 0; k < 2; k++) {
        out->wheel_rad[k] = world_wheel_angle(s->world, k);
        out->wheel_hub_z_m[k] = s->model->wheel_r_m[k];
    }
    out->ntof = s->ntof;
    out->tof_range_m = s->tof_range_m;
    for (int i = 0; i < s->ntof; i++) {
        snap_ray_t *t = &out->tof[i];
        sensor_frame(s->world, &s->model->pose[s->tof_part[i]], t->pos_m, t->axis, t->left, t->up);
        t->hit_m = s->tof_true_m[i];
    }
    for (int i = 0; i < c->robot.nparts; i++)
        if (is_ir(c, i)) {
            snap_ray_t *b = &out->part[i];
            double n[3];
            sensor_frame(s->world, &s->model->pose[i], b->pos_m, b->axis, b->left, b->up);
            b->hit_m = world_ray_normal(s->world, b->pos_m, b->axis, ir_max_m(c, i), n);
        }
    for (unsigned g = 0; g < SIM_EMITTER_GROUPS; g++) out->emitter[g] = sim_emitter(s, g);
    out->centre_post = world_has_centre_post(s->world);
    out->race = s->race;
}

/* A chassis-frame point or direction (x right, y forward, z up) of a
 * robot standing level at (x, y) facing heading, in the world (as
 * world.c's frame_point). */
static void level_point(double x, double y, double heading, const double p[3], double out[3])
{
    double a = heading - M_PI / 2, ca = cos(a), sa = sin(a);
    out[0] = x + ca * p[0] - sa * p[1];
    out[1] = y + sa * p[0] + ca * p[1];
    out[2] = p[2];
}

static void level_frame(double x, double y, double heading, const sim_pose_t *p, snap_ray_t *out)
{
    level_point(x, y, heading, p->pos_m, out->pos_m);
    level_point(0, 0, heading, p->axis, out->axis);
    level_point(0, 0, heading, p->left, out->left);
    level_point(0, 0, heading, p->up, out->up);
}

void snap_place(snap_t *out, const sim_model_t *model, const truemaze_t *m, int centre_post, double x_m, double y_m,
                double heading_rad, const double wheel_rad[2])
{
    const simcfg_t *c = model->cfg;
    out->x_m = x_m;
    out->y_m = y_m;
    out->heading_rad = heading_rad;
    out->centre_post = centre_post;
    for (int k = 0; k < 2; k++) {
        out->wheel_rad[k] = wheel_rad[k];
        out->wheel_hub_z_m[k] = model->wheel_r_m[k];
    }
    /* the ToF sensors as sim_init counts them: the robot file's first WORLD_TOF_COUNT */
    out->ntof = 0;
    out->tof_range_m = 1.2; /* m: the link's distance scale without a ToF sensor (sim.h) */
    for (int i = 0; i < c->robot.nparts && out->ntof < WORLD_TOF_COUNT; i++)
        if (c->robot.part[i].kind == sensor_kind("tof")) {
            if (out->ntof == 0) out->tof_range_m = ((const tof_spec_t *)c->robot.part[i].spec)->range_m;
            level_frame(x_m, y_m, heading_rad, &model->pose[i], &out->tof[out->ntof++]);
        }
    for (int i = 0; i < c->robot.nparts; i++)
        if (is_ir(c, i)) {
            snap_ray_t *b = &out->part[i];
            level_frame(x_m, y_m, heading_rad, &model->pose[i], b);
            b->hit_m = snap_maze_ray(c, m, centre_post, b->pos_m, b->axis, ir_max_m(c, i));
        }
}

/* ---- rays against the maze: the ODE world's boxes, cast as ODE casts them ---- */

typedef struct {
    double pos[3], u[3]; /* origin, unit direction */
    double max_m, best;  /* reach; nearest hit so far (-1 none) */
} maze_ray_t;

/* The ray against an axis-aligned box centred at (cx, cy, cz) with these
 * half sizes: a slab test in the box's own frame, taking the entry if the
 * ray starts outside and the exit if it starts inside (ODE's
 * dCollideRayBox does the same), kept if nearer than the best so far. */
static void ray_box(maze_ray_t *r, double cx, double cy, double cz, double hx, double hy, double hz)
{
    const double c[3] = { cx, cy, cz }, h[3] = { hx, hy, hz };
    double lo = -INFINITY, hi = INFINITY;
    for (int k = 0; k < 3; k++) {
        double s = r->pos[k] - c[k], v = r->u[k];
        if (v == 0) {
            if (s < -h[k] || s > h[k]) return;
            continue;
        }
        double a = (-h[k] - s) / v, b = (h[k] - s) / v;
        if (a > b) {
            double t = a;
            a = b;
            b = t;
        }
        if (a > lo) lo = a;
        if (b < hi) hi = b;
    }
    if (lo > hi) return;
    double t = lo >= 0 ? lo : hi;
    if (t < 0 || t > r->max_m) return;
    if (r->best < 0 || t < r->best) r->best = t;
}

double snap_maze_ray(const simcfg_t *cf, const truemaze_t *m, int centre_post, const double pos_m[3], const double dir[3],
                     double max_m)
{
    double n = sqrt(dir[0] * dir[0] + dir[1] * dir[1] + dir[2] * dir[2]);
    maze_ray_t r = { { pos_m[0], pos_m[1], pos_m[2] }, { dir[0] / n, dir[1] / n, dir[2] / n }, max_m, -1 };
    double cell = cf->world.cell_m, post = cf->world.post_m, th = cf->world.wall_thick_m, hz = cf->world.wall_height_m / 2;
    int cx = m->width % 2 == 0 ? m->width / 2 : -1, cy = m->height % 2 == 0 ? m->height / 2 : -1;
    /* the same boxes as world.c's build_maze: every post, then each wall once */
    for (int py = 0; py <= m->height; py++)
        for (int px = 0; px <= m->width; px++)
            if (px != cx || py != cy || centre_post) ray_box(&r, px * cell, py * cell, hz, post / 2, post / 2, hz);
    for (uint8_t y = 0; y < m->height; y++)
        for (uint8_t x = 0; x < m->width; x++) {
            truemaze_cell_t k = truemaze_cell(m, x, y);
            if (!truemaze_open(m, k, TRUEMAZE_SOUTH)) ray_box(&r, (x + 0.5) * cell, y * cell, hz, (cell - post) / 2, th / 2, hz);
            if (!truemaze_open(m, k, TRUEMAZE_WEST)) ray_box(&r, x * cell, (y + 0.5) * cell, hz, th / 2, (cell - post) / 2, hz);
            if (y == m->height - 1 && !truemaze_open(m, k, TRUEMAZE_NORTH))
                ray_box(&r, (x + 0.5) * cell, (y + 1) * cell, hz, (cell - post) / 2, th / 2, hz);
            if (x == m->width - 1 && !truemaze_open(m, k, TRUEMAZE_EAST))
                ray_box(&r, (x + 1) * cell, (y + 0.5) * cell, hz, th / 2, (cell - post) / 2, hz);
        }
    return r.best;
}

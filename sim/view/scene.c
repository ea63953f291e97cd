/* scene.c - 3D scene in legacy OpenGL (see scene.h). */
#include "scene.h"

#include "font.h"

#include <GL/gl.h>
#include <math.h>
#include <string.h>

#include "maze/solve.h"
#include "maze/truebelief.h"
#include "world/sensors/ir.h"

#define FOV_DEG 45.0  /* vertical field of view */
#define NEAR_M 0.01
#define FAR_M 30.0

static void colour(uint32_t rgb, float a)
{
    glColor4f((float)((rgb >> 16) & 255) / 255.f, (float)((rgb >> 8) & 255) / 255.f, (float)(rgb & 255) / 255.f, a);
}

void scene_camera(const sim_model_t *model, const truemaze_t *m, const snap_t *s, int cam, const scene_orbit_t *orbit,
                  double eye[3], double target[3], double up[3])
{
    const simcfg_t *c = model->cfg;
    double cell = c->world.cell_m, W = m->width * cell, H = m->height * cell;
    double x = s->x_m, y = s->y_m, h = s->heading_rad;
    double yaw, pitch, dist;
    up[0] = up[1] = 0;
    up[2] = 1;
    if (cam == SCENE_FOLLOW) {
        /* behind the robot, looking at its body centre */
        target[0] = x, target[1] = y, target[2] = c->robot.body_clearance_m + c->robot.body_h_m / 2;
        yaw = h + M_PI, pitch = 22 * M_PI / 180, dist = 0.32;
    } else if (cam == SCENE_TOP) {
        target[0] = x, target[1] = y, target[2] = 0;
        yaw = h + M_PI, pitch = 89.5 * M_PI / 180, dist = 0.55;
    } else {
        /* the whole maze from the south, high up */
        target[0] = W / 2, target[1] = H / 2 * 0.98, target[2] = 0;
        yaw = -M_PI / 2, pitch = 72 * M_PI / 180;
        dist = fmax(W, H) * 0.66 / tan(FOV_DEG / 2 * M_PI / 180) + 0.05;
    }
    if (orbit) {
        yaw += orbit->dyaw_rad;
        pitch += orbit->dpitch_rad;
        if (orbit->zoom > 0) dist *= orbit->zoom;
    }
    if (pitch > 89.5 * M_PI / 180) pitch = 89.5 * M_PI / 180;
    if (pitch < 2 * M_PI / 180) pitch = 2 * M_PI / 180;
    eye[0] = target[0] + dist * cos(pitch) * cos(yaw);
    eye[1] = target[1] + dist * cos(pitch) * sin(yaw);
    eye[2] = target[2] + dist * sin(pitch);
    if (cam == SCENE_TOP) { /* robot's forward points up the screen */
        up[0] = cos(h), up[1] = sin(h), up[2] = 0;
    }
}

/* gluLookAt without GLU. */
static void look_at(const double e[3], const double t[3], const double u[3])
{
    double f[3] = { t[0] - e[0], t[1] - e[1], t[2] - e[2] }, n = sqrt(f[0] * f[0] + f[1] * f[1] + f[2] * f[2]);
    for (int k = 0; k < 3; k++) f[k] /= n;
    double sx[3] = { f[1] * u[2] - f[2] * u[1], f[2] * u[0] - f[0] * u[2], f[0] * u[1] - f[1] * u[0] };
    n = sqrt(sx[0] * sx[0] + sx[1] * sx[1] + sx[2] * sx[2]);
    for (int k = 0; k < 3; k++) sx[k] /= n;
    double ux[3] = { sx[1] * f[2] - sx[2] * f[1], sx[2] * f[0] - sx[0] * f[2], sx[0] * f[1] - sx[1] * f[0] };
    double mm[16] = { sx[0], ux[0], -f[0], 0, sx[1], ux[1], -f[1], 0, sx[2], ux[2], -f[2], 0, 0, 0, 0, 1 };
    glMultMatrixd(mm);
    glTranslated(-e[0], -e[1], -e[2]);
}

/* Axis-aligned box (before the current transform) with normals; the top in its own colour. */
static void box(double cx, double cy, double cz, double lx, double ly, double lz, uint32_t side, uint32_t top)
{
    double x0 = cx - lx / 2, x1 = cx + lx / 2, y0 = cy - ly / 2, y1 = cy + ly / 2, z0 = cz - lz / 2, z1 = cz + lz / 2;
    glBegin(GL_QUADS);
    colour(top, 1);
    glNormal3d(0, 0, 1);
    glVertex3d(x0, y0, z1), glVertex3d(x1, y0, z1), glVertex3d(x1, y1, z1), glVertex3d(x0, y1, z1);
    colour(side, 1);
    glNormal3d(0, -1, 0);
    glVertex3d(x0, y0, z0), glVertex3d(x1, y0, z0), glVertex3d(x1, y0, z1), glVertex3d(x0, y0, z1);
    glNormal3d(0, 1, 0);
    glVertex3d(x1, y1, z0), glVertex3d(x0, y1, z0), glVertex3d(x0, y1, z1), glVertex3d(x1, y1, z1);
    glNormal3d(-1, 0, 0);
    glVertex3d(x0, y1, z0), glVertex3d(x0, y0, z0), glVertex3d(x0, y0, z1), glVertex3d(x0, y1, z1);
    glNormal3d(1, 0, 0);
    glVertex3d(x1, y0, z0), glVertex3d(x1, y1, z0), glVertex3d(x1, y1, z1), glVertex3d(x1, y0, z1);
    glNormal3d(0, 0, -1);
    glVertex3d(x0, y1, z0), glVertex3d(x1, y1, z0), glVertex3d(x1, y0, z0), glVertex3d(x0, y0, z0);
    glEnd();
}

/* Cylinder along x, centred at the origin; a stripe on the rim turns with angle. */
static void wheel(double r, double w, double angle)
{
    enum { SEG = 20 };
    glBegin(GL_QUAD_STRIP);
    for (int i = 0; i <= SEG; i++) {
        double a = 2 * M_PI * i / SEG + angle, c = cos(a), s = sin(a);
        colour(i == 0 || i == 1 ? 0xC8C8C8u : 0x202020u, 1);
        glNormal3d(0, c, s);
        glVertex3d(-w / 2, r * c, r * s);
        glVertex3d(w / 2, r * c, r * s);
    }
    glEnd();
    for (int side = -1; side <= 1; side += 2) {
        glBegin(GL_TRIANGLE_FAN);
        colour(0x505050u, 1);
        glNormal3d(side, 0, 0);
        glVertex3d(side * w / 2, 0, 0);
        for (int i = 0; i <= SEG; i++) {
            double a = 2 * M_PI * i / SEG * -side;
            glVertex3d(side * w / 2, r * cos(a), r * sin(a));
        }
        glEnd();
        /* a spoke, to see the wheel turn */
        glDisable(GL_LIGHTING);
        colour(0xE0E0E0u, 1);
        glBegin(GL_LINES);
        glVertex3d(side * (w / 2 + 0.0005), 0, 0);
        glVertex3d(side * (w / 2 + 0.0005), r * 0.9 * cos(angle), r * 0.9 * sin(angle));
        glEnd();
        glEnable(GL_LIGHTING);
    }
}

static void floor_and_cells(const simcfg_t *c, const truemaze_t *m)
{
    double cell = c->world.cell_m, W = m->width * cell, H = m->height * cell, pad = cell;
    glNormal3d(0, 0, 1);
    glBegin(GL_QUADS);
    colour(SCENE_FLOOR, 1);
    glVertex3d(-pad, -pad, 0), glVertex3d(W + pad, -pad, 0), glVertex3d(W + pad, H + pad, 0), glVertex3d(-pad, H + pad, 0);
    for (uint16_t k = 0; k < truemaze_cells(m); k++) {
        int start = k == m->start, goal = truemaze_is_goal(m, (truemaze_cell_t)k);
        if (!start && !goal) continue;
        double x0 = truemaze_x(m, (truemaze_cell_t)k) * cell + 0.012, y0 = truemaze_y(m, (truemaze_cell_t)k) * cell + 0.012,
               x1 = x0 + cell - 0.024, y1 = y0 + cell - 0.024, z = 0.0005;
        colour(start ? SCENE_START : SCENE_GOAL, 1);
        glVertex3d(x0, y0, z), glVertex3d(x1, y0, z), glVertex3d(x1, y1, z), glVertex3d(x0, y1, z);
    }
    glEnd();
}

static void walls(const simcfg_t *c, const truemaze_t *m, int centre_post)
{
    double cell = c->world.cell_m, post = c->world.post_m, th = c->world.wall_thick_m, hh = c->world.wall_height_m;
    int cx = m->width % 2 == 0 ? m->width / 2 : -1, cy = m->height % 2 == 0 ? m->height / 2 : -1;
    for (int py = 0; py <= m->height; py++)
        for (int px = 0; px <= m->width; px++)
            if (px != cx || py != cy || centre_post)
                box(px * cell, py * cell, hh / 2, post, post, hh, SCENE_WALL_SIDE, SCENE_WALL_TOP);
    for (uint8_t y = 0; y < m->height; y++)
        for (uint8_t x = 0; x < m->width; x++) {
            truemaze_cell_t k = truemaze_cell(m, x, y);
            if (!truemaze_open(m, k, TRUEMAZE_SOUTH))
                box((x + 0.5) * cell, y * cell, hh / 2, cell - post, th, hh, SCENE_WALL_SIDE, SCENE_WALL_TOP);
            if (!truemaze_open(m, k, TRUEMAZE_WEST))
                box(x * cell, (y + 0.5) * cell, hh / 2, th, cell - post, hh, SCENE_WALL_SIDE, SCENE_WALL_TOP);
            if (y == m->height - 1 && !truemaze_open(m, k, TRUEMAZE_NORTH))
                box((x + 0.5) * cell, (y + 1) * cell, hh / 2, cell - post, th, hh, SCENE_WALL_SIDE, SCENE_WALL_TOP);
            if (x == m->width - 1 && !truemaze_open(m, k, TRUEMAZE_EAST))
                box((x + 1) * cell, (y + 0.5) * cell, hh / 2, th, cell - post, hh, SCENE_WALL_SIDE, SCENE_WALL_TOP);
        }
}

/* The robot standing level at the snapshot's pose. */
static void robot(const sim_model_t *model, const snap_t *s)
{
    const simcfg_robot_t *rb = &model->cfg->robot;
    glPushMatrix();
    glTranslated(s->x_m, s->y_m, 0);
    glRotated((s->heading_rad - M_PI / 2) * 180 / M_PI, 0, 0, 1); /* robot frame: x right, y forward */
    box(0, 0, rb->body_clearance_m + rb->body_h_m / 2, rb->body_w_m, rb->body_l_m, rb->body_h_m, SCENE_ROBOT, SCENE_ROBOT);
    /* a white nose so the heading shows from above */
    box(0, rb->body_l_m / 2 - 0.006, rb->body_clearance_m + rb->body_h_m + 0.001, rb->body_w_m * 0.5, 0.01, 0.002,
        0xF0F0F0u, 0xF0F0F0u);
    for (int side = 0; side < 2; side++) {
        glPushMatrix();
        glTranslated(side == WORLD_LEFT ? -rb->wheel_x_m : rb->wheel_x_m, rb->axle_y_m, s->wheel_hub_z_m[side]);
        /* hinge angle positive = forward roll: about -x in the robot frame */
        wheel(model->wheel_r_m[side], rb->wheel_w_m, -s->wheel_rad[side]);
        glPopMatrix();
    }
    glPopMatrix();
}

/* Each ToF sensor's ray in the floor's plane along its heading, to its
 * true distance (a red point there) or its range. */
static void rays(const snap_t *s)
{
    glDisable(GL_LIGHTING);
    glLineWidth(2);
    for (int i = 0; i < s->ntof; i++) {
        const double *p = s->tof[i].pos_m;
        double dir = atan2(s->tof[i].axis[1], s->tof[i].axis[0]), d = s->tof[i].hit_m;
        double len = d >= 0 ? d : s->tof_range_m;
        glBegin(GL_LINES);
        colour(0xFFE040u, 1);
        glVertex3d(p[0], p[1], p[2]);
        glVertex3d(p[0] + len * cos(dir), p[1] + len * sin(dir), p[2]);
        glEnd();
        if (d >= 0) {
            glPointSize(7);
            glBegin(GL_POINTS);
            colour(0xFF4020u, 1);
            glVertex3d(p[0] + d * cos(dir), p[1] + d * sin(dir), p[2]);
            glEnd();
        }
    }
    glLineWidth(1);
    glEnable(GL_LIGHTING);
}

/* One IR sensor's beam: a cone from the sensor along its axis, half angle
 * its model's cone_deg, as long as the ray along the axis reaches (the
 * snapshot's: the first wall or post, else the model's max_m), in its
 * emitter group's colour. */
static void ir_beam(const simcfg_t *cf, const snap_t *s, int part)
{
    enum { SEG = 16 };
    const ir_part_spec_t *sp = (const ir_part_spec_t *)cf->robot.part[part].spec;
    const snap_ray_t *bm = &s->part[part];
    const double *pos = bm->pos_m, *ax = bm->axis, *lf = bm->left, *up = bm->up;
    double d = bm->hit_m, len = d >= 0 ? d : sp->model.max_m;
    double r = len * tan(sp->model.cone_deg * M_PI / 180);
    unsigned g = (unsigned)sp->emitter; /* 0..3, as the robot file's range check allows */
    int lit = g < SIM_EMITTER_GROUPS && s->emitter[g] != 0;
    uint32_t rgb = lit ? SCENE_IR_LIT : SCENE_IR_DARK;
    double c[3] = { pos[0] + len * ax[0], pos[1] + len * ax[1], pos[2] + len * ax[2] };
    colour(rgb, lit ? 0.55f : 0.35f);
    glBegin(GL_TRIANGLE_FAN);
    glVertex3d(pos[0], pos[1], pos[2]);
    for (int i = 0; i <= SEG; i++) {
        double a = 2 * M_PI * i / SEG, ca = cos(a) * r, sa = sin(a) * r;
        glVertex3d(c[0] + ca * lf[0] + sa * up[0], c[1] + ca * lf[1] + sa * up[1], c[2] + ca * lf[2] + sa * up[2]);
    }
    glEnd();
    colour(rgb, 1);
    glBegin(GL_LINES); /* the axis, seen even when the cone is thin */
    glVertex3d(pos[0], pos[1], pos[2]);
    glVertex3d(c[0], c[1], c[2]);
    glEnd();
}

/* Every IR sensor's beam (robot file [ir.*]), translucent. */
static void ir_beams(const simcfg_t *c, const snap_t *s)
{
    glDisable(GL_LIGHTING);
    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    glDepthMask(GL_FALSE);
    glLineWidth(2);
    for (int i = 0; i < c->robot.nparts; i++)
        if (!strcmp(c->robot.part[i].kind->name, "ir")) ir_beam(c, s, i);
    glLineWidth(1);
    glDepthMask(GL_TRUE);
    glDisable(GL_BLEND);
    glEnable(GL_LIGHTING);
}

/* The mouse's walls as bars over the wall tops (cyan where it agrees with
 * the truth, magenta where it does not) and its planned path. */
static void overlay(const simcfg_t *cf, const truemaze_t *m, const scene_belief_t *b)
{
    const maze_t *k = b->map;
    if (k->width != m->width || k->height != m->height) return;
    double cell = cf->world.cell_m, z = cf->world.wall_height_m + 0.003;
    glDisable(GL_LIGHTING);
    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    glLineWidth(4);
    glBegin(GL_LINES);
    for (uint8_t y = 0; y < m->height; y++)
        for (uint8_t x = 0; x < m->width; x++) {
            truemaze_cell_t c = truemaze_cell(m, x, y);
            for (uint8_t d = TRUEMAZE_EAST; d <= TRUEMAZE_SOUTH; d++) { /* east and south of each cell: every inner wall once */
                uint8_t known = maze_wall(k, (maze_cell_t)c, d);
                if (known != MAZE_WALL_CLOSED) continue;
                int truth = truemaze_wall(m, c, d);
                colour(truth ? SCENE_OVERLAY_WALL : SCENE_OVERLAY_WRONG, 0.9f);
                if (d == TRUEMAZE_EAST) glVertex3d((x + 1) * cell, y * cell, z), glVertex3d((x + 1) * cell, (y + 1) * cell, z);
                else glVertex3d(x * cell, y * cell, z), glVertex3d((x + 1) * cell, y * cell, z);
            }
        }
    glEnd();
    /* planned path: best from the mouse's cell and heading, unknown walls open */
    static truemaze_t plan;
    static solve_path_t path;
    truemaze_from_belief(&plan, k, 1);
    if (b->cell < truemaze_cells(&plan)) {
        plan.start = (truemaze_cell_t)b->cell;
        plan.start_heading = b->heading & 3;
        if (solve_best(&plan, &path) == 0) {
            glLineWidth(5);
            colour(0xC040FFu, 0.85f);
            glBegin(GL_LINE_STRIP);
            for (int i = 0; i < path.len; i++)
                glVertex3d((truemaze_x(&plan, path.path[i]) + 0.5) * cell, (truemaze_y(&plan, path.path[i]) + 0.5) * cell, 0.004);
            glEnd();
        }
    }
    glLineWidth(1);
    glDisable(GL_BLEND);
    glEnable(GL_LIGHTING);
}

void scene_draw(const sim_model_t *model, const truemaze_t *m, const snap_t *s, int cam, const scene_orbit_t *orbit,
                const scene_belief_t *b, int show_overlay, int x, int y, int w, int h)
{
    glClearColor(0.08f, 0.09f, 0.11f, 1);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glViewport(x, y, w, h);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    double top = NEAR_M * tan(FOV_DEG / 2 * M_PI / 180), right = top * (double)w / (h > 0 ? h : 1);
    if (w < h) { /* tall: the field of view across, the height follows */
        right = top;
        top = right * (double)h / (w > 0 ? w : 1);
    }
    glFrustum(-right, right, -top, top, NEAR_M, FAR_M);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    double eye[3], target[3], up[3];
    scene_camera(model, m, s, cam, orbit, eye, target, up);
    look_at(eye, target, up);

    glEnable(GL_DEPTH_TEST);
    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
    glEnable(GL_NORMALIZE);
    glEnable(GL_COLOR_MATERIAL);
    glColorMaterial(GL_FRONT_AND_BACK, GL_AMBIENT_AND_DIFFUSE);
    glShadeModel(GL_SMOOTH);
    /* light from above, a little from the south-west; tops are lit fully */
    GLfloat pos[4] = { 0.25f, 0.35f, 1.0f, 0 }, amb[4] = { 0.5f, 0.5f, 0.5f, 1 }, dif[4] = { 0.55f, 0.55f, 0.55f, 1 };
    GLfloat glob[4] = { 0, 0, 0, 1 };
    glLightModelfv(GL_LIGHT_MODEL_AMBIENT, glob);
    glLightfv(GL_LIGHT0, GL_POSITION, pos);
    glLightfv(GL_LIGHT0, GL_AMBIENT, amb);
    glLightfv(GL_LIGHT0, GL_DIFFUSE, dif);

    floor_and_cells(model->cfg, m);
    walls(model->cfg, m, s->centre_post);
    robot(model, s);
    rays(s);
    ir_beams(model->cfg, s);
    if (show_overlay && b && b->map) overlay(model->cfg, m, b);
    glDisable(GL_LIGHTING);
    glDisable(GL_DEPTH_TEST);
}

uint32_t scene_cell_rgb(char c)
{
    static const char letters[] = "kbacgorwyBCAGRY"; /* mms.h's letters, in mms_colour_rgb's order */
    static const uint32_t rgb[] = { 0x101014, 0x2846B4, 0x6E6E74, 0x2A8C78, 0x3C9C3C, 0xB4781E, 0xA83232, 0xB4B4B4,
                                    0xA8A028, 0x1C2A6C, 0x1E5A50, 0x505054, 0x1E5A1E, 0x641E1E, 0x646418 };
    const char *p = c ? strchr(letters, c) : NULL;
    return p ? rgb[p - letters] : 0;
}

#define CELL_TEXT_FULL 4      /* characters across a cell at the text's largest */
#define CELL_TEXT_MAX 10      /* characters drawn at most */
#define CELL_MARGIN_M 0.012   /* between a cell's tint and its walls' centre lines, m */

/* Text t centred at (cx, cy) on the floor at height z, px metres per font
 * pixel, along unit screen-up (ux, uy) and screen-right (uy, -ux). */
static void floor_text(const char *t, double cx, double cy, double z, double px, double ux, double uy)
{
    int n = (int)strnlen(t, CELL_TEXT_MAX);
    double rx = uy, ry = -ux, w = (n * FONT_ADVANCE - 1) * px, hgt = FONT_H * px;
    double ox = cx - rx * w / 2 + ux * hgt / 2, oy = cy - ry * w / 2 + uy * hgt / 2; /* the text's top left */
    for (int i = 0; i < n; i++)
        for (int row = 0; row < FONT_H; row++) {
            int bits = font_row(t[i], row);
            for (int c = 0; c < FONT_W; c++)
                if (bits & (1 << (FONT_W - 1 - c))) {
                    double a = (i * FONT_ADVANCE + c) * px, d = row * px; /* right and down from the top left */
                    double qx = ox + rx * a - ux * d, qy = oy + ry * a - uy * d;
                    glVertex3d(qx, qy, z), glVertex3d(qx + rx * px, qy + ry * px, z);
                    glVertex3d(qx + rx * px - ux * px, qy + ry * px - uy * px, z), glVertex3d(qx - ux * px, qy - uy * px, z);
                }
        }
}

void scene_draw_cells(const sim_model_t *model, const truemaze_t *m, const snap_t *s, int cam, const scene_orbit_t *orbit,
                      const char *colours, const char *texts, size_t stride)
{
    double cell = model->cfg->world.cell_m, eye[3], target[3], up[3];
    scene_camera(model, m, s, cam, orbit, eye, target, up);
    double ux = target[0] - eye[0], uy = target[1] - eye[1], n = hypot(ux, uy);
    if (n < 1e-9) ux = up[0], uy = up[1], n = hypot(ux, uy); /* looking straight down: the camera's up */
    if (n < 1e-9) ux = 0, uy = 1, n = 1;
    ux /= n, uy /= n;
    glDisable(GL_CULL_FACE); /* the text's winding depends on the camera */
    glEnable(GL_DEPTH_TEST);
    glBegin(GL_QUADS);
    for (uint16_t k = 0; k < truemaze_cells(m); k++) {
        if (!colours[k]) continue;
        double x0 = truemaze_x(m, (truemaze_cell_t)k) * cell + CELL_MARGIN_M, y0 = truemaze_y(m, (truemaze_cell_t)k) * cell + CELL_MARGIN_M,
               x1 = x0 + cell - 2 * CELL_MARGIN_M, y1 = y0 + cell - 2 * CELL_MARGIN_M, z = 0.0008; /* over the start and goal tiles */
        colour(scene_cell_rgb(colours[k]), 1);
        glVertex3d(x0, y0, z), glVertex3d(x1, y0, z), glVertex3d(x1, y1, z), glVertex3d(x0, y1, z);
    }
    double inner = cell - 2 * CELL_MARGIN_M - 0.01; /* the text's room, m */
    for (uint16_t k = 0; texts && k < truemaze_cells(m); k++) {
        const char *t = texts + k * stride;
        if (!t[0]) continue;
        int len = (int)strnlen(t, CELL_TEXT_MAX);
        double px = inner / ((len > CELL_TEXT_FULL ? len : CELL_TEXT_FULL) * FONT_ADVANCE);
        uint32_t bg = colours[k] ? scene_cell_rgb(colours[k]) : SCENE_FLOOR;
        double luma = 0.299 * ((bg >> 16) & 255) + 0.587 * ((bg >> 8) & 255) + 0.114 * (bg & 255); /* Rec. 601 weights */
        colour(luma < 128 ? 0xFFFFFFu : 0x000000u, 1);
        floor_text(t, (truemaze_x(m, (truemaze_cell_t)k) + 0.5) * cell, (truemaze_y(m, (truemaze_cell_t)k) + 0.5) * cell, 0.0011, px, ux, uy);
    }
    glEnd();
    glDisable(GL_LIGHTING);
    glDisable(GL_DEPTH_TEST);
}

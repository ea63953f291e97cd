/* diagref.c - the expected reading of a diagonal ToF sensor on the known
 * map (diagref.h). */
#include "diagref.h"

#include "plan.h"

#if PLAN_ENABLED
#include <math.h>

#include "robot_config.h"
#include "walls.h"

#define HALF_WALL_MM (RC_WALL_MM / 2) /* posts are as wide as the walls */

typedef struct {
    float t_mm;     /* along the ray to the nearest hit, or the range */
    int8_t face;    /* 0: a face across x, 1: across y, -1 none */
    float plane_mm; /* the hit face's coordinate (x for a face across x) */
    float unknown_mm; /* along the ray to the nearest unknown wall */
} ray_hit_t;

/* Ray (ox, oy) + t (dx, dy) against the box [x0, x1] x [y0, y1]: the
 * entry distance (-1: missed) and the face it enters through. */
static float ray_box(float ox, float oy, float dx, float dy, float x0, float x1, float y0, float y1, int8_t *face)
{
    float tmin = -1e9f, tmax = 1e9f;
    int8_t f = -1;
    float o[2] = {ox, oy}, d[2] = {dx, dy}, lo[2] = {x0, y0}, hi[2] = {x1, y1};
    for (int8_t a = 0; a < 2; a++) {
        if (fabsf(d[a]) < 1e-6f) {
            if (o[a] < lo[a] || o[a] > hi[a]) return -1.0f;
            continue;
        }
        float t1 = (lo[a] - o[a]) / d[a], t2 = (hi[a] - o[a]) / d[a];
        if (t1 > t2) {
            float s = t1;
            t1 = t2;
            t2 = s;
        }
        if (t1 > tmin) {
            tmin = t1;
            f = a;
        }
        if (t2 < tmax) tmax = t2;
    }
    if (tmin > tmax || tmin < 0.0f) return -1.0f;
    *face = f;
    return tmin;
}

static void ray_keep(ray_hit_t *h, float t, int8_t face, float plane, uint8_t unknown)
{
    if (t < 0.0f) return;
    if (unknown) {
        if (t < h->unknown_mm) h->unknown_mm = t;
        return;
    }
    if (t < h->t_mm) {
        h->t_mm = t;
        h->face = face;
        h->plane_mm = plane;
    }
}

/* The ray from (ox, oy) along (dx, dy) against the box [x0, x1] x
 * [y0, y1] (an unknown wall: only how near it is). */
static void ray_try(ray_hit_t *h, const float o[2], const float d[2], float x0, float x1, float y0, float y1, uint8_t unknown)
{
    int8_t f;
    float t = ray_box(o[0], o[1], d[0], d[1], x0, x1, y0, y1, &f);
    if (t < 0.0f) return;
    float lo = f == 0 ? x0 : y0, hi = f == 0 ? x1 : y1;
    ray_keep(h, t, f, d[f] > 0.0f ? lo : hi, unknown);
}

/* One ray against the posts, the east and north walls of the cells within
 * reach and the west and south boundary walls. */
static void ray_cast(const maze_t *m, const float o[2], const float d[2], float max_mm, ray_hit_t *h)
{
    h->t_mm = max_mm;
    h->face = -1;
    h->plane_mm = 0;
    h->unknown_mm = 1e9f;
    int cx0 = (int)floorf((o[0] - max_mm) / RC_CELL_MM) - 1, cx1 = (int)floorf((o[0] + max_mm) / RC_CELL_MM) + 1;
    int cy0 = (int)floorf((o[1] - max_mm) / RC_CELL_MM) - 1, cy1 = (int)floorf((o[1] + max_mm) / RC_CELL_MM) + 1;
    const float w = HALF_WALL_MM, c = RC_CELL_MM;
    for (int cy = cy0 < -1 ? -1 : cy0; cy <= cy1 && cy < m->height; cy++)
        for (int cx = cx0 < -1 ? -1 : cx0; cx <= cx1 && cx < m->width; cx++) {
            float px = (float)(cx + 1) * c, py = (float)(cy + 1) * c; /* its north-east post */
            ray_try(h, o, d, px - w, px + w, py - w, py + w, 0);
            if (cx < 0 && cy >= 0) ray_try(h, o, d, -w, w, py - c + w, py - w, 0); /* west boundary */
            if (cy < 0 && cx >= 0) ray_try(h, o, d, px - c + w, px - w, -w, w, 0); /* south boundary */
            if (cx < 0 || cy < 0) continue;
            maze_cell_t cell = maze_cell(m, (uint8_t)cx, (uint8_t)cy);
            uint8_t e = maze_wall(m, cell, MAZE_EAST), n = maze_wall(m, cell, MAZE_NORTH);
            if (e != MAZE_WALL_OPEN) ray_try(h, o, d, px - w, px + w, py - c + w, py - w, e == MAZE_WALL_UNKNOWN);
            if (n != MAZE_WALL_OPEN) ray_try(h, o, d, px - c + w, px - w, py - w, py + w, n == MAZE_WALL_UNKNOWN);
        }
}

float diagref_expect(const maze_t *m, float x_mm, float y_mm, float ang_rad, float max_mm, float margin_mm)
{
    const float fov = RC_TOF_FOV_DEG * 0.01745329f;
    ray_hit_t h[RC_TOF_RAYS];
    int best = -1;
    for (int i = 0; i < RC_TOF_RAYS; i++) {
        float a = ang_rad; /* rays evenly over the cone; one ray on its axis */
        if (RC_TOF_RAYS > 1) a += fov * ((float)i / (float)(RC_TOF_RAYS - 1) - 0.5f);
        float o[2] = {x_mm, y_mm}, d[2] = {cosf(a), sinf(a)};
        ray_cast(m, o, d, max_mm, &h[i]);
        if (h[i].face >= 0 && (best < 0 || h[i].t_mm < h[best].t_mm)) best = i;
    }
    if (best < 0) return -1.0f;
    /* the face square to the axis: across x for an axis along x */
    int8_t square = fabsf(cosf(ang_rad)) > fabsf(sinf(ang_rad)) ? 0 : 1;
    if (h[best].face != square) return -1.0f;
    for (int i = 0; i < RC_TOF_RAYS; i++) {
        if (h[i].unknown_mm <= h[best].t_mm + margin_mm) return -1.0f;
        uint8_t same = h[i].face == square && fabsf(h[i].plane_mm - h[best].plane_mm) < 0.5f;
        if (h[i].face >= 0 && !same && h[i].t_mm < h[best].t_mm + margin_mm) return -1.0f;
    }
    return h[best].t_mm;
}

/* The diagonal reference (RC_DIAG_TOF, diagref.h): the robot's position in
 * the maze (mm from the outer corner of cell (0, 0), x east, y north) is
 * p plus odometry's travel since the diagonal began, turned into the
 * maze's frame by psi; p starts where the plan has the robot then and
 * each trusted side reading moves it. On a diagonal the left sensor looks
 * along one maze axis and the right one along the other, so the estimate's
 * x and y are two independent one-dimensional Kalman filters (variance
 * var: RC_DIAG_TOF_START_MM at the start, growing by
 * RC_DIAG_TOF_DRIFT_MM2 per mm driven; a reading's variance (RC_TOF_CV x
 * its distance)^2). */

/* A diagonal straight starts from the node (x2, y2) (half units: cell
 * (x, y)'s centre at (2x, 2y)) heading h8 (eighths clockwise from north),
 * the robot carry_mm short of it (a speed run: a turn's straight after
 * it): the reference's starting point. Speed runs and command mode's
 * diagonals (cmd.c diagonal). */
void diagref_anchor(diagref_t *g, const motion_t *mo, int16_t x2, int16_t y2, uint8_t h8, float carry_mm)
{
    float a = 1.5707963f - 0.7853982f * (float)h8; /* the heading, counter-clockwise from east */
    g->lx = (float)(x2 + 1) * (RC_CELL_MM / 2);
    g->ly = (float)(y2 + 1) * (RC_CELL_MM / 2);
    g->px = g->lx - carry_mm * cosf(a);
    g->py = g->ly - carry_mm * sinf(a);
    g->ox = mo->odom.x_mm;
    g->oy = mo->odom.y_mm;
    g->psi = a - 1.5707963f - mo->heading_rad;
    g->a = a;
    g->var[0] = g->var[1] = RC_DIAG_TOF_START_MM * RC_DIAG_TOF_START_MM;
    g->dist_mm = mo->odom.dist_mm;
    g->seq[0] = walls_distance(HAL_TOF_LEFT).seq;
    g->seq[1] = walls_distance(HAL_TOF_RIGHT).seq;
}

/* On a diagonal straight: each new side reading that diagref_expect
 * trusts (and within RC_DIAG_TOF_GATE_MM of it) moves the position
 * estimate along the sensor's axis by the filter's gain times the
 * difference; the estimate's offset right of the diagonal's line steers
 * (mo->lateral_mm) as wall centring does. */
void diagref_centring(diagref_t *g, motion_t *mo, const maze_t *map)
{
    float cp = cosf(g->psi), sp = sinf(g->psi), dx = mo->odom.x_mm - g->ox, dy = mo->odom.y_mm - g->oy;
    float px = g->px + cp * dx - sp * dy, py = g->py + sp * dx + cp * dy;
    float b = 1.5707963f + mo->odom.theta_rad + g->psi, cb = cosf(b), sb = sinf(b);
    float grow = RC_DIAG_TOF_DRIFT_MM2 * (mo->odom.dist_mm - g->dist_mm);
    g->var[0] += grow;
    g->var[1] += grow;
    g->dist_mm = mo->odom.dist_mm;
    for (uint8_t i = 0; i < 2; i++) {
        hal_distance_t d = walls_distance(i ? HAL_TOF_RIGHT : HAL_TOF_LEFT);
        if (d.seq == g->seq[i]) continue;
        g->seq[i] = d.seq;
        if (d.timeout || fabsf(mo->odom.theta_rad - mo->heading_rad) > 0.035f) continue; /* 2 degrees: turning */
        float side = i ? -RC_TOF_SIDE_X_MM : RC_TOF_SIDE_X_MM; /* to the left */
        float sx = px + RC_TOF_SIDE_Y_MM * cb - side * sb, sy = py + RC_TOF_SIDE_Y_MM * sb + side * cb;
        float ax = b + (i ? -0.7853982f : 0.7853982f);
        float e = diagref_expect(map, sx, sy, ax, RC_DIAG_TOF_MAX_MM, RC_DIAG_TOF_MARGIN_MM);
        if (e < 0 || fabsf((float)d.mm - e) > RC_DIAG_TOF_GATE_MM) continue;
        uint8_t ay = fabsf(cosf(ax)) < fabsf(sinf(ax)); /* the axis is the maze's y */
        float r = RC_TOF_CV * e, gain = g->var[ay] / (g->var[ay] + r * r), k = gain * (e - (float)d.mm);
        g->var[ay] *= 1.0f - gain;
        g->px += k * cosf(ax);
        g->py += k * sinf(ax);
        px += k * cosf(ax);
        py += k * sinf(ax);
    }
    mo->lateral_mm = (px - g->lx) * sinf(g->a) - (py - g->ly) * cosf(g->a);
    mo->lateral_valid = 1;
}
#endif

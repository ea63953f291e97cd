/* test_slalom.c - the speed run's turns as slalom_fit_kinds sizes them for the
 * paper robot (firmware/robot_config.h): each turn's path, integrated from
 * the same discrete rotation profile the control tick runs, goes from its
 * entry node to its exit node on the exit heading, agrees with
 * motion_slalom_geometry, costs the planner its own time, stays within
 * the tyres' grip and the motor's top speed, and keeps the body clear of
 * the posts and of every wall the turn does not cross (slalom.h: those may
 * be closed). */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <cmocka.h>

#include <math.h>

#include "hal.h"
#include "motion.h"
#include "plan.h"
#include "profile.h"
#include "robot_config.h"
#include "slalom.h"

#define HALF_MM (RC_CELL_MM / 2)
#define D2R 0.017453293
#ifndef BODY_X_MM
/* the body as robots/paper.ini has it: 96 x 120 mm about the axle, wheels
 * 8 mm wide on a 96 mm track (out to 52 mm), 32 mm across (a build for
 * another robot gives its own: the Makefile's test_slalom_ukb) */
#define BODY_X_MM 48.0
#define BODY_Y_MM 60.0
#define WHEEL_X_MM 52.0
#define WHEEL_Y_MM 16.0
#endif
#define POST_HALF_MM 6.0 /* 12 mm posts and walls (classic rules, sim/world/config.c) */
/* clearance asked: a diagonal itself passes the posts 3.1 mm off (robot_config.h
 * RC_DIAG_*), so turns to or from one get that; the others a margin for
 * the robot's lag behind its profile */
#ifndef DIAG_CLEAR_MM
#define DIAG_CLEAR_MM 3.0
#endif
#define ORTHO_CLEAR_MM 10.0
#define GRIP_MM_S2 2943.0  /* 0.3 g: a third of the tyres' mu 1.0 */
/* the wheel speed a feed-forward cap can hold, mm/s (robot_config.h: 676 at RC_CMD_FF_MAX) */
#define WHEEL_TOP_MM_S(cap) (((cap) - RC_CMD_FRICTION) * RC_MM_S_PER_CMD)

typedef struct {
    double x, y, th; /* mm, rad clockwise from the entry heading's frame's +y */
} pose_t;

#define MAX_POSES 2000
static pose_t poses[MAX_POSES];
static int n_poses;

static void add(double x, double y, double th)
{
    if (n_poses < MAX_POSES) poses[n_poses++] = (pose_t){x, y, th};
}

/* distance from (px, py) to an axis-aligned box, 0 inside */
static double box_dist(double px, double py, double cx, double cy, double hx, double hy)
{
    double dx = fabs(px - cx) - hx, dy = fabs(py - cy) - hy;
    if (dx < 0) dx = 0;
    if (dy < 0) dy = 0;
    return hypot(dx, dy);
}

/* the nearest any point of a rectangle (half sizes ax, ay about the
 * robot's axle) comes to the box, over all poses */
static double rect_clear(double ax, double ay, double cx, double cy, double hx, double hy)
{
    double best = 1e9;
    for (int i = 0; i < n_poses; i++) {
        double c = cos(poses[i].th), s = sin(poses[i].th);
        for (double u = -1; u <= 1.0001; u += 1.0 / 16) {
            double pts[4][2] = {{u * ax, ay}, {u * ax, -ay}, {ax, u * ay}, {-ax, u * ay}};
            for (int k = 0; k < 4; k++) {
                double px = poses[i].x + pts[k][0] * c + pts[k][1] * s;
                double py = poses[i].y - pts[k][0] * s + pts[k][1] * c;
                double d = box_dist(px, py, cx, cy, hx, hy);
                if (d < best) best = d;
            }
        }
    }
    return best;
}

static int crossed(const slalom_geom_t *g, int x, int y)
{
    if (x == 0 && y == 0) return 1;
    for (int i = 0; i < g->crossed; i++)
        if (g->cross[i][0] == x && g->cross[i][1] == y) return 1;
    return 0;
}

/* the body's clearance from the posts and the walls not crossed, in the
 * table's frame (half units of HALF_MM); `vert`: the entry node is the
 * middle of a wall along y (posts then at (even, odd)), else along x */
static double clearance(const slalom_geom_t *g, int vert)
{
    double best = 1e9;
    for (int x = -6; x <= 8; x++)
        for (int y = -6; y <= 8; y++) {
            int xo = (vert ? y : x) & 1, yo = (vert ? x : y) & 1; /* as if the entry were along x */
            double hx, hy;
            if (xo && !yo) hx = hy = POST_HALF_MM;
            else if (!xo && !yo && !crossed(g, x, y)) hx = HALF_MM - POST_HALF_MM, hy = POST_HALF_MM;
            else if (xo && yo && !crossed(g, x, y)) hx = POST_HALF_MM, hy = HALF_MM - POST_HALF_MM;
            else continue;
            if (vert && !(xo && !yo)) { double t = hx; hx = hy; hy = t; } /* walls turn with the grid */
            double cx = x * HALF_MM, cy = y * HALF_MM;
            double c = fmin(rect_clear(BODY_X_MM, BODY_Y_MM, cx, cy, hx, hy), rect_clear(WHEEL_X_MM, WHEEL_Y_MM, cx, cy, hx, hy));
            if (c < best) best = c;
        }
    return best;
}

/* the turn kind as driven at v with d, the feed-forward capped at cap:
 * its poses from the entry node (the entry heading h0 rad), as motion.c
 * integrates it; returns the peak rate */
static double drive(const slalom_geom_t *g, const slalom_drive_t *d, double v, float cap, double *end_x, double *end_y,
                    double *end_th)
{
    const float dt = 1.0f / HAL_TICK_HZ;
    double h0 = g->from_diag ? 45 * D2R : 0, x = 0, y = 0, th = h0, peak = 0;
    n_poses = 0;
    for (double s = 0; s < d->before_mm; s += 2) add(s * sin(h0), s * cos(h0), h0);
    x = d->before_mm * sin(h0);
    y = d->before_mm * cos(h0);
    profile_t p;
    profile_reset(&p);
    profile_start(&p, 45.0f * g->turn, d->w_deg_s, 0, RC_SLALOM_ACCEL_DEG_S2);
    while (p.active) {
        float vw = (float)v + fabsf(p.speed) * (float)D2R * (RC_TRACK_MM / 2);
        float spare = cap - RC_CMD_FRICTION - vw / RC_MM_S_PER_CMD;
        profile_update_capped(&p, dt, spare * (1.0f / (RC_CMD_PER_ARC_MM_S2 * (RC_TRACK_MM / 2) * (float)D2R)));
        double w = p.speed * D2R;
        if (w > peak) peak = w;
        x += v * dt * sin(th + 0.5 * w * dt);
        y += v * dt * cos(th + 0.5 * w * dt);
        th += w * dt;
        add(x, y, th);
    }
    for (double s = 0; s < d->after_mm; s += 2) add(x + s * sin(th), y + s * cos(th), th);
    *end_x = x + d->after_mm * sin(th);
    *end_y = y + d->after_mm * cos(th);
    *end_th = th;
    return peak;
}

/* every turn kind k at v_kind[k] mm/s */
static void check_speeds(const float v_kind[SLALOM_KINDS], float cap)
{
    slalom_drive_t d[SLALOM_KINDS];
    float turn_s[SLALOM_KINDS];
    slalom_fit_kinds(v_kind, cap, d, turn_s);
    for (int k = SLALOM_S90; k < SLALOM_KINDS; k++) {
        const slalom_geom_t *g = &slalom_geom[k];
        float v = v_kind[k];
        if (d[k].w_deg_s <= 0) {
            assert_true(turn_s[k] < 0); /* not planned */
            continue;
        }
        double ex, ey, eth;
        double peak = drive(g, &d[k], v, cap, &ex, &ey, &eth);
        /* it ends on the exit node, on the exit heading */
        if (fabs(ex - g->exit_x * HALF_MM) >= 1.0 || fabs(ey - g->exit_y * HALF_MM) >= 1.0)
            print_message("kind %d at %.0f mm/s ends at (%.1f, %.1f) mm\n", k, (double)v, ex, ey);
        assert_true(fabs(ex - g->exit_x * HALF_MM) < 1.0 && fabs(ey - g->exit_y * HALF_MM) < 1.0);
        assert_true(fabs(eth - 45 * D2R * (g->from_diag + g->turn)) < 1e-3);
        /* the planner's time is the path's at v */
        assert_true(fabsf(turn_s[k] - (d[k].before_mm + d[k].arc_mm + d[k].after_mm) / v) < 1e-4f);
        /* grip and motor */
        assert_true(v * peak < GRIP_MM_S2);
        assert_true(v + peak * RC_TRACK_MM / 2 < WHEEL_TOP_MM_S(cap));
        /* the entry node's wall: along x, except where only the other kind
         * lets an orthogonal exit cross its own side (D135) */
        int exit_h = (g->from_diag + g->turn) & 7, vert = 0;
        if (!(exit_h & 1)) {
            int exit_vert = exit_h == 2 || exit_h == 6, same = !((g->exit_x | g->exit_y) & 1);
            vert = same ? exit_vert : !exit_vert;
        }
        double c = clearance(g, vert);
        int diag = g->from_diag || ((g->from_diag + g->turn) & 1);
        print_message("kind %d at %.0f mm/s: peak %.2f rad/s, corner at %.1f mm, clearance %.1f mm\n", k, (double)v, peak,
                      (double)(HALF_MM * hypot(g->corner_x, g->corner_y) - d[k].before_mm), c);
        assert_true(c >= (diag ? DIAG_CLEAR_MM : ORTHO_CLEAR_MM));
    }
}

/* every turn kind at one speed v */
static void check_speed(float v, float cap)
{
    float v_kind[SLALOM_KINDS];
    for (int k = 0; k < SLALOM_KINDS; k++) v_kind[k] = v;
    check_speeds(v_kind, cap);
}

/* the speed runs' turns, each kind at its own speed (robot_config.h
 * RC_SLALOM_*_MM_S): safe, and fast under the fast runs' cap */
static void test_safe_speed(void **state)
{
    (void)state;
    float v[SLALOM_KINDS];
    slalom_run_speeds(0, v);
    check_speeds(v, RC_CMD_FF_MAX);
}

static void test_fast_speed(void **state)
{
    (void)state;
    float v[SLALOM_KINDS];
    slalom_run_speeds(1, v);
    check_speeds(v, RC_RUN_FAST_CMD_FF_MAX);
}

/* and below them, where robot_config.h's figures were checked too */
static void test_300_mm_s(void **state)
{
    (void)state;
    check_speed(300.0f, RC_CMD_FF_MAX);
}

/* the geometry function's corner agrees with the path: a 90 at 300 mm/s */
static void test_geometry_agrees(void **state)
{
    (void)state;
    slalom_drive_t d[SLALOM_KINDS];
    float turn_s[SLALOM_KINDS];
    float v[SLALOM_KINDS];
    for (int k = 0; k < SLALOM_KINDS; k++) v[k] = 300.0f;
    slalom_fit_kinds(v, RC_CMD_FF_MAX, d, turn_s);
    float corner, post, len;
    motion_slalom_geometry(300.0f, 90.0f, d[SLALOM_F90].w_deg_s, RC_SLALOM_ACCEL_DEG_S2, RC_CMD_FF_MAX, &corner, &post, &len);
    assert_true(fabsf(corner - (3 * HALF_MM - d[SLALOM_F90].before_mm)) < 0.01f);
    assert_true(fabsf(post - (3 * HALF_MM - d[SLALOM_F90].after_mm)) < 0.01f);
    assert_true(fabsf(len - d[SLALOM_F90].arc_mm) < 0.01f);
    assert_true(corner <= RC_SLALOM_F90_MM + 0.01f && corner > RC_SLALOM_F90_MM - 1.0f);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_safe_speed),
        cmocka_unit_test(test_fast_speed),
        cmocka_unit_test(test_300_mm_s),
        cmocka_unit_test(test_geometry_agrees),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}

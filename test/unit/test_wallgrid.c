/* test_wallgrid.c - the cell index that picks the boxes a ray may hit
 * (sim/world/wallgrid) never misses one: for random boxes laid out as a
 * maze's posts and walls and random segments (from inside and outside the
 * maze, along cell edges, through post centres, straight up), every box
 * the segment truly meets (an exact slab test over all boxes) is visited,
 * each box at most once; and when the caller reports its nearest hit, the
 * walk that stops early still finds the nearest box of all; and the
 * rectangle queries that let a robot far from every wall skip the maze's
 * collision tree, and list the boxes near a robot part, answer as a test
 * of every box would. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <cmocka.h>

#include <math.h>
#include <stdint.h>
#include <string.h>

#include "world/wallgrid.h"

#define CELL_M 0.18
#define POST_M 0.012
#define SIDE 16         /* cells a side */
#define MAXBOX 1200
#define RAYS 50000

static double box[MAXBOX][4];
static int nbox;

static uint64_t rng_state = 88172645463325252ull;
static double uniform(void) /* xorshift64: [0, 1) */
{
    rng_state ^= rng_state << 13, rng_state ^= rng_state >> 7, rng_state ^= rng_state << 17;
    return (double)(rng_state >> 11) / 9007199254740992.0;
}

static void add(double x, double y, double lx, double ly)
{
    box[nbox][0] = x - lx / 2, box[nbox][1] = x + lx / 2, box[nbox][2] = y - ly / 2, box[nbox][3] = y + ly / 2;
    nbox++;
}

/* Posts at every corner, about half the walls, all of the outer ones. */
static void layout(void)
{
    nbox = 0;
    for (int y = 0; y <= SIDE; y++)
        for (int x = 0; x <= SIDE; x++) add(x * CELL_M, y * CELL_M, POST_M, POST_M);
    for (int y = 0; y <= SIDE; y++)
        for (int x = 0; x <= SIDE; x++) {
            if (x < SIDE && (y == 0 || y == SIDE || uniform() < 0.5))
                add((x + 0.5) * CELL_M, y * CELL_M, CELL_M - POST_M, POST_M);
            if (y < SIDE && (x == 0 || x == SIDE || uniform() < 0.5))
                add(x * CELL_M, (y + 0.5) * CELL_M, POST_M, CELL_M - POST_M);
        }
}

/* Exact: the t of the segment's entry into box i, or -1 when it misses. */
static double entry(int i, const double p[2], const double d[2])
{
    double t0 = 0, t1 = 1;
    for (int k = 0; k < 2; k++) {
        double lo = box[i][2 * k], hi = box[i][2 * k + 1];
        if (d[k] == 0) {
            if (p[k] < lo || p[k] > hi) return -1;
            continue;
        }
        double a = (lo - p[k]) / d[k], b = (hi - p[k]) / d[k];
        if (a > b) { double t = a; a = b; b = t; }
        if (a > t0) t0 = a;
        if (b < t1) t1 = b;
    }
    return t0 <= t1 ? t0 : -1;
}

typedef struct {
    int hits[MAXBOX];
    const double *p, *d;
    double best; /* nearest entry so far; INFINITY: none */
    int report;  /* return the nearest hit (early stop), or always INFINITY */
} seen_t;

static double visit(void *ctx, int id)
{
    seen_t *s = ctx;
    s->hits[id]++;
    double t = entry(id, s->p, s->d);
    if (t >= 0 && t < s->best) s->best = t;
    return s->report ? s->best : INFINITY;
}

/* A segment from a random point or a grid line or a post centre, in a
 * random or axis-aligned direction, 0.5 m long, or straight up. */
static void segment(double p[2], double d[2])
{
    double span = (SIDE + 2) * CELL_M;
    p[0] = uniform() * span - CELL_M, p[1] = uniform() * span - CELL_M;
    int kind = (int)(uniform() * 5);
    if (kind == 1) p[0] = floor(p[0] / CELL_M) * CELL_M;
    if (kind == 2) p[0] = floor(p[0] / CELL_M) * CELL_M, p[1] = floor(p[1] / CELL_M) * CELL_M;
    double a = uniform() * 2 * M_PI, len = 0.5;
    if (kind == 3) a = floor(uniform() * 4) * M_PI / 2;
    d[0] = len * cos(a), d[1] = len * sin(a);
    if (kind == 3) d[(int)(uniform() * 2)] = 0;
    if (kind == 4 && uniform() < 0.1) d[0] = d[1] = 0;
}

static void test_no_box_missed(void **state)
{
    (void)state;
    layout();
    wallgrid_t *g = wallgrid_build(CELL_M, SIDE, SIDE, nbox, (const double (*)[4])box);
    assert_non_null(g);
    static seen_t s;
    for (int r = 0; r < RAYS; r++) {
        double p[2], d[2];
        segment(p, d);
        memset(s.hits, 0, sizeof s.hits);
        s.p = p, s.d = d, s.best = INFINITY, s.report = 0;
        wallgrid_ray(g, p, d, visit, &s);
        for (int i = 0; i < nbox; i++) {
            if (s.hits[i] > 1) fail_msg("ray %d: box %d visited %d times", r, i, s.hits[i]);
            if (entry(i, p, d) >= 0 && !s.hits[i])
                fail_msg("ray %d from (%.17g, %.17g) by (%.17g, %.17g): box %d missed", r, p[0], p[1], d[0], d[1], i);
        }
    }
    wallgrid_free(g);
}

static void test_early_stop_keeps_nearest(void **state)
{
    (void)state;
    layout();
    wallgrid_t *g = wallgrid_build(CELL_M, SIDE, SIDE, nbox, (const double (*)[4])box);
    assert_non_null(g);
    static seen_t s;
    int stopped = 0;
    for (int r = 0; r < RAYS; r++) {
        double p[2], d[2], want = INFINITY;
        segment(p, d);
        for (int i = 0; i < nbox; i++) {
            double t = entry(i, p, d);
            if (t >= 0 && t < want) want = t;
        }
        memset(s.hits, 0, sizeof s.hits);
        s.p = p, s.d = d, s.best = INFINITY, s.report = 1;
        wallgrid_ray(g, p, d, visit, &s);
        if (s.best != want) fail_msg("ray %d: nearest entry %.17g, the walk found %.17g", r, want, s.best);
        int visited = 0, all = 0;
        for (int i = 0; i < nbox; i++) visited += s.hits[i] > 0, all += entry(i, p, d) >= 0;
        stopped += visited < all;
    }
    assert_true(stopped > RAYS / 10); /* the early stop does happen */
    wallgrid_free(g);
}

/* wallgrid_any: true whenever a box truly overlaps the rectangle, false
 * when every box is more than a micrometre away. */
static void test_any_overlap(void **state)
{
    (void)state;
    layout();
    wallgrid_t *g = wallgrid_build(CELL_M, SIDE, SIDE, nbox, (const double (*)[4])box);
    assert_non_null(g);
    int near = 0, clear = 0;
    for (int r = 0; r < RAYS; r++) {
        double span = (SIDE + 2) * CELL_M, x = uniform() * span - CELL_M, y = uniform() * span - CELL_M;
        double w = uniform() * 0.12, h = uniform() * 0.12;
        const double rect[4] = { x, x + w, y, y + h };
        int hit = 0, close = 0;
        for (int i = 0; i < nbox; i++) {
            hit |= box[i][0] <= rect[1] && rect[0] <= box[i][1] && box[i][2] <= rect[3] && rect[2] <= box[i][3];
            close |= box[i][0] - 1e-6 <= rect[1] && rect[0] <= box[i][1] + 1e-6 && box[i][2] - 1e-6 <= rect[3] &&
                     rect[2] <= box[i][3] + 1e-6;
        }
        int any = wallgrid_any(g, rect);
        if (hit && !any) fail_msg("rect %d: a box overlaps, wallgrid_any says none", r);
        if (!close && any) fail_msg("rect %d: no box near, wallgrid_any says one", r);
        near += any, clear += !any;
    }
    assert_true(near > 0 && clear > 0);
    wallgrid_free(g);
}

/* wallgrid_boxes: every box that overlaps the rectangle is listed, each
 * once, none more than a micrometre away; a NaN rectangle lists them all. */
static void test_boxes_listed(void **state)
{
    (void)state;
    layout();
    wallgrid_t *g = wallgrid_build(CELL_M, SIDE, SIDE, nbox, (const double (*)[4])box);
    assert_non_null(g);
    static int out[MAXBOX], count[MAXBOX];
    int listed = 0;
    for (int r = 0; r < RAYS; r++) {
        double span = (SIDE + 2) * CELL_M, x = uniform() * span - CELL_M, y = uniform() * span - CELL_M;
        double w = uniform() * 0.2, h = uniform() * 0.2;
        const double rect[4] = { x, x + w, y, y + h };
        int n = wallgrid_boxes(g, rect, out);
        memset(count, 0, sizeof count);
        for (int k = 0; k < n; k++) count[out[k]]++;
        for (int i = 0; i < nbox; i++) {
            int hit = box[i][0] <= rect[1] && rect[0] <= box[i][1] && box[i][2] <= rect[3] && rect[2] <= box[i][3];
            int close = box[i][0] - 1e-6 <= rect[1] && rect[0] <= box[i][1] + 1e-6 && box[i][2] - 1e-6 <= rect[3] &&
                        rect[2] <= box[i][3] + 1e-6;
            if (count[i] > 1) fail_msg("rect %d: box %d listed %d times", r, i, count[i]);
            if (hit && !count[i]) fail_msg("rect %d: box %d overlaps, not listed", r, i);
            if (!close && count[i]) fail_msg("rect %d: box %d far, listed", r, i);
        }
        listed += n;
    }
    assert_true(listed > 0);
    const double bad[4] = { NAN, 0, 0, 1 };
    assert_int_equal(wallgrid_boxes(g, bad, out), nbox);
    wallgrid_free(g);
}

/* wallgrid_any_box: whenever a point of a turned, slightly tilted box lies
 * inside a wall or post (0 to 50 mm high), the answer is "near"; and a box
 * in the open is "clear". */
static void test_any_box(void **state)
{
    (void)state;
    layout();
    wallgrid_t *g = wallgrid_build(CELL_M, SIDE, SIDE, nbox, (const double (*)[4])box);
    assert_non_null(g);
    int near = 0, clear = 0;
    for (int r = 0; r < RAYS / 10; r++) {
        double span = SIDE * CELL_M, yaw = uniform() * 2 * M_PI, tilt = (uniform() - 0.5) * 0.1;
        const double c[3] = { uniform() * span, uniform() * span, 0.02 }, half[3] = { 0.048, 0.06, 0.015 };
        const double axis[3][3] = { { cos(yaw), sin(yaw), 0 },
                                    { -sin(yaw) * cos(tilt), cos(yaw) * cos(tilt), sin(tilt) },
                                    { sin(yaw) * sin(tilt), -cos(yaw) * sin(tilt), cos(tilt) } };
        int inside = 0;
        for (int i = 0; i <= 10 && !inside; i++)
            for (int j = 0; j <= 10 && !inside; j++)
                for (int k = 0; k <= 2 && !inside; k++) {
                    double a = (i / 5.0 - 1) * half[0], b = (j / 5.0 - 1) * half[1], z = (k - 1.0) * half[2], q[3];
                    for (int m = 0; m < 3; m++) q[m] = c[m] + a * axis[0][m] + b * axis[1][m] + z * axis[2][m];
                    for (int n = 0; n < nbox && !inside; n++)
                        inside = q[0] >= box[n][0] && q[0] <= box[n][1] && q[1] >= box[n][2] && q[1] <= box[n][3] &&
                                 q[2] >= 0 && q[2] <= 0.05;
                }
        int any = wallgrid_any_box(g, c, axis, half, 0, 0.05, 0);
        if (inside && !any) fail_msg("box %d: a point of it is in a wall, wallgrid_any_box says clear", r);
        near += any, clear += !any;
    }
    assert_true(near > 0 && clear > 0);
    wallgrid_free(g);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_no_box_missed),
        cmocka_unit_test(test_early_stop_keeps_nearest),
        cmocka_unit_test(test_any_overlap),
        cmocka_unit_test(test_any_box),
        cmocka_unit_test(test_boxes_listed),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}

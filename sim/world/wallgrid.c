/* wallgrid.c - static boxes by cell, walked along a ray (see wallgrid.h). */
#include "wallgrid.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* Bounds grow by this much before they are filed, m: a segment that the
 * walk's rounding places a hair on the wrong side of a cell's edge still
 * finds every box within that hair (a spare candidate costs one exact test). */
#define WALLGRID_SLACK_M 1e-7

struct wallgrid {
    double cell_m, origin_m; /* the grid's corner: one cell below and left of the maze's */
    int nx, ny;              /* cells, the ring included */
    int n;                   /* boxes */
    int *start, *id;         /* the boxes of cell k: id[start[k]] .. id[start[k + 1] - 1] */
    double (*bound)[4];      /* each box's bounds grown by the slack, m */
    unsigned *seen, stamp;   /* per box: the last walk that visited it */
};

/* The cell index along one axis, clamped to the grid: below 0 is the first
 * cell, and from 0 up truncation is floor. */
static int cell_of(const wallgrid_t *g, double v_m, int n)
{
    double c = (v_m - g->origin_m) / g->cell_m;
    return c < 0 ? 0 : c >= n - 1 ? n - 1 : (int)c;
}

/* The cells box a covers: [x0, x1] x [y0, y1]. */
static void span(const wallgrid_t *g, const double a[4], int r[4])
{
    r[0] = cell_of(g, a[0] - WALLGRID_SLACK_M, g->nx), r[1] = cell_of(g, a[1] + WALLGRID_SLACK_M, g->nx);
    r[2] = cell_of(g, a[2] - WALLGRID_SLACK_M, g->ny), r[3] = cell_of(g, a[3] + WALLGRID_SLACK_M, g->ny);
}

/* Two passes over the boxes: count per cell, then file the ids. */
static void file_boxes(wallgrid_t *g, int n, const double (*aabb)[4])
{
    int r[4];
    for (int i = 0; i < n; i++) {
        span(g, aabb[i], r);
        for (int y = r[2]; y <= r[3]; y++)
            for (int x = r[0]; x <= r[1]; x++) g->start[y * g->nx + x + 1]++;
    }
    for (int k = 0; k < g->nx * g->ny; k++) g->start[k + 1] += g->start[k];
    int *fill = malloc(sizeof *fill * (size_t)(g->nx * g->ny));
    if (!fill) return;
    for (int k = 0; k < g->nx * g->ny; k++) fill[k] = g->start[k];
    for (int i = 0; i < n; i++) {
        span(g, aabb[i], r);
        for (int y = r[2]; y <= r[3]; y++)
            for (int x = r[0]; x <= r[1]; x++) g->id[fill[y * g->nx + x]++] = i;
    }
    free(fill);
}

wallgrid_t *wallgrid_build(double cell_m, int width, int height, int n, const double (*aabb)[4])
{
    wallgrid_t *g = calloc(1, sizeof *g);
    if (!g) return NULL;
    g->cell_m = cell_m, g->origin_m = -cell_m;
    g->nx = width + 2, g->ny = height + 2, g->n = n;
    size_t cells = (size_t)g->nx * (size_t)g->ny, filed = 0;
    g->start = calloc(cells + 1, sizeof *g->start);
    g->seen = calloc((size_t)n + 1, sizeof *g->seen);
    g->bound = malloc(sizeof *g->bound * ((size_t)n + 1));
    if (g->start && g->seen && g->bound) {
        int r[4];
        for (int i = 0; i < n; i++) {
            span(g, aabb[i], r);
            filed += (size_t)(r[1] - r[0] + 1) * (size_t)(r[3] - r[2] + 1);
        }
        g->id = malloc(sizeof *g->id * (filed + 1));
    }
    if (!g->start || !g->seen || !g->bound || !g->id) {
        wallgrid_free(g);
        return NULL;
    }
    for (int i = 0; i < n; i++)
        for (int k = 0; k < 4; k++) g->bound[i][k] = aabb[i][k] + (k % 2 ? WALLGRID_SLACK_M : -WALLGRID_SLACK_M);
    file_boxes(g, n, aabb);
    return g;
}

void wallgrid_free(wallgrid_t *g)
{
    if (!g) return;
    free(g->start);
    free(g->id);
    free(g->seen);
    free(g->bound);
    free(g);
}

/* A new walk: every box unvisited. */
static void next_stamp(wallgrid_t *g)
{
    if (++g->stamp == 0) { /* the stamp wrapped: forget every visit */
        memset(g->seen, 0, sizeof *g->seen * (size_t)(g->n + 1));
        g->stamp = 1;
    }
}

/* A segment p + t d, t in [0, 1], with 1 / d for the slab tests. */
typedef struct {
    double p[2], d[2], inv[2];
} seg_t;

/* The segment's stretch inside the slab lo..hi of axis k narrows [*t0, *t1]. */
static void slab(const seg_t *s, int k, double lo, double hi, double *t0, double *t1)
{
    if (s->d[k] == 0) {
        if (s->p[k] < lo || s->p[k] > hi) *t1 = -1;
        return;
    }
    double ta = (lo - s->p[k]) * s->inv[k], tb = (hi - s->p[k]) * s->inv[k];
    if (ta > tb) { double t = ta; ta = tb; tb = t; }
    if (ta > *t0) *t0 = ta;
    if (tb < *t1) *t1 = tb;
}

/* Whether the segment meets box i's grown bounds. */
static int meets(const wallgrid_t *g, int i, const seg_t *s)
{
    double t0 = 0, t1 = 1;
    slab(s, 0, g->bound[i][0], g->bound[i][1], &t0, &t1);
    if (t0 > t1) return 0;
    slab(s, 1, g->bound[i][2], g->bound[i][3], &t0, &t1);
    return t0 <= t1;
}

/* The boxes of cell (x, y) the segment meets, each visited once; the
 * nearest hit so far as visit last returned it (INFINITY before any). */
static double visit_cell(wallgrid_t *g, int x, int y, const seg_t *s, wallgrid_visit_fn visit, void *ctx, double best)
{
    if (x < 0 || y < 0 || x >= g->nx || y >= g->ny) return best;
    int k = y * g->nx + x;
    for (int j = g->start[k]; j < g->start[k + 1]; j++) {
        int i = g->id[j];
        if (g->seen[i] == g->stamp) continue;
        g->seen[i] = g->stamp;
        if (meets(g, i, s)) best = visit(ctx, i);
    }
    return best;
}

/* The walk in cell units: t runs from 0 at p to 1 at p + d; tx / ty is the
 * t of the next vertical / horizontal cell edge, dtx / dty the t of one
 * cell. Each step crosses the nearer edge; the walk takes as many steps as
 * the end's cell is edges away from the start's, and stops early once a hit
 * lies before the edge it would cross (a hit's point lies in a cell walked
 * already, and every box there was filed in it). */
void wallgrid_ray(wallgrid_t *g, const double p[2], const double d[2], wallgrid_visit_fn visit, void *ctx)
{
    next_stamp(g);
    if (!isfinite(p[0]) || !isfinite(p[1]) || !isfinite(d[0]) || !isfinite(d[1])) return;
    const seg_t s = { { p[0], p[1] }, { d[0], d[1] }, { 1.0 / d[0], 1.0 / d[1] } };
    double x0 = (p[0] - g->origin_m) / g->cell_m, y0 = (p[1] - g->origin_m) / g->cell_m;
    double dx = d[0] / g->cell_m, dy = d[1] / g->cell_m;
    int ix = (int)floor(x0), iy = (int)floor(y0);
    int ex = (int)floor(x0 + dx), ey = (int)floor(y0 + dy);
    int sx = dx > 0 ? 1 : dx < 0 ? -1 : 0, sy = dy > 0 ? 1 : dy < 0 ? -1 : 0;
    double dtx = sx ? 1.0 / fabs(dx) : INFINITY, dty = sy ? 1.0 / fabs(dy) : INFINITY;
    double tx = sx > 0 ? (ix + 1 - x0) * dtx : sx < 0 ? (x0 - ix) * dtx : INFINITY;
    double ty = sy > 0 ? (iy + 1 - y0) * dty : sy < 0 ? (y0 - iy) * dty : INFINITY;
    int steps = abs(ex - ix) + abs(ey - iy);
    double best = visit_cell(g, ix, iy, &s, visit, ctx, INFINITY);
    for (int k = 0; k < steps && best > (tx < ty ? tx : ty); k++) {
        if (tx < ty) ix += sx, tx += dtx;
        else iy += sy, ty += dty;
        best = visit_cell(g, ix, iy, &s, visit, ctx, best);
    }
}

int wallgrid_any(const wallgrid_t *g, const double r[4])
{
    if (!(r[0] <= r[1] && r[2] <= r[3])) return 1; /* not finite or empty: let the caller's full test decide */
    int c[4];
    span(g, r, c);
    for (int y = c[2]; y <= c[3]; y++)
        for (int x = c[0]; x <= c[1]; x++) {
            int k = y * g->nx + x;
            for (int j = g->start[k]; j < g->start[k + 1]; j++) {
                const double *b = g->bound[g->id[j]];
                if (b[0] <= r[1] && r[0] <= b[1] && b[2] <= r[3] && r[2] <= b[3]) return 1;
            }
        }
    return 0;
}

int wallgrid_boxes(wallgrid_t *g, const double r[4], int *out)
{
    int n = 0, c[4];
    if (!(r[0] <= r[1] && r[2] <= r[3])) {
        for (int i = 0; i < g->n; i++) out[i] = i;
        return g->n;
    }
    next_stamp(g);
    span(g, r, c);
    for (int y = c[2]; y <= c[3]; y++)
        for (int x = c[0]; x <= c[1]; x++) {
            int k = y * g->nx + x;
            for (int j = g->start[k]; j < g->start[k + 1]; j++) {
                int i = g->id[j];
                const double *b = g->bound[i];
                if (g->seen[i] == g->stamp || b[0] > r[1] || r[0] > b[1] || b[2] > r[3] || r[2] > b[3]) continue;
                g->seen[i] = g->stamp;
                out[n++] = i;
            }
        }
    return n;
}

/* Separated along unit axis u: the two centres' distance along u beyond the
 * sum of the two boxes' half extents along u (and the margin). */
static int apart_along(const double u[3], const double d[3], const double ea[3], const double axis[3][3],
                       const double half[3], double margin_m)
{
    double wall = 0, box = 0;
    for (int k = 0; k < 3; k++) {
        wall += fabs(u[k]) * ea[k];
        box += half[k] * fabs(u[0] * axis[k][0] + u[1] * axis[k][1] + u[2] * axis[k][2]);
    }
    return fabs(u[0] * d[0] + u[1] * d[1] + u[2] * d[2]) > wall + box + margin_m;
}

/* Whether box i (its grown bounds, z_lo..z_hi) and the oriented box are
 * apart along any of the six face axes. */
static int box_apart(const wallgrid_t *g, int i, const double c[3], const double axis[3][3], const double half[3],
                     double z_lo, double z_hi, double margin_m)
{
    const double *b = g->bound[i];
    const double d[3] = { 0.5 * (b[0] + b[1]) - c[0], 0.5 * (b[2] + b[3]) - c[1], 0.5 * (z_lo + z_hi) - c[2] };
    const double ea[3] = { 0.5 * (b[1] - b[0]), 0.5 * (b[3] - b[2]), 0.5 * (z_hi - z_lo) };
    static const double world[3][3] = { { 1, 0, 0 }, { 0, 1, 0 }, { 0, 0, 1 } };
    /* the world's axes first: along x and y that is the floor bounds' test,
     * which rejects most boxes of a cell */
    for (int k = 0; k < 3; k++)
        if (apart_along(world[k], d, ea, axis, half, margin_m)) return 1;
    for (int k = 0; k < 3; k++)
        if (apart_along(axis[k], d, ea, axis, half, margin_m)) return 1;
    return 0;
}

int wallgrid_any_box(const wallgrid_t *g, const double c[3], const double axis[3][3], const double half[3], double z_lo,
                     double z_hi, double margin_m)
{
    double r[4];
    for (int k = 0; k < 2; k++) {
        double e = margin_m;
        for (int j = 0; j < 3; j++) e += half[j] * fabs(axis[j][k]);
        r[2 * k] = c[k] - e, r[2 * k + 1] = c[k] + e;
    }
    if (!(r[0] <= r[1] && r[2] <= r[3])) return 1; /* not finite: let the caller's full test decide */
    int cell[4];
    span(g, r, cell);
    for (int y = cell[2]; y <= cell[3]; y++)
        for (int x = cell[0]; x <= cell[1]; x++) {
            int k = y * g->nx + x;
            for (int j = g->start[k]; j < g->start[k + 1]; j++)
                if (!box_apart(g, g->id[j], c, axis, half, z_lo, z_hi, margin_m)) return 1;
        }
    return 0;
}

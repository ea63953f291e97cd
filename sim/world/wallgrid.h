/* wallgrid.h - the maze's static boxes indexed by the cell they lie in, so
 * that a ray asks only the few boxes along its path (a 2D walk through the
 * cells, Amanatides and Woo's traversal) instead of a tree of all of them.
 *
 * The grid knows boxes only as integer ids and axis-aligned bounds; the
 * caller (world.c) keeps what the ids stand for and does the exact ray test
 * on each candidate: every box whose bounds the ray's floor projection
 * meets, each once. */
#ifndef WALLGRID_H
#define WALLGRID_H

typedef struct wallgrid wallgrid_t;

/* A grid of cell_m squares over the maze (width x height cells with its
 * corner at the origin) and one ring of cells around it, for the outer
 * walls' outside halves. aabb[i] = { min x, max x, min y, max y } in m for
 * box i of n. NULL when out of memory. */
wallgrid_t *wallgrid_build(double cell_m, int width, int height, int n, const double (*aabb)[4]);
void wallgrid_free(wallgrid_t *g);

/* The caller's exact test of box id; returns the nearest hit found so far
 * as a fraction of the segment (t in p + t d), INFINITY while none. */
typedef double (*wallgrid_visit_fn)(void *ctx, int id);

/* Call visit(ctx, id) once for each box whose floor bounds (grown by a
 * tenth of a micrometre) the segment from p (x, y, m) along d (x, y, m:
 * the horizontal extent of the whole ray) meets, cell by cell from p; the
 * walk ends once the nearest hit lies in the cells walked. */
void wallgrid_ray(wallgrid_t *g, const double p[2], const double d[2], wallgrid_visit_fn visit, void *ctx);

/* Whether any box's floor bounds (grown as above) overlap the rectangle
 * r = { min x, max x, min y, max y }, m. */
int wallgrid_any(const wallgrid_t *g, const double r[4]);

/* The boxes whose floor bounds (grown as above) overlap the rectangle
 * r = { min x, max x, min y, max y }, m, each once, into out (room for
 * every box); how many. Every box when r is not a rectangle (a NaN). */
int wallgrid_boxes(wallgrid_t *g, const double r[4], int *out);

/* Whether any box (its floor bounds grown as above, from z_lo to z_hi, m)
 * comes within margin_m of an oriented box: centre c (m), unit axes
 * axis[0..2] (each a column of the box's rotation in the world), half
 * lengths half[0..2] (m). Separation is looked for along the world's three
 * axes and the box's three (not their cross products): a "yes" may be a
 * near miss, a "no" is certain. */
int wallgrid_any_box(const wallgrid_t *g, const double c[3], const double axis[3][3], const double half[3], double z_lo,
                     double z_hi, double margin_m);

#endif

/* test_plan.c - the speed-run planner (firmware/plan.h) against hand-made
 * mazes with known best moves, a replay of every returned move on the
 * half-cell grid (legality and cost), an independent Bellman-Ford over the
 * same move set on random 6x6 mazes (the same optimal cost), and the
 * micromouseonline classic mazes ($SHARED/mazes/classic, default
 * ../shared): a path wherever the goal is reachable, never slower than the
 * orthogonal path with S90 turns only. Prints japan2018's and japan2019's
 * plans.
 *
 * The geometry here is written again from slalom.h's words, with direction
 * vectors instead of plan.c's rotations, and walls read from the cell on
 * the other side; the straights' times in double. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <cmocka.h>

#include <dirent.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "plan.h"
#include "maze/mazefile.h"
#include "maze/mazegen.h"
#include "maze/truebelief.h"

#define TOL_S 1e-4 /* cost agreement, s */
#define MOVES_MAX 1024 /* the tests' move buffers: zigzags of S90 turns in a classic maze pass MOVES_MAX */

static const int vx[8] = { 0, 1, 1, 1, 0, -1, -1, -1 }; /* heading vectors, half units */
static const int vy[8] = { 1, 1, 0, -1, -1, -1, 0, 1 };
static const char *const kind_name[SLALOM_KINDS] = { "O", "D", "S90", "F90", "F180", "F45", "F135", "D45", "D135", "V90" };

/* Turn path lengths in half units from slalom.h's geometry: the legs from
 * entry and exit to the corner, less what an arc of radius r (half units)
 * through angle a cuts off, plus the arc. */
static double turn_len_hu(double leg_in, double leg_out, double r, double a)
{
    return leg_in + leg_out - 2.0 * r * tan(a / 2.0) + r * a;
}

/* Plausible classic costs: 400 mm/s in every turn, 650 / 500 mm/s on
 * straights / diagonals, 3000 mm/s^2; each turn's time its path length at
 * 400 mm/s (radii: S90 90 mm, F90 180, F180 90, F45 180, F135 50, V90 70),
 * no legs (each turn's time from entry node to exit node). */
static plan_costs_t costs(float cell_mm)
{
    const double pi = 3.14159265358979, s2 = sqrt(2.0), hu = cell_mm / 2.0, v = 400.0;
    plan_costs_t c = { cell_mm, 650.0f, 500.0f, 3000.0f, { 0 }, { 0 }, { 0 }, { 0 } };
    for (int k = 0; k < SLALOM_KINDS; k++) c.v_turn_mm_s[k] = 400.0f;
    c.turn_s[SLALOM_S90] = (float)(turn_len_hu(1, 1, 1, pi / 2) * hu / v);
    c.turn_s[SLALOM_F90] = (float)(turn_len_hu(3, 3, 2, pi / 2) * hu / v);
    c.turn_s[SLALOM_F180] = (float)(pi * hu / v);
    c.turn_s[SLALOM_F45] = (float)(turn_len_hu(2, s2, 2, pi / 4) * hu / v);
    c.turn_s[SLALOM_F135] = (float)(turn_len_hu(2, s2, 50.0 / 90.0, 3 * pi / 4) * hu / v);
    c.turn_s[SLALOM_D45] = c.turn_s[SLALOM_F45];
    c.turn_s[SLALOM_D135] = c.turn_s[SLALOM_F135];
    c.turn_s[SLALOM_V90] = (float)(turn_len_hu(s2, s2, 70.0 / 90.0, pi / 2) * hu / v);
    return c;
}

/* Each turn kind at its own speed with straight legs at its ends (as the
 * firmware drives them, slalom_fit_kinds): the turn's time is its path length
 * less the legs, at its speed. Speeds mm/s: S90 350, F90 600, F180 450,
 * F45 and D45 500, F135 and D135 300, V90 380; legs: a tenth and a fifth of
 * a half unit (before, after) for all but the S90, which has none. */
static plan_costs_t costs_kinds(float cell_mm)
{
    static const float v[SLALOM_KINDS] = { 0, 0, 350, 600, 450, 500, 300, 500, 300, 380 };
    plan_costs_t c = costs(cell_mm);
    for (int k = SLALOM_S90; k < SLALOM_KINDS; k++) {
        float len_mm = c.turn_s[k] * c.v_turn_mm_s[k];
        c.before_mm[k] = k == SLALOM_S90 ? 0.0f : cell_mm * 0.05f;
        c.after_mm[k] = k == SLALOM_S90 ? 0.0f : cell_mm * 0.1f;
        c.v_turn_mm_s[k] = v[k];
        c.turn_s[k] = (len_mm - c.before_mm[k] - c.after_mm[k]) / v[k];
    }
    return c;
}

static plan_costs_t costs_s90_only(float cell_mm)
{
    plan_costs_t c = costs(cell_mm);
    for (int k = SLALOM_F90; k < SLALOM_KINDS; k++) c.turn_s[k] = 0.0f;
    return c;
}

/* Straight of d mm from v0 to v1, top speed vtop (at least v0, v1), s; -1
 * if it cannot be driven. */
static double straight_time(double d, double v0, double v1, double vtop, double a)
{
    double hi = fmax(v0, v1), lo = fmin(v0, v1);
    vtop = fmax(vtop, hi);
    if ((hi * hi - lo * lo) / (2 * a) > d * (1 + 1e-6)) return -1;
    double d_up = (vtop * vtop - v0 * v0) / (2 * a), d_down = (vtop * vtop - v1 * v1) / (2 * a);
    if (d_up + d_down <= d) return (vtop - v0) / a + (vtop - v1) / a + (d - d_up - d_down) / vtop;
    double vp = sqrt(fmax(hi * hi, (2 * a * d + v0 * v0 + v1 * v1) / 2));
    return (vp - v0) / a + (vp - v1) / a;
}

/* Open side at (gx, gy)? Read from the cell above (north/south sides) or to
 * the east (east/west sides), the boundary through the cell inside. */
static int side_is_open(const maze_t *m, int gx, int gy)
{
    int x, y, d;
    if (((gx ^ gy) & 1) == 0) return 0;
    if (gy & 1) { x = gx / 2; y = (gy + 1) / 2; d = MAZE_SOUTH; if (y == m->height) { y--; d = MAZE_NORTH; } }
    else { x = (gx + 1) / 2; y = gy / 2; d = MAZE_WEST; if (x == m->width) { x--; d = MAZE_EAST; } }
    if (gx < -1 || gy < -1 || x < 0 || y < 0 || x >= m->width || y >= m->height) return 0;
    return maze_wall(m, maze_cell(m, (uint8_t)x, (uint8_t)y), (uint8_t)d) == MAZE_WALL_OPEN;
}

typedef struct { int x, y, h; } pose_t;

static int fits(pose_t p)
{
    if (((p.x ^ p.y) & 1) == 0) return 0;
    if (p.h & 1) return 1;
    return (p.h == 0 || p.h == 4) ? (p.y & 1) : (p.x & 1);
}

/* Drive turn (kind, dir) from p: 1 and the exit in *out if every side it
 * crosses is open and it lands on a node that fits its exit heading. The
 * table's frame: forward = heading base, x to its right (dir mirrors). */
static int drive_turn(const maze_t *m, pose_t p, int kind, int dir, pose_t *out)
{
    const slalom_geom_t *g = &slalom_geom[kind];
    if (g->from_diag != (p.h & 1)) return 0;
    int base = (p.h - dir * g->from_diag + 8) % 8, right = (base + 2) % 8;
#define AT(px, py, axis) ((axis) == 0 ? p.x + dir * (px) * vx[right] + (py) * vx[base] \
                                       : p.y + dir * (px) * vy[right] + (py) * vy[base])
    for (int i = 0; i < g->crossed; i++)
        if (!side_is_open(m, AT(g->cross[i][0], g->cross[i][1], 0), AT(g->cross[i][0], g->cross[i][1], 1))) return 0;
    pose_t e = { AT(g->exit_x, g->exit_y, 0), AT(g->exit_x, g->exit_y, 1), (p.h + dir * g->turn + 8) % 8 };
    if (kind == SLALOM_V90) { /* the post inside the turn, next to its corner */
        int cx = AT(g->corner_x, g->corner_y, 0), cy = AT(g->corner_x, g->corner_y, 1);
        int ph = (p.h + 3 * dir + 8) % 8;
        if (!((cx + vx[ph]) & 1) || !((cy + vy[ph]) & 1)) return 0;
    }
#undef AT
    if (!fits(e)) return 0;
    *out = e;
    return 1;
}

/* Replay moves from the start: every side crossed open, every turn legal,
 * the run ends orthogonally at a goal cell's centre; returns its cost, s,
 * or -1 where it breaks a rule. Each straight runs from the speed of the
 * turn before it (at rest from the start) to that of the turn after it (to
 * rest at the end), that turn's legs included. */
static double replay(const maze_t *m, const plan_costs_t *c, const slalom_move_t *mv, int n)
{
    pose_t p = { 2 * maze_x(m, m->start), 2 * maze_y(m, m->start), 2 * m->start_heading };
    double t = 0, v0 = 0, len = 0; /* len: the straight so far, the leg of the turn before it included */
    for (int i = 0; i < n; i++) {
        double vtop = (p.h & 1) ? c->v_diag_mm_s : c->v_max_mm_s;
        if (mv[i].kind == SLALOM_ORTHO || mv[i].kind == SLALOM_DIAG) {
            if ((mv[i].kind == SLALOM_DIAG) != (p.h & 1) || mv[i].n == 0) return -1;
            if (i > 0 && mv[i - 1].kind <= SLALOM_DIAG) return -1;
            for (int k = 0; k < mv[i].n; k++) {
                p.x += vx[p.h];
                p.y += vy[p.h];
                if (((p.x ^ p.y) & 1) && !side_is_open(m, p.x, p.y)) return -1;
            }
            len += mv[i].n * c->cell_mm / 2.0 * ((p.h & 1) ? sqrt(2.0) : 1.0);
        } else {
            int k = mv[i].kind;
            if (i == 0 || mv[i].n != 1 || (mv[i].dir != 1 && mv[i].dir != -1) || !(c->turn_s[k] > 0)) return -1;
            double ts = straight_time(len + c->before_mm[k], v0, c->v_turn_mm_s[k], vtop, c->accel_mm_s2);
            if (ts < 0 || !drive_turn(m, p, k, mv[i].dir, &p)) return -1;
            t += ts + c->turn_s[k];
            v0 = c->v_turn_mm_s[k];
            len = c->after_mm[k];
        }
    }
    if (n == 0 || (p.x & 1) || (p.y & 1) || (p.h & 1) || mv[n - 1].kind != SLALOM_ORTHO) return -1;
    if (!maze_is_goal(m, maze_cell(m, (uint8_t)(p.x / 2), (uint8_t)(p.y / 2)))) return -1;
    double ts = straight_time(len, v0, 0, c->v_max_mm_s, c->accel_mm_s2);
    return ts < 0 ? -1 : t + ts;
}

static void print_plan(const char *name, const slalom_move_t *mv, int n, float t)
{
    printf("%s: %.4f s, %d moves:", name, t, n);
    for (int i = 0; i < n; i++) {
        if (mv[i].kind <= SLALOM_DIAG) printf(" %s%u", kind_name[mv[i].kind], mv[i].n);
        else printf(" %s%c", kind_name[mv[i].kind], mv[i].dir > 0 ? 'R' : 'L');
    }
    printf("\n");
}

/* Plan, check the moves by replay and the reported cost against it. */
static long kind_used[SLALOM_KINDS]; /* moves of each kind in the plans checked against the reference */

static int plan_checked(const maze_t *m, const plan_costs_t *c, slalom_move_t *mv, float *t)
{
    int n = plan_run(m, c, mv, MOVES_MAX, t);
    assert_true(n >= 0);
    if (n > 0) {
        double r = replay(m, c, mv, n);
        /* the planner sums in float: its ulp grows with the run's time */
        double tol = TOL_S + 2e-6 * r;
        if (r < 0 || fabs(r - *t) > tol) print_plan("bad plan", mv, n, *t);
        assert_true(r >= 0);
        assert_true(fabs(r - *t) <= tol);
    }
    return n;
}

/* ---- the reference: Bellman-Ford over (node, heading, the turn kind
 * that led there) after a turn ---- */

#define REF_MAX 8 /* cells per side */
#define REF_STATES ((2 * REF_MAX + 1) * (2 * REF_MAX + 1) * 8 * SLALOM_KINDS)
static double ref_d[REF_STATES];

static int ref_idx(const maze_t *m, pose_t p, int kind)
{
    return (((p.y + 1) * (2 * m->width + 1) + p.x + 1) * 8 + p.h) * SLALOM_KINDS + kind;
}

/* Every edge out of pose p reached by a turn of kind (the start: kind 0,
 * at rest), its time d so far: straights of 0.. half units from that
 * turn's speed and after its leg, each ended by a turn (its leg before
 * and its speed) or a stop at a goal cell's centre. */
static int ref_edges(const maze_t *m, const plan_costs_t *c, pose_t p, int kind, double d, double *best)
{
    int changed = 0;
    double v0 = kind ? c->v_turn_mm_s[kind] : 0, leg = kind ? c->after_mm[kind] : 0;
    double vtop = (p.h & 1) ? c->v_diag_mm_s : c->v_max_mm_s;
    pose_t q = p;
    for (int n = 0;; n++) {
        if (n > 0) {
            q.x += vx[p.h];
            q.y += vy[p.h];
            if (((q.x ^ q.y) & 1) && !side_is_open(m, q.x, q.y)) return changed;
        }
        double len = leg + n * c->cell_mm / 2.0 * ((p.h & 1) ? sqrt(2.0) : 1.0);
        if ((q.x ^ q.y) & 1) {
            for (int k = SLALOM_S90; k < SLALOM_KINDS; k++) {
                double ts = straight_time(len + c->before_mm[k], v0, c->v_turn_mm_s[k], vtop, c->accel_mm_s2);
                for (int dir = -1; dir <= 1 && c->turn_s[k] > 0 && ts >= 0; dir += 2) {
                    pose_t e;
                    if (!drive_turn(m, q, k, dir, &e)) continue;
                    double nd = d + ts + c->turn_s[k];
                    if (nd < ref_d[ref_idx(m, e, k)]) { ref_d[ref_idx(m, e, k)] = nd; changed = 1; }
                }
            }
        } else if (n > 0 && !(p.h & 1) && maze_is_goal(m, maze_cell(m, (uint8_t)(q.x / 2), (uint8_t)(q.y / 2)))) {
            double ts = straight_time(len, v0, 0, vtop, c->accel_mm_s2);
            if (ts >= 0 && d + ts < *best) *best = d + ts;
        }
    }
}

/* The best run's cost by relaxing every edge until nothing changes; HUGE_VAL if none. */
static double ref_best(const maze_t *m, const plan_costs_t *c)
{
    int gw = 2 * m->width + 1, ns = gw * (2 * m->height + 1) * 8 * SLALOM_KINDS;
    pose_t st = { 2 * maze_x(m, m->start), 2 * maze_y(m, m->start), 2 * m->start_heading };
    double best = HUGE_VAL;
    assert_true(m->width <= REF_MAX && m->height <= REF_MAX);
    for (int i = 0; i < ns; i++) ref_d[i] = HUGE_VAL;
    ref_d[ref_idx(m, st, 0)] = 0;
    for (int changed = 1; changed;) {
        changed = 0;
        for (int i = 0; i < ns; i++) {
            if (ref_d[i] == HUGE_VAL) continue;
            int kind = i % SLALOM_KINDS, ph = i / SLALOM_KINDS;
            pose_t p = { (ph / 8) % gw - 1, (ph / 8) / gw - 1, ph % 8 };
            changed |= ref_edges(m, c, p, kind, ref_d[i], &best);
        }
    }
    return best;
}

/* The firmware's map of a true maze (every wall known), as the simulator
 * hands it over at its seam (truebelief.h). */
static int generated(maze_t *m, uint8_t w, uint8_t h, uint32_t seed)
{
    static truemaze_t t;
    return mazegen_generate(&t, w, h, seed) != 0 ? -1 : truemaze_to_belief(&t, m);
}
static int loaded(maze_t *m, const char *path, char *err, size_t errlen)
{
    static truemaze_t t;
    return mazefile_load(&t, path, NULL, err, errlen) != 0 ? -1 : truemaze_to_belief(&t, m);
}

/* ---- hand-made mazes ---- */

static void closed_maze(maze_t *m, uint8_t w, uint8_t h)
{
    maze_init(m, w, h);
    maze_close_unknown(m);
}
static void open_wall(maze_t *m, uint8_t x, uint8_t y, uint8_t d)
{
    maze_set_wall(m, maze_cell(m, x, y), d, MAZE_WALL_OPEN);
}

static void expect_moves(const slalom_move_t *mv, int n, const char *want)
{
    char got[256] = "";
    for (int i = 0; i < n; i++) {
        size_t l = strlen(got);
        if (mv[i].kind <= SLALOM_DIAG) snprintf(got + l, sizeof got - l, "%s%s%u", i ? " " : "", kind_name[mv[i].kind], mv[i].n);
        else snprintf(got + l, sizeof got - l, "%s%s%c", i ? " " : "", kind_name[mv[i].kind], mv[i].dir > 0 ? 'R' : 'L');
    }
    assert_string_equal(got, want);
}

/* A 1x4 corridor, goal its far cell: one straight from rest to rest. */
static void test_corridor(void **state)
{
    (void)state;
    maze_t m;
    slalom_move_t mv[MOVES_MAX];
    float t;
    plan_costs_t c = costs(180.0f);
    closed_maze(&m, 1, 4);
    for (uint8_t y = 0; y < 3; y++) open_wall(&m, 0, y, MAZE_NORTH);
    assert_int_equal(maze_set_goal_rect(&m, 0, 3, 0, 3), 0);
    int n = plan_checked(&m, &c, mv, &t);
    expect_moves(mv, n, "O6");
    assert_true(fabs(t - straight_time(540, 0, 0, 650, 3000)) < TOL_S);
    /* an unknown wall counts as closed */
    maze_set_wall(&m, maze_cell(&m, 0, 1), MAZE_NORTH, MAZE_WALL_UNKNOWN);
    assert_int_equal(plan_run(&m, &c, mv, MOVES_MAX, &t), 0);
    assert_true(t < 0);
    /* the start a goal: nothing to drive */
    assert_int_equal(maze_set_goal_rect(&m, 0, 0, 0, 0), 0);
    assert_int_equal(plan_run(&m, &c, mv, MOVES_MAX, &t), 0);
    assert_true(t == 0.0f);
    c.accel_mm_s2 = 0;
    assert_int_equal(plan_run(&m, &c, mv, MOVES_MAX, &t), 0);
    assert_true(t < 0);
}

/* An L in 3x3: north up the west column, east along the top row. */
static void test_l_turn(void **state)
{
    (void)state;
    maze_t m;
    slalom_move_t mv[MOVES_MAX];
    float t, t_s90, t_f90;
    plan_costs_t c = costs(180.0f);
    closed_maze(&m, 3, 3);
    open_wall(&m, 0, 0, MAZE_NORTH);
    open_wall(&m, 0, 1, MAZE_NORTH);
    open_wall(&m, 0, 2, MAZE_EAST);
    open_wall(&m, 1, 2, MAZE_EAST);
    assert_int_equal(maze_set_goal_rect(&m, 2, 2, 2, 2), 0);
    c.turn_s[SLALOM_F90] = 0;
    expect_moves(mv, plan_checked(&m, &c, mv, &t_s90), "O3 S90R O3");
    c = costs(180.0f);
    c.turn_s[SLALOM_S90] = 0;
    expect_moves(mv, plan_checked(&m, &c, mv, &t_f90), "O1 F90R O1");
    c = costs(180.0f);
    int n = plan_checked(&m, &c, mv, &t);
    expect_moves(mv, n, t_f90 < t_s90 ? "O1 F90R O1" : "O3 S90R O3");
    assert_true(fabs(t - fmin(t_s90, t_f90)) < TOL_S);
    printf("L: S90 %.4f s, F90 %.4f s\n", t_s90, t_f90);
}

/* A staircase in 5x5: up two cells, then north-east steps to (4,4). */
static void test_staircase(void **state)
{
    (void)state;
    maze_t m;
    slalom_move_t mv[MOVES_MAX];
    float t;
    plan_costs_t c = costs(180.0f);
    closed_maze(&m, 5, 5);
    open_wall(&m, 0, 0, MAZE_NORTH);
    open_wall(&m, 0, 1, MAZE_NORTH);
    open_wall(&m, 0, 2, MAZE_EAST);
    open_wall(&m, 1, 2, MAZE_NORTH);
    open_wall(&m, 1, 3, MAZE_EAST);
    open_wall(&m, 2, 3, MAZE_NORTH);
    open_wall(&m, 2, 4, MAZE_EAST);
    open_wall(&m, 3, 4, MAZE_EAST);
    assert_int_equal(maze_set_goal_rect(&m, 4, 4, 4, 4), 0);
    int n = plan_checked(&m, &c, mv, &t);
    expect_moves(mv, n, "O1 F45R D3 D45R O1");
    assert_true(fabs(t - ref_best(&m, &c)) < TOL_S);
    assert_int_equal(plan_run(&m, &c, mv, 4, &t), -1);
    /* without diagonals: S90 turns all the way */
    c = costs_s90_only(180.0f);
    n = plan_checked(&m, &c, mv, &t);
    expect_moves(mv, n, "O3 S90R S90L S90R S90L S90R O3");
}

/* The mirror image of the staircase, run from the south-east corner
 * facing north: the left-hand turns and the other side types. */
static void test_staircase_left(void **state)
{
    (void)state;
    maze_t m;
    slalom_move_t mv[MOVES_MAX];
    float t;
    plan_costs_t c = costs(180.0f);
    closed_maze(&m, 5, 5);
    m.start = maze_cell(&m, 4, 0);
    open_wall(&m, 4, 0, MAZE_NORTH);
    open_wall(&m, 4, 1, MAZE_NORTH);
    open_wall(&m, 4, 2, MAZE_WEST);
    open_wall(&m, 3, 2, MAZE_NORTH);
    open_wall(&m, 3, 3, MAZE_WEST);
    open_wall(&m, 2, 3, MAZE_NORTH);
    open_wall(&m, 2, 4, MAZE_WEST);
    open_wall(&m, 1, 4, MAZE_WEST);
    assert_int_equal(maze_set_goal_rect(&m, 0, 4, 0, 4), 0);
    expect_moves(mv, plan_checked(&m, &c, mv, &t), "O1 F45L D3 D45L O1");
    assert_true(fabs(t - ref_best(&m, &c)) < TOL_S);
}

/* ---- random mazes against the reference ---- */

static uint32_t rng = 12345u;
static uint32_t next_rand(void)
{
    rng = rng * 1103515245u + 12345u;
    return rng >> 8;
}

/* 200 generated 6x6 mazes (every other one with a quarter of its walls
 * forgotten, some with the start turned), 5 cost sets each (the last each
 * turn kind at its own speed, with legs). */
static void test_random_against_reference(void **state)
{
    (void)state;
    static maze_t m;
    slalom_move_t mv[MOVES_MAX];
    int found = 0, diag_used = 0;
    for (uint32_t seed = 1; seed <= 200; seed++) {
        assert_int_equal(generated(&m, 6, 6, seed), 0);
        if (seed % 2 == 0)
            for (uint16_t i = 0; i < maze_cells(&m); i++)
                for (uint8_t d = 0; d < 2; d++)
                    if (next_rand() % 4 == 0) maze_set_wall(&m, (maze_cell_t)i, d, MAZE_WALL_UNKNOWN);
        if (seed % 5 == 0) m.start_heading = (uint8_t)(next_rand() % 4);
        for (int set = 0; set < 5; set++) {
            plan_costs_t c = set == 1 ? costs_s90_only(180.0f) : set == 4 ? costs_kinds(180.0f) : costs(set == 0 ? 180.0f : 90.0f);
            if (set >= 2) c.accel_mm_s2 = 12000.0f;
            if (set == 3) { /* fast straights, and the large turns at half their time */
                c.v_diag_mm_s = c.v_max_mm_s = 2000.0f;
                for (int k = SLALOM_F90; k < SLALOM_KINDS; k++) c.turn_s[k] *= 0.5f;
            }
            float t;
            int n = plan_checked(&m, &c, mv, &t);
            double r = ref_best(&m, &c);
            if (n == 0) { assert_true(r == HUGE_VAL); continue; }
            assert_true(fabs(r - t) <= TOL_S);
            found++;
            for (int i = 0; i < n; i++) {
                diag_used += mv[i].kind == SLALOM_DIAG;
                kind_used[mv[i].kind]++;
            }
        }
    }
    printf("random 6x6: %d plans agree with the reference, %d diagonal straights\n", found, diag_used);
    assert_true(found > 400);
    assert_true(diag_used > 0);
}

/* 200 random 6x6 maps, each wall open with chance 3/4 (many loops, long
 * diagonals), a random start and heading and a 1x1 or 2x2 goal. */
static void test_random_open_maps(void **state)
{
    (void)state;
    static maze_t m;
    slalom_move_t mv[MOVES_MAX];
    int found = 0, diag_used = 0;
    plan_costs_t c = costs(180.0f);
    for (int seed = 0; seed < 200; seed++) { /* seeds 1 mod 4 the plain costs, 3 mod 4 each turn at its own speed, even ones the large turns at half time */
        closed_maze(&m, 6, 6);
        for (uint16_t i = 0; i < maze_cells(&m); i++)
            for (uint8_t d = 0; d < 2; d++)
                if (next_rand() % 4 != 0) maze_set_wall(&m, (maze_cell_t)i, d, MAZE_WALL_OPEN);
        m.start = (maze_cell_t)(next_rand() % 36);
        m.start_heading = (uint8_t)(next_rand() % 4);
        uint8_t gx = (uint8_t)(next_rand() % 5), gy = (uint8_t)(next_rand() % 5), g = (uint8_t)(next_rand() % 2);
        assert_int_equal(maze_set_goal_rect(&m, gx, gy, (uint8_t)(gx + g), (uint8_t)(gy + g)), 0);
        float t;
        if (seed % 4 == 1) c = costs(180.0f);
        else if (seed % 4 == 3) c = costs_kinds(180.0f);
        else for (int k = SLALOM_F90; k < SLALOM_KINDS; k++) c.turn_s[k] *= 0.5f;
        int n = plan_checked(&m, &c, mv, &t);
        double r = ref_best(&m, &c);
        if (n == 0) { assert_true(r == HUGE_VAL || maze_is_goal(&m, m.start)); continue; }
        assert_true(fabs(r - t) <= TOL_S);
        found++;
        for (int i = 0; i < n; i++) {
            diag_used += mv[i].kind == SLALOM_DIAG;
            kind_used[mv[i].kind]++;
        }
        if (getenv("PLAN_VERBOSE")) print_plan("open", mv, n, t);
    }
    printf("random open 6x6: %d plans agree with the reference, %d diagonal straights\n", found, diag_used);
    assert_true(found > 100);
    assert_true(diag_used > 0);
    printf("moves in the plans checked against the reference:");
    for (int k = 0; k < SLALOM_KINDS; k++) printf(" %s %ld", kind_name[k], kind_used[k]);
    printf("\n");
    for (int k = 0; k < SLALOM_KINDS; k++) assert_true(kind_used[k] > 0);
}

/* Generated 32x32 half-size mazes: the full grid, replayed. */
static void test_halfsize(void **state)
{
    (void)state;
    static maze_t m;
    slalom_move_t mv[MOVES_MAX];
    plan_costs_t c = costs(90.0f);
    for (uint32_t seed = 1; seed <= 4; seed++) {
        float t;
        assert_int_equal(generated(&m, 32, 32, seed), 0);
        assert_true(plan_checked(&m, &c, mv, &t) > 0);
    }
}

/* ---- the classic database ---- */

/* Is a goal cell reachable from the start over open walls (cells, BFS)? */
static int reachable(const maze_t *m)
{
    static maze_cell_t q[MAZE_MAX_CELLS];
    static uint8_t seen[MAZE_MAX_CELLS];
    int head = 0, tail = 0;
    memset(seen, 0, sizeof seen);
    q[tail++] = m->start;
    seen[m->start] = 1;
    while (head < tail) {
        maze_cell_t a = q[head++], b;
        if (maze_is_goal(m, a)) return 1;
        for (uint8_t d = 0; d < 4; d++)
            if (maze_passable(m, a, d, 0) && maze_neighbour(m, a, d, &b) && !seen[b]) {
                seen[b] = 1;
                q[tail++] = b;
            }
    }
    return 0;
}

static int classic_long, classic_long_orth; /* plans longer than PLAN_MAX_MOVES */

static int check_classic(const char *path, const char *name)
{
    static maze_t m;
    char err[MAZEFILE_ERR_LEN];
    slalom_move_t mv[MOVES_MAX];
    float t, t_orth;
    if (loaded(&m, path, err, sizeof err) != 0) return 0;
    plan_costs_t c = costs(180.0f), c_orth = costs_s90_only(180.0f);
    int n = plan_checked(&m, &c, mv, &t);
    int n_orth = plan_checked(&m, &c_orth, mv, &t_orth);
    if (reachable(&m) && n == 0) printf("no plan: %s\n", name);
    classic_long += n > PLAN_MAX_MOVES;
    classic_long_orth += n_orth > PLAN_MAX_MOVES;
    assert_true(n > 0 || !reachable(&m) || maze_is_goal(&m, m.start));
    if (n > 0) {
        assert_true(n_orth > 0);
        assert_true(t <= t_orth + TOL_S);
    }
    if (strcmp(name, "japan2018.txt") == 0 || strcmp(name, "japan2019.txt") == 0) {
        plan_run(&m, &c, mv, MOVES_MAX, &t);
        print_plan(name, mv, n, t);
        n_orth = plan_run(&m, &c_orth, mv, MOVES_MAX, &t_orth);
        print_plan("  S90 only", mv, n_orth, t_orth);
    }
    return 1;
}

static void test_classic_database(void **state)
{
    (void)state;
    const char *shared = getenv("SHARED") ? getenv("SHARED") : "../shared";
    char dir[512], path[1024];
    snprintf(dir, sizeof dir, "%s/mazes/classic", shared);
    DIR *d = opendir(dir);
    if (!d) {
        printf("SKIP test_classic_database: %s not found\n", dir);
        skip();
    }
    static char names[1024][256];
    int files = 0, listed = 0;
    for (struct dirent *e; listed < 1024 && (e = readdir(d)) != NULL;)
        if (e->d_name[0] != '.' && strstr(e->d_name, ".txt")) snprintf(names[listed++], sizeof names[0], "%s", e->d_name);
    closedir(d);
    for (int i = 0; i < listed; i++) {
        snprintf(path, sizeof path, "%s/%s", dir, names[i]);
        files += check_classic(path, names[i]);
    }
    printf("classic: %d mazes planned; plans over %d moves: %d (S90 only: %d)\n", files, PLAN_MAX_MOVES,
           classic_long, classic_long_orth);
    assert_true(files > 400);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_corridor),
        cmocka_unit_test(test_l_turn),
        cmocka_unit_test(test_staircase),
        cmocka_unit_test(test_staircase_left),
        cmocka_unit_test(test_random_against_reference),
        cmocka_unit_test(test_random_open_maps),
        cmocka_unit_test(test_halfsize),
        cmocka_unit_test(test_classic_database),
    };
    return cmocka_run_group_tests_name("plan", tests, NULL, NULL);
}

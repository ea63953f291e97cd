/* slalom.c - the turns' geometry in the half-cell grid (slalom.h).
 *
 * Derived for a right turn entering at (0, 0) heading N (or NE). The
 * corner is where the entry and exit lines meet; a turn of angle A with
 * radius R starts and ends R * tan(A / 2) from its corner, so the room on
 * each side of the corner bounds R:
 *   S90   corner (0,1), the cell centre: 1 half unit each side -> R <= 90 mm;
 *   F90   straight 1, arc of R = 2 half units (180 mm) about (2,1), straight 1:
 *         cell centre to cell centre through the cell diagonally ahead;
 *   F180  arc of R = 1 half unit (90 mm) about (1,0): through the two cells
 *         side by side, crossing the side between them at its middle;
 *   F45   corner (0,2): 2 half units before it, one diagonal step after;
 *   F135  corner (0,2), exit (1,1): one diagonal step (127 mm) after it;
 *   D45, D135 the reverses of F45 and F135;
 *   V90   corner (1,1): one diagonal step before and after. */
#include "slalom.h"

#include <math.h>

#include "motion.h"
#include "plan.h"
#include "robot_config.h"

const slalom_geom_t slalom_geom[SLALOM_KINDS] = {
    [SLALOM_ORTHO] = {0},
    [SLALOM_DIAG] = {0},
    [SLALOM_S90] = {1, 1, 2, 0, 0, 1, 1, {{1, 1}}},
    [SLALOM_F90] = {3, 3, 2, 0, 0, 3, 3, {{0, 2}, {1, 3}, {3, 3}}},
    [SLALOM_F180] = {2, 0, 4, 0, 1, 0, 2, {{1, 1}, {2, 0}}},
    [SLALOM_F45] = {1, 3, 1, 0, 0, 2, 2, {{0, 2}, {1, 3}}},
    [SLALOM_F135] = {1, 1, 3, 0, 0, 2, 2, {{0, 2}, {1, 1}}},
    [SLALOM_D45] = {3, 1, 1, 1, 1, 1, 2, {{1, 1}, {3, 1}}},
    [SLALOM_D135] = {1, -1, 3, 1, 1, 1, 2, {{1, 1}, {1, -1}}},
    [SLALOM_V90] = {2, 0, 2, 1, 1, 1, 2, {{1, 1}, {2, 0}}},
};

const int8_t slalom_step_x[8] = { 0, 1, 1, 1, 0, -1, -1, -1 };
const int8_t slalom_step_y[8] = { 1, 1, 0, -1, -1, -1, 0, 1 };

void slalom_place(int8_t x, int8_t y, uint8_t from_diag, int8_t dir, uint8_t h8, int *dx, int *dy)
{
    int a = dir < 0 ? -x : x, b = y;
    uint8_t canon = from_diag ? (dir < 0 ? 7u : 1u) : 0u; /* the entry heading the table is drawn for */
    for (uint8_t q = (uint8_t)(((h8 - canon) & 7u) >> 1); q; q--) {
        int t = a;
        a = b;
        b = -t;
    }
    *dx = a;
    *dy = b;
}

/* ---- The turns as driven (slalom.h slalom_fit_kinds) ---- */
#if PLAN_ENABLED
#define HALF_MM (RC_CELL_MM / 2) /* one half unit of the grid */
#define TURN_NO_FIT_S (-1.0f)    /* plan_costs_t: a turn not used */

/* the distance from each turn's start to its corner (robot_config.h,
 * where each figure's clearance is given); 0: not driven */
static const float corner_target_mm[SLALOM_KINDS] = {
    [SLALOM_S90] = RC_SLALOM_S90_MM,   [SLALOM_F90] = RC_SLALOM_F90_MM,   [SLALOM_F180] = RC_CELL_MM,
    [SLALOM_F45] = RC_SLALOM_F45_MM,   [SLALOM_F135] = RC_SLALOM_F135_MM, [SLALOM_D45] = RC_SLALOM_D45_MM,
    [SLALOM_D135] = RC_SLALOM_D135_MM, [SLALOM_V90] = RC_SLALOM_V90_MM,
};

/* The peak rate, deg/s, that keeps the corner of a turn of `degrees` at v
 * within target_mm of both its start and its end (the loosest such turn:
 * the shortest path), by bisection; 0 if even the fastest rate the motor
 * allows does not. *pre_mm, *post_mm, *arc_mm: that turn's
 * (motion_slalom_geometry; a U: its width and its end's advance). */
static float fit_rate(float v, float ff_max_cmd, float degrees, float target_mm, float *pre_mm, float *post_mm, float *arc_mm)
{
    float lo = RC_SLALOM_W_MIN_DEG_S, hi = RC_SLALOM_W_MAX_DEG_S, a, b, len;
    uint8_t u = degrees > 179.0f; /* a U: only its width counts */
    motion_slalom_geometry(v, degrees, hi, RC_SLALOM_ACCEL_DEG_S2, ff_max_cmd, &a, &b, &len);
    if ((u ? a : fmaxf(a, b)) > target_mm) return 0;
    for (uint8_t i = 0; i < 24; i++) {
        float mid = 0.5f * (lo + hi);
        motion_slalom_geometry(v, degrees, mid, RC_SLALOM_ACCEL_DEG_S2, ff_max_cmd, &a, &b, &len);
        if ((u ? a : fmaxf(a, b)) > target_mm) lo = mid;
        else hi = mid;
    }
    motion_slalom_geometry(v, degrees, hi, RC_SLALOM_ACCEL_DEG_S2, ff_max_cmd, pre_mm, post_mm, arc_mm);
    return hi;
}

/* Size turn kind k for forward speed v: *d, and its time from entry node
 * to exit node, s (TURN_NO_FIT_S: it does not fit, or is not driven). */
static float fit_kind(uint8_t k, float v, float ff_max_cmd, slalom_drive_t *d)
{
    const slalom_geom_t *g = &slalom_geom[k];
    d->w_deg_s = d->before_mm = d->arc_mm = d->after_mm = 0;
    if (k < SLALOM_S90 || corner_target_mm[k] <= 0 || !(v > 0)) return TURN_NO_FIT_S;
    float pre = 0, post = 0, arc = 0;
    d->w_deg_s = fit_rate(v, ff_max_cmd, 45.0f * g->turn, corner_target_mm[k], &pre, &post, &arc);
    if (d->w_deg_s <= 0) return TURN_NO_FIT_S;
    if (g->turn == 4) { /* F180: from the entry node to the exit node, level */
        d->before_mm = post < 0 ? -post : 0;
        d->after_mm = d->before_mm + post;
    } else {
        d->before_mm = HALF_MM * hypotf(g->corner_x, g->corner_y) - pre;
        d->after_mm = HALF_MM * hypotf(g->exit_x - g->corner_x, g->exit_y - g->corner_y) - post;
    }
    d->arc_mm = arc;
    if (d->before_mm < 0 || d->after_mm < 0) {
        d->w_deg_s = 0;
        return TURN_NO_FIT_S;
    }
    return (d->before_mm + d->arc_mm + d->after_mm) / v;
}

void slalom_run_speeds(uint8_t fast, float v_mm_s[SLALOM_KINDS])
{
    static const float v_safe[SLALOM_KINDS] = {
        [SLALOM_S90] = RC_SLALOM_SAFE_MM_S,       [SLALOM_F90] = RC_SLALOM_F90_SAFE_MM_S,
        [SLALOM_F180] = RC_SLALOM_F180_SAFE_MM_S, [SLALOM_F45] = RC_SLALOM_F45_SAFE_MM_S,
        [SLALOM_D45] = RC_SLALOM_F45_SAFE_MM_S,   [SLALOM_F135] = RC_SLALOM_SAFE_MM_S,
        [SLALOM_D135] = RC_SLALOM_SAFE_MM_S,      [SLALOM_V90] = RC_SLALOM_SAFE_MM_S,
    };
    static const float v_fast[SLALOM_KINDS] = {
        [SLALOM_S90] = RC_SLALOM_FAST_MM_S,       [SLALOM_F90] = RC_SLALOM_F90_FAST_MM_S,
        [SLALOM_F180] = RC_SLALOM_F180_FAST_MM_S, [SLALOM_F45] = RC_SLALOM_F45_FAST_MM_S,
        [SLALOM_D45] = RC_SLALOM_F45_FAST_MM_S,   [SLALOM_F135] = RC_SLALOM_FAST_MM_S,
        [SLALOM_D135] = RC_SLALOM_FAST_MM_S,      [SLALOM_V90] = RC_SLALOM_FAST_MM_S,
    };
    for (uint8_t k = 0; k < SLALOM_KINDS; k++) v_mm_s[k] = fast ? v_fast[k] : v_safe[k];
}

void slalom_fit_kinds(const float v_mm_s[SLALOM_KINDS], float ff_max_cmd, slalom_drive_t drive[SLALOM_KINDS],
                      float turn_s[SLALOM_KINDS])
{
    for (uint8_t k = 0; k < SLALOM_KINDS; k++) turn_s[k] = fit_kind(k, v_mm_s[k], ff_max_cmd, &drive[k]);
}
#endif

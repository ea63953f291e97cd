/* plan.c - the speed run's time-optimal path (plan.h): Dijkstra with a
 * binary heap on static arrays over (half-cell grid node, heading, the
 * turn that led there) states.
 *
 * Grid coordinates are slalom.h's: cell (x, y) has its centre at (2x, 2y);
 * a node (gx, gy) runs from -1 to 2 W - 1 (2 H - 1), stored at (gx + 1,
 * gy + 1) in a grid of (2 W + 1) x (2 H + 1) points, 8 headings each, each
 * heading ARRIVALS states (one per turn kind; the start's is slot 0: no
 * turn ends on a cell centre, so nothing else reaches it). */
#include "plan.h"

#if PLAN_ENABLED

#include <math.h>
#include <stddef.h>

#define GRID_W (2 * MAZE_MAX_W + 1)
#define GRID_H (2 * MAZE_MAX_H + 1)
#define ARRIVALS (SLALOM_KINDS - SLALOM_S90) /* the turn kinds a state can be reached by */
#define STATES ((uint32_t)GRID_W * GRID_H * 8 * ARRIVALS)
#define NOT_SEEN 0xFFFFFFFFu /* hpos: never reached */
#define DONE 0xFFFFFFFEu     /* hpos: settled */
#define LEFT_BIT 0x80u   /* prev_turn: the turn was a left one */
#define SQRT2 1.41421356f

static float dist[STATES];        /* best time found to the state, s */
static uint32_t prev[STATES];     /* the state the best edge starts from */
static uint8_t prev_n[STATES];    /* that edge's straight, half units or half steps */
static uint8_t prev_turn[STATES]; /* that edge's turn: kind | LEFT_BIT */
static uint32_t heap[STATES];     /* binary min-heap of states by dist */
static uint32_t hpos[STATES];     /* a state's place in heap, NOT_SEEN or DONE */


typedef struct {
    const maze_t *m;
    const plan_costs_t *c;
    int gw;            /* grid points per row for this map */
    uint32_t start;    /* the start state */
    uint32_t heap_n;   /* states in the heap */
    float best;        /* the cheapest run found so far, s */
    uint32_t best_s;   /* its last turn's exit state */
    uint8_t best_n;    /* its last straight, half units */
} search_t;

/* the state at (gx, gy) heading h, reached by a turn of kind (the start: SLALOM_S90's slot) */
static uint32_t state_of(const search_t *S, int gx, int gy, uint8_t h, uint8_t kind)
{
    return ((uint32_t)(((gy + 1) * S->gw) + gx + 1) * 8 + h) * ARRIVALS + (uint32_t)(kind - SLALOM_S90);
}

/* Is the side whose middle is (gx, gy) known open? Posts, centres and
 * points off the maze are not. */
static int side_open(const maze_t *m, int gx, int gy)
{
    if (gx < -1 || gy < -1 || gx > 2 * m->width - 1 || gy > 2 * m->height - 1) return 0;
    if ((gx & 1) == (gy & 1)) return 0;
    if (gy & 1) { /* a north/south side: the north side of the cell below */
        if (gy < 0) return 0;
        return maze_wall(m, maze_cell(m, (uint8_t)(gx / 2), (uint8_t)((gy - 1) / 2)), MAZE_NORTH) == MAZE_WALL_OPEN;
    }
    if (gx < 0) return 0; /* an east/west side: the east side of the cell to its west */
    return maze_wall(m, maze_cell(m, (uint8_t)((gx - 1) / 2), (uint8_t)(gy / 2)), MAZE_EAST) == MAZE_WALL_OPEN;
}

/* Can the robot stand on (gx, gy) heading h? An orthogonal heading must
 * cross the side it stands on; a diagonal one stands on any side middle. */
static int node_fits(int gx, int gy, uint8_t h)
{
    if ((gx & 1) == (gy & 1)) return 0;
    if (h & 1) return 1;
    return (h & 2) ? (gx & 1) : (gy & 1);
}

/* Time of a straight of d_mm from v0 to v1 with top speed vtop, s; < 0 if
 * it is too short to change speed so much. */
static float straight_s(float d_mm, float v0, float v1, float vtop, float a)
{
    float hi = v0 > v1 ? v0 : v1;
    if (vtop < hi) vtop = hi;
    float vp2 = a * d_mm + 0.5f * (v0 * v0 + v1 * v1); /* peak speed squared of the triangle */
    if (vp2 < hi * hi * (1.0f - 1e-6f)) return -1.0f;
    if (vp2 <= vtop * vtop) {
        float vp = vp2 > hi * hi ? sqrtf(vp2) : hi;
        return (2.0f * vp - v0 - v1) / a;
    }
    float d_ramps = (2.0f * vtop * vtop - v0 * v0 - v1 * v1) / (2.0f * a);
    return (2.0f * vtop - v0 - v1) / a + (d_mm - d_ramps) / vtop;
}

/* Turn `kind` to side dir (+1 right, -1 left) entered at (gx, gy) heading h:
 * 1 and its exit node and heading if it is legal there, else 0. The table
 * holds the right turn entered heading N (orthogonal) or NE (diagonal); a
 * left turn mirrors x (entering N or NW), then the move is rotated onto h.
 * A diagonal entry can stand on either kind of side middle; the table's
 * turns fit one kind: D45 and D135 because only there their exit is a
 * node, V90 by the rule that its corner is the side middle it crosses at
 * the turn's middle heading (the post inside the turn, one half unit away). */
static int turn_exit(const maze_t *m, int gx, int gy, uint8_t h, uint8_t kind, int8_t dir,
                     int *ex, int *ey, uint8_t *eh)
{
    const slalom_geom_t *g = &slalom_geom[kind];
    if (g->from_diag != (h & 1)) return 0;
    int x, y;
    slalom_place(g->exit_x, g->exit_y, g->from_diag, dir, h, &x, &y);
    *ex = gx + x;
    *ey = gy + y;
    *eh = (uint8_t)((h + dir * g->turn) & 7);
    if (!node_fits(*ex, *ey, *eh)) return 0;
    if (kind == SLALOM_V90) {
        slalom_place(g->corner_x, g->corner_y, g->from_diag, dir, h, &x, &y);
        if (!node_fits(gx + x, gy + y, (uint8_t)((h + dir) & 7))) return 0;
    }
    for (uint8_t i = 0; i < g->crossed; i++) {
        slalom_place(g->cross[i][0], g->cross[i][1], g->from_diag, dir, h, &x, &y);
        if (!side_open(m, gx + x, gy + y)) return 0;
    }
    return 1;
}

static int heap_less(uint32_t a, uint32_t b) { return dist[heap[a]] < dist[heap[b]]; }

static void heap_swap(uint32_t a, uint32_t b)
{
    uint32_t t = heap[a];
    heap[a] = heap[b];
    heap[b] = t;
    hpos[heap[a]] = a;
    hpos[heap[b]] = b;
}

static void heap_up(uint32_t i)
{
    while (i > 0 && heap_less(i, (i - 1) / 2)) {
        heap_swap(i, (i - 1) / 2);
        i = (i - 1) / 2;
    }
}

static uint32_t heap_pop(search_t *S)
{
    uint32_t top = heap[0], i = 0;
    hpos[top] = DONE;
    if (--S->heap_n == 0) return top;
    heap[0] = heap[S->heap_n];
    hpos[heap[0]] = 0;
    for (;;) {
        uint32_t l = 2 * i + 1, r = l + 1, k = i;
        if (l < S->heap_n && heap_less(l, k)) k = l;
        if (r < S->heap_n && heap_less(r, k)) k = r;
        if (k == i) return top;
        heap_swap(i, k);
        i = k;
    }
}

/* A cheaper way to state s: from state `from`, straight n, turn. */
static void relax(search_t *S, uint32_t s, float t, uint32_t from, uint8_t n, uint8_t turn)
{
    if (hpos[s] == DONE || t >= dist[s]) return;
    dist[s] = t;
    prev[s] = from;
    prev_n[s] = n;
    prev_turn[s] = turn;
    if (hpos[s] == NOT_SEEN) {
        hpos[s] = S->heap_n;
        heap[S->heap_n++] = s;
    }
    heap_up(hpos[s]);
}

/* Every turn from (x, y) heading h, reached from state s by a straight of
 * n half units, d_mm with the leg of the turn before it, from v0 at top
 * speed vtop: each turn kind's time with its own leg and speed (none where
 * that straight cannot be driven). */
static void try_turns(search_t *S, uint32_t s, int x, int y, uint8_t h, uint8_t n, float d_mm, float v0, float vtop)
{
    const plan_costs_t *c = S->c;
    for (uint8_t k = SLALOM_S90; k < SLALOM_KINDS; k++) {
        if (!(c->turn_s[k] > 0.0f)) continue;
        float ts = -1.0f;
        for (int8_t dir = 1; dir >= -1; dir = (int8_t)(dir - 2)) {
            int ex, ey;
            uint8_t eh;
            if (!turn_exit(S->m, x, y, h, k, dir, &ex, &ey, &eh)) continue;
            if (ts < 0.0f) ts = straight_s(d_mm + c->before_mm[k], v0, c->v_turn_mm_s[k], vtop, c->accel_mm_s2);
            if (ts < 0.0f) break;
            relax(S, state_of(S, ex, ey, eh, k), dist[s] + ts + c->turn_s[k], s, n, (uint8_t)(k | (dir < 0 ? LEFT_BIT : 0u)));
        }
    }
}

/* Every edge out of state s at (gx, gy) heading h: the straight ahead
 * grows half a unit (step) at a time while the sides it crosses are open;
 * at each side middle a turn may end it, at a goal cell's centre a stop. */
static void expand(search_t *S, uint32_t s, int gx, int gy, uint8_t h, uint8_t kind)
{
    const plan_costs_t *c = S->c;
    const maze_t *m = S->m;
    uint8_t at_start = s == S->start;
    float v0 = at_start ? 0.0f : c->v_turn_mm_s[kind];
    float leg_mm = at_start ? 0.0f : c->after_mm[kind];
    float step_mm = (h & 1) ? c->cell_mm * 0.5f * SQRT2 : c->cell_mm * 0.5f;
    float vtop = (h & 1) ? c->v_diag_mm_s : c->v_max_mm_s;
    for (int n = 0; n <= 255; n++) {
        int x = gx + n * slalom_step_x[h], y = gy + n * slalom_step_y[h];
        float d_mm = leg_mm + (float)n * step_mm;
        if ((x ^ y) & 1) { /* a side middle */
            if (n > 0 && !side_open(m, x, y)) return;
            try_turns(S, s, x, y, h, (uint8_t)n, d_mm, v0, vtop);
        } else if (n > 0 && !(h & 1) && maze_is_goal(m, maze_cell(m, (uint8_t)(x / 2), (uint8_t)(y / 2)))) {
            float t = straight_s(d_mm, v0, 0.0f, vtop, c->accel_mm_s2);
            if (t >= 0.0f && dist[s] + t < S->best) {
                S->best = dist[s] + t;
                S->best_s = s;
                S->best_n = (uint8_t)n;
            }
        }
    }
}

/* The run ending with state S->best_s's chain and the last straight, in
 * order; its count, or -1 if more than max. */
static int emit(const search_t *S, slalom_move_t *moves, int max)
{
    int k = 1;
    for (uint32_t s = S->best_s; s != S->start; s = prev[s]) k += 1 + (prev_n[s] > 0);
    if (k > max) return -1;
    int i = k;
    moves[--i] = (slalom_move_t){ SLALOM_ORTHO, 0, S->best_n };
    for (uint32_t s = S->best_s; s != S->start; s = prev[s]) {
        moves[--i] = (slalom_move_t){ (uint8_t)(prev_turn[s] & ~LEFT_BIT), (prev_turn[s] & LEFT_BIT) ? -1 : 1, 1 };
        if (prev_n[s] > 0)
            moves[--i] = (slalom_move_t){ ((prev[s] / ARRIVALS) & 1) ? SLALOM_DIAG : SLALOM_ORTHO, 0, prev_n[s] };
    }
    return k;
}

static int costs_ok(const maze_t *map, const plan_costs_t *c)
{
    if (!(map && c && map->width >= 1 && map->height >= 1 && map->width <= MAZE_MAX_W &&
          map->height <= MAZE_MAX_H && c->cell_mm > 0.0f && c->v_max_mm_s > 0.0f && c->v_diag_mm_s > 0.0f &&
          c->accel_mm_s2 > 0.0f))
        return 0;
    for (uint8_t k = SLALOM_S90; k < SLALOM_KINDS; k++)
        if (c->turn_s[k] > 0.0f && !(c->v_turn_mm_s[k] > 0.0f && c->before_mm[k] >= 0.0f && c->after_mm[k] >= 0.0f))
            return 0;
    return 1;
}

int plan_run(const maze_t *map, const plan_costs_t *c, slalom_move_t *moves, int max, float *time_s)
{
    *time_s = -1.0f;
    if (!costs_ok(map, c)) return 0;
    if (maze_is_goal(map, map->start)) {
        *time_s = 0.0f;
        return 0;
    }
    search_t S = { map, c, 2 * map->width + 1, 0, 0, INFINITY, 0, 0 };
    uint32_t n_states = (uint32_t)S.gw * (uint32_t)(2 * map->height + 1) * 8 * ARRIVALS;
    for (uint32_t i = 0; i < n_states; i++) {
        dist[i] = INFINITY;
        hpos[i] = NOT_SEEN;
    }
    S.start = state_of(&S, 2 * maze_x(map, map->start), 2 * maze_y(map, map->start),
                       (uint8_t)(2 * (map->start_heading & 3)), SLALOM_S90);
    dist[S.start] = 0.0f;
    hpos[S.start] = 0;
    heap[S.heap_n++] = S.start;
    while (S.heap_n > 0) {
        uint32_t s = heap_pop(&S);
        if (dist[s] >= S.best) break;
        uint32_t p = s / (8 * ARRIVALS);
        expand(&S, s, (int)(p % (uint32_t)S.gw) - 1, (int)(p / (uint32_t)S.gw) - 1, (uint8_t)((s / ARRIVALS) % 8),
               (uint8_t)(s % ARRIVALS + SLALOM_S90));
    }
    if (S.best == INFINITY) return 0;
    *time_s = S.best;
    return emit(&S, moves, max);
}

#else
typedef int plan_disabled_t; /* ISO C wants a translation unit to declare something */
#endif

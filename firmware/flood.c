/* flood.c - classic and heading-aware floodfill in nibble-packed storage.
 * See flood.h for the representation and why. */
#include "flood.h"

#include <string.h>

#define MOD 15u      /* costs are stored modulo 15 */
#define UNSEEN 15u   /* nibble of a configuration not yet reached */

/* Branches instead of a variable shift: the AVR shifts one bit per cycle
 * in a loop, but swaps nibbles in one. */
static uint8_t nib_get(const flood_t *f, uint16_t i)
{
    uint8_t b = f->cost[i >> 1];
    return (i & 1u) ? (uint8_t)(b >> 4) : (uint8_t)(b & 0x0Fu);
}

static void nib_set(flood_t *f, uint16_t i, uint8_t v)
{
    uint8_t *b = &f->cost[i >> 1];
    *b = (i & 1u) ? (uint8_t)((*b & 0x0Fu) | (uint8_t)(v << 4)) : (uint8_t)((*b & 0xF0u) | v);
}

static void open_add(flood_t *f, uint16_t i) { f->open[i >> 3] |= (uint8_t)(1u << (i & 7u)); }

void flood_target_clear(flood_t *f) { memset(f->target, 0, sizeof f->target); }

void flood_target_add(flood_t *f, maze_cell_t c) { f->target[c >> 3] |= (uint8_t)(1u << (c & 7u)); }

int flood_is_target(const flood_t *f, maze_cell_t c) { return (f->target[c >> 3] >> (c & 7u)) & 1u; }

void flood_target_goal(flood_t *f, const maze_t *m)
{
    memcpy(f->target, m->goal, sizeof f->target < sizeof m->goal ? sizeof f->target : sizeof m->goal);
}

/* Recover an absolute value from its residue v, given a true value within
 * 7 of near. */
static uint16_t decode(uint8_t v, uint16_t near)
{
    int32_t base = (int32_t)near - 7;
    int32_t r = ((int32_t)v - base) % (int32_t)MOD;
    if (r < 0) r += MOD;
    int32_t a = base + r;
    return a < 0 ? FLOOD_UNREACHABLE : (uint16_t)a;
}

uint16_t flood_cost(const flood_t *f, maze_cell_t c, uint8_t h, uint16_t near)
{
    uint8_t v = nib_get(f, (uint16_t)(c * 4u + (h & 3u)));
    return v == UNSEEN ? FLOOD_UNREACHABLE : decode(v, near);
}

uint16_t flood_cell_dist(const flood_t *f, maze_cell_t c, uint16_t near)
{
    return flood_cost(f, c, 0, near);
}

/* Level-synchronous BFS shared by both floods. In the heading-aware flood
 * node i = cell*4 + heading; in the classic flood node i = cell*4 (heading
 * slot 0 only). `relax` lists the predecessors of a node. */
typedef uint8_t (*preds_fn)(const maze_t *m, uint16_t i, uint8_t flags, uint16_t out[4]);

static uint8_t preds_heading(const maze_t *m, uint16_t i, uint8_t flags, uint16_t out[4])
{
    maze_cell_t c = (maze_cell_t)(i >> 2);
    uint8_t h = (uint8_t)(i & 3u), n = 0;
    /* rotating into heading h from either side */
    out[n++] = (uint16_t)(c * 4u + maze_turn(h, 1));
    out[n++] = (uint16_t)(c * 4u + maze_turn(h, -1));
    /* driving forward in heading h from the cell behind */
    if (maze_passable(m, c, maze_turn(h, 2), flags & FLOOD_UNKNOWN_OPEN))
        out[n++] = (uint16_t)(maze_step(m, c, maze_turn(h, 2)) * 4u + h);
    return n;
}

static uint8_t preds_cell(const maze_t *m, uint16_t i, uint8_t flags, uint16_t out[4])
{
    maze_cell_t c = (maze_cell_t)(i >> 2);
    uint8_t n = 0;
    for (uint8_t d = 0; d < 4; d++)
        if (maze_passable(m, c, d, flags & FLOOD_UNKNOWN_OPEN))
            out[n++] = (uint16_t)(maze_step(m, c, d) * 4u);
    return n;
}

static uint16_t bfs(flood_t *f, const maze_t *m, uint16_t src, uint8_t flags,
                    uint8_t headings, preds_fn preds)
{
    uint16_t cells = maze_cells(m);
    uint16_t nbytes = (uint16_t)((cells * 4u + 7u) / 8u);
    uint16_t level = 0, src_cost = FLOOD_UNREACHABLE;
    int added = 0;

    memset(f->cost, 0xFF, sizeof f->cost);
    memset(f->open, 0, sizeof f->open);
    for (uint16_t c = 0; c < cells; c++) {
        if (!flood_is_target(f, (maze_cell_t)c)) continue;
        for (uint8_t h = 0; h < headings; h++) {
            nib_set(f, (uint16_t)(c * 4u + h), 0);
            open_add(f, (uint16_t)(c * 4u + h));
            added = 1;
        }
    }
    if (nib_get(f, src) == 0) {
        src_cost = 0;
        if (!(flags & FLOOD_FULL)) return 0;
    }

    while (added) {
        uint8_t now = (uint8_t)(level % MOD), next = (uint8_t)((level + 1u) % MOD);
        added = 0;
        for (uint16_t b = 0; b < nbytes; b++) {
            if (!f->open[b]) continue;
            uint16_t i = (uint16_t)(b * 8u);
            for (uint8_t mask = 1; mask; mask = (uint8_t)(mask << 1), i++) {
                uint16_t p[4];
                if (!(f->open[b] & mask) || nib_get(f, i) != now) continue;
                f->open[b] &= (uint8_t)~mask;
                uint8_t np = preds(m, i, flags, p);
                for (uint8_t k = 0; k < np; k++) {
                    if (nib_get(f, p[k]) != UNSEEN) continue;
                    nib_set(f, p[k], next);
                    open_add(f, p[k]);
                    added = 1;
                    if (p[k] == src) {
                        src_cost = (uint16_t)(level + 1u);
                        if (!(flags & FLOOD_FULL)) return src_cost;
                    }
                }
            }
        }
        level++;
    }
    return src_cost;
}

uint16_t flood_run(flood_t *f, const maze_t *m, maze_cell_t src, uint8_t src_heading, uint8_t flags)
{
    return bfs(f, m, (uint16_t)(src * 4u + (src_heading & 3u)), flags, 4, preds_heading);
}

uint16_t flood_cells(flood_t *f, const maze_t *m, maze_cell_t src, uint8_t flags)
{
    return bfs(f, m, (uint16_t)(src * 4u), flags, 1, preds_cell);
}

int flood_next_cell_dir(const flood_t *f, const maze_t *m, maze_cell_t c, uint8_t h, uint16_t k, uint8_t flags)
{
    static const int8_t order[4] = { 0, 1, -1, 2 }; /* straight, right, left, back */
    if (k == 0 || k == FLOOD_UNREACHABLE) return -1;
    for (uint8_t j = 0; j < 4; j++) {
        uint8_t d = maze_turn(h, order[j]);
        if (maze_passable(m, c, d, flags & FLOOD_UNKNOWN_OPEN) &&
            flood_cell_dist(f, maze_step(m, c, d), k) + 1u == k)
            return d;
    }
    return -1;
}

int flood_next_dir(const flood_t *f, const maze_t *m, maze_cell_t c, uint8_t h,
                   uint16_t k, uint8_t flags)
{
    static const int8_t order[4] = { 0, 1, -1, 2 }; /* straight, right, left, back */
    static const uint8_t rot_cost[4] = { 0, 1, 1, 2 };
    if (k == 0 || k == FLOOD_UNREACHABLE) return -1;
    /* with FLOOD_PREFER_KNOWN, a first pass over known-open walls only */
    for (uint8_t pass = (flags & FLOOD_PREFER_KNOWN) ? 0 : 1; pass < 2; pass++)
        for (uint8_t j = 0; j < 4; j++) {
            uint8_t d = maze_turn(h, order[j]);
            if (!maze_passable(m, c, d, pass ? (flags & FLOOD_UNKNOWN_OPEN) : 0)) continue;
            uint16_t rest = flood_cost(f, maze_step(m, c, d), d, k);
            if (rest != FLOOD_UNREACHABLE && rest + 1u + rot_cost[j] == k) return d;
        }
    return -1;
}

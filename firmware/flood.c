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

/* ---- the BFS ----
 * Level-synchronous over cells: level k expands every cell of the current
 * frontier (cells holding a configuration of cost k); every configuration
 * it reaches for the first time costs k+1 and puts its cell in the next
 * frontier. A nibble is written once, so the field does not depend on the
 * order in which the cells of a level are expanded.
 *
 * Frontier layout: f->front[y * ROW + x / 8] bit x % 8 is cell (x, y) of
 * level k, and the same bit FRONT bytes further is level k+1. ROW and FRONT
 * are compile-time constants (2 and 32 for 16x16), so a cell's neighbours
 * in the next frontier are fixed offsets from its byte in the current one
 * (the AVR adds them in the load instruction). A list holds the indices of
 * the non-zero bytes of each frontier: japan2018's true map has 114 levels
 * of ~5 non-zero bytes, and scanning and copying all 32 bytes per level
 * cost 96,000 of that flood's 239,000 cycles.
 *
 * Measured on the AVR (avr-gcc 5.4 -Os, simavr; docs/BENCHMARKS.md): the
 * old BFS over configurations took 586,511 cycles for a blank 16x16 map
 * (per configuration a call through a function pointer and nibble reads
 * and writes, per level a scan of all 128 bytes of its open set).
 * Expanding a cell's four headings at once, reading its wall byte once,
 * and the lists: 138,418. The
 * code's shape matters to avr-gcc's register allocation: the same steps
 * written as separate functions, or with pointers stepped per cell instead
 * of the cell index, spill to the stack and cost 5-25 % more. */
#define ROW FLOOD_ROW_BYTES
#define FRONT FLOOD_FRONT_BYTES

/* Side d of a cell passable, bit d set, from its wall byte (maze.h: bit d
 * wall, bit 4+d known); unknown = 0x0F if unknown walls count as open. */
static uint8_t open_sides(uint8_t w, uint8_t unknown)
{
    uint8_t known = (uint8_t)(w >> 4);
    return (uint8_t)((known & (uint8_t)~w) | (unknown & (uint8_t)~known));
}

/* Put a cell in the next frontier: bit of frontier byte *t, whose index is
 * idx; a byte that was empty joins the list ln of non-zero bytes. Returns
 * the list's new end. */
static uint8_t *mark(uint8_t *t, uint8_t bit, uint8_t idx, uint8_t *ln)
{
    if (!*t) *ln++ = idx;
    *t |= bit;
    return ln;
}

/* The cell east / west of the one at bit of current frontier byte fc,
 * index i. */
static uint8_t *mark_east(uint8_t *fc, uint8_t bit, uint8_t i, uint8_t *ln)
{
    if (bit == 0x80u) return mark(fc + FRONT + 1, 1u, (uint8_t)(i + 1u), ln);
    return mark(fc + FRONT, (uint8_t)(bit << 1), i, ln);
}

static uint8_t *mark_west(uint8_t *fc, uint8_t bit, uint8_t i, uint8_t *ln)
{
    if (bit == 1u) return mark(fc + FRONT - 1, 0x80u, (uint8_t)(i - 1u), ln);
    return mark(fc + FRONT, (uint8_t)(bit >> 1), i, ln);
}

/* The state of a flood between levels. */
typedef struct {
    uint8_t *cost;       /* 2 bytes per cell: headings N | E << 4, S | W << 4 */
    const uint8_t *wall; /* m->cell */
    uint8_t *front;      /* current frontier; the next one is FRONT bytes on */
    uint8_t *list;       /* indices of the current frontier's non-zero bytes */
    uint8_t *next_list;  /* the same for the next frontier, being built */
    uint8_t count;       /* entries in list */
    uint8_t width;       /* cells */
    uint16_t up;         /* cost bytes from a cell to the cell north of it */
    uint8_t unknown;     /* 0x0F if unknown walls count as open, else 0 */
} bfs_t;

/* The first cell of frontier byte i. */
static maze_cell_t first_cell(const bfs_t *b, uint8_t i)
{
    return (maze_cell_t)((maze_cell_t)(i / ROW) * b->width + (i % ROW) * 8u);
}

/* Heading-aware level: expand the configurations of cost k (k mod 15 =
 * now) of every cell of the current frontier, all four headings of a cell
 * at once; x = 15 ^ ((k+1) mod 15) XORed into an unseen nibble makes it
 * k+1. Clears the current frontier's bytes it reads; returns the next
 * frontier's list length. */
static uint8_t level_configs(const bfs_t *b, uint8_t now, uint8_t x)
{
    uint8_t *ln = b->next_list;
    const uint16_t up = b->up;
    const uint8_t now2 = (uint8_t)(now * 0x11u), xh = (uint8_t)(x << 4);
    for (uint8_t n = 0; n < b->count; n++) {
        uint8_t i = b->list[n];
        uint8_t *fc = b->front + i;
        uint8_t bits = *fc;
        *fc = 0;
        maze_cell_t c = first_cell(b, i);
        uint8_t bit = 1;
        if (!(bits & 0x0Fu)) { /* skip an empty half */
            bits >>= 4;
            bit = 0x10;
            c = (maze_cell_t)(c + 4u);
        }
        for (; bits; bit = (uint8_t)(bit << 1), bits >>= 1, c++) {
            if (!(bits & 1u)) continue;
            uint8_t *p = b->cost + 2u * c;
            uint8_t lo = p[0], hi = p[1], at = 0;
            /* at: heading bits (1 north .. 8 west) of cost k; a nibble
             * equals k where lo/hi XOR k in both nibbles has a 0 nibble */
            uint8_t tl = (uint8_t)(lo ^ now2), th = (uint8_t)(hi ^ now2);
            if (!(tl & 0x0Fu)) at |= 1u;
            if (tl < 0x10u) at |= 2u;
            if (!(th & 0x0Fu)) at |= 4u;
            if (th < 0x10u) at |= 8u;
            /* a quarter turn: unseen east/west next to a north/south of
             * cost k, and north/south next to an east/west */
            if (at & 5u) {
                if (lo >= 0xF0u) lo ^= xh;
                if (hi >= 0xF0u) hi ^= xh;
            }
            if (at & 10u) {
                if ((lo & 0x0Fu) == UNSEEN) lo ^= x;
                if ((hi & 0x0Fu) == UNSEEN) hi ^= x;
            }
            if (lo != p[0] || hi != p[1]) {
                p[0] = lo;
                p[1] = hi;
                ln = mark(fc + FRONT, bit, i, ln);
            }
            /* a forward move in heading h, from the cell behind (side h+2) */
            uint8_t open = open_sides(b->wall[c], b->unknown);
            if ((at & 1u) && (open & (1u << MAZE_SOUTH))) {
                uint8_t *q = p - up;
                if ((*q & 0x0Fu) == UNSEEN) {
                    *q ^= x;
                    ln = mark(fc + FRONT - ROW, bit, (uint8_t)(i - ROW), ln);
                }
            }
            if ((at & 2u) && (open & (1u << MAZE_WEST))) {
                uint8_t *q = p - 2;
                if (*q >= (UNSEEN << 4)) {
                    *q ^= xh;
                    ln = mark_west(fc, bit, i, ln);
                }
            }
            if ((at & 4u) && (open & (1u << MAZE_NORTH))) {
                uint8_t *q = p + up + 1;
                if ((*q & 0x0Fu) == UNSEEN) {
                    *q ^= x;
                    ln = mark(fc + FRONT + ROW, bit, (uint8_t)(i + ROW), ln);
                }
            }
            if ((at & 8u) && (open & (1u << MAZE_EAST))) {
                uint8_t *q = p + 3;
                if (*q >= (UNSEEN << 4)) {
                    *q ^= xh;
                    ln = mark_east(fc, bit, i, ln);
                }
            }
        }
    }
    return (uint8_t)(ln - b->next_list);
}

/* Classic level: each frontier cell (its nibble is k) reaches its open
 * neighbours. As level_configs. */
static uint8_t level_cells(const bfs_t *b, uint8_t x)
{
    uint8_t *ln = b->next_list;
    for (uint8_t n = 0; n < b->count; n++) {
        uint8_t i = b->list[n];
        uint8_t *fc = b->front + i;
        uint8_t bits = *fc;
        *fc = 0;
        maze_cell_t c = first_cell(b, i);
        for (uint8_t bit = 1; bits; bit = (uint8_t)(bit << 1), bits >>= 1, c++) {
            if (!(bits & 1u)) continue;
            uint8_t *p = b->cost + 2u * c;
            uint8_t open = open_sides(b->wall[c], b->unknown);
            if ((open & (1u << MAZE_NORTH)) && (p[b->up] & 0x0Fu) == UNSEEN) {
                p[b->up] ^= x;
                ln = mark(fc + FRONT + ROW, bit, (uint8_t)(i + ROW), ln);
            }
            if ((open & (1u << MAZE_EAST)) && (p[2] & 0x0Fu) == UNSEEN) {
                p[2] ^= x;
                ln = mark_east(fc, bit, i, ln);
            }
            if ((open & (1u << MAZE_SOUTH)) && (*(p - b->up) & 0x0Fu) == UNSEEN) {
                *(p - b->up) ^= x;
                ln = mark(fc + FRONT - ROW, bit, (uint8_t)(i - ROW), ln);
            }
            if ((open & (1u << MAZE_WEST)) && (*(p - 2) & 0x0Fu) == UNSEEN) {
                *(p - 2) ^= x;
                ln = mark_west(fc, bit, i, ln);
            }
        }
    }
    return (uint8_t)(ln - b->next_list);
}

/* Heading-aware (headings 4) or classic (headings 1) flood; src_i is the
 * source's nibble index. */
static uint16_t bfs(flood_t *f, const maze_t *m, uint16_t src_i, uint8_t flags, uint8_t headings)
{
    const uint16_t cells = maze_cells(m);
    bfs_t b;
    uint16_t level = 0, src_cost = FLOOD_UNREACHABLE;
    uint8_t now = 0;

    b.cost = f->cost;
    b.wall = m->cell;
    b.front = f->front;
    b.list = f->list[0];
    b.next_list = f->list[1];
    b.count = 0;
    b.width = m->width;
    b.up = (uint16_t)(2u * b.width);
    b.unknown = (flags & FLOOD_UNKNOWN_OPEN) ? 0x0Fu : 0u;
    memset(f->cost, 0xFF, sizeof f->cost);
    memset(f->front, 0, sizeof f->front);
    /* targets: cost 0, in the first frontier (few cells: one division each) */
    for (uint16_t t = 0; t < (cells + 7u) / 8u; t++) {
        if (!f->target[t]) continue;
        for (uint8_t j = 0; j < 8; j++) {
            maze_cell_t c = (maze_cell_t)(t * 8u + j);
            if (c >= cells || !flood_is_target(f, c)) continue;
            f->cost[2u * c] = headings == 4 ? 0x00u : 0xF0u;
            if (headings == 4) f->cost[2u * c + 1u] = 0x00u;
            uint8_t i = (uint8_t)((c / b.width) * ROW + (c % b.width) / 8u);
            if (!f->front[i]) b.list[b.count++] = i;
            f->front[i] |= (uint8_t)(1u << ((c % b.width) & 7u));
        }
    }
    if (nib_get(f, src_i) == 0) {
        src_cost = 0;
        if (!(flags & FLOOD_FULL)) return 0;
    }

    while (b.count) {
        uint8_t next = (uint8_t)(now == MOD - 1u ? 0u : now + 1u), x = (uint8_t)(UNSEEN ^ next);
        uint8_t count = headings == 4 ? level_configs(&b, now, x) : level_cells(&b, x);
        if (src_cost == FLOOD_UNREACHABLE && nib_get(f, src_i) != UNSEEN) {
            src_cost = (uint16_t)(level + 1u);
            if (!(flags & FLOOD_FULL)) break;
        }
        /* level k+1 becomes current: its bytes move down, the lists swap */
        uint8_t *t = b.list;
        b.list = b.next_list;
        b.next_list = t;
        b.count = count;
        for (uint8_t n = 0; n < count; n++) {
            uint8_t i = b.list[n];
            f->front[i] = f->front[FRONT + i];
            f->front[FRONT + i] = 0;
        }
        level++;
        now = next;
    }
    return src_cost;
}

uint16_t flood_run(flood_t *f, const maze_t *m, maze_cell_t src, uint8_t src_heading, uint8_t flags)
{
    return bfs(f, m, (uint16_t)(src * 4u + (src_heading & 3u)), flags, 4);
}

uint16_t flood_cells(flood_t *f, const maze_t *m, maze_cell_t src, uint8_t flags)
{
    return bfs(f, m, (uint16_t)(src * 4u), flags, 1);
}

/* The j-th direction tried (0..3), relative to heading h: straight, right,
 * left, back (computed, not a table: an AVR copies tables into its RAM).
 * Its quarter turns are (j + 1) / 2. */
static int8_t turn_order(uint8_t j) { return j == 2 ? -1 : j == 3 ? 2 : (int8_t)j; }

int flood_next_cell_dir(const flood_t *f, const maze_t *m, maze_cell_t c, uint8_t h, uint16_t k, uint8_t flags)
{
    if (k == 0 || k == FLOOD_UNREACHABLE) return -1;
    for (uint8_t j = 0; j < 4; j++) {
        uint8_t d = maze_turn(h, turn_order(j));
        if (maze_passable(m, c, d, flags & FLOOD_UNKNOWN_OPEN) &&
            flood_cell_dist(f, maze_step(m, c, d), k) + 1u == k)
            return d;
    }
    return -1;
}

int flood_next_dir(const flood_t *f, const maze_t *m, maze_cell_t c, uint8_t h,
                   uint16_t k, uint8_t flags)
{
    if (k == 0 || k == FLOOD_UNREACHABLE) return -1;
    /* with FLOOD_PREFER_KNOWN, a first pass over known-open walls only */
    for (uint8_t pass = (flags & FLOOD_PREFER_KNOWN) ? 0 : 1; pass < 2; pass++)
        for (uint8_t j = 0; j < 4; j++) {
            uint8_t d = maze_turn(h, turn_order(j));
            if (!maze_passable(m, c, d, pass ? (flags & FLOOD_UNKNOWN_OPEN) : 0)) continue;
            uint16_t rest = flood_cost(f, maze_step(m, c, d), d, k);
            if (rest != FLOOD_UNREACHABLE && rest + 1u + (j + 1u) / 2u == k) return d;
        }
    return -1;
}

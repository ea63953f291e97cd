/* mazegen.c - legal competition mazes from a seed.
 *
 * 1. Every wall closed; the goal area opened inside.
 * 2. Randomised depth-first search from the start over the cells, with an
 *    explicit stack. The goal area is one room: the search may enter it
 *    once (its single entrance) and never leaves it. The start's east wall
 *    is never opened, so the first move is north.
 * 3. Loops: knock out about 1 in 14 of the remaining interior walls (at
 *    least one), never a goal perimeter wall, never the start's east wall,
 *    never one whose removal would leave a post without any wall.
 * A tree has no wall-less post (its four cells would form a cycle), so the
 * post rule holds after step 2 and step 3 keeps it. */
#include "mazegen.h"

#include <string.h>

/* xorshift32 (Marsaglia 2003): small, fast, same on every machine. */
static uint32_t rng_next(uint32_t *s)
{
    uint32_t x = *s;
    x ^= x << 13;
    x ^= x >> 17;
    x ^= x << 5;
    return *s = x;
}

static uint32_t rng_below(uint32_t *s, uint32_t n) { return rng_next(s) % n; }

/* Closed wall segments touching post (px, py); px 0..w, py 0..h. A segment
 * outside the maze does not exist; boundary segments are closed. */
static int post_walls(const truemaze_t *m, int px, int py)
{
    int n = 0, w = m->width, h = m->height;
    if (px < w && py > 0 && py <= h) n += !truemaze_open(m, truemaze_cell(m, (uint8_t)px, (uint8_t)(py - 1)), TRUEMAZE_NORTH);
    else if (px < w && py == 0) n++;
    if (px > 0 && py > 0 && py <= h) n += !truemaze_open(m, truemaze_cell(m, (uint8_t)(px - 1), (uint8_t)(py - 1)), TRUEMAZE_NORTH);
    else if (px > 0 && py == 0) n++;
    if (py < h && px > 0 && px <= w) n += !truemaze_open(m, truemaze_cell(m, (uint8_t)(px - 1), (uint8_t)py), TRUEMAZE_EAST);
    else if (py < h && px == 0) n++;
    if (py > 0 && px > 0 && px <= w) n += !truemaze_open(m, truemaze_cell(m, (uint8_t)(px - 1), (uint8_t)(py - 1)), TRUEMAZE_EAST);
    else if (py > 0 && px == 0) n++;
    return n;
}

/* Is the wall on side d of c the goal's perimeter or the start's east? */
static int protected_wall(const truemaze_t *m, truemaze_cell_t c, uint8_t d)
{
    truemaze_cell_t n;
    if (!truemaze_neighbour(m, c, d, &n)) return 1;
    if (truemaze_is_goal(m, c) != truemaze_is_goal(m, n)) return 1;
    if ((c == m->start && d == TRUEMAZE_EAST) || (n == m->start && d == TRUEMAZE_WEST)) return 1;
    return 0;
}

static void carve(truemaze_t *m, uint32_t *rng)
{
    static truemaze_cell_t stack[TRUEMAZE_MAX_CELLS];
    static uint8_t seen[TRUEMAZE_MAX_CELLS];
    uint16_t top = 0;
    int goal_entered = 0;

    memset(seen, 0, sizeof seen);
    stack[top++] = m->start;
    seen[m->start] = 1;
    while (top) {
        truemaze_cell_t c = stack[top - 1], n, options[4];
        uint8_t dirs[4], k = 0;
        for (uint8_t d = 0; d < 4; d++) {
            if (!truemaze_neighbour(m, c, d, &n) || seen[n]) continue;
            if (c == m->start && d == TRUEMAZE_EAST) continue;
            if (truemaze_is_goal(m, n) && goal_entered) continue;
            options[k] = n;
            dirs[k++] = d;
        }
        if (!k) {
            top--;
            continue;
        }
        uint8_t j = (uint8_t)rng_below(rng, k);
        truemaze_set_wall(m, c, dirs[j], 0);
        if (truemaze_is_goal(m, options[j])) {
            /* the whole goal room is reached; the search does not go on from it */
            goal_entered = 1;
            for (uint16_t g = 0; g < truemaze_cells(m); g++)
                if (truemaze_is_goal(m, (truemaze_cell_t)g)) seen[g] = 1;
            continue;
        }
        seen[options[j]] = 1;
        stack[top++] = options[j];
    }
}

/* Returns the number of walls knocked out. */
static uint16_t add_loops(truemaze_t *m, uint32_t *rng)
{
    uint16_t closed = 0;
    for (uint16_t c = 0; c < truemaze_cells(m); c++)
        for (uint8_t d = TRUEMAZE_NORTH; d <= TRUEMAZE_EAST; d++)
            if (!protected_wall(m, (truemaze_cell_t)c, d) && !truemaze_open(m, (truemaze_cell_t)c, d)) closed++;
    uint16_t want = closed / 14 ? closed / 14 : 1, done = 0;
    for (uint32_t tries = 0; done < want && tries < 100000u; tries++) {
        truemaze_cell_t c = (truemaze_cell_t)rng_below(rng, truemaze_cells(m));
        uint8_t d = (uint8_t)rng_below(rng, 2); /* TRUEMAZE_NORTH or TRUEMAZE_EAST */
        if (protected_wall(m, c, d) || truemaze_open(m, c, d)) continue;
        int x = truemaze_x(m, c), y = truemaze_y(m, c);
        /* the two posts at the ends of this wall */
        int ax = d == TRUEMAZE_NORTH ? x : x + 1, ay = y + 1;
        int bx = x + 1, by = d == TRUEMAZE_NORTH ? y + 1 : y;
        if (post_walls(m, ax, ay) < 2 || post_walls(m, bx, by) < 2) continue;
        truemaze_set_wall(m, c, d, 0);
        done++;
    }
    return done;
}

int mazegen_generate(truemaze_t *m, uint8_t width, uint8_t height, uint32_t seed)
{
    if (width < MAZEGEN_MIN_SIZE || height < MAZEGEN_MIN_SIZE || width > MAZEGEN_MAX_SIZE ||
        height > MAZEGEN_MAX_SIZE || truemaze_init(m, width, height) != 0)
        return -1;
    /* spread the seed so that seeds 1, 2, 3 start far apart; never 0 */
    uint32_t rng = seed * 2654435761u ^ 0x9E3779B9u;
    if (!rng) rng = 1;
    for (int i = 0; i < 8; i++) rng_next(&rng);

    /* A small maze can come out of the search with no wall that may be
     * knocked out under the post rule: search again (same seed, the PRNG
     * moves on), so every maze has a loop. */
    for (int attempt = 0; attempt < 64; attempt++) {
        truemaze_init(m, width, height);
        for (uint16_t c = 0; c < truemaze_cells(m); c++)
            for (uint8_t d = TRUEMAZE_NORTH; d <= TRUEMAZE_EAST; d++) {
                truemaze_cell_t n;
                if (truemaze_is_goal(m, (truemaze_cell_t)c) && truemaze_neighbour(m, (truemaze_cell_t)c, d, &n) && truemaze_is_goal(m, n))
                    truemaze_set_wall(m, (truemaze_cell_t)c, d, 0);
            }
        carve(m, &rng);
        if (add_loops(m, &rng) > 0) break;
    }
    return 0;
}

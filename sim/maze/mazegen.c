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
static int post_walls(const maze_t *m, int px, int py)
{
    int n = 0, w = m->width, h = m->height;
    if (px < w && py > 0 && py <= h) n += !maze_passable(m, maze_cell(m, (uint8_t)px, (uint8_t)(py - 1)), MAZE_NORTH, 0);
    else if (px < w && py == 0) n++;
    if (px > 0 && py > 0 && py <= h) n += !maze_passable(m, maze_cell(m, (uint8_t)(px - 1), (uint8_t)(py - 1)), MAZE_NORTH, 0);
    else if (px > 0 && py == 0) n++;
    if (py < h && px > 0 && px <= w) n += !maze_passable(m, maze_cell(m, (uint8_t)(px - 1), (uint8_t)py), MAZE_EAST, 0);
    else if (py < h && px == 0) n++;
    if (py > 0 && px > 0 && px <= w) n += !maze_passable(m, maze_cell(m, (uint8_t)(px - 1), (uint8_t)(py - 1)), MAZE_EAST, 0);
    else if (py > 0 && px == 0) n++;
    return n;
}

/* Is the wall on side d of c the goal's perimeter or the start's east? */
static int protected_wall(const maze_t *m, maze_cell_t c, uint8_t d)
{
    maze_cell_t n;
    if (!maze_neighbour(m, c, d, &n)) return 1;
    if (maze_is_goal(m, c) != maze_is_goal(m, n)) return 1;
    if ((c == m->start && d == MAZE_EAST) || (n == m->start && d == MAZE_WEST)) return 1;
    return 0;
}

static void carve(maze_t *m, uint32_t *rng)
{
    static maze_cell_t stack[MAZE_MAX_CELLS];
    static uint8_t seen[MAZE_MAX_CELLS];
    uint16_t top = 0;
    int goal_entered = 0;

    memset(seen, 0, sizeof seen);
    stack[top++] = m->start;
    seen[m->start] = 1;
    while (top) {
        maze_cell_t c = stack[top - 1], n, options[4];
        uint8_t dirs[4], k = 0;
        for (uint8_t d = 0; d < 4; d++) {
            if (!maze_neighbour(m, c, d, &n) || seen[n]) continue;
            if (c == m->start && d == MAZE_EAST) continue;
            if (maze_is_goal(m, n) && goal_entered) continue;
            options[k] = n;
            dirs[k++] = d;
        }
        if (!k) {
            top--;
            continue;
        }
        uint8_t j = (uint8_t)rng_below(rng, k);
        maze_set_wall(m, c, dirs[j], MAZE_WALL_OPEN);
        if (maze_is_goal(m, options[j])) {
            /* the whole goal room is reached; the search does not go on from it */
            goal_entered = 1;
            for (uint16_t g = 0; g < maze_cells(m); g++)
                if (maze_is_goal(m, (maze_cell_t)g)) seen[g] = 1;
            continue;
        }
        seen[options[j]] = 1;
        stack[top++] = options[j];
    }
}

/* Returns the number of walls knocked out. */
static uint16_t add_loops(maze_t *m, uint32_t *rng)
{
    uint16_t closed = 0;
    for (uint16_t c = 0; c < maze_cells(m); c++)
        for (uint8_t d = MAZE_NORTH; d <= MAZE_EAST; d++)
            if (!protected_wall(m, (maze_cell_t)c, d) && !maze_passable(m, (maze_cell_t)c, d, 0)) closed++;
    uint16_t want = closed / 14 ? closed / 14 : 1, done = 0;
    for (uint32_t tries = 0; done < want && tries < 100000u; tries++) {
        maze_cell_t c = (maze_cell_t)rng_below(rng, maze_cells(m));
        uint8_t d = (uint8_t)rng_below(rng, 2); /* MAZE_NORTH or MAZE_EAST */
        if (protected_wall(m, c, d) || maze_passable(m, c, d, 0)) continue;
        int x = maze_x(m, c), y = maze_y(m, c);
        /* the two posts at the ends of this wall */
        int ax = d == MAZE_NORTH ? x : x + 1, ay = y + 1;
        int bx = x + 1, by = d == MAZE_NORTH ? y + 1 : y;
        if (post_walls(m, ax, ay) < 2 || post_walls(m, bx, by) < 2) continue;
        maze_set_wall(m, c, d, MAZE_WALL_OPEN);
        done++;
    }
    return done;
}

int mazegen_generate(maze_t *m, uint8_t width, uint8_t height, uint32_t seed)
{
    if (width < MAZEGEN_MIN_SIZE || height < MAZEGEN_MIN_SIZE || width > MAZEGEN_MAX_SIZE ||
        height > MAZEGEN_MAX_SIZE || maze_init(m, width, height) != 0)
        return -1;
    /* spread the seed so that seeds 1, 2, 3 start far apart; never 0 */
    uint32_t rng = seed * 2654435761u ^ 0x9E3779B9u;
    if (!rng) rng = 1;
    for (int i = 0; i < 8; i++) rng_next(&rng);

    /* A small maze can come out of the search with no wall that may be
     * knocked out under the post rule: search again (same seed, the PRNG
     * moves on), so every maze has a loop. */
    for (int attempt = 0; attempt < 64; attempt++) {
        maze_init(m, width, height);
        maze_close_unknown(m);
        for (uint16_t c = 0; c < maze_cells(m); c++)
            for (uint8_t d = MAZE_NORTH; d <= MAZE_EAST; d++) {
                maze_cell_t n;
                if (maze_is_goal(m, (maze_cell_t)c) && maze_neighbour(m, (maze_cell_t)c, d, &n) && maze_is_goal(m, n))
                    maze_set_wall(m, (maze_cell_t)c, d, MAZE_WALL_OPEN);
            }
        carve(m, &rng);
        if (add_loops(m, &rng) > 0) break;
    }
    return 0;
}

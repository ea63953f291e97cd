/* test_flood_ref.c - the firmware's floods against a plain reference: a
 * FIFO breadth-first search with a uint16 cost per configuration (or per
 * cell), written here from the rules in flood.h. Every maze of
 * $SHARED/mazes/classic (default ../shared) and of mazes/, plus random
 * maps of odd sizes; each as its true map, its blank map and a map with
 * half of its walls forgotten; targets the goal and the start cell; unknown
 * walls open and closed; full floods and floods stopping at a source.
 * Checked: the returned cost, the cost of every configuration the flood
 * reached, which configurations a flood stopping at its source reached,
 * and the direction flood_next_dir / flood_next_cell_dir picks at every
 * step of the path walked down the one field (as a speed run does).
 * Built twice: with the host's 32x32 maximum, and as test_flood_ref16 with
 * the AVR's 16x16 (maze_cell_t is then uint8_t, as on the mouse). */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <cmocka.h>

#include <dirent.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "flood.h"
#include "maze/mazefile.h"
#include "maze/truebelief.h"

#define NONE 0xFFFFu
#define SOURCES 12 /* non-full floods per map, flag set and target set */

static flood_t f;
static uint16_t ref[FLOOD_CONFIGS];   /* reference cost per config (or cell) */
static uint16_t queue[FLOOD_CONFIGS];
static long floods_checked;

static const int8_t order[4] = { 0, 1, -1, 2 }; /* straight, right, left, back */
static const uint8_t rot_cost[4] = { 0, 1, 1, 2 };

/* Heading-aware reference: cost to reach a target cell from (c, h), where a
 * forward move and a quarter turn each cost 1. BFS backwards from the
 * targets over predecessors. */
static void ref_configs(const maze_t *m, int unknown_open)
{
    uint16_t n = (uint16_t)(maze_cells(m) * 4u), head = 0, tail = 0;
    for (uint16_t i = 0; i < FLOOD_CONFIGS; i++) ref[i] = NONE;
    for (uint16_t c = 0; c < maze_cells(m); c++)
        if (flood_is_target(&f, (maze_cell_t)c))
            for (uint8_t h = 0; h < 4; h++) {
                ref[c * 4 + h] = 0;
                queue[tail++] = (uint16_t)(c * 4 + h);
            }
    while (head < tail) {
        uint16_t i = queue[head++];
        maze_cell_t c = (maze_cell_t)(i / 4), b;
        uint8_t h = (uint8_t)(i % 4);
        uint16_t p[3];
        int np = 0;
        p[np++] = (uint16_t)(c * 4 + (h + 1) % 4);
        p[np++] = (uint16_t)(c * 4 + (h + 3) % 4);
        uint8_t back = (uint8_t)((h + 2) % 4);
        if (maze_passable(m, c, back, unknown_open) && maze_neighbour(m, c, back, &b))
            p[np++] = (uint16_t)(b * 4 + h);
        for (int k = 0; k < np; k++)
            if (ref[p[k]] == NONE) {
                assert_true(p[k] < n);
                ref[p[k]] = (uint16_t)(ref[i] + 1);
                queue[tail++] = p[k];
            }
    }
}

/* Classic reference: cell distances to the targets. */
static void ref_cells(const maze_t *m, int unknown_open)
{
    uint16_t head = 0, tail = 0;
    for (uint16_t i = 0; i < FLOOD_CONFIGS; i++) ref[i] = NONE;
    for (uint16_t c = 0; c < maze_cells(m); c++)
        if (flood_is_target(&f, (maze_cell_t)c)) {
            ref[c] = 0;
            queue[tail++] = c;
        }
    while (head < tail) {
        maze_cell_t c = (maze_cell_t)queue[head++], b;
        for (uint8_t d = 0; d < 4; d++)
            if (maze_passable(m, c, d, unknown_open) && maze_neighbour(m, c, d, &b) && ref[b] == NONE) {
                ref[b] = (uint16_t)(ref[c] + 1);
                queue[tail++] = b;
            }
    }
}

/* The direction flood.h promises for a mouse at (c, h) with cost k, from the
 * reference costs (cost_of(n, d) = cost of configuration or cell). */
static int ref_next(const maze_t *m, maze_cell_t c, uint8_t h, uint16_t k, uint8_t flags, int heading)
{
    if (k == 0 || k == NONE) return -1;
    /* with FLOOD_PREFER_KNOWN (heading-aware only), known-open walls first */
    for (int pass = (heading && (flags & FLOOD_PREFER_KNOWN)) ? 0 : 1; pass < 2; pass++)
        for (int j = 0; j < 4; j++) {
            uint8_t d = (uint8_t)((h + 4 + order[j]) % 4);
            maze_cell_t n;
            int open = pass ? (flags & FLOOD_UNKNOWN_OPEN) != 0 : 0;
            if (!maze_passable(m, c, d, open) || !maze_neighbour(m, c, d, &n)) continue;
            uint16_t rest = heading ? ref[n * 4 + d] : ref[n];
            if (rest != NONE && rest + 1u + (heading ? rot_cost[j] : 0u) == k) return d;
        }
    return -1;
}

/* Every configuration (heading) or cell (!heading) against the reference,
 * after a flood that returned k; full: the flood had FLOOD_FULL. A flood
 * that stopped at its source holds every configuration up to the source's
 * cost and none dearer (flood.h). */
static void check_field(const maze_t *m, int heading, int full, uint16_t k)
{
    uint16_t n = heading ? (uint16_t)(maze_cells(m) * 4u) : maze_cells(m);
    for (uint16_t i = 0; i < n; i++) {
        maze_cell_t c = (maze_cell_t)(heading ? i / 4 : i);
        uint8_t h = (uint8_t)(heading ? i % 4 : 0);
        uint16_t slot = (uint16_t)(c * 4u + h); /* nibble index, flood.h */
        int reached = ((f.cost[slot / 2] >> (slot % 2 * 4)) & 15u) != 15u;
        if (reached) {
            assert_int_not_equal(ref[i], NONE);
            assert_int_equal(flood_cost(&f, c, h, ref[i]), ref[i]);
            if (!full && k != NONE) assert_true(ref[i] <= k);
        } else if (ref[i] != NONE) {
            assert_true(!full && k != NONE && ref[i] > k);
        }
    }
}

/* Walk the path down from (c, h) on the field of one flood, checking each
 * decision against the reference. */
static void check_walk(const maze_t *m, maze_cell_t c, uint8_t h, uint16_t k, uint8_t flags, int heading)
{
    for (int steps = 0; steps < 4 * FLOOD_CONFIGS; steps++) {
        int want = ref_next(m, c, h, k, flags, heading);
        int got = heading ? flood_next_dir(&f, m, c, h, k, flags) : flood_next_cell_dir(&f, m, c, h, k, flags);
        assert_int_equal(got, want);
        if (got < 0) return;
        uint8_t d = (uint8_t)got;
        if (heading) {
            if (d != h) { /* turn on the spot */
                k = (uint16_t)(k - (((d - h) & 3u) == 2 ? 2u : 1u));
                h = d;
                continue;
            }
        } else {
            h = d;
        }
        assert_true(maze_neighbour(m, c, d, &c));
        k--;
    }
    fail_msg("path does not end");
}

static uint32_t rng = 2463534242u;
static uint32_t next_rand(void)
{
    rng ^= rng << 13;
    rng ^= rng >> 17;
    rng ^= rng << 5;
    return rng;
}

/* Both floods, unknown walls open and closed, targets = goal and = start. */
static void check_map(const maze_t *m)
{
    uint16_t cells = maze_cells(m);
    for (int targets = 0; targets < 2; targets++)
        for (uint8_t uo = 0; uo <= FLOOD_UNKNOWN_OPEN; uo += FLOOD_UNKNOWN_OPEN)
            for (int heading = 0; heading < 2; heading++) {
                if (targets) {
                    flood_target_clear(&f);
                    flood_target_add(&f, m->start);
                } else {
                    flood_target_goal(&f, m);
                }
                if (heading) ref_configs(m, uo);
                else ref_cells(m, uo);
                for (int s = 0; s <= SOURCES; s++) {
                    /* s = 0: the start configuration, full flood */
                    maze_cell_t c = s ? (maze_cell_t)(next_rand() % cells) : m->start;
                    uint8_t h = s ? (uint8_t)(next_rand() % 4) : m->start_heading;
                    uint8_t flags = (uint8_t)(uo | (s ? 0 : FLOOD_FULL));
                    uint16_t want = heading ? ref[c * 4 + h] : ref[c];
                    uint16_t k = heading ? flood_run(&f, m, c, h, flags) : flood_cells(&f, m, c, flags);
                    assert_int_equal(k, want);
                    check_field(m, heading, s == 0, k);
                    check_walk(m, c, h, k, uo, heading);
                    check_walk(m, c, h, k, (uint8_t)(uo | FLOOD_PREFER_KNOWN), heading);
                    floods_checked++;
                }
            }
}

/* The true map, its blank map, and the true map with about half of its
 * interior walls made unknown again (a map in mid-search). */
static void check_maze(const maze_t *t)
{
    static maze_t m;
    check_map(t);
    maze_forget(&m, t);
    check_map(&m);
    m = *t;
    for (uint16_t c = 0; c < maze_cells(&m); c++)
        for (uint8_t d = 0; d < 2; d++) /* north and east: each wall once */
            if (next_rand() % 2) maze_set_wall(&m, (maze_cell_t)c, d, MAZE_WALL_UNKNOWN);
    check_map(&m);
}

static int ends_with_txt(const char *s)
{
    size_t n = strlen(s);
    return n > 4 && !strcmp(s + n - 4, ".txt");
}

/* Every maze file of a directory; returns how many. */
static int check_dir(const char *dir)
{
    static truemaze_t truth;
    static maze_t t; /* the firmware's map of it, every wall known */
    char path[1024], err[MAZEFILE_ERR_LEN];
    int files = 0;
    DIR *d = opendir(dir);
    if (!d) return 0;
    struct dirent *e;
    while ((e = readdir(d)) != NULL) {
        if (!ends_with_txt(e->d_name)) continue;
        snprintf(path, sizeof path, "%s/%s", dir, e->d_name);
        if (mazefile_load(&truth, path, NULL, err, sizeof err) != 0) continue; /* mazes/README.md etc. */
        if (truemaze_to_belief(&truth, &t) != 0) continue; /* larger than this build's MAZE_MAX_SIZE */
        check_maze(&t);
        files++;
    }
    closedir(d);
    return files;
}

static void test_repo_mazes(void **state)
{
    (void)state;
    /* 5x5 .. 32x32; a 16x16 build (test_flood_ref16) loads all but 32x32 */
    assert_true(check_dir("mazes") >= (MAZE_MAX_SIZE >= 32 ? 6 : 5));
}

static void test_classic_database(void **state)
{
    (void)state;
    const char *shared = getenv("SHARED") ? getenv("SHARED") : "../shared";
    char dir[512];
    snprintf(dir, sizeof dir, "%s/mazes/classic", shared);
    long before = floods_checked;
    int files = check_dir(dir);
    if (files == 0) {
        printf("SKIP test_classic_database: %s not found\n", dir);
        skip();
    }
    assert_true(files > 400);
    assert_true(floods_checked - before > 400L * 3 * 8 * (SOURCES + 1) - 1);
}

/* Random walls (open, closed, unknown) on sizes from 1x1 to 20x20 (or the
 * build's maximum) in steps, goal = the centre set maze_init gives. */
static void test_random_sizes(void **state)
{
    (void)state;
    static maze_t m;
    const uint8_t max = MAZE_MAX_SIZE < 20 ? MAZE_MAX_SIZE : 20;
    for (uint8_t w = 1; w <= max; w += 3)
        for (uint8_t h = 1; h <= max; h += 2) {
            assert_int_equal(maze_init(&m, w, h), 0);
            for (uint16_t c = 0; c < maze_cells(&m); c++)
                for (uint8_t d = 0; d < 2; d++) {
                    uint32_t r = next_rand() % 4;
                    maze_set_wall(&m, (maze_cell_t)c, d, r == 0 ? MAZE_WALL_CLOSED : r == 1 ? MAZE_WALL_UNKNOWN : MAZE_WALL_OPEN);
                }
            m.start = (maze_cell_t)(next_rand() % maze_cells(&m));
            m.start_heading = (uint8_t)(next_rand() % 4);
            check_map(&m);
        }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_repo_mazes),
        cmocka_unit_test(test_random_sizes),
        cmocka_unit_test(test_classic_database),
    };
    return cmocka_run_group_tests_name("flood_ref", tests, NULL, NULL);
}

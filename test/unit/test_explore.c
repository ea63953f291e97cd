/* test_explore.c - the search strategy: hand-built mazes with the hal_log
 * lines checked through a link-time mock (-Wl,--wrap=hal_log), grid-mode
 * runs on generated mazes and on every classic maze of the database. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <cmocka.h>

#include <dirent.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "explore.h"
#include "maze/grid.h"
#include "hal.h"
#include "maze/mazefile.h"
#include "maze/mazegen.h"
#include "maze/solve.h"
#include "maze/truebelief.h"

static int log_checked; /* while set, every hal_log line must be expected */

void __wrap_hal_log(const char *line);
void __wrap_hal_log(const char *line)
{
    if (log_checked) check_expected(line);
}

static int time_mocked; /* while set, hal_micros returns queued values */

uint32_t __wrap_hal_micros(void);
uint32_t __wrap_hal_micros(void)
{
    return time_mocked ? (uint32_t)mock() : 0u;
}

static explore_t mouse;

static void closed_maze(truemaze_t *m, uint8_t w, uint8_t h)
{
    truemaze_init(m, w, h);
}

/* Drive the mouse through truth; returns the moves made. */
static int drive(const truemaze_t *truth, uint8_t *moves, int max)
{
    static maze_t blank;
    int n = 0;
    assert_int_equal(truemaze_to_belief(truth, &blank), 0);
    explore_init(&mouse, &blank);
    for (;;) {
        explore_sense(&mouse, grid_sense(truth, mouse.cell, mouse.heading));
        int d = explore_next(&mouse);
        if (d < 0 || n >= max) return n;
        assert_true(truemaze_open(truth, mouse.cell, (uint8_t)d)); /* never into a wall */
        moves[n++] = (uint8_t)d;
        explore_moved(&mouse, (uint8_t)d);
    }
}

/* L route (0,0)->(0,2)->(1,2) in a closed 4x4: 3 steps to the goal, proven
 * there (cost 4: 3 forward + 1 turn), 3 steps back. */
static void test_l_route_proven_and_logged(void **state)
{
    (void)state;
    truemaze_t t;
    uint8_t mv[64];
    closed_maze(&t, 4, 4);
    truemaze_set_wall(&t, truemaze_cell(&t, 0, 0), TRUEMAZE_NORTH, 0);
    truemaze_set_wall(&t, truemaze_cell(&t, 0, 1), TRUEMAZE_NORTH, 0);
    truemaze_set_wall(&t, truemaze_cell(&t, 0, 2), TRUEMAZE_EAST, 0);
    log_checked = 1;
    expect_string(__wrap_hal_log, line, "explore: run path proven at step 3, cost 4");
    int n = drive(&t, mv, 64);
    log_checked = 0;
    assert_int_equal(n, 6);
    const uint8_t want[6] = { MAZE_NORTH, MAZE_NORTH, MAZE_EAST, MAZE_WEST, MAZE_SOUTH, MAZE_SOUTH };
    assert_memory_equal(mv, want, 6);
    assert_int_equal(mouse.phase, EXPLORE_DONE);
    assert_int_equal(mouse.proven_at_step, 3);
    assert_int_equal(mouse.run_cost, 4);
    assert_int_equal(explore_run_dir(&mouse, t.start, MAZE_NORTH), MAZE_NORTH);
}

/* A boxed-in start: the run ends at once, reported, never a loop. */
static void test_unreachable_goal_ends(void **state)
{
    (void)state;
    truemaze_t t;
    uint8_t mv[8];
    closed_maze(&t, 4, 4);
    log_checked = 1;
    expect_string(__wrap_hal_log, line, "explore: goal unreachable");
    assert_int_equal(drive(&t, mv, 8), 0);
    log_checked = 0;
    assert_int_equal(mouse.phase, EXPLORE_NO_GOAL);
    assert_int_equal(mouse.proven_at_step, EXPLORE_NEVER);
}

/* Goal reachable only after a detour that the optimistic flood first
 * ignores: the mouse must still end with the true best path. */
static void test_generated_mazes_end_optimal(void **state)
{
    (void)state;
    static truemaze_t t;
    for (uint8_t size = 4; size <= 32; size += 2)
        for (uint32_t seed = 1; seed <= 3; seed++) {
            grid_result_t r;
            assert_int_equal(mazegen_generate(&t, size, size, seed), 0);
            assert_int_equal(grid_explore(&t, &r), 0);
            assert_true(r.goal_reachable);
            assert_true(r.final_path_optimal);
            assert_true(r.ended_at_start);
            assert_true(r.proven_at_step > 0 && (uint32_t)r.proven_at_step <= r.steps);
            assert_int_equal(r.steps, r.steps_forward + r.steps_left + r.steps_right + r.steps_back);
        }
}

static int ends_with_txt(const char *s)
{
    size_t n = strlen(s);
    return n > 4 && !strcmp(s + n - 4, ".txt");
}

/* Every classic maze: reachable -> the final path is the true best;
 * unreachable -> reported as such. Zero exceptions. */
static void test_database_classic_all_optimal(void **state)
{
    (void)state;
    const char *shared = getenv("SHARED") ? getenv("SHARED") : "../shared";
    char dir[512], path[1024], err[MAZEFILE_ERR_LEN];
    static truemaze_t t;
    snprintf(dir, sizeof dir, "%s/mazes/classic", shared);
    DIR *d = opendir(dir);
    if (!d) {
        printf("SKIP test_database_classic_all_optimal: %s not found\n", dir);
        skip();
    }
    struct dirent *e;
    int files = 0, unreachable = 0, bad = 0;
    while ((e = readdir(d)) != NULL) {
        if (!ends_with_txt(e->d_name)) continue;
        snprintf(path, sizeof path, "%s/%s", dir, e->d_name);
        assert_int_equal(mazefile_load(&t, path, NULL, err, sizeof err), 0);
        grid_result_t r;
        int rc = grid_explore(&t, &r);
        files++;
        if (!r.goal_reachable) {
            unreachable++;
            assert_int_equal(rc, 1);
            assert_int_equal(r.proven_at_step, -1);
            continue;
        }
        if (rc != 0 || !r.final_path_optimal) {
            printf("not optimal: %s\n", path);
            bad++;
        }
    }
    closedir(d);
    assert_true(files > 400);
    assert_int_equal(bad, 0);
    assert_int_equal(unreachable, 2); /* 001.txt and 001-anomaly-test.txt */
}

/* explore_next keeps the longest planning time, measured with hal_micros,
 * also across the 32-bit wrap of the microsecond clock. */
static void test_planning_time_from_hal_micros(void **state)
{
    (void)state;
    maze_t t;
    maze_init(&t, 5, 5); /* open 5x5: the first decision is a move */
    explore_init(&mouse, &t);
    time_mocked = 1;
    will_return(__wrap_hal_micros, 1000);
    will_return(__wrap_hal_micros, 1250);
    assert_true(explore_next(&mouse) >= 0);
    assert_int_equal(mouse.plan_us_max, 250);
    will_return(__wrap_hal_micros, 0xFFFFFF00u);
    will_return(__wrap_hal_micros, 0x00000100u);
    assert_true(explore_next(&mouse) >= 0);
    assert_int_equal(mouse.plan_us_max, 0x200);
    will_return(__wrap_hal_micros, 50);
    will_return(__wrap_hal_micros, 60);
    explore_next(&mouse);
    assert_int_equal(mouse.plan_us_max, 0x200);
    time_mocked = 0;
}

/* explore_dir_ahead walks the last flood's field down a straight: at every
 * cell it gives what a fresh flood from that cell gives, towards the goal
 * and towards the start, from every configuration that starts a straight. */
static void test_dir_ahead_matches_fresh_floods(void **state)
{
    (void)state;
    static truemaze_t t;
    static uint8_t mv[1024];
    char err[MAZEFILE_ERR_LEN];
    assert_int_equal(mazefile_load(&t, "mazes/gen-16x16-s1.txt", NULL, err, sizeof err), 0);
    drive(&t, mv, (int)sizeof mv);
    assert_int_equal(mouse.phase, EXPLORE_DONE);
    int checked = 0;
    for (int home = 0; home < 2; home++) {
        for (maze_cell_t c = 0; c < 256; c++) {
            for (uint8_t h = 0; h < 4; h++) {
                int d = home ? explore_home_dir(&mouse, c, h) : explore_run_dir(&mouse, c, h);
                if (d != h) continue;
                int ahead[16];
                maze_cell_t cells[16], cc = c;
                int n = 0;
                while (n < 16 && maze_neighbour(&mouse.map, cc, h, &cc)) {
                    cells[n] = cc;
                    ahead[n] = explore_dir_ahead(&mouse, cc, h, (uint8_t)(n + 1));
                    if (ahead[n++] != h) break;
                }
                for (int i = 0; i < n; i++) {
                    int fresh = home ? explore_home_dir(&mouse, cells[i], h) : explore_run_dir(&mouse, cells[i], h);
                    assert_int_equal(ahead[i], fresh);
                    checked++;
                }
            }
        }
    }
    assert_int_equal(checked, 402); /* cells on straights of the known map, both ways */
    mouse.path_cost = FLOOD_UNREACHABLE; /* no flood asked: no direction */
    assert_int_equal(explore_dir_ahead(&mouse, 0, MAZE_NORTH, 1), -1);
}

/* A speed run floods once, at its start (mouse.c run_plan): walking that
 * field with path_cost lowered by the cells and quarter turns made gives the
 * same headings as a fresh flood at every configuration of the path, to the
 * goal and back home. */
static void test_one_flood_per_run(void **state)
{
    (void)state;
    static truemaze_t t;
    static uint8_t mv[1024];
    char err[MAZEFILE_ERR_LEN];
    assert_int_equal(mazefile_load(&t, "mazes/gen-16x16-s1.txt", NULL, err, sizeof err), 0);
    drive(&t, mv, (int)sizeof mv);
    assert_int_equal(mouse.phase, EXPLORE_DONE);
    maze_cell_t from = mouse.map.start;
    uint8_t from_h = mouse.map.start_heading;
    for (int home = 0; home < 2; home++) {
        static int8_t ref[512];
        int n = 0, turns = 0;
        maze_cell_t c = from;
        uint8_t h = from_h;
        for (;;) { /* fresh floods */
            int d = home ? explore_home_dir(&mouse, c, h) : explore_run_dir(&mouse, c, h);
            assert_true(n < 512);
            ref[n++] = (int8_t)d;
            if (d < 0) break;
            if (d == h) assert_true(maze_neighbour(&mouse.map, c, h, &c));
            else h = (uint8_t)d, turns++;
        }
        c = from;
        h = from_h;
        int d = home ? explore_home_dir(&mouse, c, h) : explore_run_dir(&mouse, c, h);
        for (int i = 0; i < n; i++) { /* the first flood only */
            if (i) d = explore_dir_ahead(&mouse, c, h, 0);
            assert_int_equal(d, ref[i]);
            if (d < 0) break;
            if (d == h) {
                assert_true(maze_neighbour(&mouse.map, c, h, &c));
                mouse.path_cost--;
            } else {
                mouse.path_cost = (uint16_t)(mouse.path_cost - (((d - h) & 3) == 2 ? 2u : 1u));
                h = (uint8_t)d;
            }
        }
        assert_int_equal(mouse.path_cost, 0);
        assert_true(turns >= 10 && n > 30); /* a real path (34 steps, 13 turns to the goal) */
        from = c; /* back home from the goal, facing the way the run ended */
        from_h = h;
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_l_route_proven_and_logged),
        cmocka_unit_test(test_unreachable_goal_ends),
        cmocka_unit_test(test_planning_time_from_hal_micros),
        cmocka_unit_test(test_dir_ahead_matches_fresh_floods),
        cmocka_unit_test(test_one_flood_per_run),
        cmocka_unit_test(test_generated_mazes_end_optimal),
        cmocka_unit_test(test_database_classic_all_optimal),
    };
    return cmocka_run_group_tests_name("explore", tests, NULL, NULL);
}

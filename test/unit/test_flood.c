/* test_flood.c - classic and heading-aware floodfill on hand-built mazes,
 * costs checked by hand, and the nibble encoding against the host solver. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <cmocka.h>

#include "flood.h"
#include "maze/solve.h"
#include "maze/truebelief.h"

static flood_t f;

/* Close every wall, then open the listed moves: from (x,y) towards d. */
static void closed_maze(maze_t *m, uint8_t w, uint8_t h)
{
    maze_init(m, w, h);
    maze_close_unknown(m);
}
static void open_wall(maze_t *m, uint8_t x, uint8_t y, uint8_t d)
{
    maze_set_wall(m, maze_cell(m, x, y), d, MAZE_WALL_OPEN);
}

/* 3x1 corridor, goal the middle cell (odd width: 1 cell), unknown walls. */
static void test_corridor_rotation_costs(void **state)
{
    (void)state;
    maze_t m;
    maze_init(&m, 3, 1);
    maze_cell_t s = maze_cell(&m, 0, 0);
    assert_true(maze_is_goal(&m, maze_cell(&m, 1, 0)));
    flood_target_goal(&f, &m);
    assert_int_equal(flood_run(&f, &m, s, MAZE_EAST, FLOOD_UNKNOWN_OPEN), 1);  /* forward */
    assert_int_equal(flood_run(&f, &m, s, MAZE_NORTH, FLOOD_UNKNOWN_OPEN), 2); /* turn right, forward */
    assert_int_equal(flood_run(&f, &m, s, MAZE_SOUTH, FLOOD_UNKNOWN_OPEN), 2); /* turn left, forward */
    assert_int_equal(flood_run(&f, &m, s, MAZE_WEST, FLOOD_UNKNOWN_OPEN), 3);  /* 180 = 2, forward */
    /* unknown walls closed: no way out of the start cell */
    assert_int_equal(flood_run(&f, &m, s, MAZE_EAST, 0), FLOOD_UNREACHABLE);
    /* the goal itself costs 0 in every heading */
    assert_int_equal(flood_run(&f, &m, maze_cell(&m, 1, 0), MAZE_WEST, FLOOD_UNKNOWN_OPEN), 0);
}

/* 4x4, all walls closed except the L-shaped route (0,0)->(0,1)->(0,2)->(1,2);
 * (1,2) is in the 2x2 centre goal (1..2, 1..2). */
static void test_l_route(void **state)
{
    (void)state;
    maze_t m;
    closed_maze(&m, 4, 4);
    open_wall(&m, 0, 0, MAZE_NORTH);
    open_wall(&m, 0, 1, MAZE_NORTH);
    open_wall(&m, 0, 2, MAZE_EAST);
    maze_cell_t s = maze_cell(&m, 0, 0);
    flood_target_goal(&f, &m);
    assert_int_equal(flood_run(&f, &m, s, MAZE_NORTH, 0), 4); /* 2 forward, turn, 1 forward */
    assert_int_equal(flood_run(&f, &m, s, MAZE_EAST, 0), 5);
    assert_int_equal(flood_run(&f, &m, s, MAZE_WEST, 0), 5);
    assert_int_equal(flood_run(&f, &m, s, MAZE_SOUTH, 0), 6);
    /* from (0,2) facing south: turn left to east (1) + forward (1) */
    assert_int_equal(flood_run(&f, &m, maze_cell(&m, 0, 2), MAZE_SOUTH, 0), 2);
    /* next moves along the route */
    uint16_t k = flood_run(&f, &m, s, MAZE_NORTH, FLOOD_FULL);
    assert_int_equal(flood_next_dir(&f, &m, s, MAZE_NORTH, k, 0), MAZE_NORTH);
    assert_int_equal(flood_cost(&f, maze_cell(&m, 0, 1), MAZE_NORTH, k), 3);
    assert_int_equal(flood_next_dir(&f, &m, maze_cell(&m, 0, 2), MAZE_NORTH, 2, 0), MAZE_EAST);
    assert_int_equal(flood_next_dir(&f, &m, maze_cell(&m, 1, 2), MAZE_EAST, 0, 0), -1);
    /* classic flood: 3 cells */
    assert_int_equal(flood_cells(&f, &m, s, 0), 3);
    assert_int_equal(flood_cells(&f, &m, maze_cell(&m, 3, 3), 0), FLOOD_UNREACHABLE);
}

/* Classic floodfill on the open 5x5 (unknown open): Manhattan distance to
 * the single centre cell (2,2). */
static void test_classic_open(void **state)
{
    (void)state;
    maze_t m;
    maze_init(&m, 5, 5);
    flood_target_goal(&f, &m);
    assert_int_equal(flood_cells(&f, &m, maze_cell(&m, 0, 0), FLOOD_UNKNOWN_OPEN | FLOOD_FULL), 4);
    for (uint8_t y = 0; y < 5; y++)
        for (uint8_t x = 0; x < 5; x++)
            assert_int_equal(flood_cell_dist(&f, maze_cell(&m, x, y), 4),
                             (x > 2 ? x - 2 : 2 - x) + (y > 2 ? y - 2 : 2 - y));
}

/* Straight on is preferred when it is one of the best moves. */
static void test_prefers_straight(void **state)
{
    (void)state;
    maze_t m;
    maze_init(&m, 8, 8);
    maze_cell_t s = maze_cell(&m, 0, 0);
    flood_target_goal(&f, &m);
    uint16_t k = flood_run(&f, &m, s, MAZE_NORTH, FLOOD_UNKNOWN_OPEN);
    assert_int_equal(k, 7); /* 3 north, turn, 3 east to (3,3) */
    assert_int_equal(flood_next_dir(&f, &m, s, MAZE_NORTH, k, FLOOD_UNKNOWN_OPEN), MAZE_NORTH);
    k = flood_run(&f, &m, s, MAZE_EAST, FLOOD_UNKNOWN_OPEN);
    assert_int_equal(flood_next_dir(&f, &m, s, MAZE_EAST, k, FLOOD_UNKNOWN_OPEN), MAZE_EAST);
}

/* Classic move choice, and known-open walls winning ties when asked. */
static void test_next_cell_dir_and_prefer_known(void **state)
{
    (void)state;
    maze_t m;
    maze_init(&m, 5, 5); /* goal (2,2); every interior wall unknown */
    maze_cell_t s = maze_cell(&m, 0, 0);
    flood_target_goal(&f, &m);
    uint16_t k = flood_cells(&f, &m, s, FLOOD_UNKNOWN_OPEN);
    assert_int_equal(k, 4);
    assert_int_equal(flood_next_cell_dir(&f, &m, s, MAZE_NORTH, k, FLOOD_UNKNOWN_OPEN), MAZE_NORTH);
    assert_int_equal(flood_next_cell_dir(&f, &m, s, MAZE_EAST, k, FLOOD_UNKNOWN_OPEN), MAZE_EAST);
    assert_int_equal(flood_next_cell_dir(&f, &m, s, MAZE_SOUTH, k, FLOOD_UNKNOWN_OPEN), MAZE_EAST); /* right */
    assert_int_equal(flood_next_cell_dir(&f, &m, s, MAZE_NORTH, k, 0), -1); /* unknown closed */
    /* (2,0) facing north, targets (1,0) and (3,0): right and left tie at
     * cost 2; right wins unless west is known open and east unknown, with
     * FLOOD_PREFER_KNOWN */
    maze_cell_t c = maze_cell(&m, 2, 0);
    flood_target_clear(&f);
    flood_target_add(&f, maze_cell(&m, 1, 0));
    flood_target_add(&f, maze_cell(&m, 3, 0));
    k = flood_run(&f, &m, c, MAZE_NORTH, FLOOD_UNKNOWN_OPEN | FLOOD_FULL);
    assert_int_equal(k, 2);
    assert_int_equal(flood_next_dir(&f, &m, c, MAZE_NORTH, k, FLOOD_UNKNOWN_OPEN), MAZE_EAST);
    maze_set_wall(&m, c, MAZE_WEST, MAZE_WALL_OPEN);
    assert_int_equal(flood_next_dir(&f, &m, c, MAZE_NORTH, k, FLOOD_UNKNOWN_OPEN), MAZE_EAST);
    assert_int_equal(flood_next_dir(&f, &m, c, MAZE_NORTH, k, FLOOD_UNKNOWN_OPEN | FLOOD_PREFER_KNOWN), MAZE_WEST);
}

/* A serpentine 8x8 where costs run far past the nibble's 15: every
 * configuration's flood cost equals the host solver's exact cost. */
static void test_serpentine_matches_solver(void **state)
{
    (void)state;
    maze_t m;
    closed_maze(&m, 8, 8);
    for (uint8_t y = 0; y < 8; y++) {
        for (uint8_t x = 0; x + 1 < 8; x++) open_wall(&m, x, y, MAZE_EAST);
        if (y + 1 < 8) open_wall(&m, (y % 2) ? 0 : 7, y, MAZE_NORTH);
    }
    /* the centre goal 3..4 x 3..4 is reached along the rows */
    static truemaze_t solved; /* m for the host solver */
    truemaze_from_belief(&solved, &m, 0);
    flood_target_goal(&f, &m);
    for (uint16_t c = 0; c < maze_cells(&m); c++)
        for (uint8_t h = 0; h < 4; h++) {
            uint16_t want = solve_cost_from(&solved, c, h);
            assert_int_equal(flood_run(&f, &m, (maze_cell_t)c, h, 0), want);
            assert_int_equal(flood_run(&f, &m, (maze_cell_t)c, h, FLOOD_FULL), want);
        }
    assert_true(solve_cost_from(&solved, maze_cell(&m, 7, 7), MAZE_WEST) > 20);
}

/* Random partial knowledge: flood with unknown open/closed agrees with the
 * solver for every start configuration. */
static void test_random_maps_match_solver(void **state)
{
    (void)state;
    uint32_t rng = 12345u;
    for (int round = 0; round < 40; round++) {
        maze_t m;
        uint8_t w = (uint8_t)(4 + round % 13), h = (uint8_t)(4 + (round * 7) % 13);
        maze_init(&m, w, h);
        for (uint16_t c = 0; c < maze_cells(&m); c++)
            for (uint8_t d = 0; d < 2; d++) {
                rng ^= rng << 13; rng ^= rng >> 17; rng ^= rng << 5;
                uint8_t r = (uint8_t)(rng % 4);
                maze_set_wall(&m, (maze_cell_t)c, d, r == 0 ? MAZE_WALL_CLOSED : r == 1 ? MAZE_WALL_OPEN : MAZE_WALL_UNKNOWN);
            }
        flood_target_goal(&f, &m);
        for (int open = 0; open <= 1; open++) {
            static truemaze_t solved; /* m for the host solver, unknown walls open or closed */
            truemaze_from_belief(&solved, &m, open);
            for (uint16_t c = 0; c < maze_cells(&m); c += 3)
                assert_int_equal(flood_run(&f, &m, (maze_cell_t)c, (uint8_t)(c % 4), open ? FLOOD_UNKNOWN_OPEN : 0),
                                 solve_cost_from(&solved, c, (uint8_t)(c % 4)));
        }
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_corridor_rotation_costs),
        cmocka_unit_test(test_l_route),
        cmocka_unit_test(test_classic_open),
        cmocka_unit_test(test_prefers_straight),
        cmocka_unit_test(test_next_cell_dir_and_prefer_known),
        cmocka_unit_test(test_serpentine_matches_solver),
        cmocka_unit_test(test_random_maps_match_solver),
    };
    return cmocka_run_group_tests_name("flood", tests, NULL, NULL);
}

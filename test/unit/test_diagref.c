/* test_diagref.c - the expected reading of a diagonal ToF sensor on the
 * known map (firmware/diagref.h) in a 3 x 3 maze of the paper robot's
 * 180 mm cells and 12 mm walls: a wall face square to the axis is read at
 * its distance; an unknown wall, nothing in range, or a post's side (a
 * face along the axis) nearest give -1. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <cmocka.h>

#include <math.h>

#include "diagref.h"
#include "maze.h"
#include "robot_config.h"

#define NORTH_RAD 1.5707963f

/* 3 x 3, every inner wall open */
static void open_maze(maze_t *m)
{
    maze_init(m, 3, 3);
    for (uint8_t y = 0; y < 3; y++)
        for (uint8_t x = 0; x < 3; x++) {
            if (x < 2) maze_set_wall(m, maze_cell(m, x, y), MAZE_EAST, MAZE_WALL_OPEN);
            if (y < 2) maze_set_wall(m, maze_cell(m, x, y), MAZE_NORTH, MAZE_WALL_OPEN);
        }
}

/* from the middle of cell (1, 1) looking north at its closed north wall:
 * the face 6 mm short of the line at 360 mm */
static void test_wall_face(void **state)
{
    (void)state;
    maze_t m;
    open_maze(&m);
    maze_set_wall(&m, maze_cell(&m, 1, 1), MAZE_NORTH, MAZE_WALL_CLOSED);
    float e = diagref_expect(&m, 270.0f, 200.0f, NORTH_RAD, 200.0f, 8.0f);
    assert_true(fabsf(e - 154.0f) < 0.01f);
    /* open: the boundary's face at 534 mm, beyond 200 but within 400 */
    maze_set_wall(&m, maze_cell(&m, 1, 1), MAZE_NORTH, MAZE_WALL_OPEN);
    assert_true(diagref_expect(&m, 270.0f, 200.0f, NORTH_RAD, 200.0f, 8.0f) < 0.0f);
    e = diagref_expect(&m, 270.0f, 200.0f, NORTH_RAD, 400.0f, 8.0f);
    assert_true(fabsf(e - 334.0f) < 0.01f);
}

static void test_unknown_wall(void **state)
{
    (void)state;
    maze_t m;
    open_maze(&m);
    maze_set_wall(&m, maze_cell(&m, 1, 1), MAZE_NORTH, MAZE_WALL_UNKNOWN);
    assert_true(diagref_expect(&m, 270.0f, 200.0f, NORTH_RAD, 400.0f, 8.0f) < 0.0f);
}

/* 14 mm right of the post at (180, 360), looking north: the cone's left
 * edge meets the post's east side (a face along the axis) 65 mm away,
 * before anything square to the axis */
static void test_post_side(void **state)
{
    (void)state;
    maze_t m;
    open_maze(&m);
    assert_true(diagref_expect(&m, 200.0f, 300.0f, NORTH_RAD, 400.0f, 8.0f) < 0.0f);
    /* 30 mm right of it the whole cone passes: the boundary, 234 mm */
    assert_true(fabsf(diagref_expect(&m, 216.0f, 300.0f, NORTH_RAD, 400.0f, 8.0f) - 234.0f) < 0.01f);
    /* looking east from the middle of cell (1, 1) at its closed east wall */
    maze_set_wall(&m, maze_cell(&m, 1, 1), MAZE_EAST, MAZE_WALL_CLOSED);
    assert_true(fabsf(diagref_expect(&m, 270.0f, 270.0f, 0.0f, 200.0f, 8.0f) - 84.0f) < 0.01f);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_wall_face),
        cmocka_unit_test(test_unknown_wall),
        cmocka_unit_test(test_post_side),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}

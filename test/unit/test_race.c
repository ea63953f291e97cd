/* test_race.c - contest timers: global start, laps, abandoned runs, best
 * run, over-time flag, the lap table. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <cmocka.h>

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "world/race.h"

static truemaze_t m;
static race_t r;

/* centre of cell (x, y) in metres, 180 mm cells */
static double at(int i) { return (i + 0.5) * 0.18; }

static void test_laps_and_best(void **state)
{
    (void)state;
    truemaze_init(&m, 4, 4); /* goal (1..2, 1..2), start (0,0) */
    race_init(&r, &m, 0.18, 600);
    assert_int_equal(race_update(&r, 0.5, at(0), at(0)), 0);
    assert_true(race_global_s(&r, 0.5) == 0.0); /* not started while in the start cell */
    race_update(&r, 1.0, at(0), at(1));          /* leaves: global timer and run 1 start */
    assert_true(race_global_s(&r, 3.0) == 2.0);
    assert_int_equal(race_update(&r, 11.0, at(1), at(1)), 1); /* enters the goal */
    assert_int_equal(r.nlaps, 1);
    assert_true(r.laps[0].start_s == 0.0 && r.laps[0].end_s == 10.0);
    race_update(&r, 12.0, at(1), at(2)); /* wandering in and out of the goal: no new lap */
    assert_int_equal(race_update(&r, 13.0, at(2), at(2)), 0);
    race_update(&r, 20.0, at(0), at(0)); /* back at the start */
    race_update(&r, 21.0, at(0), at(1)); /* run 2 */
    race_update(&r, 24.0, at(0), at(0)); /* abandoned: back without the goal */
    race_update(&r, 25.0, at(0), at(1)); /* run 3 */
    assert_int_equal(race_update(&r, 30.0, at(1), at(1)), 1);
    assert_int_equal(r.nlaps, 2);
    assert_true(r.laps[1].start_s == 24.0 && r.laps[1].end_s == 29.0);
    assert_int_equal(r.best, 1);
    char *text = NULL;
    size_t len = 0;
    FILE *mem = open_memstream(&text, &len);
    race_print_table(&r, mem);
    fclose(mem);
    assert_string_equal(text, "Lap   Start time  End time    Run time  \n"
                              "1     0:00.000    0:10.000    0:10.000  \n"
                              "2     0:24.000    0:29.000    0:05.000    best\n");
    free(text);
}

static void test_over_time(void **state)
{
    (void)state;
    truemaze_init(&m, 4, 4);
    race_init(&r, &m, 0.18, 10);
    race_update(&r, 0.0, at(0), at(1));
    race_update(&r, 12.0, at(1), at(1)); /* after the limit */
    assert_int_equal(r.nlaps, 1);
    assert_true(r.laps[0].over_time && r.over_time);
    assert_int_equal(r.best, -1);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_laps_and_best),
        cmocka_unit_test(test_over_time),
    };
    return cmocka_run_group_tests_name("race", tests, NULL, NULL);
}

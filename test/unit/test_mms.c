/* test_mms.c - the mms API's stats (mms Stats.cpp semantics) and the
 * command parser on the answers that need no robot (ideal walls, no
 * simulation): formats, invalid commands ignored, text and colours. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <cmocka.h>

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "mms/mms.h"

static truemaze_t truth;
static mms_t mm;

static void stat_is(const mms_stats_t *s, const char *name, const char *want)
{
    char out[32];
    assert_int_equal(mms_stats_get(s, name, out, sizeof out), 0);
    assert_string_equal(out, want);
}

static void test_stats(void **state)
{
    (void)state;
    mms_stats_t s;
    char out[32];
    mms_stats_init(&s);
    stat_is(&s, "score", "2000");
    stat_is(&s, "best-run-turns", "-1");
    stat_is(&s, "best-run-effective-distance", "-1");
    stat_is(&s, "total-distance", "0");
    assert_int_equal(mms_stats_get(&s, "nope", out, sizeof out), -1);
    mms_stats_start_run(&s);
    mms_stats_distance(&s, 10); /* README: moveForward(5) = distance 5, effective 3.5 */
    stat_is(&s, "total-distance", "5");
    stat_is(&s, "current-run-effective-distance", "3.5");
    mms_stats_distance(&s, 4); /* two cells count fully */
    mms_stats_turn(&s);
    stat_is(&s, "current-run-effective-distance", "5.5");
    mms_stats_finish_run(&s);
    stat_is(&s, "best-run-turns", "1");
    stat_is(&s, "best-run-distance", "7");
    /* 1 + 5.5 + 0.1 * (1 + 5.5) */
    stat_is(&s, "score", "7.15");
    /* a reset: 15 points on the next run's effective distance */
    mms_stats_reset_penalty(&s);
    mms_stats_end_unfinished(&s);
    mms_stats_distance(&s, 2); /* not in a run: totals only */
    stat_is(&s, "current-run-effective-distance", "5.5");
    mms_stats_start_run(&s);
    stat_is(&s, "current-run-effective-distance", "15");
    mms_stats_distance(&s, 2);
    mms_stats_finish_run(&s); /* 16 > 6.5: not the best */
    stat_is(&s, "best-run-effective-distance", "5.5");
    stat_is(&s, "total-effective-distance", "22.5");
    /* half steps: half a cell each; whole cells in getStat (rounded down) */
    mms_stats_distance(&s, 1);
    stat_is(&s, "total-distance", "9");
    stat_is(&s, "total-effective-distance", "23");
    mms_stats_distance(&s, 5); /* 2.5 cells: 0.5 after the second */
    stat_is(&s, "total-distance", "12");
    stat_is(&s, "total-effective-distance", "25.25");
}

static void setup_maze(void)
{
    truemaze_init(&truth, 3, 3);
    for (uint16_t c = 0; c < truemaze_cells(&truth); c++)
        for (uint8_t d = 0; d < 4; d++) truemaze_set_wall(&truth, (truemaze_cell_t)c, d, 0);
    truemaze_set_wall(&truth, truemaze_cell(&truth, 0, 1), TRUEMAZE_NORTH, 1);
    truemaze_set_wall(&truth, truemaze_cell(&truth, 0, 0), TRUEMAZE_EAST, 1);
    mms_opts_t o = { "test", 1, 1000, -1, NULL, 0, 0 };
    mms_init(&mm, &o, &truth);
}

static const char *run(const char *line)
{
    static char resp[64];
    assert_int_equal(mms_execute(&mm, NULL, line, resp, sizeof resp), 0);
    return resp;
}

static void test_queries(void **state)
{
    (void)state;
    setup_maze(); /* the mouse (not started) stands at (0,0) facing north */
    assert_string_equal(run("mazeWidth"), "3");
    assert_string_equal(run(" mazeHeight "), "3");
    assert_string_equal(run("wallFront"), "false");
    assert_string_equal(run("wallFront 2"), "false");
    assert_string_equal(run("wallFront 3"), "true"); /* the far wall of (0,1) */
    assert_string_equal(run("wallRight"), "true");
    assert_string_equal(run("wallLeft"), "true");
    assert_string_equal(run("wallBack"), "true");
    assert_string_equal(run("wallFrontLeft"), "true");
    assert_string_equal(run("getStat score"), "2000");
    assert_string_equal(run("wasReset"), "false");
    assert_string_equal(run("moveForward 0"), "crash");
    assert_string_equal(run("moveForwardHalf 3"), "crash");
    assert_string_equal(run("turnLeft45"), "crash"); /* not in command mode */
    assert_string_equal(run("moveForward 4"), "crash"); /* through the wall north of (0,1): refused */
    assert_string_equal(run("ackReset"), "ack");
    assert_int_equal(mm.resets, 1);
    long inv = mm.invalid;
    const char *bad[] = { "", "foo", "mazeWidth 1", "getStat", "getStat x", "setColor 0 0 q", "setWall 0 0 x",
                          "setWall 5 5 n", "clearColor 1", "moveForward 1 2", "wallFront 1 2" };
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) assert_string_equal(run(bad[i]), "");
    assert_int_equal(mm.invalid, inv + (long)(sizeof bad / sizeof bad[0]));
}

/* An algorithm that asks wasReset MMS_IDLE_POLLS times without a move
 * idles: with --mms-reset-at idle the Reset button is pressed then (the
 * 10th answer is true), until ackReset; then it counts afresh. */
static void test_reset_on_idle(void **state)
{
    (void)state;
    setup_maze();
    mm.o.reset_on_idle = 1;
    for (int round = 0; round < 2; round++) {
        for (int i = 1; i < MMS_IDLE_POLLS; i++) assert_string_equal(run("wasReset"), "false");
        assert_string_equal(run("wasReset"), "true");
        assert_string_equal(run("wasReset"), "true"); /* until ackReset */
        assert_string_equal(run("ackReset"), "ack");
        assert_string_equal(run("wasReset"), "false");
        assert_int_equal(mm.resets, round + 1);
        mm.idle_polls = 0;
    }
    assert_int_equal(mm.idle, 0);
}

static void test_drawing(void **state)
{
    (void)state;
    setup_maze();
    assert_string_equal(run("setColor 1 2 R"), "");
    assert_int_equal(mm.color[truemaze_cell(&truth, 1, 2)], 'R');
    run("clearColor 1 2");
    assert_int_equal(mm.color[truemaze_cell(&truth, 1, 2)], 0);
    run("setText 2 1 0123456789ABC");
    assert_string_equal(mm.text[truemaze_cell(&truth, 2, 1)], "0123456789");
    run("setText 0 0 a b\x01");
    assert_string_equal(mm.text[0], "a b?");
    /* UTF-8: one '?' per character (2, 3 and 4 bytes), a stray byte alone; 10 characters */
    run("setText 1 0 \xc3\xa9t\xc3\xa9 \xe2\x82\xac\xf0\x9f\x90\xadx\x80y\xc3z");
    assert_string_equal(mm.text[truemaze_cell(&truth, 1, 0)], "?t? ??x?y?");
    run("setText 1 0 \xc3\xa9\xc3\xa9\xc3\xa9\xc3\xa9\xc3\xa9\xc3\xa9\xc3\xa9\xc3\xa9\xc3\xa9\xc3\xa9\xc3\xa9");
    assert_string_equal(mm.text[truemaze_cell(&truth, 1, 0)], "??????????");
    run("clearAllText");
    assert_string_equal(mm.text[0], "");
    run("setWall 1 1 e");
    assert_int_equal(mm.drawn_walls[truemaze_cell(&truth, 1, 1)], 1u << TRUEMAZE_EAST);
    assert_int_equal(mm.drawn_walls[truemaze_cell(&truth, 2, 1)], 1u << TRUEMAZE_WEST);
    run("clearWall 2 1 W");
    assert_int_equal(mm.drawn_walls[truemaze_cell(&truth, 1, 1)], 0);
    assert_int_equal(mm.invalid, 0);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_stats),
        cmocka_unit_test(test_queries),
        cmocka_unit_test(test_reset_on_idle),
        cmocka_unit_test(test_drawing),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}

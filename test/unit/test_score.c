/* test_score.c - the scoring rules on runs of known times (score.h):
 * best run, run time plus a share of the search time, touch penalties, the
 * runs that count (number of runs, time limit), rounding to 1 ms. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <cmocka.h>

#include "contest/score.h"

/* three runs: 40 s searching from the first exit, then two speed runs */
static const score_run_t runs3[] = {
    { 40.0, 0.0, 0, 0 },
    { 12.5, 90.0, 0, 0 },
    { 11.0, 150.0, 1, 0 },
};

static void test_best_run(void **state)
{
    (void)state;
    score_rules_t r = { SCORE_BEST_RUN, 0, 0, 0 };
    double s = -1;
    assert_int_equal(score_best(&r, runs3, 3, &s), 2); /* the fastest run, whatever its search time */
    assert_true(s == 11.0);
    assert_true(score_run(&r, &runs3[1]) == 12.5); /* no search term under best_run */
}

static void test_run_plus_search(void **state)
{
    (void)state;
    score_rules_t r = { SCORE_RUN_PLUS_SEARCH, 30, 2, 0 }; /* APEC: run + search/30, 2 s a touch */
    double s = -1;
    assert_true(score_run(&r, &runs3[0]) == 40.0);
    assert_true(score_run(&r, &runs3[1]) == 15.5);       /* 12.5 + 90/30 */
    assert_true(score_run(&r, &runs3[2]) == 18.0);       /* 11 + 150/30 + 2 */
    assert_int_equal(score_best(&r, runs3, 3, &s), 1);  /* the second run wins under this rule */
    assert_true(s == 15.5);
}

static void test_touch_penalty_best_run(void **state)
{
    (void)state;
    score_rules_t r = { SCORE_BEST_RUN, 0, 5, 0 }; /* a touch costs 5 s: run 3 scores 16 */
    double s = -1;
    assert_int_equal(score_best(&r, runs3, 3, &s), 1);
    assert_true(s == 12.5);
}

static void test_runs_that_count(void **state)
{
    (void)state;
    score_rules_t r = { SCORE_BEST_RUN, 0, 0, 2 }; /* only the first two runs count */
    double s = -1;
    assert_true(score_counts(&r, runs3, 1));
    assert_false(score_counts(&r, runs3, 2));
    assert_int_equal(score_best(&r, runs3, 3, &s), 1);
    assert_true(s == 12.5);
    score_run_t late[] = { { 30, 0, 0, 0 }, { 9, 595, 0, 1 } }; /* the second ended after the limit */
    r.runs = 0;
    assert_int_equal(score_best(&r, late, 2, &s), 0);
    assert_true(s == 30);
    late[0].over_time = 1;
    s = -1;
    assert_int_equal(score_best(&r, late, 2, &s), -1); /* none counts: no score, s untouched */
    assert_true(s == -1);
}

static void test_rounding(void **state)
{
    (void)state;
    score_rules_t r = { SCORE_RUN_PLUS_SEARCH, 30, 0, 0 };
    score_run_t run = { 10.001, 0.01, 0, 0 }; /* 10.001 + 0.000333 s */
    assert_true(score_run(&r, &run) == 10.001);
    run.search_s = 0.02; /* + 0.000667 s */
    assert_true(score_run(&r, &run) == 10.002);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_best_run),        cmocka_unit_test(test_run_plus_search),
        cmocka_unit_test(test_touch_penalty_best_run), cmocka_unit_test(test_runs_that_count),
        cmocka_unit_test(test_rounding),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}

/* test_validate.c - the validation table's grading (sim/validate/validate.h):
 * a fitted figure is reported and never graded, whatever its residual; a
 * prediction with a bar is graded; one with no bar is reported; the JSON
 * gives every check its kind and source, and "pass" null where nothing is
 * graded; the summary line counts predictions and fitted figures apart. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <cmocka.h>

#include <stdio.h>
#include <string.h>

#include "validate/validate.h"

/* A fitted figure far off (+100 %), a passing and a failing prediction, a
 * limit, and a prediction with no bar. */
static int table(validate_check_t *v)
{
    const validate_check_t rows[] = {
        { "fit_far_off", "rpm", "a datasheet point the model is built from", 450, 900, 0, VALIDATE_REPORT,
          VALIDATE_FITTED, 1 },
        { "pred_ok", "rpm", "a datasheet point the fit left out", 320, 330, 5, VALIDATE_NEAR, VALIDATE_PREDICTED, 1 },
        { "pred_bad", "W", "a datasheet point the fit left out", 0.31, 0.335, 5, VALIDATE_NEAR, VALIDATE_PREDICTED, 0 },
        { "limit_ok", "mm", "a physical requirement", 2, 0.4, 0, VALIDATE_MAX, VALIDATE_PREDICTED, 1 },
        { "residual", "deg/mm", "a figure at another step", 1.6, 1.4, 0, VALIDATE_REPORT, VALIDATE_PREDICTED, 1 },
    };
    memcpy(v, rows, sizeof rows);
    return (int)(sizeof rows / sizeof rows[0]);
}

static void graded_only_predictions_with_a_bar(void **state)
{
    (void)state;
    validate_check_t v[8];
    int n = table(v);
    assert_false(validate_graded(&v[0]));
    assert_true(validate_graded(&v[1]));
    assert_true(validate_graded(&v[2]));
    assert_true(validate_graded(&v[3]));
    assert_false(validate_graded(&v[4]));
    validate_summary_t s = validate_summary(v, n);
    assert_int_equal(s.graded, 3);
    assert_int_equal(s.passed, 2);
    assert_int_equal(s.fitted, 1);
    assert_int_equal(s.reported, 1);
}

static void fitted_far_off_is_not_a_failure(void **state)
{
    (void)state;
    validate_check_t v[8];
    table(v);
    validate_summary_t s = validate_summary(v, 1); /* the fitted figure alone */
    assert_int_equal(s.graded, 0);
    assert_int_equal(s.passed, 0);
    assert_int_equal(s.fitted, 1);
}

static void json_kinds_sources_and_null_pass(void **state)
{
    (void)state;
    validate_check_t v[8];
    int n = table(v);
    json_t *j = validate_json(v, n), *a = json_object_get(j, "checks");
    assert_int_equal(json_array_size(a), n);
    static const char *kinds[] = { "fitted", "predicted", "predicted", "predicted", "predicted" };
    static const int pass[] = { -1, 1, 0, 1, -1 }; /* -1: null, not graded */
    for (int i = 0; i < n; i++) {
        json_t *k = json_array_get(a, (size_t)i);
        assert_string_equal(json_string_value(json_object_get(k, "kind")), kinds[i]);
        assert_string_equal(json_string_value(json_object_get(k, "source")), v[i].source);
        json_t *p = json_object_get(k, "pass");
        if (pass[i] < 0) assert_true(json_is_null(p));
        else assert_int_equal(json_is_true(p), pass[i]);
    }
    assert_int_equal(json_integer_value(json_object_get(j, "predicted")), 3);
    assert_int_equal(json_integer_value(json_object_get(j, "passed")), 2);
    assert_int_equal(json_integer_value(json_object_get(j, "fitted")), 1);
    assert_int_equal(json_integer_value(json_object_get(j, "reported")), 1);
    json_decref(j);
}

static void table_kind_column_and_summary_line(void **state)
{
    (void)state;
    validate_check_t v[8];
    int n = table(v);
    char buf[4096] = "";
    FILE *f = fmemopen(buf, sizeof buf - 1, "w");
    assert_non_null(f);
    validate_print(v, n, f);
    fclose(f);
    assert_non_null(strstr(buf, "check                      kind "));
    assert_non_null(strstr(buf, "\nfit_far_off                fitted "));
    assert_non_null(strstr(buf, "\n2 of 3 predicted checks pass; 1 fitted figures reported; 1 prediction reported with no bar\n"));
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(graded_only_predictions_with_a_bar),
        cmocka_unit_test(fitted_far_off_is_not_a_failure),
        cmocka_unit_test(json_kinds_sources_and_null_pass),
        cmocka_unit_test(table_kind_column_and_summary_line),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}

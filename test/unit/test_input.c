/* test_input.c - --input's actions (sim/contest/input.h): parsing, time
 * order, errors with their column. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <cmocka.h>

#include <math.h>
#include <string.h>

#include "contest/input.h"

static void test_parse_and_order(void **state)
{
    (void)state;
    static input_t in;
    char err[300];
    assert_int_equal(input_parse(&in, "0.2 send=X; 0.5 switches=2; 1.0 button; 2.0 occlude=left; 0.9 reset;3 end", err, sizeof err), 0);
    static const struct {
        double t;
        input_kind_t k;
        int v;
    } want[] = { { 0.2, INPUT_SEND, 0 }, { 0.5, INPUT_SWITCHES, 2 }, { 0.9, INPUT_RESET, 0 }, { 1.0, INPUT_BUTTON_DOWN, 0 },
                 { 1.1, INPUT_BUTTON_UP, 0 }, { 2.0, INPUT_OCCLUDE, -1 }, { 3.0, INPUT_END, 0 } };
    assert_int_equal(in.n, 7);
    for (int i = 0; i < 7; i++) {
        assert_true(fabs(in.a[i].t_s - want[i].t) < 1e-12 && in.a[i].kind == want[i].k && in.a[i].value == want[i].v);
    }
    assert_string_equal(in.a[0].text, "X");
    assert_string_equal(in.a[5].text, "left"); /* the sensor's name: resolved against the robot in run.c */
    assert_true(in.a[5].spec == 1 && in.a[5].col == 45);
    assert_int_equal(input_needs_board(&in), 1);
    /* due in order, each once */
    assert_null(input_due(&in, 0.1));
    assert_int_equal(input_due(&in, 0.2)->kind, INPUT_SEND);
    assert_null(input_due(&in, 0.2));
    assert_int_equal(input_due(&in, 1.05)->kind, INPUT_SWITCHES);
    assert_int_equal(input_due(&in, 1.05)->kind, INPUT_RESET);
    assert_int_equal(input_due(&in, 1.05)->kind, INPUT_BUTTON_DOWN);
    assert_null(input_due(&in, 1.05));
    /* equal times keep the order given */
    assert_int_equal(input_parse(&in, "1 button=down; 1 button=up; 1 occlude=right", err, sizeof err), 0);
    assert_true(in.a[0].kind == INPUT_BUTTON_DOWN && in.a[1].kind == INPUT_BUTTON_UP && in.a[2].kind == INPUT_OCCLUDE &&
                !strcmp(in.a[2].text, "right"));
    assert_int_equal(input_parse(&in, "1 occlude=front", err, sizeof err), 0); /* any name: a centred [tof.front] */
    assert_string_equal(in.a[0].text, "front");
    assert_int_equal(input_parse(&in, "1 occlude=left; 2 end", err, sizeof err), 0);
    assert_int_equal(input_needs_board(&in), 0);
}

static void test_errors(void **state)
{
    (void)state;
    static input_t in;
    char err[300];
    static const struct {
        const char *spec, *want;
    } bad[] = {
        { "0.5 wave", "--input:1:5: unknown action (" },
        { "1 switches=16", "--input:1:3: switches=N wants N in 0..15: switches=16" },
        { "1 switches=x", "--input:1:3: switches=N wants N in 0..15" },
        { "button", "--input:1:1: want 'T ACTION'" },
        { "1 end; -2 end", "--input:1:8: want 'T ACTION'" },
        { "1 ", "--input:1:3: missing action" },
        { "1 end;2  ;", "--input:1:10: missing action" },
        { "1 push=", "--input:1:3: push=DX_MM[,DYAW_DEG[,SECONDS]] wants 1 to 3 numbers" },
        { "1 push=10,x", "--input:1:3: push=DX_MM[,DYAW_DEG[,SECONDS]] wants numbers: 10,x" },
        { "1 push=1,2,3,4", "--input:1:3: push=DX_MM[,DYAW_DEG[,SECONDS]] wants 1 to 3 numbers: 1,2,3,4" },
        { "1 push=6000", "--input:1:3: push: DX_MM within +-5000 mm" },
        { "1 push=10,0,0.01", "--input:1:3: push: SECONDS within 0.05..60 s" },
        { "1 push=1000,0,1", "--input:1:3: push: faster than a hand" },
        { "1 push=0,900,1", "--input:1:3: push: faster than a hand" },
        { "1 occlude=", "--input:1:3: occlude=NAME wants a sensor's name from the robot file" },
        { "1 occlude=abcdefghijklmnop", "--input:1:3: occlude=NAME wants a sensor's name" },
    };
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
        assert_int_equal(input_parse(&in, bad[i].spec, err, sizeof err), -1);
        if (strncmp(err, bad[i].want, strlen(bad[i].want)) != 0) fail_msg("'%s': got '%s'", bad[i].spec, err);
    }
    char many[2000] = "";
    for (int i = 0; i < 65; i++) strcat(many, "1 reset;");
    assert_int_equal(input_parse(&in, many, err, sizeof err), -1);
    assert_non_null(strstr(err, "more than 64 actions"));
}

/* Several --input flags add up: merged in time order, equal times in the order given. */
static void test_several_add_up(void **state)
{
    (void)state;
    static input_t in;
    char err[300];
    assert_int_equal(input_parse(&in, "2 send=B; 0.5 switches=3", err, sizeof err), 0);
    assert_int_equal(input_add(&in, "1 reset; 2 end", err, sizeof err), 0);
    assert_int_equal(in.n, 4);
    assert_true(in.a[0].kind == INPUT_SWITCHES && in.a[0].value == 3);
    assert_true(in.a[1].kind == INPUT_RESET);
    assert_true(in.a[2].kind == INPUT_SEND && !strcmp(in.a[2].text, "B"));
    assert_true(in.a[3].kind == INPUT_END);
    static input_t p;
    assert_int_equal(input_parse(&p, "1 button=0.75", err, sizeof err), 0); /* a press held 0.75 s */
    assert_int_equal(p.n, 2);
    assert_true(p.a[0].kind == INPUT_BUTTON_DOWN && p.a[1].kind == INPUT_BUTTON_UP);
    assert_float_equal(p.a[1].t_s - p.a[0].t_s, 0.75, 1e-12);
    assert_int_equal(input_parse(&p, "1 button=61", err, sizeof err), -1);
    assert_int_equal(input_parse(&p, "1 button=x", err, sizeof err), -1);
    assert_int_equal(input_add(&in, "3 wave", err, sizeof err), -1);
    assert_string_equal(err, "--input:3:3: unknown action (switches=N, button, button=SECONDS, button=down, button=up, reset, "
                             "occlude=NAME, push=DX_MM[,DYAW_DEG[,SECONDS]], lift, place, send=TEXT, end): wave");
}

/* push, lift and place: the numbers with their defaults; they act on the
 * world, so they need no board. */
static void test_push_lift_place(void **state)
{
    (void)state;
    static input_t in;
    char err[300];
    assert_int_equal(input_parse(&in, "1 push=180; 2 push=-20.5,90; 3 lift; 3.5 push=10,0,0.5; 4 place", err, sizeof err), 0);
    assert_int_equal(in.n, 5);
    assert_true(in.a[0].kind == INPUT_PUSH && in.a[0].push[0] == 180 && in.a[0].push[1] == 0 && in.a[0].push[2] == INPUT_PUSH_S);
    assert_true(in.a[1].push[0] == -20.5 && in.a[1].push[1] == 90 && in.a[1].push[2] == INPUT_PUSH_S);
    assert_true(in.a[2].kind == INPUT_LIFT && in.a[4].kind == INPUT_PLACE);
    assert_true(in.a[3].push[0] == 10 && in.a[3].push[2] == 0.5);
    assert_int_equal(input_needs_board(&in), 0);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_parse_and_order),
        cmocka_unit_test(test_errors),
        cmocka_unit_test(test_several_add_up),
        cmocka_unit_test(test_push_lift_place),
    };
    return cmocka_run_group_tests_name("input", tests, NULL, NULL);
}

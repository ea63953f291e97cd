/* test_armboard.c - the STM32 board around the chip (sim/arm/armboard.c)
 * with our own firmware (test/firmware/arm/boardtest.c, build/arm/boardtest.elf) on
 * boards/bulebule.ini and robots/bulebule.ini: the DRV8833 bridges' duty
 * from TIM3's two PWMs per motor (IN1 at 100 %, IN2 at 50 %: forward at
 * half duty, DRV8833 tables 1-2) into sim_state_t.cmd, zero with both low;
 * the wheels turned by hand reach TIM2 and TIM4 in encoder mode as the
 * robot file's edges (encoder_ppr x gear per wheel turn), counting up
 * forward on both (the board's ch1_leads); the console's banner; the same
 * state after the same steps. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <cmocka.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "arm/armboard.h"
#include "maze/mazefile.h"
#include "world/config.h"
#include "world/model.h"
#include "world/robot.h"

#define IMAGE "build/arm/boardtest.elf"

typedef struct {
    simcfg_t cfg;
    truemaze_t maze;
    sim_model_t model;
    sim_state_t sim;
    armboard_t *b;
} rig_t;

static rig_t *rig_new(void)
{
    char err[600];
    static stm32board_spec_t sp;
    rig_t *r = calloc(1, sizeof *r);
    assert_non_null(r);
    config_defaults(&r->cfg);
    if (stm32board_load(&sp, "boards/bulebule.ini", err, sizeof err) || robot_load(&r->cfg, "robots/bulebule.ini", err, sizeof err) ||
        mazefile_load(&r->maze, "mazes/gen-5x5-s1.txt", NULL, err, sizeof err))
        fail_msg("%s", err);
    sim_model_build(&r->model, &r->cfg, 1);
    assert_int_equal(sim_init(&r->sim, &r->model, &r->maze, 1), 0);
    r->b = armboard_open(&sp, IMAGE, NULL, &r->sim, r->cfg.sim.step_s, 0u, err, sizeof err);
    if (!r->b) fail_msg("%s (make %s)", err, IMAGE);
    return r;
}

static void rig_free(rig_t *r)
{
    armboard_close(r->b);
    sim_free(&r->sim);
    free(r);
}

static void run_s(rig_t *r, double s)
{
    int n = (int)lround(s / r->cfg.sim.step_s);
    for (int i = 0; i < n; i++) {
        sim_step(&r->model, &r->sim);
        assert_int_equal(armboard_step(r->b), 0);
    }
}

static void test_bridges(void **state)
{
    rig_t *r = rig_new();
    run_s(r, 0.15);
    size_t n;
    assert_non_null(strstr(armboard_console(r->b, &n), "boardtest\n"));
    assert_int_equal(r->sim.cmd[0], 0); /* both inputs low: coast */
    assert_int_equal(r->sim.cmd[1], 0);
    armboard_button(r->b, -1, 1);
    run_s(r, 0.1);                      /* the firmware's next 100 ms line sees the button */
    /* PWM1, ARR 1023: IN1 high for 1023 of 1024 counts, IN2 for 512: forward for 511/1024 of the period */
    assert_float_equal(armboard_stats(r->b)->duty_max[0], 511.0 / 1024.0, 1e-12);
    assert_int_equal(r->sim.cmd[0], lround(511.0 / 1024.0 * 1023.0));
    assert_int_equal(r->sim.cmd[1], lround(511.0 / 1024.0 * 1023.0));
    rig_free(r);
}

static void test_encoders_by_hand(void **state)
{
    rig_t *r = rig_new();
    run_s(r, 0.05);
    assert_int_equal(sim_push(&r->sim, 0.050, 0.0, 0.5), 0); /* 50 mm forward by hand over 0.5 s */
    run_s(r, 0.8);
    stm32f1_soc_t *s = armboard_soc(r->b);
    const drive_spec_t *d = &r->model.drive[0];
    double per_m = d->encoder_ppr * d->gear_ratio / (2.0 * M_PI * r->model.wheel_r_m[0]); /* edges per metre rolled */
    double want = 0.050 * per_m; /* edges for 50 mm */
    int16_t left = (int16_t)s->tim[1].cnt, right = (int16_t)s->tim[3].cnt;
    assert_true(fabs(left - want) < 0.05 * want);
    assert_true(fabs(right - want) < 0.05 * want);
    assert_true(armboard_stats(r->b)->encoder_edges[0] >= (uint64_t)(0.9 * want));
    rig_free(r);
}

static void test_same_twice(void **state)
{
    rig_t *a = rig_new(), *b = rig_new();
    armboard_button(a->b, -1, 1), armboard_button(b->b, -1, 1);
    run_s(a, 0.4), run_s(b, 0.4);
    size_t na, nb;
    assert_string_equal(armboard_console(a->b, &na), armboard_console(b->b, &nb));
    assert_int_equal(armboard_stats(a->b)->cycles, armboard_stats(b->b)->cycles);
    assert_int_equal(armboard_soc(a->b)->tim[1].cnt, armboard_soc(b->b)->tim[1].cnt);
    rig_free(a);
    rig_free(b);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_bridges),
        cmocka_unit_test(test_encoders_by_hand),
        cmocka_unit_test(test_same_twice),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}

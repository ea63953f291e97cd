/* test_tick_hold.c - fw_loop uses the motion state only with the control
 * tick held off (hal.h: hal_tick_hold, hal_tick_release), and lets the tick
 * run while it floods.
 *
 * On an 8-bit MCU fw_tick runs from a timer interrupt and a float is four
 * byte loads: a tick between them gives fw_loop half an old and half a new
 * value (UKMARSBOT's search read a profile position crossing 128 mm,
 * 127.2 -> 128.8, as 508.8, sensed a cell 120 mm early and drove into its
 * wall). A host float does not tear, so this test checks the discipline
 * instead: the whole HAL is defined here (no hal/sim), recording whether
 * the tick is held at each call fw_loop makes. The mouse searches a 4x4
 * maze with ideal wheels (a wheel turns at RC_MM_S_PER_CMD mm/s per unit
 * of its command), side walls everywhere and none ahead: it senses the
 * cells north of the start, then finds the goal walled off. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <cmocka.h>

#include <math.h>
#include <string.h>

#include "hal.h"
#include "maze.h"
#include "mouse.h"
#include "robot_config.h"

static int held;        /* between hal_tick_hold and hal_tick_release */
static int in_loop;     /* inside fw_loop */
static int nested;      /* hal_tick_hold while held, or a release while not */
static int unheld;      /* sensor, encoder, motor or belief calls from fw_loop with the tick running */
static int pass_holds;  /* hal_tick_hold calls in this fw_loop pass */
static int planned;     /* hal_belief in this pass: the search planned */
static uint32_t now_us;
static int16_t motor[2];
static int32_t enc[2];
static float wheel_mm[2];
static hal_distance_t tof[3];

static void loop_call(void)
{
    if (in_loop && !held) unheld++;
}

void hal_tick_hold(void)
{
    if (held || !in_loop) nested++;
    held = 1;
    pass_holds++;
}

void hal_tick_release(void)
{
    if (!held || !in_loop) nested++;
    held = 0;
}

/* explore_next times its flood and may log: both with the tick running */
uint32_t hal_micros(void) { return now_us; }

void hal_motor_set(int16_t left, int16_t right)
{
    loop_call();
    motor[0] = left;
    motor[1] = right;
}

int32_t hal_encoder(uint8_t side)
{
    loop_call();
    return enc[side & 1];
}

void hal_encoder_reset(void) { enc[0] = enc[1] = 0; }

hal_distance_t hal_distance(uint8_t sensor)
{
    loop_call();
    return tof[sensor % 3];
}

void hal_log(const char *line) { (void)line; }

void hal_belief(const struct maze_s *map, uint16_t cell, uint8_t heading, uint8_t state)
{
    (void)map; (void)cell; (void)heading; (void)state;
    loop_call();
    planned = 1;
}

uint8_t hal_maze(hal_maze_t *m)
{
    (void)m;
    return 0;
}

uint8_t hal_ir_count(void) { return 0; }
void hal_emitter(uint8_t group, uint8_t on) { (void)group; (void)on; }
uint16_t hal_ir_raw(uint8_t sensor)
{
    (void)sensor;
    return 0;
}
uint8_t hal_ir_seq(void) { return 0; }
uint8_t hal_gyro_present(void) { return 0; }
int32_t hal_gyro_mdps(void) { return 0; }
uint16_t hal_battery_mv(void) { return 0; }

/* Each pass of fw_loop leaves the tick running; a pass that planned
 * (explore_next's flood) let it run between two holds. */
static void test_loop_holds_the_tick(void **state)
{
    (void)state;
    maze_t m;
    maze_init(&m, 4, 4);
    now_us = 0;
    tof[HAL_TOF_FRONT] = (hal_distance_t){ 1200, 1, 0 };
    tof[HAL_TOF_LEFT] = tof[HAL_TOF_RIGHT] = (hal_distance_t){ 62, 0, 0 };
    fw_set_maze(&m);
    fw_setup();
    int plans = 0;
    for (int i = 0; i < 3000; i++) { /* 3 s at 1 kHz */
        fw_tick();
        pass_holds = 0;
        planned = 0;
        in_loop = 1;
        fw_loop();
        in_loop = 0;
        assert_false(held);
        assert_true(pass_holds >= 1);
        if (planned) {
            plans++;
            assert_true(pass_holds >= 2);
        }
        now_us += 1000;
        for (int w = 0; w < 2; w++) {
            wheel_mm[w] += motor[w] * RC_MM_S_PER_CMD * 0.001f;
            enc[w] = (int32_t)lroundf(wheel_mm[w] / RC_MM_PER_COUNT);
        }
        if (now_us % 30000u == 0)
            for (int k = 0; k < 3; k++) tof[k].seq++;
    }
    assert_int_equal(nested, 0);
    assert_int_equal(unheld, 0);
    assert_true(plans >= 2); /* cells sensed on the way north */
    assert_true(wheel_mm[0] > 2 * RC_CELL_MM && wheel_mm[1] > 2 * RC_CELL_MM);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_loop_holds_the_tick),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}

/* test_firmware.c - odometry, speed profiles, the wheel controller's crash
 * stop and the contest state machine, against a HAL mocked at link time
 * (-Wl,--wrap=hal_*): encoder counts, ToF readings and time come from the
 * test, motor commands and log lines go to it. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <cmocka.h>

#include <math.h>
#include <string.h>

#include "hal.h"
#include "motion.h"
#include "mouse.h"
#include "odom.h"
#include "profile.h"
#include "robot_config.h"

/* ---- the mocked HAL ---- */
static int32_t enc[2];
static int16_t motor[2];
static uint32_t now_us;
static hal_distance_t tof[3];
static int log_checked;

uint32_t __wrap_hal_micros(void);
void __wrap_hal_motor_set(int16_t left, int16_t right);
int32_t __wrap_hal_encoder(uint8_t side);
hal_distance_t __wrap_hal_distance(uint8_t sensor);
void __wrap_hal_log(const char *line);
uint8_t __wrap_hal_maze(hal_maze_t *m);

uint32_t __wrap_hal_micros(void) { return now_us; }
void __wrap_hal_motor_set(int16_t left, int16_t right)
{
    motor[0] = left;
    motor[1] = right;
}
int32_t __wrap_hal_encoder(uint8_t side) { return enc[side & 1]; }
hal_distance_t __wrap_hal_distance(uint8_t sensor) { return tof[sensor % 3]; }
void __wrap_hal_log(const char *line)
{
    if (log_checked) check_expected(line);
}

/* the maze the contest announces (hal_maze), announced = 0: none */
static hal_maze_t announced;
static uint8_t announced_ok;
uint8_t __wrap_hal_maze(hal_maze_t *m)
{
    if (announced_ok) *m = announced;
    return announced_ok;
}

static void near(double got, double want, double tol)
{
    if (fabs(got - want) > tol) fail_msg("got %.6g, want %.6g +- %.3g", got, want, tol);
}

static void test_odometry(void **state)
{
    (void)state;
    odom_t o;
    odom_init(&o, 100, 100);
    odom_update(&o, 1100, 1100, 0.5f); /* 1000 counts each: straight */
    near(o.dist_mm, 1000 * RC_MM_PER_COUNT, 1e-3);
    near(o.theta_rad, 0, 1e-6);
    near(o.y_mm, 1000 * RC_MM_PER_COUNT, 1e-3);
    /* on the spot, left back and right forward: counter-clockwise */
    int32_t n = (int32_t)lroundf(0.25f * 3.14159265f * RC_ODOM_TRACK_MM / RC_MM_PER_COUNT); /* a quarter turn */
    odom_update(&o, 1100 - n, 1100 + n, 0.5f);
    near(o.theta_rad, 3.14159265 / 2, 0.005);
    near(o.dist_mm, 1000 * RC_MM_PER_COUNT, 1e-3); /* no distance */
}

static void test_profile_trapezoid(void **state)
{
    (void)state;
    profile_t p;
    profile_reset(&p);
    profile_start(&p, 900.0f, 700.0f, 0.0f, 3000.0f);
    float vmax = 0, t = 0;
    while (p.active && t < 5.0f) {
        profile_update(&p, 0.001f);
        if (p.speed > vmax) vmax = p.speed;
        t += 0.001f;
    }
    assert_false(p.active);
    near(p.pos, 900, 1e-3);
    near(p.speed, 0, 1e-6);
    near(vmax, 700, 1e-3);
    near(t, 900.0 / 700 + 700.0 / 3000, 0.01); /* d/v + v/a */
    /* too short to reach v_max: a triangle */
    profile_start(&p, 50.0f, 700.0f, 0.0f, 3000.0f);
    vmax = 0;
    while (p.active) {
        profile_update(&p, 0.001f);
        if (p.speed > vmax) vmax = p.speed;
    }
    near(vmax, sqrt(3000.0 * 50), 15);
    /* backwards, and moving the end while under way */
    profile_start(&p, -30.0f, 200.0f, 0.0f, 3000.0f);
    for (int i = 0; i < 20; i++) profile_update(&p, 0.001f);
    assert_true(p.speed < 0 && p.pos < 0);
    profile_start(&p, 100.0f, 500.0f, 500.0f, 3000.0f);
    profile_update(&p, 0.001f);
    profile_set_remaining(&p, profile_remaining(&p) + 180.0f);
    near(p.target, 280, 1e-3);
}

/* Commanded forward but the wheels do not turn: crash stop, reported. */
static void test_motion_stall_is_a_crash(void **state)
{
    (void)state;
    motion_t m;
    enc[0] = enc[1] = 0;
    motion_init(&m);
    motion_forward(&m, 500.0f, 700.0f, 0.0f);
    motion_tick(&m, 0.001f);
    assert_true(motor[0] > 0 && motor[1] > 0); /* feed-forward drives */
    log_checked = 1;
    expect_string(__wrap_hal_log, line, "motion: stuck, motors off");
    for (int i = 0; i < 2000 && !m.crashed; i++) motion_tick(&m, 0.001f);
    log_checked = 0;
    assert_true(m.crashed);
    assert_int_equal(motor[0], 0);
    assert_int_equal(motor[1], 0);
}

/* Following the profile, wheels turning as commanded: no crash, and the
 * commands are symmetric on a straight. */
static void test_motion_tracks_straight(void **state)
{
    (void)state;
    motion_t m;
    enc[0] = enc[1] = 0;
    motion_init(&m);
    motion_forward(&m, 180.0f, 700.0f, 0.0f);
    float pos = 0;
    for (int i = 0; i < 1000 && motion_busy(&m); i++) {
        pos += m.fwd.speed * 0.001f; /* the wheels follow the setpoint exactly */
        enc[0] = enc[1] = (int32_t)lroundf(pos / RC_MM_PER_COUNT);
        motion_tick(&m, 0.001f);
        assert_int_equal(motor[0], motor[1]);
    }
    assert_false(m.crashed);
    near(m.odom.dist_mm, 180, 1.0);
}

/* A smooth turn at search speed: starts and ends 60-90 mm from the turn
 * point (its body keeps clear of the posts and walls only there), and its
 * path length is speed x duration of the rotation profile. */
static void test_smooth_geometry(void **state)
{
    (void)state;
    float d, len, d2, len2;
    motion_smooth_geometry(RC_SMOOTH_MM_S, &d, &len);
    assert_true(d > 60.0f && d < 90.0f);
    /* a quarter circle through the same points would be pi/2 * d long;
     * the ramps make the real path longer than that and shorter than the
     * two legs */
    assert_true(len > 1.5708f * d * 0.98f && len < 2.0f * d);
    /* slow enough that the outer wheel's feed-forward never limits the
     * rotation's speeding up, the profile is the same in time at any
     * speed: twice the speed, twice the size */
    motion_smooth_geometry(RC_SMOOTH_MM_S / 4, &d, &len);
    motion_smooth_geometry(RC_SMOOTH_MM_S / 2, &d2, &len2);
    near(d2, 2 * d, 0.01 * d);
    near(len2, 2 * len, 1e-3 * len);
    /* at search speed that limit makes the turn longer than the unlimited
     * profile would (the rotation takes longer to reach its top speed) */
    float d3, len3;
    motion_smooth_geometry(RC_SMOOTH_MM_S, &d3, &len3);
    assert_true(len3 > 2 * len2 * 0.999f);
}

/* Turning about a point beside the robot: the forward profile is the
 * rotation's scaled by the radius, so both end together, and the distance
 * is the arc (left pivot, counter-clockwise: forward). */
static void test_turn_about(void **state)
{
    (void)state;
    motion_t m;
    enc[0] = enc[1] = 0;
    motion_init(&m);
    motion_turn_about(&m, 90.0f, 6.0f);
    near(m.fwd.target, 6.0f * 1.5707963f, 1e-4);
    int ticks = 0;
    while ((m.fwd.active || m.rot.active) && ticks < 5000) {
        profile_update(&m.fwd, 0.001f);
        profile_update(&m.rot, 0.001f);
        near(m.fwd.pos, m.rot.pos * 6.0f * 0.017453293f, 0.05);
        ticks++;
    }
    assert_false(m.fwd.active);
    assert_false(m.rot.active);
    motion_turn_about(&m, -90.0f, 6.0f); /* clockwise about a left pivot: backwards */
    assert_true(m.fwd.target < 0);
}

/* The diagonal sensors' readings of a flat wall dist_mm ahead of the body
 * centre (along the wall's normal), the robot turned delta_rad
 * counter-clockwise from that normal: each sensor sits at (-+X, Y), looks
 * 45 degrees out and reads along its cone's inner edge. */
static float ray_to_wall(int right, float delta_rad, float dist_mm)
{
    /* the cone's inner edge, 32.5 degrees off the heading: the ray of the
     * 25 deg cone nearest the normal of a wall ahead (RC_DIAG_EDGE_*) */
    float sx = right ? RC_TOF_SIDE_X_MM : -RC_TOF_SIDE_X_MM, dx = right ? RC_DIAG_EDGE_SIN : -RC_DIAG_EDGE_SIN;
    float sy = sx * sinf(delta_rad) + RC_TOF_SIDE_Y_MM * cosf(delta_rad); /* in the wall's frame */
    float dy = dx * sinf(delta_rad) + RC_DIAG_EDGE_COS * cosf(delta_rad);
    return (dist_mm - sy) / dy;
}

/* Heading from two diagonal readings of one wall: exact for any angle and
 * distance; turned left, the left reading is the longer one. */
static void test_wall_angle(void **state)
{
    (void)state;
    const float deg[] = { -4.0f, -1.0f, 0.0f, 0.3f, 2.5f };
    const float dist[] = { 78.0f, 84.0f, 90.0f }; /* 84: the wall ahead of a cell centre */
    for (unsigned i = 0; i < sizeof deg / sizeof deg[0]; i++)
        for (unsigned j = 0; j < sizeof dist / sizeof dist[0]; j++) {
            float d = deg[i] * 0.017453293f;
            float l = ray_to_wall(0, d, dist[j]), r = ray_to_wall(1, d, dist[j]);
            near(motion_wall_angle(l, r), d, 1e-4);
        }
    /* centred and square: both readings 34 / cos(32.5 deg) = 40.3 mm, no angle */
    near(ray_to_wall(0, 0, 84.0f), 40.31, 0.01);
    near(motion_wall_angle(40.0f, 40.0f), 0, 1e-6);
    /* 1 mm between the readings is ~0.39 degrees */
    assert_true(motion_wall_angle(41.0f, 40.0f) > 0.006f && motion_wall_angle(41.0f, 40.0f) < 0.0075f);
}

/* The start cell boxed in: the mouse reports it, says the contest is over
 * (once) and stops. */
static void test_mouse_no_goal(void **state)
{
    (void)state;
    maze_t m;
    maze_init(&m, 4, 4);
    enc[0] = enc[1] = 0;
    now_us = 0;
    for (int i = 0; i < 3; i++) tof[i] = (hal_distance_t){ 20, 0, 0 }; /* walls all round */
    fw_set_maze(&m);
    log_checked = 1;
    expect_string(__wrap_hal_log, line, "explore: goal unreachable");
    expect_string(__wrap_hal_log, line, "contest done: no path to the goal");
    fw_setup();
    for (int i = 0; i < 10; i++) {
        fw_tick();
        fw_loop();
        now_us += 1000;
    }
    log_checked = 0;
    assert_int_equal(mouse_status()->mode, MOUSE_NO_GOAL);
    assert_int_equal(motor[0], 0);
    assert_int_equal(motor[1], 0);
}

/* An open start cell: the mouse sets off north (both wheels forward). */
static void test_mouse_sets_off(void **state)
{
    (void)state;
    maze_t m;
    maze_init(&m, 4, 4);
    enc[0] = enc[1] = 0;
    now_us = 0;
    tof[HAL_TOF_FRONT] = (hal_distance_t){ 1200, 1, 0 };
    tof[HAL_TOF_LEFT] = tof[HAL_TOF_RIGHT] = (hal_distance_t){ 62, 0, 0 };
    fw_set_maze(&m);
    fw_setup();
    for (int i = 0; i < 50; i++) {
        fw_tick();
        fw_loop();
        now_us += 1000;
        float t = (float)(i + 1) * 0.001f; /* the wheels follow the accelerating profile */
        enc[0] = enc[1] = (int32_t)lroundf(0.5f * RC_ACCEL_MM_S2 * t * t / RC_MM_PER_COUNT);
    }
    assert_int_equal(mouse_status()->mode, MOUSE_SEARCH);
    assert_true(motor[0] > 0 && motor[1] > 0);
    assert_int_equal(mouse_status()->heading, MAZE_NORTH);
}

/* The wheels as ideal motors without inertia or friction: each turns at
 * RC_MM_S_PER_CMD mm/s per unit of its command (the firmware's friction
 * feed-forward then only adds gain); the ToF sensors see nothing and
 * deliver a reading every 30 ms. */
static float wheel_mm[2];
static void run_ms(int ms)
{
    for (int i = 0; i < ms; i++) {
        fw_tick();
        fw_loop();
        now_us += 1000;
        for (int w = 0; w < 2; w++) {
            wheel_mm[w] += motor[w] * RC_MM_S_PER_CMD * 0.001f;
            enc[w] = (int32_t)lroundf(wheel_mm[w] / RC_MM_PER_COUNT);
        }
        if (now_us % 30000u == 0)
            for (int k = 0; k < 3; k++) tof[k] = (hal_distance_t){ .mm = 1200, .timeout = 1, .seq = (uint8_t)(tof[k].seq + 1) };
    }
}

static void cmd_done(void)
{
    for (int i = 0; i < 100 && mouse_cmd_status() == MOUSE_CMD_BUSY; i++) run_ms(100);
    assert_int_equal(mouse_cmd_status(), MOUSE_CMD_DONE);
}

/* Command mode (mms 1.2's diagonals): 45-degree turns give eight
 * headings; a diagonal from a cell centre aims at a post and one across
 * the maze's boundary wall is refused, nothing moving; a diagonal of two
 * half steps from the boundary north of (0,0), facing north-east, ends on
 * the boundary north of (1,1), facing into (1,2); a half step north from
 * there senses (1,2). */
static void test_mouse_cmd_diagonal(void **state)
{
    (void)state;
    maze_t m;
    maze_init(&m, 4, 4);
    enc[0] = enc[1] = 0;
    wheel_mm[0] = wheel_mm[1] = 0;
    now_us = 0;
    fw_set_maze(&m);
    fw_setup();
    mouse_cmd_mode();
    cmd_done(); /* the start cell sensed */
    assert_int_equal(mouse_cmd_turn45(1), 0);
    assert_int_equal(mouse_cmd_turn45(1), -1); /* busy */
    cmd_done();
    assert_int_equal(mouse_cmd_heading8(), 1);
    assert_int_equal(mouse_status()->heading, MAZE_NORTH);
    assert_int_equal(mouse_cmd_forward(1), -1); /* from a centre: a post */
    assert_int_equal(mouse_cmd_turn45(-1), 0);
    cmd_done();
    assert_int_equal(mouse_cmd_heading8(), 0);
    assert_int_equal(mouse_cmd_forward(1), 0); /* onto the boundary north of (0,0) */
    cmd_done();
    assert_int_equal(mouse_status()->cell, maze_cell(&m, 0, 1));
    assert_int_equal(mouse_cmd_edge(), 1 + MAZE_SOUTH);
    assert_int_equal(mouse_cmd_turn45(-1), 0);
    cmd_done();
    assert_int_equal(mouse_cmd_heading8(), 7);
    assert_int_equal(mouse_cmd_forward(1), -1); /* north-west: across the west wall of (0,1) */
    assert_int_equal(mouse_cmd_turn(1), 0); /* a quarter turn keeps the diagonal */
    cmd_done();
    assert_int_equal(mouse_cmd_heading8(), 1);
    assert_int_equal(mouse_status()->heading, MAZE_NORTH);
    assert_int_equal(mouse_cmd_forward(2), 0);
    cmd_done();
    assert_int_equal(mouse_cmd_moved(), 2);
    assert_int_equal(mouse_status()->cell, maze_cell(&m, 1, 2));
    assert_int_equal(mouse_cmd_edge(), 1 + MAZE_SOUTH);
    assert_int_equal(mouse_cmd_heading8(), 1);
    assert_false(mouse_status()->mode == MOUSE_CRASHED);
    /* driven: the half step, then 2 x 127.3 mm along the diagonal (the turns cancel) */
    near(0.5 * (wheel_mm[0] + wheel_mm[1]), 90.0 + 2 * 127.279, 3.0);
    /* the diagonal sensed nothing; a straight from its end senses the cell
     * it enters first (here: no walls seen, so open) */
    maze_cell_t c12 = maze_cell(&m, 1, 2);
    assert_int_equal(maze_wall(mouse_map(), c12, MAZE_WEST), MAZE_WALL_UNKNOWN);
    assert_int_equal(mouse_cmd_turn45(-1), 0);
    cmd_done();
    assert_int_equal(mouse_cmd_forward(1), 0);
    cmd_done();
    assert_int_equal(mouse_status()->cell, c12);
    assert_int_equal(mouse_cmd_edge(), 0);
    assert_int_equal(maze_wall(mouse_map(), c12, MAZE_WEST), MAZE_WALL_OPEN);
    assert_int_equal(maze_wall(mouse_map(), c12, MAZE_NORTH), MAZE_WALL_OPEN);
    assert_int_equal(maze_wall(mouse_map(), c12, MAZE_EAST), MAZE_WALL_OPEN);
}

/* fw_setup takes the maze the contest announces: size, start, the goal
 * rectangle and nothing else; without one, or one the build cannot hold,
 * a classic 16x16 with the centre goal. */
static void test_mouse_announced_maze(void **state)
{
    (void)state;
    const maze_t *map = mouse_map();
    announced = (hal_maze_t){ 32, 32, 0, 0, MAZE_NORTH, 24, 5, 26, 7 };
    announced_ok = 1;
    fw_setup();
    assert_int_equal(map->width, 32);
    assert_int_equal(map->height, 32);
    assert_int_equal(map->start, maze_cell(map, 0, 0));
    assert_int_equal(mouse_status()->cell, maze_cell(map, 0, 0));
    for (uint8_t y = 0; y < 32; y++)
        for (uint8_t x = 0; x < 32; x++)
            assert_int_equal(maze_is_goal(map, maze_cell(map, x, y)), x >= 24 && x <= 26 && y >= 5 && y <= 7);
    announced = (hal_maze_t){ 21, 21, 0, 0, MAZE_NORTH, 1, 0, 2, 1 }; /* taiwan2017hef's goal */
    fw_setup();
    assert_int_equal(map->width, 21);
    assert_true(maze_is_goal(map, maze_cell(map, 1, 0)) && maze_is_goal(map, maze_cell(map, 2, 1)));
    assert_false(maze_is_goal(map, maze_cell(map, 10, 10)));
    announced.width = MAZE_MAX_SIZE + 1; /* more than the build holds */
    fw_setup();
    assert_int_equal(map->width, 16);
    assert_true(maze_is_goal(map, maze_cell(map, 7, 7)) && maze_is_goal(map, maze_cell(map, 8, 8)));
    announced_ok = 0;
    fw_setup();
    assert_int_equal(map->width, 16);
    assert_int_equal(map->height, 16);
    assert_true(maze_is_goal(map, maze_cell(map, 7, 8)) && !maze_is_goal(map, maze_cell(map, 6, 7)));
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_odometry),
        cmocka_unit_test(test_profile_trapezoid),
        cmocka_unit_test(test_motion_stall_is_a_crash),
        cmocka_unit_test(test_motion_tracks_straight),
        cmocka_unit_test(test_smooth_geometry),
        cmocka_unit_test(test_turn_about),
        cmocka_unit_test(test_wall_angle),
        cmocka_unit_test(test_mouse_no_goal),
        cmocka_unit_test(test_mouse_sets_off),
        cmocka_unit_test(test_mouse_cmd_diagonal),
        cmocka_unit_test(test_mouse_announced_maze),
    };
    return cmocka_run_group_tests_name("firmware", tests, NULL, NULL);
}

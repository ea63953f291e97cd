/* test_world.c - the ODE world: rays against the maze, straight-line speed
 * from the motor model, no tunnelling into walls, staying on the floor,
 * the centre post toggle, determinism. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <cmocka.h>

#include <math.h>
#include <string.h>

#include "world/config.h"
#include "world/motor.h"
#include "world/sim.h"
#include "world/world.h"

static simcfg_t cfg;
static sim_model_t model; /* of cfg */

static int setup(void **state)
{
    (void)state;
    config_defaults(&cfg);
    sim_model_build(&model, &cfg, 1);
    return 0;
}

static void closed(truemaze_t *m, uint8_t w, uint8_t h)
{
    truemaze_init(m, w, h);
}

/* Rays hit the walls the maze says are there, at the right distance. */
static void test_rays_hit_maze_walls(void **state)
{
    (void)state;
    truemaze_t m;
    closed(&m, 4, 4);
    truemaze_set_wall(&m, truemaze_cell(&m, 0, 0), TRUEMAZE_NORTH, 0);
    truemaze_set_wall(&m, truemaze_cell(&m, 0, 1), TRUEMAZE_NORTH, 0);
    world_t *w = world_create(&model, &m, 0.5, 0.5, M_PI / 2); /* robot out of the way */
    assert_non_null(w);
    double c = cfg.world.cell_m, half = cfg.world.wall_thick_m / 2, z = 0.02;
    /* from the centre of (0,0): east wall 90 - 6 mm away */
    assert_true(fabs(world_ray(w, c / 2, c / 2, z, 0, 1.0) - (c / 2 - half)) < 0.001);
    /* north: (0,0)->(0,1)->(0,2) open, wall north of (0,2) */
    assert_true(fabs(world_ray(w, c / 2, c / 2, z, M_PI / 2, 1.0) - (2.5 * c - half)) < 0.001);
    /* out of range: nothing */
    assert_true(world_ray(w, c / 2, c / 2, z, M_PI / 2, 0.3) < 0);
    /* above the walls: nothing */
    assert_true(world_ray(w, c / 2, c / 2, cfg.world.wall_height_m + 0.01, 0, 1.0) < 0);
    world_destroy(w);
}

/* Toggling the centre post adds or removes it for rays (and contacts). */
static void test_centre_post_toggle(void **state)
{
    (void)state;
    truemaze_t m;
    truemaze_init(&m, 4, 4); /* every wall, all opened below: posts everywhere */
    for (uint16_t c = 0; c < 16; c++)
        for (uint8_t d = 0; d < 4; d++) truemaze_set_wall(&m, (truemaze_cell_t)c, d, 0);
    world_t *w = world_create(&model, &m, 0.09, 0.09, M_PI / 2);
    double c = cfg.world.cell_m, y = 2 * c, z = 0.02;
    /* along the post row y = 2 cells, from the west wall's inside: the first
     * post hit is (1,2), then (2,2) the centre; start just east of (1,2) */
    double x0 = c + 0.02;
    assert_true(world_has_centre_post(w));
    assert_true(fabs(world_ray(w, x0, y, z, 0, 1.0) - (c - 0.02 - cfg.world.post_m / 2)) < 0.001);
    world_set_centre_post(w, 0);
    assert_false(world_has_centre_post(w));
    assert_true(fabs(world_ray(w, x0, y, z, 0, 1.0) - (2 * c - 0.02 - cfg.world.post_m / 2)) < 0.001);
    world_set_centre_post(w, 1);
    assert_true(world_has_centre_post(w));
    world_destroy(w);
}

typedef struct {
    double x, y, h, v, z_min, z_max;
    unsigned collisions;
} run_t;

/* One step with both motors at these commands (motor.h's drive and after). */
static void motor_world_step(world_t *w, motor_t mo[2], int cmd_l, int cmd_r)
{
    motor_drive_t d[2];
    int cmd[2] = { cmd_l, cmd_r };
    for (int i = 0; i < 2; i++) d[i] = motor_drive(&mo[i], cmd[i], world_wheel_rate(w, i), cfg.sim.step_s);
    world_step(w, d);
    for (int i = 0; i < 2; i++) motor_after(&mo[i], &d[i], world_wheel_rate(w, i), cfg.sim.step_s);
}

/* Drive with constant commands for seconds; motors per motor.c. */
static run_t drive(const truemaze_t *m, double x0, double y0, double h0, int cmd_l, int cmd_r, double seconds)
{
    world_t *w = world_create(&model, m, x0, y0, h0);
    motor_t mo[2];
    motor_init(&mo[0], &cfg.robot.drive[0], 6.0, 0, 1.0);
    motor_init(&mo[1], &cfg.robot.drive[0], 6.0, 0, 1.0);
    run_t r = { 0, 0, 0, 0, 1, -1, 0 };
    int steps = (int)lround(seconds / cfg.sim.step_s);
    for (int i = 0; i < steps; i++) {
        motor_world_step(w, mo, cmd_l, cmd_r);
        double z = world_body_z(w);
        if (z < r.z_min) r.z_min = z;
        if (z > r.z_max) r.z_max = z;
    }
    double om;
    world_pose(w, &r.x, &r.y, &r.h);
    world_velocity(w, &r.v, &om);
    r.collisions = world_collisions(w);
    world_destroy(w);
    return r;
}

/* Straight along a 16-cell corridor at half command: speed = wheel radius
 * * no-load speed of the motor at that voltage (no drag is modelled). */
static void test_straight_speed(void **state)
{
    (void)state;
    truemaze_t m;
    truemaze_init(&m, 16, 1);
    for (uint8_t x = 0; x + 1 < 16; x++) truemaze_set_wall(&m, truemaze_cell(&m, x, 0), TRUEMAZE_EAST, 0);
    /* 1.5 s: steady after ~0.6 s (the rotors' inertia) */
    run_t r = drive(&m, 0.09, 0.09, 0.0, 512, 512, 1.5);
    double want = motor_free_speed(&cfg.robot.drive[0], 512.0 / 1023 * 6.0) * model.wheel_r_m[WORLD_LEFT];
    if (fabs(r.v - want) > 0.03 * want) fail_msg("speed %.4f m/s, want %.4f", r.v, want);
    assert_true(r.x > 0.09 + 0.3);                        /* it went east */
    /* the exact solver keeps a symmetric robot straight */
    assert_true(fabs(r.y - 0.09) < 0.0005 && fabs(r.h) < 0.001);
    assert_int_equal(r.collisions, 0);
}

/* Full speed into the wall at the end of a 3-cell corridor: stops at the
 * wall, never passes through it. */
static void test_no_tunnelling(void **state)
{
    (void)state;
    truemaze_t m;
    truemaze_init(&m, 3, 1);
    truemaze_set_wall(&m, truemaze_cell(&m, 0, 0), TRUEMAZE_EAST, 0);
    truemaze_set_wall(&m, truemaze_cell(&m, 1, 0), TRUEMAZE_EAST, 0);
    run_t r = drive(&m, 0.09, 0.09, 0.0, 1023, 1023, 3.0);
    double wall_x = 3 * cfg.world.cell_m - cfg.world.wall_thick_m / 2;
    assert_true(r.x + cfg.robot.body_l_m / 2 <= wall_x + 0.002); /* front of the body at the wall */
    assert_true(r.x > wall_x - cfg.robot.body_l_m / 2 - 0.03);    /* and it got there */
    assert_true(r.collisions >= 1);
}

/* A minute of driving in circles in an open 8x8: the body stays level on
 * the floor. */
static void test_stays_on_floor(void **state)
{
    (void)state;
    truemaze_t m;
    truemaze_init(&m, 8, 8);
    for (uint16_t c = 0; c < 64; c++)
        for (uint8_t d = 0; d < 4; d++) truemaze_set_wall(&m, (truemaze_cell_t)c, d, 0);
    /* circle between posts: post-free interior only exists between posts, so
     * drive slowly round the centre post on a ~0.3 m radius */
    run_t r = drive(&m, 4 * 0.18 - 0.3, 4 * 0.18, M_PI / 2, 300, 200, 60.0);
    double z0 = cfg.robot.body_clearance_m + cfg.robot.body_h_m / 2;
    assert_true(r.z_min > z0 - 0.004 && r.z_max < z0 + 0.004);
}

/* The same inputs give the same final state, bit for bit. */
static void test_deterministic(void **state)
{
    (void)state;
    truemaze_t m;
    truemaze_init(&m, 4, 4);
    truemaze_set_wall(&m, truemaze_cell(&m, 0, 0), TRUEMAZE_NORTH, 0);
    run_t a = drive(&m, 0.09, 0.09, M_PI / 2, 700, 650, 1.5);
    run_t b = drive(&m, 0.09, 0.09, M_PI / 2, 700, 650, 1.5);
    assert_true(a.x == b.x && a.y == b.y && a.h == b.h && a.v == b.v && a.z_min == b.z_min && a.z_max == b.z_max);
    assert_int_equal(a.collisions, b.collisions);
}

/* world_place puts the robot where it is told, at rest; with NULL wheels
 * the hinge angles (what the encoders count) do not jump (mms ackReset),
 * with given wheels they are those angles (mmview replay). */
static void test_place(void **state)
{
    (void)state;
    truemaze_t m;
    truemaze_init(&m, 4, 4);
    truemaze_set_wall(&m, truemaze_cell(&m, 0, 0), TRUEMAZE_NORTH, 0);
    world_t *w = world_create(&model, &m, 0.09, 0.09, M_PI / 2);
    motor_t mo[2];
    motor_init(&mo[0], &cfg.robot.drive[0], 6.0, 0, 1.0);
    motor_init(&mo[1], &cfg.robot.drive[0], 6.0, 0, 1.0);
    for (int i = 0; i < 300; i++) motor_world_step(w, mo, 900, 700); /* drive off north, turning a little */
    double a0 = world_wheel_angle(w, WORLD_LEFT), a1 = world_wheel_angle(w, WORLD_RIGHT), x, y, h, v, om;
    assert_true(fabs(a0) > 0.5 && fabs(a0 - a1) > 0.05);
    world_place(w, 0.09, 0.09, M_PI / 2, NULL);
    world_pose(w, &x, &y, &h);
    world_velocity(w, &v, &om);
    assert_true(fabs(x - 0.09) < 1e-9 && fabs(y - 0.09) < 1e-9 && fabs(h - M_PI / 2) < 1e-9 && v == 0 && om == 0);
    assert_true(fabs(world_wheel_angle(w, WORLD_LEFT) - a0) < 1e-9 && fabs(world_wheel_angle(w, WORLD_RIGHT) - a1) < 1e-9);
    const double wheels[2] = { 0.25, -1.5 };
    world_place(w, 0.27, 0.09, 0.0, wheels);
    world_pose(w, &x, &y, &h);
    assert_true(fabs(x - 0.27) < 1e-9 && fabs(y - 0.09) < 1e-9 && fabs(h) < 1e-9);
    assert_true(fabs(world_wheel_angle(w, WORLD_LEFT) - 0.25) < 1e-9 && fabs(world_wheel_angle(w, WORLD_RIGHT) + 1.5) < 1e-9);
    unsigned before = world_collisions(w);
    motor_init(&mo[0], &cfg.robot.drive[0], 6.0, 0, 1.0); /* carried: no current left in the motors */
    motor_init(&mo[1], &cfg.robot.drive[0], 6.0, 0, 1.0);
    for (int i = 0; i < 200; i++) motor_world_step(w, mo, 0, 0); /* it settles where it was put */
    world_pose(w, &x, &y, &h);
    if (!(fabs(x - 0.27) < 0.002 && fabs(y - 0.09) < 0.002 && world_collisions(w) == before))
        fail_msg("settled at %.4f %.4f, %u new collisions", x, y, world_collisions(w) - before);
    world_destroy(w);
}

/* Rows that hold an axle (the gearbox's stiction, the motor's) act about
 * the chassis' axle whichever way the robot was built: in an open 8x8, a
 * turn on one slow wheel (a command too weak to break the gearbox's
 * stiction at first) and a stop, from rest facing north and facing east,
 * end at the same place and heading relative to the start, in both wheel
 * forms. */
static void test_heading_invariant(void **state)
{
    (void)state;
    truemaze_t m;
    truemaze_init(&m, 8, 8);
    for (uint16_t c = 0; c < 64; c++)
        for (uint8_t d = 0; d < 4; d++) truemaze_set_wall(&m, (truemaze_cell_t)c, d, 0);
    const int forms[2] = { SIM_WHEELS_HINGE, SIM_WHEELS_SPIN };
    double x0 = 3.5 * cfg.world.cell_m, y0 = 3.5 * cfg.world.cell_m;
    for (int f = 0; f < 2; f++) {
        cfg.sim.wheels = forms[f];
        sim_model_build(&model, &cfg, 1);
        run_t n = drive(&m, x0, y0, M_PI / 2, 400, 40, 0.6), e = drive(&m, x0, y0, 0.0, 400, 40, 0.6);
        /* facing east is facing north turned a quarter clockwise: north's (dx, dy) is east's (-dy, dx) */
        double dxn = n.x - x0, dyn = n.y - y0, dxe = e.x - x0, dye = e.y - y0;
        double dh = remainder((n.h - M_PI / 2) - e.h, 2 * M_PI);
        if (!(fabs(dxn + dye) < 1e-4 && fabs(dyn - dxe) < 1e-4 && fabs(dh) < 1e-3 && hypot(dxn, dyn) > 0.02))
            fail_msg("wheels form %d: north moved (%.5f, %.5f) m, east (%.5f, %.5f) m, headings differ by %.5f rad", forms[f], dxn, dyn, dxe, dye, dh);
    }
    config_defaults(&cfg);
    sim_model_build(&model, &cfg, 1);
}

/* Full command for 2 s across an open 8x8 from its middle: the sideways
 * drift (m) of the robot sim_init builds for this config and seed. */
static double veer(const simcfg_t *c, uint64_t seed)
{
    static truemaze_t m;
    static sim_state_t s;
    truemaze_init(&m, 8, 8);
    for (uint16_t k = 0; k < 64; k++)
        for (uint8_t d = 0; d < 4; d++) truemaze_set_wall(&m, (truemaze_cell_t)k, d, 0);
    m.start = truemaze_cell(&m, 4, 0);
    m.start_heading = TRUEMAZE_NORTH;
    static sim_model_t s_model;
    sim_model_build(&s_model, c, seed);
    assert_int_equal(sim_init(&s, &s_model, &m, seed), 0);
    double x0, y0, h, x, y;
    world_pose(s.world, &x0, &y0, &h);
    s.cmd[0] = s.cmd[1] = MOTOR_CMD_MAX;
    for (int i = 0; i < 2000; i++) sim_step(s.model, &s);
    world_pose(s.world, &x, &y, &h);
    sim_free(&s);
    return x - x0;
}

/* Veer comes only from the asymmetries: none drives straight; a larger
 * right wheel turns the robot left; the per-seed variation gives each seed
 * its own robot, the same every time. */
static void test_asymmetry_and_variation(void **state)
{
    (void)state;
    simcfg_t c = cfg;
    assert_true(fabs(veer(&c, 1)) < 1e-4);
    c.asym.wheel_d_diff_m = 0.0002;
    double left = veer(&c, 1);
    if (!(left < -0.002)) fail_msg("right wheel 0.2 mm larger: %.4f m sideways, want left", left);
    c = cfg;
    c.asym.motor_k_diff_pct = 2; /* a right motor with a 2 % larger constant tops out 2 % slower: right */
    double right = veer(&c, 1);
    if (!(right > 0.002)) fail_msg("right motor constant +2 %%: %.4f m sideways, want right", right);
    c = cfg;
    c.var.wheel_d_sigma_m = 0.0002;
    double a = veer(&c, 1), b = veer(&c, 2), a2 = veer(&c, 1);
    assert_true(a == a2 && a != b && fabs(a) > 1e-4);
}

/* occlude=NAME: any IR or ToF sensor by its robot-file name, the centred
 * [tof.front] too: its readings see the object; an unknown name is -1. */
static void test_occlude_by_name(void **state)
{
    (void)state;
    static truemaze_t m;
    static sim_state_t s;
    closed(&m, 4, 4);
    assert_int_equal(sim_init(&s, &model, &m, 1), 0);
    int k = sim_occlude_find(&s, "front");
    assert_true(k >= 0 && cfg.robot.part[k].x_m == 0);
    assert_int_equal(sim_occlude_find(&s, "nope"), -1);
    char names[100];
    sim_occlude_names(&s, names, sizeof names);
    assert_string_equal(names, "left, front, right");
    sim_occlude(&s, k, 0.02, 0.3);
    for (int i = 0; i < 100; i++) sim_step(s.model, &s);
    assert_true(fabs(s.tof_true_m[WORLD_TOF_FRONT] - 0.02) < 1e-12);
    for (int i = 0; i < 300; i++) sim_step(s.model, &s); /* the hand gone: the wall ahead again (~25 mm) */
    assert_true(s.tof_true_m[WORLD_TOF_FRONT] > 0.021);
    sim_free(&s);
}

/* A series diode's drop (sim_set_supply_drop) on the motors' supply and
 * the divider's alike: the bridges see the terminal voltage less it, and
 * the robot at full command is slower by about the drop's share. */
static double top_speed(double drop_v, double *supply_v, double *terminal_v, double *motor_v)
{
    static truemaze_t m;
    static sim_state_t s;
    truemaze_init(&m, 8, 8);
    for (uint16_t k = 0; k < 64; k++)
        for (uint8_t d = 0; d < 4; d++) truemaze_set_wall(&m, (truemaze_cell_t)k, d, 0);
    m.start = truemaze_cell(&m, 4, 0);
    m.start_heading = TRUEMAZE_NORTH;
    assert_int_equal(sim_init(&s, &model, &m, 1), 0);
    sim_set_supply_drop(&s, drop_v);
    s.cmd[0] = s.cmd[1] = MOTOR_CMD_MAX;
    for (int i = 0; i < 500; i++) sim_step(s.model, &s);
    double v, w;
    world_velocity(s.world, &v, &w);
    *supply_v = sim_supply_v(&s);
    *terminal_v = sim_battery_v(&s);
    *motor_v = s.motor[0].battery_v;
    sim_free(&s);
    return v;
}

static void test_supply_drop(void **state)
{
    (void)state;
    double sup0, term0, mot0, sup1, term1, mot1;
    double v0 = top_speed(0.0, &sup0, &term0, &mot0), v1 = top_speed(1.0, &sup1, &term1, &mot1);
    assert_true(sup0 == term0 && fabs(sup1 - (term1 - 1.0)) < 1e-12);
    assert_true(fabs(mot0 - mot1 - 1.0) < 0.05); /* each motor's supply: 1 V lower (the sag differs a little) */
    double want = v0 * (mot1 / mot0);
    if (!(v1 < v0 && fabs(v1 - want) < 0.1 * want)) fail_msg("speed %.4f m/s with a 1 V drop, %.4f without (want ~%.4f)", v1, v0, want);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_rays_hit_maze_walls),
        cmocka_unit_test(test_centre_post_toggle),
        cmocka_unit_test(test_straight_speed),
        cmocka_unit_test(test_no_tunnelling),
        cmocka_unit_test(test_stays_on_floor),
        cmocka_unit_test(test_deterministic),
        cmocka_unit_test(test_place),
        cmocka_unit_test(test_heading_invariant),
        cmocka_unit_test(test_asymmetry_and_variation),
        cmocka_unit_test(test_occlude_by_name),
        cmocka_unit_test(test_supply_drop),
    };
    return cmocka_run_group_tests_name("world", tests, setup, NULL);
}

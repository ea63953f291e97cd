/* test_telem.c - the telemetry publisher in-process over memq:// (LCM's
 * in-process provider): which messages go out on which steps, their
 * content decoded with the generated types, lap events, the belief from
 * hal_belief with its cost field and path; a belief handed in by the
 * caller (NULL: none); the firmware's variables handed in (MM_WATCH); the
 * cost field; open errors. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <cmocka.h>

#include <lcm/lcm.h>
#include <math.h>
#include <stdio.h>
#include <string.h>
#include <unistd.h>

#include "world/config.h"
#include "hal.h"
#include "hal_sim.h"
#include "mmlcm_belief_t.h"
#include "mmlcm_motors_t.h"
#include "mmlcm_parts_t.h"
#include "mmlcm_pose_t.h"
#include "mmlcm_race_event_t.h"
#include "mmlcm_race_t.h"
#include "mmlcm_sensors_t.h"
#include "mmlcm_watch_t.h"
#include "world/sim.h"
#include "maze/truebelief.h"
#include "telemetry/telem.h"

/* What the subscribers saw. */
static struct {
    int pose, motors, sensors, race, events, belief;
    int64_t pose_ut[64];
    mmlcm_race_event_t ev[8];
    int64_t belief_ut;
    int belief_cell, belief_heading, belief_state, belief_ncells, path_len, path0, path_last;
    int8_t walls[MAZE_MAX_CELLS];
    int16_t cost[MAZE_MAX_CELLS];
    int last_cmd0;
    double last_x;
    int parts, parts_n, parts_nvalues[4], emitters, emitter_mask;
    int64_t parts_ut, sensors_ut;
    char parts_kind[4][8], parts_name[4][16], parts_units[4][32];
    double parts_v[4][4], battery_v, battery_soc;
    mmlcm_sensors_t last_sensors;
} seen;

static void on_pose(const lcm_recv_buf_t *rb, const char *ch, const mmlcm_pose_t *m, void *u)
{
    if (seen.pose < 64) seen.pose_ut[seen.pose] = m->utime;
    seen.pose++;
    seen.last_x = m->x_m;
}
static void on_motors(const lcm_recv_buf_t *rb, const char *ch, const mmlcm_motors_t *m, void *u)
{
    seen.motors++;
    seen.last_cmd0 = m->command[0];
}
static void on_sensors(const lcm_recv_buf_t *rb, const char *ch, const mmlcm_sensors_t *m, void *u)
{
    seen.sensors++;
    seen.last_sensors = *m;
}
static void on_parts(const lcm_recv_buf_t *rb, const char *ch, const mmlcm_parts_t *m, void *u)
{
    seen.parts++;
    seen.parts_ut = m->utime;
    seen.parts_n = m->nparts;
    for (int i = 0; i < m->nparts && i < 4; i++) {
        snprintf(seen.parts_kind[i], sizeof seen.parts_kind[i], "%s", m->parts[i].kind);
        snprintf(seen.parts_name[i], sizeof seen.parts_name[i], "%s", m->parts[i].name);
        snprintf(seen.parts_units[i], sizeof seen.parts_units[i], "%s", m->parts[i].units);
        seen.parts_nvalues[i] = m->parts[i].nvalues;
        for (int k = 0; k < m->parts[i].nvalues && k < 4; k++) seen.parts_v[i][k] = m->parts[i].values[k];
    }
    seen.battery_v = m->battery_v;
    seen.battery_soc = m->battery_soc;
    seen.emitters = m->nemitters;
    seen.emitter_mask = 0;
    for (int g = 0; g < m->nemitters; g++) seen.emitter_mask |= (m->emitter[g] != 0) << g;
}
static void on_race(const lcm_recv_buf_t *rb, const char *ch, const mmlcm_race_t *m, void *u) { seen.race++; }
static void on_event(const lcm_recv_buf_t *rb, const char *ch, const mmlcm_race_event_t *m, void *u)
{
    if (seen.events < 8) seen.ev[seen.events] = *m;
    seen.events++;
}
static void on_belief(const lcm_recv_buf_t *rb, const char *ch, const mmlcm_belief_t *m, void *u)
{
    seen.belief++;
    seen.belief_ut = m->utime;
    seen.belief_cell = m->cell;
    seen.belief_heading = m->heading;
    seen.belief_state = m->state;
    seen.belief_ncells = m->ncells;
    memcpy(seen.walls, m->walls, (size_t)m->ncells);
    memcpy(seen.cost, m->cost, (size_t)m->ncells * sizeof *m->cost);
    seen.path_len = m->path_len;
    seen.path0 = m->path_len ? m->path[0] : -1;
    seen.path_last = m->path_len ? m->path[m->path_len - 1] : -1;
}

static void open_maze(maze_t *m)
{
    maze_init(m, 4, 4); /* every interior wall unknown, goal the centre 2x2 */
}

static void drain(lcm_t *l)
{
    while (lcm_handle_timeout(l, 0) > 0) {
    }
}

/* MM_PARTS with every MM_SENSORS: the paper robot's three ToF (left,
 * front, right) with the same readings as MM_SENSORS, the battery as the
 * simulation has it, the four emitter groups. */
static void check_parts(const sim_state_t *sim)
{
    static const char *names[3] = { "left", "front", "right" };
    assert_int_equal(seen.parts, seen.sensors);
    assert_int_equal(seen.parts_ut, seen.last_sensors.utime);
    assert_int_equal(seen.parts_n, 3);
    for (int i = 0; i < 3; i++) {
        assert_string_equal(seen.parts_kind[i], "tof");
        assert_string_equal(seen.parts_name[i], names[i]);
        assert_string_equal(seen.parts_units[i], "mm timeout true_mm");
        assert_int_equal(seen.parts_nvalues[i], 3);
        assert_int_equal(lround(seen.parts_v[i][0]), seen.last_sensors.tof_mm[i]);
        assert_int_equal(seen.parts_v[i][1] != 0, seen.last_sensors.tof_timeout[i] != 0);
        double t = seen.last_sensors.tof_true_m[i];
        assert_true(t < 0 ? seen.parts_v[i][2] == -1 : fabs(seen.parts_v[i][2] - t * 1000) < 1e-9);
    }
    assert_true(seen.battery_v == sim_battery_v(sim));
    assert_true(seen.battery_soc > 0.99 && seen.battery_soc <= 1);
    assert_int_equal(seen.emitters, SIM_EMITTER_GROUPS);
    assert_int_equal(seen.emitter_mask, 1 << 2); /* group 2 lit by the test */
}

/* 95 steps at 100 Hz: poses at steps 10..90 and the final 95; one race
 * state (the final one, the period being 100 steps); events from the race
 * state; one belief with its time. */
static void test_memq_messages(void **state)
{
    (void)state;
    static truemaze_t m; /* the world: every wall present */
    static sim_state_t sim;
    static telem_t t;
    simcfg_t cfg;
    char err[300];
    config_defaults(&cfg);
    truemaze_init(&m, 4, 4);
    static sim_model_t sim_model;
    sim_model_build(&sim_model, &cfg, 1);
    assert_int_equal(sim_init(&sim, &sim_model, &m, 1), 0);
    hal_sim_attach(&sim);
    memset(&seen, 0, sizeof seen);
    telem_opts_t o = { "memq://", NULL, 100.0, NULL, NULL };
    assert_int_equal(telem_open(&t, &o, &sim, err, sizeof err), 0);
    lcm_t *l = t.lcm;
    mmlcm_pose_t_subscription_t *s1 = mmlcm_pose_t_subscribe(l, "MM_POSE", on_pose, NULL);
    mmlcm_motors_t_subscription_t *s2 = mmlcm_motors_t_subscribe(l, "MM_MOTORS", on_motors, NULL);
    mmlcm_sensors_t_subscription_t *s3 = mmlcm_sensors_t_subscribe(l, "MM_SENSORS", on_sensors, NULL);
    mmlcm_race_t_subscription_t *s4 = mmlcm_race_t_subscribe(l, "MM_RACE", on_race, NULL);
    mmlcm_race_event_t_subscription_t *s5 = mmlcm_race_event_t_subscribe(l, "MM_RACE_EVENT", on_event, NULL);
    mmlcm_belief_t_subscription_t *s6 = mmlcm_belief_t_subscribe(l, "MM_BELIEF", on_belief, NULL);
    mmlcm_parts_t_subscription_t *s7 = mmlcm_parts_t_subscribe(l, "MM_PARTS", on_parts, NULL);

    static maze_t map;
    open_maze(&map);
    maze_set_wall(&map, 0, MAZE_NORTH, MAZE_WALL_CLOSED);
    sim_emitter_set(&sim, 2, 1);
    for (int i = 0; i < 95; i++) {
        sim.cmd[0] = sim.cmd[1] = 300;
        sim_step(sim.model, &sim);
        /* the robot stays in the start cell: a lap is written into the race
         * state by hand, after the step's own race_update */
        if (sim.step == 41) { /* a run starts */
            sim.race.in_run = 1;
            sim.race.started = 1;
            sim.race.global_start_s = 0.041;
            sim.race.run_start_s = 0.041;
        }
        if (sim.step == 61) { /* and ends at the goal */
            sim.race.in_run = 0;
            sim.race.laps[0] = (race_lap_t){ 0.0, 0.020, 0 };
            sim.race.nlaps = 1;
            sim.race.best = 0;
        }
        telem_step(&t, &sim, hal_sim_belief());
        if (sim.step == 30) hal_belief(&map, 1, MAZE_EAST, 0); /* as fw_loop would */
        drain(l);
    }
    telem_finish(&t, &sim, hal_sim_belief());
    drain(l);

    assert_int_equal(seen.pose, 10);
    assert_int_equal(seen.motors, 10);
    assert_int_equal(seen.sensors, 10);
    assert_int_equal(seen.race, 1);
    check_parts(&sim);
    for (int i = 0; i < 9; i++) assert_int_equal(seen.pose_ut[i], (i + 1) * 10000);
    assert_int_equal(seen.pose_ut[9], 95000);
    double x, y, h;
    world_pose(sim.world, &x, &y, &h);
    assert_true(seen.last_x == x); /* the final pose exactly */
    assert_int_equal(seen.last_cmd0, 300);

    assert_int_equal(seen.events, 2);
    assert_int_equal(seen.ev[0].kind, MMLCM_RACE_EVENT_T_LAP_START);
    assert_int_equal(seen.ev[0].utime, 41000);
    assert_int_equal(seen.ev[0].lap, 1);
    assert_int_equal(seen.ev[1].kind, MMLCM_RACE_EVENT_T_LAP_END);
    assert_int_equal(seen.ev[1].utime, 61000);
    assert_true(fabs(seen.ev[1].run_s - 0.020) < 1e-12);
    assert_true(seen.ev[1].best);

    assert_int_equal(seen.belief, 1);
    assert_int_equal(seen.belief_ut, 30000); /* the time of the hal_belief call */
    assert_int_equal(seen.belief_cell, 1);
    assert_int_equal(seen.belief_heading, MAZE_EAST);
    assert_int_equal(seen.belief_ncells, 16);
    for (int c = 0; c < 16; c++) assert_int_equal((uint8_t)seen.walls[c], map.cell[c]);
    /* the centre 2x2 is cells 5, 6, 9, 10; cell 1 is one step from 5 */
    assert_int_equal(seen.cost[5], 0);
    assert_int_equal(seen.cost[1], 1);
    assert_int_equal(seen.cost[0], 2);
    assert_int_equal(seen.path0, 1);
    assert_true(maze_is_goal(&map, (maze_cell_t)seen.path_last));
    assert_int_equal(seen.path_len, 2);

    mmlcm_pose_t_unsubscribe(l, s1);
    mmlcm_motors_t_unsubscribe(l, s2);
    mmlcm_sensors_t_unsubscribe(l, s3);
    mmlcm_race_t_unsubscribe(l, s4);
    mmlcm_race_event_t_unsubscribe(l, s5);
    mmlcm_belief_t_unsubscribe(l, s6);
    mmlcm_parts_t_unsubscribe(l, s7);
    assert_int_equal(telem_close(&t, err, sizeof err), 0);
    hal_sim_attach(NULL);
    sim_free(&sim);
}

/* The belief is what the caller hands telem_step, no backend behind it:
 * none while it is NULL or not yet reported (seq 0); a report is published
 * once, with its own time; telem_finish sends one not yet sent. */
static void test_belief_handed(void **state)
{
    (void)state;
    static truemaze_t m; /* the world: every wall present */
    static sim_state_t sim;
    static telem_t t;
    static sim_belief_t b;
    simcfg_t cfg;
    char err[300];
    config_defaults(&cfg);
    truemaze_init(&m, 4, 4);
    static sim_model_t sim_model;
    sim_model_build(&sim_model, &cfg, 1);
    assert_int_equal(sim_init(&sim, &sim_model, &m, 1), 0);
    memset(&seen, 0, sizeof seen);
    telem_opts_t o = { "memq://", NULL, 100.0, NULL, NULL };
    assert_int_equal(telem_open(&t, &o, &sim, err, sizeof err), 0);
    lcm_t *l = t.lcm;
    mmlcm_belief_t_subscription_t *sb = mmlcm_belief_t_subscribe(l, "MM_BELIEF", on_belief, NULL);
    open_maze(&b.map);
    int want[5] = { 0, 0, 1, 1, 2 }; /* beliefs seen after each step */
    for (int i = 0; i < 5; i++) {
        if (i == 2) b = (sim_belief_t){ 1, 1000, b.map, 2, MAZE_SOUTH, 0 }; /* the first report */
        if (i == 4) b.seq = 2, b.t_us = 3000, b.cell = 3;                   /* a second one */
        sim_step(sim.model, &sim);
        telem_step(&t, &sim, i == 0 ? NULL : &b);
        drain(l);
        assert_int_equal(seen.belief, want[i]);
    }
    assert_int_equal(seen.belief_ut, 3000);
    assert_int_equal(seen.belief_cell, 3);
    b.seq = 3; /* reported during the last loop: sent at the end */
    telem_finish(&t, &sim, &b);
    drain(l);
    assert_int_equal(seen.belief, 3);
    mmlcm_belief_t_unsubscribe(l, sb);
    assert_int_equal(telem_close(&t, err, sizeof err), 0);
    sim_free(&sim);
}

static struct {
    int n;
    int64_t ut[8];
    double v[8];
    char name[16], type[8];
} watched;

static void on_watch(const lcm_recv_buf_t *rb, const char *ch, const mmlcm_watch_t *m, void *u)
{
    if (watched.n < 8 && m->nvars == 1) {
        watched.ut[watched.n] = m->utime;
        watched.v[watched.n] = m->value[0];
        snprintf(watched.name, sizeof watched.name, "%s", m->name[0]);
        snprintf(watched.type, sizeof watched.type, "%s", m->type[0]);
    }
    watched.n++;
}

/* MM_WATCH: the values the caller hands telem_watch after the step, sent
 * on the steps the high-rate channels go out (100 Hz: every 10th 1 ms step)
 * with their utime, and at the end with the last step's. */
static void test_watch_handed(void **state)
{
    (void)state;
    static truemaze_t m; /* the world: every wall present */
    static sim_state_t sim;
    static telem_t t;
    simcfg_t cfg;
    char err[300];
    config_defaults(&cfg);
    truemaze_init(&m, 4, 4);
    static sim_model_t sim_model;
    sim_model_build(&sim_model, &cfg, 1);
    assert_int_equal(sim_init(&sim, &sim_model, &m, 1), 0);
    memset(&watched, 0, sizeof watched);
    telem_opts_t o = { "memq://", NULL, 100.0, NULL, NULL };
    assert_int_equal(telem_open(&t, &o, &sim, err, sizeof err), 0);
    lcm_t *l = t.lcm;
    mmlcm_watch_t_subscription_t *sw = mmlcm_watch_t_subscribe(l, "MM_WATCH", on_watch, NULL);
    static const char *const names[1] = { "ticks" }, *const types[1] = { "u16" };
    for (int i = 0; i < 25; i++) {
        sim_step(sim.model, &sim);
        telem_step(&t, &sim, NULL);
        double v = (double)sim.step; /* the firmware's counter after this step */
        telem_watch(&t, &sim, 1, names, types, &v);
        drain(l);
    }
    assert_int_equal(watched.n, 2);
    telem_finish(&t, &sim, NULL);
    drain(l);
    assert_int_equal(watched.n, 3);
    assert_true(watched.ut[0] == 10000 && watched.ut[1] == 20000 && watched.ut[2] == 25000);
    assert_true(watched.v[0] == 10 && watched.v[1] == 20 && watched.v[2] == 25);
    assert_string_equal(watched.name, "ticks");
    assert_string_equal(watched.type, "u16");
    mmlcm_watch_t_unsubscribe(l, sw);
    assert_int_equal(telem_close(&t, err, sizeof err), 0);
    sim_free(&sim);
}

/* Walls known closed stop the flood; unknown walls count open. */
static void test_cost_field(void **state)
{
    (void)state;
    static maze_t m;
    static truemaze_t seen_open; /* m as the flood sees it: unknown walls open */
    int16_t cost[MAZE_MAX_CELLS];
    maze_init(&m, 3, 3); /* goal: the centre cell 4 */
    truemaze_from_belief(&seen_open, &m, 1);
    telem_cost_field(&seen_open, cost);
    int16_t want[9] = { 2, 1, 2, 1, 0, 1, 2, 1, 2 };
    for (int c = 0; c < 9; c++) assert_int_equal(cost[c], want[c]);
    /* wall cell 0 in: no way out */
    maze_set_wall(&m, 0, MAZE_NORTH, MAZE_WALL_CLOSED);
    maze_set_wall(&m, 0, MAZE_EAST, MAZE_WALL_CLOSED);
    /* and make the long way round for cell 1: north closed */
    maze_set_wall(&m, 1, MAZE_NORTH, MAZE_WALL_CLOSED);
    truemaze_from_belief(&seen_open, &m, 1);
    telem_cost_field(&seen_open, cost);
    assert_int_equal(cost[0], -1);
    assert_int_equal(cost[1], 3); /* 1 -> 2 -> 5 -> 4 */
    assert_int_equal(cost[4], 0);
}

/* Open errors: one message, nothing left open, no file created. */
static void test_open_errors(void **state)
{
    (void)state;
    static truemaze_t m; /* the world: every wall present */
    static sim_state_t sim;
    static telem_t t;
    simcfg_t cfg;
    char err[300], path[64];
    config_defaults(&cfg);
    truemaze_init(&m, 4, 4);
    static sim_model_t sim_model;
    sim_model_build(&sim_model, &cfg, 1);
    assert_int_equal(sim_init(&sim, &sim_model, &m, 1), 0);
    telem_opts_t o = { NULL, "/nonexistent-dir/x.lcmlog", 0, NULL, NULL };
    assert_int_equal(telem_open(&t, &o, &sim, err, sizeof err), -1);
    assert_non_null(strstr(err, "cannot write the LCM log"));
    assert_null(strchr(err, '\n'));

    snprintf(path, sizeof path, "/tmp/test_telem_%d.lcmlog", (int)getpid());
    telem_opts_t o2 = { "nosuch://x", path, 0, NULL, NULL };
    assert_int_equal(telem_open(&t, &o2, &sim, err, sizeof err), -1);
    assert_non_null(strstr(err, "nosuch://x: cannot open the LCM URL"));
    assert_int_equal(access(path, F_OK), -1); /* the log was not created */
    sim_free(&sim);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_memq_messages),
        cmocka_unit_test(test_belief_handed),
        cmocka_unit_test(test_watch_handed),
        cmocka_unit_test(test_cost_field),
        cmocka_unit_test(test_open_errors),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}

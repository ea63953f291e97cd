/* test_robot.c - the robot file (sim/world/robot.h): robots/paper.ini is
 * the built-in robot; --print-robot's text loads back to the same robot;
 * each kind of bad file is one line "FILE:LINE: KIND.NAME.key: reason"
 * (or "FILE: reason" for what no one line holds) and leaves the config as
 * it was; and a robot with more sensors than the paper's (a gyro, five IR)
 * runs with no code for it beyond its file. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <cmocka.h>

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "maze/mazefile.h"
#include "world/config.h"
#include "world/robot.h"
#include "world/sim.h"

static char *paper; /* robots/paper.ini's text */

static char *read_all(const char *path)
{
    FILE *f = fopen(path, "rb");
    assert_non_null(f);
    static char buf[1 << 16];
    size_t n = fread(buf, 1, sizeof buf - 1, f);
    fclose(f);
    buf[n] = '\0';
    return strdup(buf);
}

static char *print(const simcfg_t *c)
{
    char *text = NULL;
    size_t len = 0;
    FILE *mem = open_memstream(&text, &len);
    assert_non_null(mem);
    robot_print(c, mem);
    fclose(mem);
    return text;
}

/* text with the first `old` after `after` (NULL: the start) replaced by `new` */
static char *replace(const char *text, const char *after, const char *old, const char *new)
{
    const char *from = after ? strstr(text, after) : text;
    assert_non_null(from);
    const char *at = strstr(from, old);
    assert_non_null(at);
    char *out = malloc(strlen(text) + strlen(new) + 1);
    assert_non_null(out);
    memcpy(out, text, (size_t)(at - text));
    strcpy(out + (at - text), new);
    strcat(out, at + strlen(old));
    return out;
}

static char *append(const char *text, const char *more)
{
    char *out = malloc(strlen(text) + strlen(more) + 1);
    assert_non_null(out);
    strcpy(out, text);
    strcat(out, more);
    return out;
}

/* The line of the first line of text that starts with `start`. */
static int line_of(const char *text, const char *start)
{
    int line = 1;
    for (const char *p = text; *p; line++) {
        if (!strncmp(p, start, strlen(start))) return line;
        p = strchr(p, '\n');
        if (!p) break;
        p++;
    }
    fail_msg("no line starts with %s", start);
    return -1;
}

/* text fails to load as "r.ini" with exactly `want` (%d: line), and the
 * config is unchanged. */
static void refused(char *text, const char *want, int line)
{
    simcfg_t c, before;
    char err[600], exp[600];
    config_defaults(&c);
    before = c;
    snprintf(exp, sizeof exp, want, line);
    int rc = robot_load_string(&c, text, "r.ini", err, sizeof err);
    free(text);
    assert_int_equal(rc, -1);
    assert_string_equal(err, exp);
    assert_memory_equal(&c, &before, sizeof c);
}

static void test_paper_file_is_the_builtin(void **state)
{
    (void)state;
    static simcfg_t a, b;
    char err[400];
    config_defaults(&a);
    config_defaults(&b);
    assert_int_equal(robot_load(&b, "robots/paper.ini", err, sizeof err), 0);
    assert_memory_equal(&a, &b, sizeof a);
    char *ta = print(&a), *tb = print(&b);
    assert_string_equal(ta, tb);
    free(ta);
    free(tb);
    assert_int_equal(a.robot.nparts, 3);
    assert_int_equal(robot_count(&a, "tof"), 3);
}

static void test_print_load_round_trip(void **state)
{
    (void)state;
    static simcfg_t a, b;
    char err[400];
    config_defaults(&a);
    char *t1 = print(&a);
    config_defaults(&b);
    assert_int_equal(robot_load_string(&b, t1, a.robot.path, err, sizeof err), 0);
    char *t2 = print(&b);
    assert_string_equal(t1, t2);
    /* the same robot, apart from where its sections stood */
    for (int i = 0; i < b.robot.nparts; i++) b.robot.part[i].line = a.robot.part[i].line;
    assert_memory_equal(&a, &b, sizeof a);
    free(t1);
    free(t2);
}

static void test_errors(void **state)
{
    (void)state;
    int n = 1; /* the line after the file's last */
    for (const char *p = paper; *p; p++) n += *p == '\n';
    refused(append(paper, "\n[wheel.x]\n"), "r.ini:%d: wheel.x: unknown kind (chassis motor encoder battery measured tof ir gyro)", n + 1);
    char *t = replace(paper, "[tof.front]", "yaw_deg = 0\n", "");
    refused(t, "r.ini:%d: tof.front.yaw_deg: missing key", line_of(paper, "[tof.front]"));
    refused(replace(paper, NULL, "body_w_mm = 96", "body_w_mm = 5"), "r.ini:%d: chassis.body.body_w_mm: 5 mm is out of range [10, 300]",
            line_of(paper, "body_w_mm"));
    refused(replace(paper, NULL, "body_w_mm = 96", "body_w_mm = wide"), "r.ini:%d: chassis.body.body_w_mm: 'wide' is not a number",
            line_of(paper, "body_w_mm"));
    refused(replace(paper, "[motor.left]", "gear_ratio = 29.86", "gear_ratio = 29.86 x"),
            "r.ini:%d: motor.left.gear_ratio: '29.86 x' is not a number", line_of(paper, "gear_ratio"));
    refused(replace(paper, "[tof.front]", "y_mm = 55", "y_mm = 70"),
            "r.ini:%d: tof.front.y_mm: pose outside the chassis (body 96 x 120 mm, 25 mm high above the floor)",
            line_of(paper, "[tof.front]"));
    refused(append(paper, "\n[ir.front]\nx_mm = 0\ny_mm = 50\nz_mm = 10\nyaw_deg = 0\nemitter = 0\n"),
            "r.ini:%d: ir.front: two sensors with one name (tof is taken)", n + 1);
    refused(append(paper, "\n[chassis.other]\n"), "r.ini:%d: chassis.other: a robot has one chassis", n + 1);
    refused(append(paper, "\n[chassis.body]\n"), "r.ini:%d: chassis.body: a second [chassis.body] (two components with one name)", n + 1);
    refused(append(paper, "\n[battery.spare]\n"), "r.ini:%d: battery.spare: a robot has one battery", n + 1);
    {
        const char *from = strstr(paper, "[motor.right]"), *to = strstr(paper, "[encoder.left]");
        char *cut = strdup(paper);
        memmove(cut + (from - paper), cut + (to - paper), strlen(to) + 1);
        refused(cut, "r.ini: no [motor.right] section: a robot has a chassis, motor and encoder left and right, and a battery%.0d", 0);
    }
    refused(append(paper, "\n[tof.back]\nx_mm = 0\ny_mm = -55\nz_mm = 15\nyaw_deg = 180\n"),
            "r.ini: more than 3 tof sensors (the HAL has left, front, right)%.0d", 0);
    refused(append("body_w_mm = 96\n", paper), "r.ini:%d: body_w_mm: a key outside any [KIND.NAME] section", 1);
    refused(append(paper, "\nthis is not a key\n"), "r.ini:%d: syntax error (want key = value or [KIND.NAME])", n + 1);
    refused(append(paper, "\n[world]\ncell_m = 0.18\n"), "r.ini:%d: [world]: want [KIND.NAME], e.g. [ir.left_front]", n + 1);
    refused(append(paper, "\n[sim]\nstep_s = 0.001\n"), "r.ini:%d: [sim]: want [KIND.NAME], e.g. [ir.left_front]", n + 1);
    refused(replace(paper, NULL, "tyre_mu_dynamic = 1.0", "tyre_mu_dynamic = 1.5"),
            "r.ini: chassis.body.tyre_mu_dynamic: 1.5 is above tyre_mu 1%.0d", 0);
    /* libinih reads an indented line as more of the key above: body_mass_g would be 1999 */
    refused(replace(paper, NULL, "body_mass_g = 127", "body_mass_g = 127\n  1999"),
            "r.ini:%d: chassis.body.body_mass_g: an indented line continues its value (INI continuation lines are refused: start the "
            "line in its first column)",
            line_of(paper, "body_mass_g") + 1);
    char twice[200];
    int mass = line_of(paper, "body_mass_g"), sec = line_of(paper, "[tof.front]");
    int yaw = sec - 1 + line_of(strstr(paper, "[tof.front]"), "yaw_deg");
    snprintf(twice, sizeof twice, "r.ini:%%d: chassis.body.body_mass_g: given twice (first on line %d)", mass);
    refused(replace(paper, NULL, "body_mass_g = 127", "body_mass_g = 127\nbody_mass_g = 200"), twice, mass + 1);
    snprintf(twice, sizeof twice, "r.ini:%%d: tof.front.yaw_deg: given twice (first on line %d)", yaw);
    refused(replace(paper, "[tof.front]", "yaw_deg = 0", "yaw_deg = 0\nyaw_deg = 5"), twice, yaw + 1);
    refused(replace(paper, "[battery.main]", "r_ohm = 0", "r_ohm = 0\nvolts = 7"),
            "r.ini:%d: battery.main.volts: unknown key (a battery has: ocv_v r_ohm capacity_mah divider)", line_of(paper, "r_ohm") + 1);

    /* a file: its path as NAME */
    char path[] = "/tmp/mm-robot-XXXXXX";
    int fd = mkstemp(path);
    assert_true(fd >= 0);
    t = replace(paper, NULL, "body_w_mm = 96", "body_w_mm = 500");
    assert_true(write(fd, t, strlen(t)) == (ssize_t)strlen(t));
    close(fd);
    free(t);
    simcfg_t c, before;
    char err[600], exp[600];
    config_defaults(&c);
    before = c;
    assert_int_equal(robot_load(&c, path, err, sizeof err), -1);
    snprintf(exp, sizeof exp, "%s:%d: chassis.body.body_w_mm: 500 mm is out of range [10, 300]", path, line_of(paper, "body_w_mm"));
    assert_string_equal(err, exp);
    assert_memory_equal(&c, &before, sizeof c);
    unlink(path);
}

/* A motor or encoder named other than left or right. */
static void test_error_side_name(void **state)
{
    (void)state;
    refused(replace(paper, NULL, "[motor.right]", "[motor.rite]"), "r.ini:%d: motor.rite: the motor is named left or right",
            line_of(paper, "[motor.right]"));
    refused(replace(paper, NULL, "[encoder.right]", "[encoder.middle]"), "r.ini:%d: encoder.middle: the encoder is named left or right",
            line_of(paper, "[encoder.right]"));
}

/* A gyro and five IR sensors: the loader, the simulation and the HAL's
 * queries take them from the file alone. */
static void test_more_sensors(void **state)
{
    (void)state;
    static const char more[] =
        "\n[gyro.extra]\nx_mm = 0\ny_mm = 0\nz_mm = 10\nyaw_deg = 0\n"
        "\n[ir.lf]\nx_mm = -40\ny_mm = 50\nz_mm = 15\nyaw_deg = 90\nemitter = 0\n"
        "\n[ir.l]\nx_mm = -40\ny_mm = 0\nz_mm = 15\nyaw_deg = 90\nemitter = 0\n"
        "\n[ir.f]\nx_mm = 0\ny_mm = 58\nz_mm = 15\nyaw_deg = 0\nemitter = 1\n"
        "\n[ir.r]\nx_mm = 40\ny_mm = 0\nz_mm = 15\nyaw_deg = -90\nemitter = 2\n"
        "\n[ir.rf]\nx_mm = 40\ny_mm = 50\nz_mm = 15\nyaw_deg = -90\nemitter = 2\n";
    char *text = append(paper, more), err[600];
    static simcfg_t c;
    static sim_state_t s;
    static truemaze_t m;
    config_defaults(&c);
    if (robot_load_string(&c, text, "more.ini", err, sizeof err) != 0) fail_msg("%s", err);
    free(text);
    assert_int_equal(c.robot.nparts, 9);
    if (mazefile_load(&m, "mazes/gen-5x5-s1.txt", NULL, err, sizeof err) != 0) fail_msg("%s", err);
    static sim_model_t s_model;
    sim_model_build(&s_model, &c, 1);
    assert_int_equal(sim_init(&s, &s_model, &m, 1), 0);
    assert_int_equal(sim_ir_count(&s), 5);
    assert_int_equal(sim_has_gyro(&s), 1);
    for (int i = 0; i < 500; i++) { /* half a second driving forward */
        s.cmd[0] = s.cmd[1] = 200;
        sim_step(s.model, &s);
    }
    assert_false(s.diverged);
    unsigned dark[5], lit[5];
    for (unsigned g = 0; g < SIM_EMITTER_GROUPS; g++) sim_emitter_set(&s, g, 0);
    for (unsigned i = 0; i < 5; i++) dark[i] = sim_ir_read(&s, i);
    for (unsigned g = 0; g < SIM_EMITTER_GROUPS; g++) sim_emitter_set(&s, g, 1);
    for (unsigned i = 0; i < 5; i++) lit[i] = sim_ir_read(&s, i);
    for (unsigned i = 0; i < 5; i++) {
        assert_in_range(dark[i], 0, 1023);
        assert_in_range(lit[i], 0, 1023);
    }
    /* the start cell's west wall is an outer wall: 44 mm from the left sensors */
    assert_true(lit[0] > dark[0] + 50);
    assert_true(lit[1] > dark[1] + 50);
    /* only the lit group's sensors see their light */
    sim_emitter_set(&s, 0, 0);
    assert_true(sim_ir_read(&s, 1) < dark[1] + 10);
    assert_int_equal(sim_ir_read(&s, 5), 0); /* past the count */
    double v[4];
    assert_int_equal(sim_part_values(&s, 3, v), 2); /* the gyro: dps, true dps */
    sim_free(&s);
}

static int setup(void **state)
{
    (void)state;
    paper = read_all("robots/paper.ini");
    return paper ? 0 : -1;
}

static int teardown(void **state)
{
    (void)state;
    free(paper);
    return 0;
}

/* UKMARSBOT at full command from rest for 0.3 s, with its battery's
 * internal resistance r_ohm: the wheel speed, the battery's terminal
 * voltage at the end and the charge drawn. */
static void ukmarsbot_burst(double r_ohm, double *w, double *v, double *mah)
{
    static simcfg_t c;
    static sim_state_t s;
    static truemaze_t m;
    char err[600];
    config_defaults(&c);
    if (robot_load(&c, "robots/ukmarsbot.ini", err, sizeof err) != 0) fail_msg("%s", err);
    c.robot.battery.r_ohm = r_ohm;
    if (mazefile_load(&m, "mazes/gen-5x5-s1.txt", NULL, err, sizeof err) != 0) fail_msg("%s", err);
    static sim_model_t s_model;
    sim_model_build(&s_model, &c, 1);
    assert_int_equal(sim_init(&s, &s_model, &m, 1), 0);
    for (int i = 0; i < 300; i++) {
        s.cmd[0] = s.cmd[1] = MOTOR_CMD_MAX;
        sim_step(s.model, &s);
    }
    *w = world_wheel_rate(s.world, 0);
    *v = sim_battery_v(&s);
    *mah = battery_drawn_mah(&s.battery);
    assert_true(battery_ocv(&s.battery) <= battery_spec_full_v(&c.robot.battery));
    sim_free(&s);
}

/* The battery is in the motors' circuit: its sag under their current
 * slows the robot and the terminal voltage falls; the charge drawn is the
 * current's integral, within what two stalled motors would draw. */
static void test_battery_sag(void **state)
{
    (void)state;
    double w0, v0, q0, w1, v1, q1;
    ukmarsbot_burst(0.0, &w0, &v0, &q0);
    ukmarsbot_burst(1.2, &w1, &v1, &q1);
    assert_true(w1 < w0 - 1.0);          /* rad/s: the sag costs speed */
    assert_true(v1 < v0 - 0.05);         /* V: the terminal voltage sags with R */
    /* mAh drawn: above 0, below both motors stalled for the whole 0.3 s (8.4 V / 8.65 ohm each) */
    double stall_mah = 2 * 8.4 / 8.65 * 0.3 / 3.6;
    if (!(q0 > 0.1 * stall_mah && q0 < stall_mah && q1 > 0.1 * stall_mah && q1 < stall_mah))
        fail_msg("drawn %g and %g mAh (stalled: %g)", q0, q1, stall_mah);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_paper_file_is_the_builtin),
        cmocka_unit_test(test_print_load_round_trip),
        cmocka_unit_test(test_errors),
        cmocka_unit_test(test_error_side_name),
        cmocka_unit_test(test_more_sensors),
        cmocka_unit_test(test_battery_sag),
    };
    return cmocka_run_group_tests_name("robot", tests, setup, teardown);
}

/* test_config.c - the robot/world config: defaults, INI errors with
 * FILE:LINE, print -> load round trip, hash. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <cmocka.h>

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "world/config.h"

static simcfg_t c;
static char err[300];

static void test_defaults_are_the_papers_robot(void **state)
{
    (void)state;
    config_defaults(&c);
    assert_true(c.world.cell_m == 0.180 && c.robot.body_w_m == 0.096 && c.robot.body_l_m == 0.120 && c.robot.body_mass_kg == 0.127);
    assert_true(c.robot.wheel_left_d_m == 0.032 && c.robot.wheel_right_d_m == 0.032 && c.robot.wheel_x_m == 0.048);
    /* the Pololu 30:1 LP 6V datasheet's figures (the motor model derives R, Ke, eta from them), both sides */
    for (int i = 0; i < 2; i++) {
        const drive_spec_t *d = &c.robot.drive[i];
        assert_true(d->gear_ratio == 29.86 && d->rated_v == 6.0 && d->no_load_rpm == 450 && d->no_load_a == 0.02 &&
                    d->stall_torque_nm == 0.028439 && d->stall_a == 0.36 && d->rotor_inertia_kgm2 == 2.0e-8);
        assert_true(d->motor_model == MOTOR_MODEL_DATASHEET && d->l_h == 0.001 && d->encoder_ppr == 12 && d->driver_r_ohm == 0);
    }
    assert_true(c.sim.solver == SIM_SOLVER_EXACT && c.robot.battery.ocv_n == 1 && c.robot.battery.ocv_v[0] == 6.0 && c.robot.battery.r_ohm == 0);
    assert_true(c.robot.nparts == 3 && c.sim.step_s == 0.001 && c.sim.time_limit_s == 600);
}

static void test_load_and_errors(void **state)
{
    (void)state;
    static const struct {
        const char *text, *want;
    } bad[] = {
        { "[sim]\ntime_limit_s = 7.4\nbogus = 1\n", "c.ini:3: sim.bogus: unknown key" },
        { "[sim]\ntime_limit_s =\n", "c.ini:2: sim.time_limit_s: missing value" },
        { "\n[sim]\ntime_limit_s = -3\n", "c.ini:3: sim.time_limit_s: -3 s is out of range [1, 86400]" },
        { "[world]\nbody_wall_mu = lots\n", "c.ini:2: world.body_wall_mu: 'lots' is not a number" },
        { "[world]\nthis line has no equals sign\n", "c.ini:2: syntax error" },
        { "[robot]\ntyre_mu = 0.3\n", "c.ini:2: robot.tyre_mu: a robot's number: it belongs in the robot file" },
        { "[motor]\nbattery_v = 7\n", "c.ini:2: motor.battery_v: a robot's number" },
        { "[world]\npost_m = 0.005\n", "c.ini: world.post_m: posts thinner than walls" },
        { "[world]\ncell_m = 0.01\n", "c.ini:2: world.cell_m: 0.01 m is out of range" },
        { "[nosuch]\nx = 1\n", "c.ini:2: nosuch.x: unknown key" },
        { "[sim]\nsolver_iterations = 10.5\n", "c.ini:2: sim.solver_iterations: 10.5 is not a whole number" },
        /* libinih would set time_limit_s to 1999: an indented line continues a key's value */
        { "[sim]\ntime_limit_s = 7\n  1999\n",
          "c.ini:3: sim.time_limit_s: an indented line continues its value (INI continuation lines are refused: start the line in "
          "its first column)" },
        { "[sim]\ntime_limit_s = 7\n\n; a comment\n\t8\n", "c.ini:5: sim.time_limit_s: an indented line continues its value" },
        { "[sim]\ntime_limit_s = 7\ntime_limit_s = 8\n", "c.ini:3: sim.time_limit_s: given twice (first on line 2)" },
        { "[sim]\ntime_limit_s = 7\n[world]\ncell_m = 0.18\n[sim]\ntime_limit_s = 8\n",
          "c.ini:6: sim.time_limit_s: given twice (first on line 2)" },
        /* the first error in the file's order, whether the scan's or a key's */
        { "[sim]\ntime_limit_s = 0\ntime_limit_s = 8\n", "c.ini:2: sim.time_limit_s: 0 s is out of range" },
        { "[sim]\ntime_limit_s = 7\ntime_limit_s = 8\nbogus = 1\n", "c.ini:3: sim.time_limit_s: given twice" },
        { "[sim\ntime_limit_s = 7\n", "c.ini:1: '[' without ']'" },
        /* the firmware's tick is HAL_TICK_HZ, compiled in: no key */
        { "[sim]\ncontrol_hz = 1000\n", "c.ini:2: sim.control_hz: unknown key" },
    };
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
        config_defaults(&c);
        assert_int_equal(config_load_string(&c, bad[i].text, "c.ini", err, sizeof err), -1);
        if (strncmp(err, bad[i].want, strlen(bad[i].want)) != 0) fail_msg("case %zu: got \"%s\"", i, err);
        assert_true(c.sim.time_limit_s == 600 && c.world.body_wall_mu == 0.3); /* nothing applied */
    }
    config_defaults(&c);
    assert_int_equal(config_load_string(&c, "; plastic on plastic\n[world]\nbody_wall_mu = 0.35\n", "p.ini", err, sizeof err), 0);
    assert_true(c.world.body_wall_mu == 0.35);
    /* an indented key straight after its section is a key (libinih's reading), and an indented comment a comment */
    assert_int_equal(config_load_string(&c, "[world]\n  body_wall_mu = 0.4\n  ; plastic\n", "p.ini", err, sizeof err), 0);
    assert_true(c.world.body_wall_mu == 0.4);
    assert_int_equal(config_load(&c, "/nonexistent/c.ini", err, sizeof err), -1);
    assert_string_equal(err, "/nonexistent/c.ini: cannot open: No such file or directory");
}

/* libinih reads lines of up to 197 bytes (plus CR LF) whole and split
 * longer ones: a comment's tail set a key and later line numbers were off.
 * A longer line, a NUL byte and a file that is not regular are errors. */
static void test_long_lines_and_files(void **state)
{
    (void)state;
    char text[700], comment[400];
    memset(comment, 'x', sizeof comment);
    for (int len = 196; len <= 199; len++) {
        /* a comment line of len bytes whose tail reads as a key */
        int pad = len - 1 - (int)strlen(" time_limit_s = 7.5");
        snprintf(text, sizeof text, "[sim]\r\n;%.*s time_limit_s = 7.5\r\nbogus = 1\n", pad, comment);
        config_defaults(&c);
        assert_int_equal(config_load_string(&c, text, "c.ini", err, sizeof err), -1);
        if (len <= 197) assert_string_equal(err, "c.ini:3: sim.bogus: unknown key");
        else {
            char want[80];
            snprintf(want, sizeof want, "c.ini:2: line too long (%d bytes; at most 197)", len);
            assert_string_equal(err, want);
        }
        assert_true(c.sim.time_limit_s == 600);
    }
    /* the same from a file, and a NUL byte (libinih stopped there in silence) */
    char path[] = "/tmp/test_config_XXXXXX";
    int fd = mkstemp(path);
    assert_true(fd >= 0);
    FILE *f = fdopen(fd, "wb");
    fprintf(f, "[sim]\n;%.*s time_limit_s = 7.5\n", 250, comment);
    fclose(f);
    config_defaults(&c);
    assert_int_equal(config_load(&c, path, err, sizeof err), -1);
    char want[120];
    snprintf(want, sizeof want, "%s:2: line too long (270 bytes; at most 197)", path);
    assert_string_equal(err, want);
    f = fopen(path, "wb");
    fwrite("[sim]\ntime_limit_s = 7\0\nbogus = 1\n", 1, 34, f);
    fclose(f);
    assert_int_equal(config_load(&c, path, err, sizeof err), -1);
    snprintf(want, sizeof want, "%s:2: NUL byte", path);
    assert_string_equal(err, want);
    f = fopen(path, "wb");
    fputs("[sim]\ntime_limit_s = 7.5\n", f);
    fclose(f);
    assert_int_equal(config_load(&c, path, err, sizeof err), 0);
    assert_true(c.sim.time_limit_s == 7.5);
    remove(path);
    /* a directory read as an empty file before: nothing was applied, no error */
    assert_int_equal(config_load(&c, "/tmp", err, sizeof err), -1);
    assert_string_equal(err, "/tmp: not a regular file (a directory)");
}

/* A value with more than 9 digits prints with them: with %.9g,
 * wheel_x_m = 0.079999999999 printed as 0.08, which the corridor check
 * (2 * 0.08 + 0.008 >= 0.18 - 0.012) rejects: a log's MM_MAZE config
 * of an accepted run did not load in the replay (found by fuzz_config).
 * The same for a config key (the robot's are in test_robot). */
static void test_print_exact(void **state)
{
    (void)state;
    simcfg_t d;
    char *text = NULL, h1[65], h2[65];
    size_t len = 0;
    config_defaults(&c);
    assert_int_equal(config_load_string(&c, "[world]\nwall_thick_m = 0.011999999999\n", "c.ini", err, sizeof err), 0);
    FILE *mem = open_memstream(&text, &len);
    config_print(&c, mem);
    fclose(mem);
    assert_non_null(strstr(text, "wall_thick_m = 0.011999999999 ; m;"));
    assert_non_null(strstr(text, "cell_m = 0.18 ; m;")); /* the defaults print as before */
    config_defaults(&d);
    if (config_load_string(&d, text, "printed", err, sizeof err) != 0) fail_msg("%s", err);
    assert_memory_equal(&c, &d, sizeof c);
    free(text);
    config_hash(&c, h1);
    d.world.wall_thick_m = 0.012;
    config_hash(&d, h2);
    assert_string_not_equal(h1, h2);
}

static void test_print_round_trip_and_hash(void **state)
{
    (void)state;
    simcfg_t d;
    char h1[65], h2[65];
    config_defaults(&c);
    c.sim.time_limit_s = 7.4;
    char *text = NULL;
    size_t len = 0;
    FILE *mem = open_memstream(&text, &len);
    config_print(&c, mem);
    fclose(mem);
    assert_non_null(strstr(text, "time_limit_s = 7.4 ; s;"));
    /* libinih reads lines of up to 200 characters (INI_MAX_LINE) and
     * takes the rest of a longer one for a line of its own */
    for (const char *l = text; *l;) {
        const char *e = strchr(l, '\n');
        size_t n = e ? (size_t)(e - l) : strlen(l);
        if (n >= 199) fail_msg("printed line of %zu characters: %.60s...", n, l);
        l += n + (e != NULL);
    }
    config_defaults(&d);
    assert_int_equal(config_load_string(&d, text, "printed", err, sizeof err), 0);
    assert_memory_equal(&c, &d, sizeof c);
    free(text);
    config_hash(&c, h1);
    config_hash(&d, h2);
    assert_int_equal(strlen(h1), 64);
    assert_string_equal(h1, h2);
    d.sim.time_limit_s = 7.5;
    config_hash(&d, h2);
    assert_string_not_equal(h1, h2);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_defaults_are_the_papers_robot),
        cmocka_unit_test(test_load_and_errors),
        cmocka_unit_test(test_long_lines_and_files),
        cmocka_unit_test(test_print_exact),
        cmocka_unit_test(test_print_round_trip_and_hash),
    };
    return cmocka_run_group_tests_name("config", tests, NULL, NULL);
}

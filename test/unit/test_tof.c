/* test_tof.c - the ToF sensor's ranging profiles (ST VL53L0X DocID029104
 * Table 13) from a robot file: each profile's period, range and noise
 * (4 % of the distance at a 33 ms budget, Table 12, times sqrt(33 ms /
 * budget)), its sigma at several distances, its timeout beyond the range,
 * and a key the file gives winning over the profile's figure. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <cmocka.h>

#include <math.h>
#include <stdio.h>
#include <string.h>

#include "world/config.h"
#include "world/robot.h"
#include "world/sensors/tof.h"

extern const char robot_paper_ini[]; /* robots/paper.ini, built in */

/* The datasheet's profiles as the robot file names them: period ms, range
 * mm. */
static const struct {
    const char *name;
    double period_ms, range_mm;
} want[] = {
    { "default", 30, 1200 },
    { "high_accuracy", 200, 1200 },
    { "long_range", 33, 2000 },
    { "high_speed", 20, 1200 },
};

/* sigma / distance for a timing budget, ms */
static double cv_for(double budget_ms) { return 0.04 * sqrt(33.0 / budget_ms); }
#define NPROFILES (sizeof want / sizeof want[0])

static char text[16384];

/* The paper robot with every "profile = default" line replaced by `with`
 * (one or more lines). */
static const char *paper_with(const char *with)
{
    const char *from = robot_paper_ini, *hit;
    size_t n = 0;
    while ((hit = strstr(from, "profile = default\n")) != NULL) {
        n += (size_t)snprintf(text + n, sizeof text - n, "%.*s%s\n", (int)(hit - from), from, with);
        from = hit + strlen("profile = default\n");
    }
    snprintf(text + n, sizeof text - n, "%s", from);
    return text;
}

/* The first ToF sensor's spec of the robot text; fails the test if it does not load. */
static tof_spec_t load_tof(const char *robot)
{
    static simcfg_t c;
    config_defaults(&c);
    char err[300];
    if (robot_load_string(&c, robot, "test.ini", err, sizeof err) != 0) fail_msg("%s", err);
    return *(const tof_spec_t *)(const void *)c.robot.part[robot_part_of_kind(&c, "tof", 0)].spec;
}

static void test_profiles_set_period_range_cv(void **state)
{
    (void)state;
    for (size_t i = 0; i < NPROFILES; i++) {
        char line[64];
        snprintf(line, sizeof line, "profile = %s", want[i].name);
        tof_spec_t s = load_tof(paper_with(line));
        assert_true(fabs(s.period_s - want[i].period_ms / 1000) < 1e-12);
        assert_true(fabs(s.range_m - want[i].range_mm / 1000) < 1e-12);
        assert_true(fabs(s.cv - cv_for(want[i].period_ms)) < 1e-12);
    }
}

/* A key the file gives wins, before or after the profile line. */
static void test_given_key_wins(void **state)
{
    (void)state;
    tof_spec_t s = load_tof(paper_with("range_mm = 900\nprofile = long_range\ncv = 0.05"));
    assert_true(fabs(s.range_m - 0.9) < 1e-12);
    assert_true(s.cv == 0.05);
    assert_true(fabs(s.period_s - 0.033) < 1e-12);
    s = load_tof(paper_with("period_ms = 50\nprofile = high_speed"));
    assert_true(fabs(s.period_s - 0.05) < 1e-12);
    assert_true(fabs(s.cv - cv_for(50)) < 1e-12 && fabs(s.range_m - 1.2) < 1e-12); /* cv from the given period */
}

/* Each profile's readings of a wall at 0.1, 0.5 and 0.9 of its range:
 * mean the distance, standard deviation cv x distance, within sampling
 * tolerance (20000 readings: the sd's own spread is 0.5 %). */
static void test_profile_sigma_at_distances(void **state)
{
    (void)state;
    static const double frac[] = { 0.1, 0.5, 0.9 };
    for (size_t i = 0; i < NPROFILES; i++) {
        char line[64];
        snprintf(line, sizeof line, "profile = %s", want[i].name);
        tof_spec_t s = load_tof(paper_with(line));
        for (size_t j = 0; j < sizeof frac / sizeof frac[0]; j++) {
            double d = frac[j] * s.range_m, sum = 0, sum2 = 0;
            tof_t t;
            tof_init(&t, &s, 11 + j, (unsigned)i);
            const int n = 20000;
            for (int k = 0; k < n; k++) {
                tof_reading_t r = tof_measure(&t, d);
                assert_false(r.timeout);
                sum += r.dist_m;
                sum2 += r.dist_m * r.dist_m;
            }
            double mean = sum / n, sd = sqrt(sum2 / n - mean * mean);
            if (fabs(mean - d) > 0.003 * d) fail_msg("%s at %g m: mean %g", want[i].name, d, mean);
            double cv = cv_for(want[i].period_ms);
            if (fabs(sd - cv * d) > 0.03 * cv * d) fail_msg("%s at %g m: sd %g, want %g", want[i].name, d, sd, cv * d);
        }
    }
}

/* Beyond the profile's range every reading is a timeout: a wall at 1.5 m
 * is out of reach of the default profile, in reach of long range. */
static void test_timeout_beyond_profile_range(void **state)
{
    (void)state;
    tof_spec_t def = load_tof(paper_with("profile = default"));
    tof_spec_t lr = load_tof(paper_with("profile = long_range"));
    tof_t a, b;
    tof_init(&a, &def, 3, 0);
    tof_init(&b, &lr, 3, 0);
    for (int k = 0; k < 1000; k++) {
        tof_reading_t r = tof_measure(&a, 1.5);
        assert_true(r.timeout && r.dist_m == def.range_m);
        assert_false(tof_measure(&b, 1.5).timeout);
        assert_true(tof_measure(&a, def.range_m * 1.001).timeout);
        assert_false(tof_measure(&a, def.range_m * 0.999).timeout);
        assert_true(tof_measure(&b, lr.range_m * 1.001).timeout);
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_profiles_set_period_range_cv),
        cmocka_unit_test(test_given_key_wins),
        cmocka_unit_test(test_profile_sigma_at_distances),
        cmocka_unit_test(test_timeout_beyond_profile_range),
    };
    return cmocka_run_group_tests_name("tof", tests, NULL, NULL);
}

/* test_config_sweep.c - every config key at its minimum and at its
 * maximum (the other keys at their defaults) simulates: a short firmware
 * contest on mazes/gen-5x5-s1.txt ends with exit 0 or 1 and not with
 * exit_reason physics_diverged; never a signal (ODE aborted on five such
 * values before the motor's damping went implicit, issue 15). Each run
 * is a child process, two at a time. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <cmocka.h>

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>
#include <unistd.h>

#include "contest/run.h"
#include "world/config.h"

#define SWEEP_TIME_LIMIT_S 4.0 /* simulated seconds per run: the search is under way */
#define SWEEP_JOBS 2

/* An extreme that another key's cross-check rejects with the defaults
 * gets a companion that makes the pair consistent. */
static const struct {
    const char *key; /* section.key */
    int at_max;
    const char *companion; /* INI lines */
} companions[] = {
    { "world.cell_m", 0, "[robot]\nwheel_x_m = 0.01\nwheel_w_m = 0.005\n" },
    { "world.wall_thick_m", 1, "[world]\npost_m = 0.05\n" },
    { "world.post_m", 0, "[world]\nwall_thick_m = 0.001\n" },
    { "robot.wheel_x_m", 1, "[world]\ncell_m = 0.5\n" },
    { "robot.tyre_mu", 0, "[robot]\ntyre_mu_dynamic = 0.01\n" },
    { "robot.tyre_mu_dynamic", 1, "[robot]\ntyre_mu = 3\n" },
    { "motor.no_load_a", 1, "[motor]\nstall_a = 100\n" },
    { "motor.stall_a", 0, "[motor]\nno_load_a = 0\n" },
};

typedef struct {
    char name[80]; /* section.key=value */
    char path[64];
    pid_t pid;
} job_t;

static const char *companion_of(const char *name, int at_max)
{
    for (size_t i = 0; i < sizeof companions / sizeof companions[0]; i++)
        if (!strcmp(companions[i].key, name) && companions[i].at_max == at_max) return companions[i].companion;
    return "";
}

/* The child: one contest with the config at path; exit code as mmsim's,
 * 9 if the physics diverged. */
static void child(const char *path)
{
    run_opts_t o;
    memset(&o, 0, sizeof o);
    o.config_path = path;
    o.seed = 1;
    o.time_limit_s = SWEEP_TIME_LIMIT_S;
    o.runs = 3;
    o.centre_post = -1;
    o.jobs = 1;
    json_t *out = NULL;
    int rc = run_one(&o, "mazes/gen-5x5-s1.txt", &out, 0);
    json_t *why = out ? json_object_get(out, "exit_reason") : NULL;
    if (why && !strcmp(json_string_value(why), "physics_diverged")) rc = 9;
    if (getenv("SWEEP_VERBOSE")) /* SWEEP_VERBOSE=1: each run's end */
        fprintf(stderr, "%s: exit %d, %s after %.3f s\n", path, rc, why ? json_string_value(why) : "?",
                out ? json_real_value(json_object_get(out, "sim_time_s")) : -1.0);
    fflush(NULL);
    _exit(rc);
}

static void start(job_t *j, size_t i, const char *section, const char *key, int at_max, double v)
{
    char ini[512], err[400], name[48], num[32];
    const char *word = config_key_word(i, v); /* a word key: its first and last word */
    snprintf(num, sizeof num, "%.17g", v);
    snprintf(name, sizeof name, "%s.%s", section, key);
    snprintf(j->name, sizeof j->name, "%s=%s", name, word ? word : num);
    snprintf(ini, sizeof ini, "[%s]\n%s = %s\n%s", section, key, word ? word : num, companion_of(name, at_max));
    simcfg_t c;
    config_defaults(&c);
    if (config_load_string(&c, ini, j->name, err, sizeof err) != 0) fail_msg("%s: config rejected: %s", j->name, err);
    snprintf(j->path, sizeof j->path, "/tmp/mm-sweep-XXXXXX");
    int fd = mkstemp(j->path);
    assert_true(fd >= 0);
    assert_true(write(fd, ini, strlen(ini)) == (ssize_t)strlen(ini));
    close(fd);
    fflush(NULL);
    j->pid = fork();
    assert_true(j->pid >= 0);
    if (j->pid == 0) {
        if (getenv("SWEEP_VERBOSE")) fprintf(stderr, "%s: %s\n", j->path, j->name);
        child(j->path);
    }
}

static int finish(job_t *j)
{
    int status;
    assert_true(waitpid(j->pid, &status, 0) == j->pid);
    unlink(j->path);
    if (WIFSIGNALED(status)) {
        print_error("%s: killed by signal %d\n", j->name, WTERMSIG(status));
        return 1;
    }
    int code = WEXITSTATUS(status);
    if (code == 9) print_error("%s: the physics diverged\n", j->name);
    else if (code > 1) print_error("%s: exit %d\n", j->name, code);
    return code > 1;
}

static void test_every_key_at_its_extremes(void **state)
{
    (void)state;
    job_t jobs[SWEEP_JOBS];
    int running = 0, failed = 0, runs = 0;
    for (size_t i = 0; i < config_key_count(); i++) {
        const char *section, *key;
        double lo, hi;
        assert_int_equal(config_key_info(i, &section, &key, &lo, &hi), 0);
        for (int at_max = 0; at_max < 2; at_max++) {
            if (running == SWEEP_JOBS) {
                failed += finish(&jobs[0]);
                jobs[0] = jobs[1];
                running--;
            }
            start(&jobs[running++], i, section, key, at_max, at_max ? hi : lo);
            runs++;
        }
    }
    while (running) {
        failed += finish(&jobs[0]);
        jobs[0] = jobs[1];
        running--;
    }
    assert_true(runs >= 80);
    if (failed) fail_msg("%d of %d runs at a key's extreme did not simulate", failed, runs);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_every_key_at_its_extremes),
    };
    return cmocka_run_group_tests_name("config_sweep", tests, NULL, NULL);
}

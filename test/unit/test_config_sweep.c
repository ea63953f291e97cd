/* test_config_sweep.c - every config key and every robot file key at its
 * minimum and at its maximum (the other keys at their defaults, the robot
 * the paper's) either simulates or is refused with one clear line.
 *
 * Config keys: a short firmware contest on mazes/gen-5x5-s1.txt ends with
 * exit 0 or 1 and not with exit_reason physics_diverged; never a signal
 * (ODE aborts on some of these values unless the motor's damping is
 * implicit). Refused: only what `refused` lists, with its reason.
 *
 * Robot keys (robot_key_info: the fixed parts' and each sensor kind's
 * pose and schema keys): a copy of robots/paper.ini with the key at its
 * end (in [motor.left] and [motor.right] alike, the paper's [tof.front],
 * and a sensor section of its own for a kind the paper robot has none of)
 * either loads and then simulates as above (with a robot that has IR
 * sensors or a gyro, sim_step and sim_ir_read too), or is refused with one
 * line "NAME:..." (a pose outside the chassis, say). Each run is a child
 * process, two at a time. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <cmocka.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>
#include <unistd.h>

#include "contest/run.h"
#include "maze/mazefile.h"
#include "world/config.h"
#include "world/robot.h"
#include "world/sensors/ir.h"
#include "world/sim.h"

#define SWEEP_TIME_LIMIT_S 4.0 /* simulated seconds per run: the search is under way */
#define SWEEP_JOBS 2
#define SWEEP_MAZE "mazes/gen-5x5-s1.txt"

/* An extreme that another key's cross-check rejects with the defaults
 * gets a companion that makes the pair consistent: config lines (config
 * keys) or robot edits "section key value" (robot keys; a motor edit is
 * made on both motors). */
static const struct {
    const char *key; /* section.key (config) or kind.key (robot) */
    int at_max;
    const char *config;      /* INI lines for the config file */
    const char *robot[2][3]; /* edits of the robot file */
} companions[] = {
    { "world.wall_thick_m", 1, "[world]\npost_m = 0.05\n", { { NULL } } },
    { "world.post_m", 0, "[world]\nwall_thick_m = 0.001\n", { { NULL } } },
    { "chassis.wheel_track_mm", 1, "[world]\ncell_m = 0.5\n", { { NULL } } },
    { "chassis.tyre_mu", 0, "", { { "chassis", "tyre_mu_dynamic", "0.01" } } },
    { "chassis.tyre_mu_dynamic", 1, "", { { "chassis", "tyre_mu", "3" } } },
    { "motor.no_load_a", 1, "", { { "motor", "stall_a", "100" } } },
    { "motor.stall_a", 0, "", { { "motor", "no_load_a", "0" } } },
    { "ir.max_mm", 0, "", { { "ir", "near_mm", "0.1" } } },
};
#define NCOMP (sizeof companions / sizeof companions[0])

/* Config extremes that cannot load, and why. world.cell_m's minimum: the
 * paper robot (104 mm over its tyres) does not fit its corridors (checked
 * once the config and the robot are both loaded). */
static const struct {
    const char *key;
    int at_max;
    const char *reason;
} refused[] = {
    { "world.cell_m", 0, "world.cell_m: the robot is wider than a corridor" },
};

typedef struct {
    char name[96]; /* section.key=value */
    char cfg_path[64], robot_path[64];
    pid_t pid;
} job_t;

static char *paper; /* robots/paper.ini */

static int comp_index(const char *name, int at_max)
{
    for (size_t i = 0; i < NCOMP; i++)
        if (!strcmp(companions[i].key, name) && companions[i].at_max == at_max) return (int)i;
    return -1;
}

static char *read_all(const char *path)
{
    FILE *f = fopen(path, "rb");
    assert_non_null(f);
    static char buf[1 << 16];
    size_t n = fread(buf, 1, sizeof buf - 1, f);
    fclose(f);
    buf[n] = '\0';
    char *s = strdup(buf);
    assert_non_null(s);
    return s;
}

/* The child: one contest with the files; exit code as mmsim's, 9 if the
 * physics diverged, 10 if an IR reading or the gyro was out of its range. */
static void child(const char *cfg_path, const char *robot_path)
{
    if (robot_path[0]) {
        /* the robot's other sensors, stepped and read directly (a firmware
         * contest reads only the ToF) */
        simcfg_t c;
        char err[400];
        static truemaze_t m;
        config_defaults(&c);
        if ((cfg_path[0] && config_load(&c, cfg_path, err, sizeof err) != 0) || robot_load(&c, robot_path, err, sizeof err) != 0 ||
            mazefile_load(&m, SWEEP_MAZE, NULL, err, sizeof err) != 0) {
            fprintf(stderr, "%s\n", err);
            _exit(2);
        }
        if (robot_count(&c, "ir") > 0 || robot_count(&c, "gyro") > 0) {
            static sim_state_t s;
            static sim_model_t s_model;
            sim_model_build(&s_model, &c, 1);
            if (sim_init(&s, &s_model, &m, 1) != 0) _exit(3);
            for (unsigned g = 0; g < SIM_EMITTER_GROUPS; g++) sim_emitter_set(&s, g, 1);
            for (int i = 0; i < 200 && !s.diverged; i++) {
                s.cmd[0] = s.cmd[1] = 300;
                sim_step(s.model, &s);
                for (int k = 0; k < sim_ir_count(&s); k++) {
                    int kk = robot_part_of_kind(s.model->cfg, "ir", (unsigned)k);
                    double bits = ((const ir_part_spec_t *)s.model->cfg->robot.part[kk].spec)->model.adc_bits;
                    if (sim_ir_read(&s, (unsigned)k) > (unsigned)ldexp(1, (int)bits) - 1) _exit(10);
                }
                if (!isfinite(sim_gyro_rad_s(&s))) _exit(10);
            }
            int diverged = s.diverged;
            sim_free(&s);
            if (diverged) _exit(9);
        }
    }
    run_opts_t o;
    memset(&o, 0, sizeof o);
    o.config_path = cfg_path[0] ? cfg_path : NULL;
    o.robot_path = robot_path[0] ? robot_path : NULL;
    o.seed = 1;
    o.time_limit_s = SWEEP_TIME_LIMIT_S;
    o.runs = 3;
    o.centre_post = -1;
    o.jobs = 1;
    json_t *out = NULL;
    int rc = run_one(&o, SWEEP_MAZE, &out, 0);
    json_t *why = out ? json_object_get(out, "exit_reason") : NULL;
    if (why && !strcmp(json_string_value(why), "physics_diverged")) rc = 9;
    if (getenv("SWEEP_VERBOSE")) /* SWEEP_VERBOSE=1: each run's end */
        fprintf(stderr, "%s %s: exit %d, %s after %.3f s\n", cfg_path, robot_path, rc, why ? json_string_value(why) : "?",
                out ? json_real_value(json_object_get(out, "sim_time_s")) : -1.0);
    fflush(NULL);
    _exit(rc);
}

static void write_tmp(char *path, size_t len, const char *text)
{
    snprintf(path, len, "/tmp/mm-sweep-XXXXXX");
    int fd = mkstemp(path);
    assert_true(fd >= 0);
    assert_true(write(fd, text, strlen(text)) == (ssize_t)strlen(text));
    close(fd);
}

static void start(job_t *j, const char *cfg_text, const char *robot_text)
{
    j->cfg_path[0] = j->robot_path[0] = '\0';
    if (cfg_text[0]) write_tmp(j->cfg_path, sizeof j->cfg_path, cfg_text);
    if (robot_text) write_tmp(j->robot_path, sizeof j->robot_path, robot_text);
    fflush(NULL);
    j->pid = fork();
    assert_true(j->pid >= 0);
    if (j->pid == 0) {
        if (getenv("SWEEP_VERBOSE")) fprintf(stderr, "%s %s: %s\n", j->cfg_path, j->robot_path, j->name);
        child(j->cfg_path, j->robot_path);
    }
}

static int finish(job_t *j)
{
    int status;
    assert_true(waitpid(j->pid, &status, 0) == j->pid);
    if (j->cfg_path[0]) unlink(j->cfg_path);
    if (j->robot_path[0]) unlink(j->robot_path);
    if (WIFSIGNALED(status)) {
        print_error("%s: killed by signal %d\n", j->name, WTERMSIG(status));
        return 1;
    }
    int code = WEXITSTATUS(status);
    if (code == 9) print_error("%s: the physics diverged\n", j->name);
    else if (code == 10) print_error("%s: an IR reading or the gyro out of range\n", j->name);
    else if (code > 1) print_error("%s: exit %d\n", j->name, code);
    return code > 1;
}

/* Two at a time: the next job's slot (finishing the oldest if both run). */
typedef struct {
    job_t jobs[SWEEP_JOBS];
    int running, failed, runs, refused;
} pool_t;

static job_t *slot(pool_t *p)
{
    if (p->running == SWEEP_JOBS) {
        p->failed += finish(&p->jobs[0]);
        memmove(&p->jobs[0], &p->jobs[1], sizeof p->jobs[0] * (SWEEP_JOBS - 1));
        p->running--;
    }
    p->runs++;
    return &p->jobs[p->running++];
}

static void drain(pool_t *p)
{
    while (p->running) {
        p->failed += finish(&p->jobs[0]);
        memmove(&p->jobs[0], &p->jobs[1], sizeof p->jobs[0] * (SWEEP_JOBS - 1));
        p->running--;
    }
}

/* A refused load's message: one line, "NAME:..." */
static int one_line(const char *err, const char *name)
{
    return !strncmp(err, name, strlen(name)) && err[strlen(name)] == ':' && !strchr(err, '\n');
}

static void test_every_config_key_at_its_extremes(void **state)
{
    (void)state;
    pool_t p = { .running = 0 };
    for (size_t i = 0; i < config_key_count(); i++) {
        const char *section, *key;
        double lo, hi;
        assert_int_equal(config_key_info(i, &section, &key, &lo, &hi), 0);
        for (int at_max = 0; at_max < 2; at_max++) {
            double v = at_max ? hi : lo;
            char ini[512], err[400], name[48], num[32];
            const char *word = config_key_word(i, v); /* a word key: its first and last word */
            int c = comp_index((snprintf(name, sizeof name, "%s.%s", section, key), name), at_max);
            snprintf(num, sizeof num, "%.17g", v);
            job_t j;
            snprintf(j.name, sizeof j.name, "%s=%s", name, word ? word : num);
            snprintf(ini, sizeof ini, "[%s]\n%s = %s\n%s", section, key, word ? word : num, c >= 0 ? companions[c].config : "");
            simcfg_t cfg;
            config_defaults(&cfg);
            const char *why = NULL;
            for (size_t r = 0; r < sizeof refused / sizeof refused[0]; r++)
                if (!strcmp(refused[r].key, name) && refused[r].at_max == at_max) why = refused[r].reason;
            int rc = config_load_string(&cfg, ini, j.name, err, sizeof err);
            /* as mmsim does (run_load_config): the robot against the world once both are known */
            char why_fit[300];
            if (rc == 0 && robot_fits(&cfg, why_fit, sizeof why_fit) != 0) {
                snprintf(err, sizeof err, "%s: %s", j.name, why_fit);
                rc = -1;
            }
            if (why) {
                if (rc == 0 || !one_line(err, j.name) || !strstr(err, why))
                    fail_msg("%s: want refused with '%s', got %s", j.name, why, rc ? err : "loaded");
                p.refused++;
                continue;
            }
            if (rc != 0) fail_msg("%s: config rejected: %s", j.name, err);
            *slot(&p) = j;
            start(&p.jobs[p.running - 1], ini, NULL);
        }
    }
    drain(&p);
    assert_true(p.runs + p.refused >= 40);
    if (p.failed) fail_msg("%d of %d runs at a config key's extreme did not simulate", p.failed, p.runs);
}

/* The paper robot's text with `key = value` in each section named by
 * `section` ("motor": both motors) and `extra` appended. */
static char *edit(const char *text, const char *section, const char *key, const char *value)
{
    size_t cap = strlen(text) + 4096;
    char *out = malloc(cap);
    assert_non_null(out);
    out[0] = '\0';
    size_t n = 0;
    int in = 0;
    size_t klen = strlen(key);
    for (const char *p = text; *p;) {
        const char *e = strchr(p, '\n');
        size_t len = e ? (size_t)(e - p) + 1 : strlen(p);
        int drop = 0;
        if (*p == '[') {
            size_t slen = strlen(section);
            in = !strncmp(p + 1, section, slen) && (p[1 + slen] == ']' || (p[1 + slen] == '.' && !strchr(section, '.')));
            memcpy(out + n, p, len), n += len;
            if (in) n += (size_t)snprintf(out + n, cap - n, "%s = %s\n", key, value);
            p += len;
            continue;
        }
        if (in && !strncmp(p, key, klen) && (p[klen] == ' ' || p[klen] == '=')) drop = 1;
        if (!drop) memcpy(out + n, p, len), n += len;
        p += len;
    }
    out[n] = '\0';
    return out;
}

/* The section a kind's key is swept in, and what the robot needs added. */
static const char *where(const char *kind, const char **add)
{
    *add = "";
    if (!strcmp(kind, "chassis") || !strcmp(kind, "motor") || !strcmp(kind, "encoder") || !strcmp(kind, "battery")) return kind;
    if (!strcmp(kind, "tof")) return "tof.front";
    if (!strcmp(kind, "ir")) {
        *add = "\n[ir.sweep]\nx_mm = 20\ny_mm = 50\nz_mm = 15\nyaw_deg = -30\nemitter = 0\n";
        return "ir.sweep";
    }
    if (!strcmp(kind, "gyro")) {
        *add = "\n[gyro.sweep]\nx_mm = 0\ny_mm = 0\nz_mm = 10\nyaw_deg = 0\n";
        return "gyro.sweep";
    }
    fail_msg("a sensor kind the sweep does not know: %s (add it to where())", kind);
    return NULL;
}

static void test_every_robot_key_at_its_extremes(void **state)
{
    (void)state;
    pool_t p = { .running = 0 };
    size_t nkeys = robot_key_count();
    for (size_t i = 0; i < nkeys; i++) {
        const char *kind, *key;
        double lo, hi;
        assert_int_equal(robot_key_info(i, &kind, &key, &lo, &hi), 0);
        for (int at_max = 0; at_max < 2; at_max++) {
            double v = at_max ? hi : lo;
            char name[48], num[32], err[400];
            const char *word = robot_key_word(i, v), *add;
            snprintf(num, sizeof num, "%.17g", v);
            snprintf(name, sizeof name, "%s.%s", kind, key);
            int c = comp_index(name, at_max);
            const char *section = where(kind, &add);
            char *base = malloc(strlen(paper) + strlen(add) + 1);
            assert_non_null(base);
            strcpy(base, paper);
            strcat(base, add);
            char *text = edit(base, section, key, word ? word : num);
            free(base);
            for (int e = 0; c >= 0 && e < 2 && companions[c].robot[e][0]; e++) {
                const char *cs = companions[c].robot[e][0];
                char *t2 = edit(text, !strcmp(cs, kind) ? section : cs, companions[c].robot[e][1], companions[c].robot[e][2]);
                free(text);
                text = t2;
            }
            const char *cfg_text = c >= 0 ? companions[c].config : "";
            job_t j;
            snprintf(j.name, sizeof j.name, "[%s] %s=%s", section, key, word ? word : num);
            simcfg_t cfg;
            config_defaults(&cfg);
            if (cfg_text[0] && config_load_string(&cfg, cfg_text, "companion", err, sizeof err) != 0)
                fail_msg("%s: companion config rejected: %s", j.name, err);
            simcfg_t before = cfg;
            if (robot_load_string(&cfg, text, "sweep.ini", err, sizeof err) != 0) {
                if (!one_line(err, "sweep.ini")) fail_msg("%s: refused without one clear line: %s", j.name, err);
                if (memcmp(&cfg, &before, sizeof cfg)) fail_msg("%s: a refused robot changed the config", j.name);
                if (getenv("SWEEP_VERBOSE")) fprintf(stderr, "%s: refused: %s\n", j.name, err);
                p.refused++;
                free(text);
                continue;
            }
            *slot(&p) = j;
            start(&p.jobs[p.running - 1], cfg_text, text);
            free(text);
        }
    }
    drain(&p);
    assert_true(nkeys >= 60);
    assert_int_equal(p.runs + p.refused, 2 * (int)nkeys);
    /* most extremes load: a refusal is a cross-check (pose, friction, corridor) */
    assert_true(p.runs > p.refused);
    if (p.failed) fail_msg("%d of %d runs at a robot key's extreme did not simulate", p.failed, p.runs);
}

static int setup(void **state)
{
    (void)state;
    paper = read_all("robots/paper.ini");
    return 0;
}

static int teardown(void **state)
{
    (void)state;
    free(paper);
    return 0;
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_every_config_key_at_its_extremes),
        cmocka_unit_test(test_every_robot_key_at_its_extremes),
    };
    return cmocka_run_group_tests_name("config_sweep", tests, setup, teardown);
}

/* config.c - the key table (unit, physical range, source of the default),
 * loading through the INI reader (inifile.h), printing and hashing. */
#include "config.h"

#include <glib.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "inifile.h"
#include "keytab.h"
#include "robot.h"

/* A key of section sec, stored in the group grp of simcfg_t. */
#define K(sec, grp, name, def, min, max, unit, source) \
    { sec, #name, offsetof(simcfg_t, grp.name), def, min, max, unit, source, NULL, 0, 0, 0, KEYTAB_DOUBLE, 0, NULL }
/* a key whose value is a whole number (an int) */
#define KW(sec, grp, name, def, min, max, unit, source) \
    { sec, #name, offsetof(simcfg_t, grp.name), def, min, max, unit, source, NULL, 0, 0, 0, KEYTAB_INT, 0, NULL }
/* a key whose value is one of the words (an int: the word's index) */
#define W(sec, grp, name, def, words, source) \
    { sec, #name, offsetof(simcfg_t, grp.name), def, 0, sizeof words / sizeof words[0] - 1, "word", source, words, 0, 0, 0, KEYTAB_INT, 0, NULL }

static const char *const solvers[] = { "quickstep", "exact" };
static const char *const wheel_forms[] = { "hinge", "spin" };

static const keytab_t keys[] = {
    K("world", world, cell_m, 0.180, 0.05, 0.5, "m", "classic rules: 180 mm cells (half-size: 90 mm)"),
    K("world", world, wall_thick_m, 0.012, 0.001, 0.05, "m", "classic rules: 12 mm walls"),
    K("world", world, wall_height_m, 0.050, 0.005, 0.2, "m", "classic rules: 50 mm walls"),
    K("world", world, post_m, 0.012, 0.001, 0.05, "m", "classic rules: 12x12 mm posts"),
    KW("world", world, centre_post, 1, 0, 1, "0/1", "classic rules allow the goal's centre post"),
    K("world", world, body_wall_mu, 0.3, 0, 3, "1", "ours: plastic on painted wood; only matters in a crash"),
    /* Contacts as springs and dampers: the same N/m and N*s/m at every step
     * (world.c: ERP = h*kp/(h*kp + kd), CFM = 1/(h*kp + kd), the ODE manual's
     * "soft constraint" formula). */
    K("world", world, tyre_kp_n_m, 1.2e4, 1e3, 1e7, "N/m",
      "derived: silicone tyre 1.5 mm thick, 4x4 mm patch, E = 1.1 MPa (Shore 30A by Gent's relation): E*A/t; rests 60 um deep"),
    K("world", world, tyre_kd_n_s_m, 10, 0, 1e4, "N*s/m", "ours: damping ratio about 0.17 for a wheel's share of the robot (75 g) on its tyre"),
    K("world", world, wall_kp_n_m, 2.5e5, 1e3, 1e8, "N/m",
      "derived: a 12x50 mm MDF wall (E = 3.5 GPa) over its 168 mm span between posts, loaded mid-span: 48*E*I/L^3"),
    K("world", world, wall_kd_n_s_m, 80, 0, 1e5, "N*s/m", "ours: restitution about 0.5 for a 0.15 kg robot on wall_kp_n_m (damping ratio 0.2)"),
    K("world", world, caster_kp_n_m, 1.2e4, 1e3, 1e8, "N/m", "ours: as tyre_kp_n_m: the robot rests on its tyres and skids at once, and a stiffer skid would take the tyres' load"),
    K("world", world, caster_kd_n_s_m, 10, 0, 1e5, "N*s/m", "ours: as tyre_kd_n_s_m"),
    K("world", world, wall_reflectivity, 0.85, 0, 1, "1", "ours: matt white wall faces (IR sensors; their gains in the robot file are for reflectivity 1)"),
    K("world", world, wall_gloss, 0, 0, 1, "1", "ours: matt (ORION fits matt walls); gloss paint: 0.04, Fresnel (n-1)^2/(n+1)^2, n = 1.5 (IR sensors)"),
    K("world", world, wall_gloss_exp, 100, 1, 10000, "1", "ours: satin paint's lobe, half power 6.7 deg off the mirror (IR sensors; sim/world/sensors/README.md)"),
    /* the u16 65535 of compat distances stands for this; a reading at or beyond it goes as a timeout
     * (inih reads lines of at most 200 characters: the printed line must fit) */
    K("link", link, compat_range_m, 1.0, 0.05, 10, "m",
      "paper's Unity simulator: its TimeOfFlight asset has range 1.0 m, its Arduino library converts with 1.0 m"),
    /* Asymmetries: each 0 by default (a symmetric robot drives straight);
     * set one to see the veer it alone causes. */
    K("asymmetry", asym, wheel_d_diff_m, 0, -0.005, 0.005, "m", "right wheel diameter minus left (the mean stays the robot file's)"),
    K("asymmetry", asym, motor_k_diff_pct, 0, -20, 20, "%", "right motor's constant (back-EMF and torque) relative to the left's, in per cent of the mean"),
    K("asymmetry", asym, tyre_mu_diff, 0, -1, 1, "1", "right tyre's friction minus left's (the mean stays the robot file's tyre_mu)"),
    K("asymmetry", asym, com_x_m, 0, -0.02, 0.02, "m", "body's centre of mass to the right of the centre line"),
    K("asymmetry", asym, com_y_m, 0, -0.02, 0.02, "m", "body's centre of mass ahead of the body's centre"),
    /* Per-seed variation of the asymmetries (Monte Carlo robustness runs):
     * each run adds a draw from N(0, sigma^2), from its own stream seeded by
     * the run's seed; 0 = none. */
    K("variation", var, wheel_d_sigma_m, 0, 0, 0.002, "m", "spread of wheel_d_diff_m between robots (tyres differ by ~0.1 mm when trimmed by hand)"),
    K("variation", var, motor_k_sigma_pct, 0, 0, 10, "%", "spread of motor_k_diff_pct (motors of one batch differ by a few per cent)"),
    K("variation", var, tyre_mu_sigma, 0, 0, 0.5, "1", "spread of tyre_mu_diff"),
    K("variation", var, com_sigma_m, 0, 0, 0.01, "m", "spread of com_x_m and com_y_m"),
    /* The firmware's control tick is no key: it is hal.h's HAL_TICK_HZ,
     * compiled into the firmware (the contest calls fw_tick every
     * 1/HAL_TICK_HZ s of simulation time). */
    K("sim", sim, step_s, 0.001, 1e-5, 0.01, "s", "1 kHz physics"),
    W("sim", sim, solver, 1, solvers, "exact: dWorldStep, no creep at rest, drives straight (docs/GUIDE-robot.md); quickstep slid a resting robot 10 mm/min on hinged wheels (docs/BENCHMARKS.md)"),
    KW("sim", sim, solver_iterations, 10, 1, 200, "1", "solver = quickstep only: at 5 a resting robot creeps 0.17 mm/min on spin bodies (--validate fails it); on hinges the wheels give and a straight run crabs 1.4 degrees"),
    W("sim", sim, wheels, 1, wheel_forms, "spin: each wheel's spin a body of its own (9 solver rows, a 47 % cheaper ODE step than hinge: docs/BENCHMARKS.md); hinge: each wheel a body on a hinge (19 rows)"),
    K("sim", sim, time_limit_s, 600, 1, 86400, "s", "contest rules: 10 minutes"),
};

#define NKEYS (sizeof keys / sizeof keys[0])

size_t config_key_count(void) { return NKEYS; }

int config_key_info(size_t i, const char **section, const char **key, double *min, double *max)
{
    if (i >= NKEYS) return -1;
    *section = keys[i].section;
    *key = keys[i].key;
    *min = keys[i].min;
    *max = keys[i].max;
    return 0;
}

const char *config_key_word(size_t i, double v)
{
    if (i >= NKEYS || !keys[i].choices || v < 0 || v > keys[i].max) return NULL;
    return keys[i].choices[(int)v];
}

double config_key_value(const simcfg_t *c, size_t i) { return i < NKEYS ? keytab_get(&keys[i], c) : 0.0; }

void config_defaults(simcfg_t *c)
{
    memset(c, 0, sizeof *c);
    keytab_defaults(keys, NKEYS, c);
    robot_defaults(c);
}

static int on_key(void *user, const char *section, const char *name, const char *val, char *why, size_t len)
{
    const keytab_t *k = keytab_find(keys, NKEYS, section, name);
    if (!k && robot_section(section)) {
        snprintf(why, len, "%s.%s: a robot's number: it belongs in the robot file (--robot FILE, docs/ROBOTS.md)", section, name);
        return -1;
    }
    if (!k) {
        snprintf(why, len, "%s.%s: unknown key", section, name);
        return -1;
    }
    return keytab_set(k, user, section, val, why, len);
}

/* Cross-key checks that one key's range cannot express. */
static int check(const simcfg_t *c, char *reason, size_t len)
{
    if (c->world.post_m < c->world.wall_thick_m) {
        snprintf(reason, len, "world.post_m: posts thinner than walls");
        return -1;
    }
    return 0;
}

/* The config from text (NULL: the file at name) over c; c changes only
 * if the whole file is good. */
static int load(simcfg_t *c, const char *text, const char *name, char *err, size_t errlen)
{
    simcfg_t work = *c;
    const inifile_t r = { NULL, on_key, &work, "want key = value or [section]" };
    int rc = text ? inifile_parse(&r, text, strlen(text), name, err, errlen) : inifile_load(&r, name, CONFIG_MAX_BYTES, err, errlen);
    if (rc != 0) return -1;
    char reason[200];
    if (check(&work, reason, sizeof reason) != 0) {
        snprintf(err, errlen, "%s: %s", name, reason);
        return -1;
    }
    *c = work;
    return 0;
}

int config_load(simcfg_t *c, const char *path, char *err, size_t errlen) { return load(c, NULL, path, err, errlen); }

int config_load_string(simcfg_t *c, const char *text, const char *name, char *err, size_t errlen)
{
    return load(c, text, name, err, errlen);
}

void config_print(const simcfg_t *c, FILE *out)
{
    const char *section = "";
    for (size_t i = 0; i < NKEYS; i++) {
        if (strcmp(section, keys[i].section) != 0) {
            section = keys[i].section;
            fprintf(out, "%s[%s]\n", i ? "\n" : "", section);
        }
        keytab_print(&keys[i], c, out);
    }
}

void config_hash(const simcfg_t *c, char out[65])
{
    char *text = NULL;
    size_t len = 0;
    FILE *mem = open_memstream(&text, &len);
    config_print(c, mem);
    fputc('\n', mem);
    robot_print(c, mem);
    fclose(mem);
    gchar *hex = g_compute_checksum_for_string(G_CHECKSUM_SHA256, text, (gssize)len);
    snprintf(out, 65, "%s", hex);
    g_free(hex);
    free(text);
}

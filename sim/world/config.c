/* config.c - the key table (unit, physical range, source of the default),
 * INI loading through libinih, printing and hashing. */
#include "config.h"

#include <errno.h>
#include <glib.h>
#include <ini.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "io/infile.h"

typedef struct {
    const char *section, *key;
    size_t offset;
    double def, min, max;
    const char *unit, *source;
    const char *const *choices; /* a word key: its words, the value is the index */
    int whole;                  /* 1: a whole number (a count, or 0/1) */
} cfgkey_t;

#define K(sec, name, def, min, max, unit, source) \
    { sec, #name, offsetof(simcfg_t, name), def, min, max, unit, source, NULL, 0 }
/* a key whose value is a whole number */
#define KW(sec, name, def, min, max, unit, source) \
    { sec, #name, offsetof(simcfg_t, name), def, min, max, unit, source, NULL, 1 }
/* a key whose value is one of the words (stored as the word's index) */
#define W(sec, name, def, words, source) \
    { sec, #name, offsetof(simcfg_t, name), def, 0, sizeof words / sizeof words[0] - 1, "word", source, words, 1 }

static const char *const motor_models[] = { "paper", "datasheet" };
static const char *const solvers[] = { "quickstep", "exact" };

static const cfgkey_t keys[] = {
    K("world", cell_m, 0.180, 0.05, 0.5, "m", "classic rules: 180 mm cells (half-size: 90 mm)"),
    K("world", wall_thick_m, 0.012, 0.001, 0.05, "m", "classic rules: 12 mm walls"),
    K("world", wall_height_m, 0.050, 0.005, 0.2, "m", "classic rules: 50 mm walls"),
    K("world", post_m, 0.012, 0.001, 0.05, "m", "classic rules: 12x12 mm posts"),
    KW("world", centre_post, 1, 0, 1, "0/1", "classic rules allow the goal's centre post"),
    K("world", body_wall_mu, 0.3, 0, 3, "1", "ours: plastic on painted wood; only matters in a crash"),
    K("robot", body_w_m, 0.096, 0.01, 0.3, "m", "paper Table 1"),
    K("robot", body_l_m, 0.120, 0.01, 0.3, "m", "paper Table 1"),
    K("robot", body_h_m, 0.020, 0.002, 0.1, "m", "paper Table 1"),
    K("robot", body_mass_kg, 0.127, 0.001, 2, "kg", "paper section 4.3: body 127 g"),
    K("robot", body_clearance_m, 0.005, 0.0005, 0.05, "m", "ours: body rides 5 mm above the floor (wheel radius 16 mm)"),
    K("robot", wheel_d_m, 0.032, 0.005, 0.1, "m", "paper Table 1"),
    K("robot", wheel_w_m, 0.008, 0.001, 0.05, "m", "paper Table 1"),
    K("robot", wheel_mass_kg, 0.010, 0.0005, 0.5, "kg", "paper section 4.3: wheels 10 g each"),
    K("robot", wheel_x_m, 0.048, 0.005, 0.15, "m", "wheel centre planes at the body's sides (96 mm track)"),
    K("robot", axle_y_m, 0.0, -0.1, 0.1, "m", "axle at the middle of the body: in-place turns sweep 77 mm"),
    K("robot", caster_r_m, 0.005, 0.001, 0.05, "m", "paper: rear caster sphere"),
    K("robot", caster_mass_kg, 0.010, 0.0005, 0.5, "kg", "paper section 4.3: caster 10 g"),
    K("robot", caster_y_m, -0.055, -0.2, 0.2, "m", "rear of the 120 mm body"),
    K("robot", tyre_mu, 1.0, 0.01, 3, "1", "silicone tyres on a painted maze floor; the paper's Unity value is 0.35"),
    K("robot", tyre_mu_dynamic, 1.0, 0.01, 3, "1", "equal to tyre_mu by default; the paper's Unity value is 0.25"),
    K("robot", tyre_slip_m_s, 0.005, 0, 1, "m/s", "ours: above 5 mm/s of slip a tyre slides (dynamic friction)"),
    /* The Pololu 30:1 LP 6V micro metal gearmotor (item 2202), datasheet
     * "Micro Metal Gearmotors", Pololu, Rev 2.0 May 2018, p. 1 and 3: no load
     * 450 rpm, 0.02 A; max efficiency 320 rpm, 0.66 kg*mm, 0.11 A; stall 2.9
     * kg*mm, 0.36 A; all at 6 V. The motor constants are derived (motor.h). */
    W("motor", motor_model, 1, motor_models, "datasheet: losses and rotor inertia, fitted to the datasheet (README); paper: eq. 1-5, no losses"),
    K("motor", rated_v, 6.0, 0.5, 50, "V", "Pololu datasheet: the figures below are at 6 V"),
    K("motor", no_load_rpm, 450, 1, 100000, "rpm", "Pololu datasheet: output shaft, 6 V"),
    K("motor", no_load_a, 0.02, 0, 10, "A", "Pololu datasheet: 6 V"),
    K("motor", stall_torque_nm, 0.028439, 1e-5, 10, "N*m", "Pololu datasheet: 2.9 kg*mm = 0.028439 N*m at the output shaft, 6 V"),
    K("motor", stall_a, 0.36, 0.001, 100, "A", "Pololu datasheet: 6 V"),
    K("motor", l_h, 0.001, 1e-7, 1, "H", "paper's shipped value (Pololu publishes none)"),
    K("motor", battery_v, 6.0, 0.5, 50, "V", "paper: 6 V rated"),
    K("motor", battery_r_ohm, 0.0, 0, 100, "ohm", "internal resistance (voltage sag); off by default"),
    K("drivetrain", gear_ratio, 29.86, 1, 1000, "1", "Pololu datasheet: 29.86:1 (the '30:1')"),
    K("drivetrain", rotor_inertia_kgm2, 2.0e-8, 0, 1e-3, "kg*m^2", "ours: solid cylinder of 8 mm, 2.5 g (the armature; no datasheet figure); x N^2 at the wheel; not in the paper model"),
    K("encoder", encoder_ppr, 12, 1, 100000, "pulses/motor rev", "paper: 12 PPR magnetic encoder = 358.32 counts per wheel turn"),
    K("tof", tof_range_m, 1.2, 0.05, 10, "m", "VL53L0X long range, as the paper's simulator (its Arduino side assumed 1.0 m)"),
    K("tof", tof_blind_m, 0.0, 0, 0.5, "m", "paper: no blind spot modelled"),
    K("tof", tof_cv, 0.05, 0, 1, "1", "noise sigma = cv * distance (paper)"),
    K("tof", tof_period_s, 0.030, 0.001, 1, "s", "VL53L0X default timing budget ~30 ms"),
    K("tof", tof_x_m, 0.040, 0, 0.15, "m", "side sensors near the front corners"),
    K("tof", tof_y_m, 0.050, -0.15, 0.15, "m", "side sensors near the front edge"),
    K("tof", tof_front_y_m, 0.055, -0.15, 0.15, "m", "front sensor inside the front edge"),
    K("tof", tof_side_angle_deg, 45, 0, 90, "deg", "paper: corner sensors at 45 degrees"),
    /* the u16 65535 of compat distances stands for this; a reading at or beyond it goes as a timeout
     * (inih reads lines of at most 200 characters: the printed line must fit) */
    K("link", compat_range_m, 1.0, 0.05, 10, "m",
      "paper's Unity simulator: its TimeOfFlight asset has range 1.0 m, its Arduino library converts with 1.0 m"),
    /* Asymmetries: each 0 by default (a symmetric robot drives straight);
     * set one to see the veer it alone causes. */
    K("asymmetry", wheel_d_diff_m, 0, -0.005, 0.005, "m", "right wheel diameter minus left (the mean stays robot.wheel_d_m)"),
    K("asymmetry", motor_k_diff_pct, 0, -20, 20, "%", "right motor's constant (back-EMF and torque) relative to the left's, in per cent of the mean"),
    K("asymmetry", tyre_mu_diff, 0, -1, 1, "1", "right tyre's friction minus left's (the mean stays robot.tyre_mu)"),
    K("asymmetry", com_x_m, 0, -0.02, 0.02, "m", "body's centre of mass to the right of the centre line"),
    K("asymmetry", com_y_m, 0, -0.02, 0.02, "m", "body's centre of mass ahead of the body's centre"),
    /* Per-seed variation of the asymmetries (Monte Carlo robustness runs):
     * each run adds a draw from N(0, sigma^2), from its own stream seeded by
     * the run's seed; 0 = none. */
    K("variation", wheel_d_sigma_m, 0, 0, 0.002, "m", "spread of wheel_d_diff_m between robots (tyres differ by ~0.1 mm when trimmed by hand)"),
    K("variation", motor_k_sigma_pct, 0, 0, 10, "%", "spread of motor_k_diff_pct (motors of one batch differ by a few per cent)"),
    K("variation", tyre_mu_sigma, 0, 0, 0.5, "1", "spread of tyre_mu_diff"),
    K("variation", com_sigma_m, 0, 0, 0.01, "m", "spread of com_x_m and com_y_m"),
    K("sim", step_s, 0.001, 1e-5, 0.01, "s", "1 kHz physics"),
    W("sim", solver, 1, solvers, "exact: dWorldStep, no creep at rest, drives straight (README); quickstep slid a resting robot 10 mm/min"),
    KW("sim", solver_iterations, 10, 1, 200, "1", "solver = quickstep only: at 5 the wheel hinges give and a straight run crabs 1.4 degrees"),
    K("sim", contact_erp, 0.4, 0.01, 1, "1", "ours: contact error reduction; stiff enough that the robot rests within 0.1 mm"),
    K("sim", contact_cfm, 1e-5, 0, 1, "m/N", "ours: contact softness"),
    K("sim", control_hz, 1000, 10, 100000, "Hz", "firmware control tick"),
    K("sim", time_limit_s, 600, 1, 86400, "s", "contest rules: 10 minutes"),
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

static double value(const simcfg_t *c, const cfgkey_t *k);

const char *config_key_word(size_t i, double v)
{
    if (i >= NKEYS || !keys[i].choices || v < 0 || v > keys[i].max) return NULL;
    return keys[i].choices[(int)v];
}

double config_key_value(const simcfg_t *c, size_t i) { return i < NKEYS ? value(c, &keys[i]) : 0.0; }

static double *field(simcfg_t *c, const cfgkey_t *k) { return (double *)((char *)c + k->offset); }
static double value(const simcfg_t *c, const cfgkey_t *k) { return *(const double *)((const char *)c + k->offset); }

void config_defaults(simcfg_t *c)
{
    memset(c, 0, sizeof *c);
    for (size_t i = 0; i < NKEYS; i++) *field(c, &keys[i]) = keys[i].def;
}

typedef struct {
    simcfg_t *cfg;
    char reason[200]; /* the first error's text */
    int failed;
} load_t;

static int on_key(void *user, const char *section, const char *name, const char *val)
{
    load_t *l = user;
    const cfgkey_t *k = NULL;
    if (l->failed) return 1; /* report the first error only */
    for (size_t i = 0; i < NKEYS; i++)
        if (!strcmp(keys[i].section, section) && !strcmp(keys[i].key, name)) k = &keys[i];
    l->failed = 1;
    if (!k) {
        snprintf(l->reason, sizeof l->reason, "%s.%s: unknown key", section, name);
        return 0;
    }
    if (!val || !*val) {
        snprintf(l->reason, sizeof l->reason, "%s.%s: missing value", section, name);
        return 0;
    }
    if (k->choices) {
        for (int i = 0; i <= (int)k->max; i++)
            if (!strcmp(val, k->choices[i])) {
                *field(l->cfg, k) = i;
                l->failed = 0;
                return 1;
            }
        int n = snprintf(l->reason, sizeof l->reason, "%s.%s: '%s' is not one of", section, name, val);
        for (int i = 0; i <= (int)k->max && n > 0 && (size_t)n < sizeof l->reason; i++)
            n += snprintf(l->reason + n, sizeof l->reason - (size_t)n, " %s", k->choices[i]);
        return 0;
    }
    char *end;
    errno = 0;
    double v = strtod(val, &end);
    while (*end == ' ' || *end == '\t') end++;
    if (errno || end == val || *end || !isfinite(v)) {
        snprintf(l->reason, sizeof l->reason, "%s.%s: '%s' is not a number", section, name, val);
        return 0;
    }
    if (k->whole && v != floor(v)) {
        snprintf(l->reason, sizeof l->reason, "%s.%s: %g is not a whole number", section, name, v);
        return 0;
    }
    if (v < k->min || v > k->max) {
        snprintf(l->reason, sizeof l->reason, "%s.%s: %g %s is out of range [%g, %g]", section, name, v, k->unit, k->min, k->max);
        return 0;
    }
    *field(l->cfg, k) = v;
    l->failed = 0;
    return 1;
}

/* Cross-key checks that one key's range cannot express. */
static int check(const simcfg_t *c, char *reason, size_t len)
{
    if (c->tyre_mu_dynamic > c->tyre_mu) {
        snprintf(reason, len, "robot.tyre_mu_dynamic: %g is above tyre_mu %g", c->tyre_mu_dynamic, c->tyre_mu);
        return -1;
    }
    if (2 * c->wheel_x_m + c->wheel_w_m >= c->cell_m - c->wall_thick_m) {
        snprintf(reason, len, "robot.wheel_x_m: the robot is wider than a corridor");
        return -1;
    }
    if (c->no_load_a >= c->stall_a) {
        snprintf(reason, len, "motor.no_load_a: %g A is not below stall_a %g A", c->no_load_a, c->stall_a);
        return -1;
    }
    if (c->post_m < c->wall_thick_m) {
        snprintf(reason, len, "world.post_m: posts thinner than walls");
        return -1;
    }
    return 0;
}

static int finish(load_t *l, int rc, const char *name, char *err, size_t errlen)
{
    if (rc < 0) { /* ini_parse_string: out of memory */
        snprintf(err, errlen, "%s: cannot parse: out of memory", name);
        return -1;
    }
    if (rc > 0) {
        snprintf(err, errlen, "%s:%d: %s", name, rc, l->failed ? l->reason : "syntax error (want key = value or [section])");
        return -1;
    }
    char reason[200];
    if (check(l->cfg, reason, sizeof reason) != 0) {
        snprintf(err, errlen, "%s: %s", name, reason);
        return -1;
    }
    return 0;
}

/* libinih reads each line into a buffer of INI_MAX_LINE bytes (with the
 * line end and a NUL) and parses the rest of a longer line as a line of
 * its own, so a long comment could set a key and later line numbers were
 * off; a NUL would end the text early. Both are errors here. */
#define CONFIG_MAX_LINE (INI_MAX_LINE - 3) /* bytes of a line without its CR LF */

static int scan_lines(const char *text, size_t len, const char *name, char *err, size_t errlen)
{
    size_t line = 1, start = 0;
    for (size_t i = 0; i <= len; i++) {
        if (i < len && text[i] == '\0') {
            snprintf(err, errlen, "%s:%zu: NUL byte", name, line);
            return -1;
        }
        if (i < len && text[i] != '\n') continue;
        size_t n = i - start;
        if (n > 0 && text[i - 1] == '\r') n--;
        if (n > CONFIG_MAX_LINE) {
            snprintf(err, errlen, "%s:%zu: line too long (%zu bytes; at most %d)", name, line, n, CONFIG_MAX_LINE);
            return -1;
        }
        line++;
        start = i + 1;
    }
    return 0;
}

static int load_text(simcfg_t *c, const char *text, size_t len, const char *name, char *err, size_t errlen)
{
    simcfg_t work = *c; /* nothing changes unless the whole file is good */
    load_t l = { &work, "", 0 };
    if (scan_lines(text, len, name, err, errlen) != 0) return -1;
    int rc = ini_parse_string(text, on_key, &l);
    if (finish(&l, rc, name, err, errlen) != 0) return -1;
    *c = work;
    return 0;
}

int config_load(simcfg_t *c, const char *path, char *err, size_t errlen)
{
    size_t len;
    /* a regular file of a bounded size: a FIFO or /dev/zero hung, a
     * directory read as an empty file */
    char *text = infile_read(path, CONFIG_MAX_BYTES, &len, err, errlen);
    if (!text) return -1;
    int rc = load_text(c, text, len, path, err, errlen);
    free(text);
    return rc;
}

int config_load_string(simcfg_t *c, const char *text, const char *name, char *err, size_t errlen)
{
    return load_text(c, text, strlen(text), name, err, errlen);
}

/* v in as few digits as read back the same double, at least 9: the
 * defaults print as before, and a value given with more digits prints
 * with them (with 9 only, 0.079999999999 printed as 0.08, which the
 * corridor check rejected when the printed config, as a log's MM_MAZE,
 * was loaded again; and two such configs had the same hash). */
static const char *number(double v, char *buf, size_t len)
{
    for (int digits = 9; digits <= 17; digits++) {
        snprintf(buf, len, "%.*g", digits, v);
        if (strtod(buf, NULL) == v) break;
    }
    return buf;
}

void config_print(const simcfg_t *c, FILE *out)
{
    const char *section = "";
    for (size_t i = 0; i < NKEYS; i++) {
        if (strcmp(section, keys[i].section) != 0) {
            section = keys[i].section;
            fprintf(out, "%s[%s]\n", i ? "\n" : "", section);
        }
        char num[32];
        if (keys[i].choices)
            fprintf(out, "%s = %s ; %s; %s\n", keys[i].key, keys[i].choices[(int)value(c, &keys[i])], keys[i].unit,
                    keys[i].source);
        else
            fprintf(out, "%s = %s ; %s; %s\n", keys[i].key, number(value(c, &keys[i]), num, sizeof num), keys[i].unit,
                    keys[i].source);
    }
}

void config_hash(const simcfg_t *c, char out[65])
{
    char *text = NULL;
    size_t len = 0;
    FILE *mem = open_memstream(&text, &len);
    config_print(c, mem);
    fclose(mem);
    gchar *hex = g_compute_checksum_for_string(G_CHECKSUM_SHA256, text, (gssize)len);
    snprintf(out, 65, "%s", hex);
    g_free(hex);
    free(text);
}

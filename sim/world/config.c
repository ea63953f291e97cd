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
} cfgkey_t;

#define K(sec, name, def, min, max, unit, source) \
    { sec, #name, offsetof(simcfg_t, name), def, min, max, unit, source }

static const cfgkey_t keys[] = {
    K("world", cell_m, 0.180, 0.05, 0.5, "m", "classic rules: 180 mm cells (half-size: 90 mm)"),
    K("world", wall_thick_m, 0.012, 0.001, 0.05, "m", "classic rules: 12 mm walls"),
    K("world", wall_height_m, 0.050, 0.005, 0.2, "m", "classic rules: 50 mm walls"),
    K("world", post_m, 0.012, 0.001, 0.05, "m", "classic rules: 12x12 mm posts"),
    K("world", centre_post, 1, 0, 1, "0/1", "classic rules allow the goal's centre post"),
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
    K("motor", gear_ratio, 29.86, 1, 1000, "1", "Pololu 30:1 LP 6 V micro metal gearmotor (paper)"),
    K("motor", kt_nm_per_a, 0.079025, 1e-5, 10, "N*m/A", "T_stall/i_stall at the output shaft (paper eq. 4, Pololu 30:1 LP 6 V)"),
    K("motor", r_ohm, 16.6667, 0.01, 1000, "ohm", "V_rated/i_stall = 6 V / 0.36 A (paper eq. 5)"),
    K("motor", l_h, 0.001, 1e-7, 1, "H", "paper's shipped value"),
    K("motor", battery_v, 6.0, 0.5, 50, "V", "paper: 6 V rated"),
    K("motor", battery_r_ohm, 0.0, 0, 100, "ohm", "internal resistance (voltage sag); off by default"),
    K("motor", rotor_inertia_kgm2, 0.0, 0, 1e-3, "kg*m^2", "rotor inertia at the motor shaft; off by default"),
    K("encoder", encoder_ppr, 12, 1, 100000, "pulses/motor rev", "paper: 12 PPR magnetic encoder = 358.32 counts per wheel turn"),
    K("tof", tof_range_m, 1.2, 0.05, 10, "m", "VL53L0X long range, as the paper's simulator (its Arduino side assumed 1.0 m)"),
    K("tof", tof_blind_m, 0.0, 0, 0.5, "m", "paper: no blind spot modelled"),
    K("tof", tof_cv, 0.05, 0, 1, "1", "noise sigma = cv * distance (paper)"),
    K("tof", tof_period_s, 0.030, 0.001, 1, "s", "VL53L0X default timing budget ~30 ms"),
    K("tof", tof_x_m, 0.040, 0, 0.15, "m", "side sensors near the front corners"),
    K("tof", tof_y_m, 0.050, -0.15, 0.15, "m", "side sensors near the front edge"),
    K("tof", tof_front_y_m, 0.055, -0.15, 0.15, "m", "front sensor inside the front edge"),
    K("tof", tof_side_angle_deg, 45, 0, 90, "deg", "paper: corner sensors at 45 degrees"),
    K("sim", step_s, 0.001, 1e-5, 0.01, "s", "1 kHz physics"),
    K("sim", solver_iterations, 10, 1, 200, "1", "ODE quickstep iterations: at 5 the wheel hinges give and a straight run crabs 1.4 degrees (5 mm sideways in the first 200 mm); 10 tracks 20 and 40 within 0.3 mm"),
    K("sim", contact_erp, 0.4, 0.01, 1, "1", "ours: contact error reduction; stiff enough that the robot rests within 0.1 mm"),
    K("sim", contact_cfm, 1e-5, 0, 1, "m/N", "ours: contact softness, keeps quickstep stable at 5 iterations"),
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
    char *end;
    errno = 0;
    double v = strtod(val, &end);
    while (*end == ' ' || *end == '\t') end++;
    if (errno || end == val || *end || !isfinite(v)) {
        snprintf(l->reason, sizeof l->reason, "%s.%s: '%s' is not a number", section, name, val);
        return 0;
    }
    if ((!strcmp(name, "solver_iterations") || !strcmp(name, "centre_post")) && v != floor(v)) {
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

/* mkprofile - the firmware's robot profile from a robot file: the keys of
 * its [firmware] section (and [firmware.avr]'s, the values an AVR image
 * takes where they differ), with the figures the firmware shares with the
 * physics taken from the robot's own keys (sim/world/fwprofile.h), written
 * as a C header of RC_* constants that the firmware includes as
 * robot_profile.h (firmware/robot_config.h). The Makefile runs it for each
 * robot the firmware is built for: build/gen/NAME/robot_profile.h.
 *
 *   mkprofile ROBOT.ini OUT.h
 *
 * The feed-forward's motor figures (mm_s_per_cmd, cmd_friction,
 * cmd_per_mm_s2, cmd_per_arc_mm_s2) must agree with what the robot's motor
 * and chassis keys, or its [measured.*] characterisation, give for a
 * command step of cmd_max_v / cmd_max (check_motor).
 *
 * Exit codes: 0 written, 2 bad input (one line: FILE:LINE: reason),
 * 3 the output could not be written (nothing half written is left). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "io/number.h"
#include "io/outfile.h"
#include "world/fwprofile.h"
#include "world/inifile.h"
#include "world/robot.h"

enum { EXIT_OK = 0, EXIT_BAD_INPUT = 2, EXIT_EXTERNAL = 3 };
#define VAL_MAX 200
#define FW_MAX 128

/* the physics keys the firmware shares, by fw_from_t */
static const struct {
    const char *section, *key;
} phys_keys[] = {
    { NULL, NULL },
    { "chassis", "wheel_left_d_mm" }, /* and wheel_right_d_mm: phys_right */
    { "chassis", "wheel_track_mm" },
    { "encoder.left", "encoder_ppr" }, /* times [motor.left] gear_ratio: phys_gear */
    { "tof.front", "y_mm" },
    { "tof.right", "x_mm" },
    { "tof.right", "y_mm" },
    { "tof.right", "fov_deg" },
    { "tof.right", "rays" },
};
#define N(a) (sizeof(a) / sizeof((a)[0]))

/* the keys the feed-forward check reads (motor_figures); def: the robot
 * reader's default, NULL: none ("" for [measured.*]: optional) */
enum { M_BODY, M_WHEEL, M_CASTERS, M_CASTER, M_MODEL, M_RATED_V, M_RPM, M_I0, M_STALL_T, M_STALL_A, M_GEAR, M_ROTOR,
       M_DRIVER_R, M_KM, M_TM, M_N };
static const struct {
    const char *section, *key, *def;
} mot_keys[M_N] = {
    { "chassis", "body_mass_g", NULL },        { "chassis", "wheel_mass_g", NULL },
    { "chassis", "casters", "1" },             { "chassis", "caster_mass_g", NULL },
    { "motor.left", "model", NULL },           { "motor.left", "rated_v", NULL },
    { "motor.left", "no_load_rpm", NULL },     { "motor.left", "no_load_a", NULL },
    { "motor.left", "stall_torque_nm", NULL }, { "motor.left", "stall_a", NULL },
    { "motor.left", "gear_ratio", NULL },      { "motor.left", "rotor_inertia_kgm2", "0" },
    { "motor.left", "driver_r_ohm", "0" },     { "measured", "fwd_km_mm_s_v", "" },
    { "measured", "fwd_tm_s", "" },
};

/* the keys the yaw's feed-forward check reads besides mot_keys (arc_figure),
 * as mot_keys; these may be negative */
enum { A_BODY_W, A_BODY_L, A_YAW_J, A_COM_Y, A_AXLE_Y, A_CASTER_Y, A_CASTER2_Y, A_TRACK, A_ROT_KM, A_ROT_TM, A_N };
static const struct {
    const char *section, *key, *def;
} arc_keys[A_N] = {
    { "chassis", "body_w_mm", NULL },   { "chassis", "body_l_mm", NULL },    { "chassis", "body_yaw_inertia_kgm2", "0" },
    { "chassis", "body_com_y_mm", "0" }, { "chassis", "axle_y_mm", NULL },   { "chassis", "caster_y_mm", NULL },
    { "chassis", "caster2_y_mm", "0" }, { "chassis", "wheel_track_mm", NULL }, { "measured", "rot_km_deg_s_v", "" },
    { "measured", "rot_tm_s", "" },
};

typedef struct {
    const char *path;
    char val[2][FW_MAX][VAL_MAX]; /* [0] [firmware], [1] [firmware.avr]; "" none */
    int line[2];                  /* of the sections, 0: none */
    char phys[N(phys_keys)][VAL_MAX], phys_right[VAL_MAX], phys_gear[VAL_MAX];
    char mot[M_N][VAL_MAX], measured[VAL_MAX]; /* mot_keys' values ("" none); the [measured.*] section's name */
    char arc[A_N][VAL_MAX];                     /* arc_keys' values ("" none) */
} prof_t;

static int on_section(void *user, const char *section, int line, char *why, size_t len)
{
    prof_t *p = user;
    (void)why, (void)len;
    if (fw_section(section)) p->line[strcmp(section, "firmware") != 0] = line;
    return 0;
}

/* section's kind: "chassis" for "chassis.body" */
static int kind_is(const char *section, const char *kind)
{
    size_t n = strlen(kind);
    return !strncmp(section, kind, n) && (section[n] == '.' || section[n] == '\0');
}

/* key of section is the one named by want_section (a kind, or "kind.name" exactly) */
static int key_is(const char *section, const char *key, const char *want_section, const char *want_key)
{
    return !strcmp(key, want_key) && (strchr(want_section, '.') ? !strcmp(section, want_section) : kind_is(section, want_section));
}

static int on_key(void *user, const char *section, const char *key, const char *val, char *why, size_t len)
{
    prof_t *p = user;
    for (size_t i = 0; i < M_N; i++)
        if (key_is(section, key, mot_keys[i].section, mot_keys[i].key)) {
            snprintf(p->mot[i], VAL_MAX, "%s", val);
            if (kind_is(section, "measured")) snprintf(p->measured, VAL_MAX, "%s", section);
        }
    for (size_t i = 0; i < A_N; i++)
        if (key_is(section, key, arc_keys[i].section, arc_keys[i].key)) {
            snprintf(p->arc[i], VAL_MAX, "%s", val);
            if (kind_is(section, "measured")) snprintf(p->measured, VAL_MAX, "%s", section);
        }
    if (fw_section(section)) {
        const fw_key_t *k = fw_key_find(key);
        if (!k) {
            snprintf(why, len, "%s.%s: unknown key (the firmware's keys: docs/ROBOTS.md)", section, key);
            return -1;
        }
        if (fw_value_check(k, section, val, why, len)) return -1;
        snprintf(p->val[strcmp(section, "firmware") != 0][k - fw_keys], VAL_MAX, "%s", val);
        return 0;
    }
    for (size_t i = 1; i < N(phys_keys); i++)
        if (key_is(section, key, phys_keys[i].section, phys_keys[i].key)) snprintf(p->phys[i], VAL_MAX, "%s", val);
    if (kind_is(section, "chassis") && !strcmp(key, "wheel_right_d_mm")) snprintf(p->phys_right, VAL_MAX, "%s", val);
    if (!strcmp(section, "motor.left") && !strcmp(key, "gear_ratio")) snprintf(p->phys_gear, VAL_MAX, "%s", val);
    return 0;
}

/* a double as the shortest decimal that is the same float, a C float constant */
static void float_text(double d, char *out, size_t n)
{
    char buf[64];
    for (int prec = 1; prec <= 9; prec++) {
        snprintf(buf, sizeof buf, "%.*g", prec, d);
        if ((float)strtod(buf, NULL) == (float)d) break;
    }
    int e = strchr(buf, 'e') || strchr(buf, '.');
    snprintf(out, n, "%s%s%sf%s", d < 0 ? "(" : "", buf, e ? "" : ".0", d < 0 ? ")" : "");
}

static int num(const char *s, double *v)
{
    return *s && io_decimal(s, strlen(s), v) == 0;
}

/* a physics key's number as the robot reader takes it (2e-8 too) */
static int real(const char *s, double *v)
{
    char *end;
    *v = strtod(s, &end);
    return *s && end != s && *end == '\0' && isfinite(*v);
}

/* The C text of a key the physics gives (k->from): 0, 1 if the robot file
 * lacks what it needs, -1 with the reason in err for a number that is not. */
static int derived(const prof_t *p, const fw_key_t *k, char *out, size_t n, char *err, size_t errlen)
{
    double a, b = 1;
    const char *t = p->phys[k->from];
    if (!*t) return 1;
    if (!num(t, &a)) goto bad;
    if (k->from == FW_FROM_WHEELS) {
        if (!num(p->phys_right, &b)) goto bad;
        a = (a + b) / 2;
    }
    if (k->from == FW_FROM_COUNTS) {
        if (!num(p->phys_gear, &b)) goto bad;
        a *= b;
    }
    if (k->type == FW_INT) {
        if (a != floor(a) || fabs(a) > 1e9) goto bad;
        snprintf(out, n, a < 0 ? "(%.0f)" : "%.0f", a);
    } else {
        float_text(a, out, n);
    }
    return 0;
bad:
    snprintf(err, errlen, "%s: [%s] %s: not a number the firmware can take for %s", p->path, phys_keys[k->from].section,
             phys_keys[k->from].key, k->key);
    return -1;
}

/* C text of key i for image (0 all, 1 AVR): 0, or 2 with err */
static int value(const prof_t *p, size_t i, int avr, char *out, size_t n, char *err, size_t errlen)
{
    const fw_key_t *k = &fw_keys[i];
    const char *v = avr && *p->val[1][i] ? p->val[1][i] : p->val[0][i];
    if (*v) {
        if (fw_value_c(k, v, out, n) == 0) return 0;
        snprintf(err, errlen, "%s: firmware.%s: value too long", p->path, k->key);
        return 2;
    }
    int rc = k->from ? derived(p, k, out, n, err, errlen) : 1;
    if (rc < 0) return 2;
    if (rc > 0) {
        if (k->from)
            snprintf(err, errlen, "%s:%d: firmware.%s: missing key (and no [%s] %s to take it from)", p->path, p->line[0],
                     k->key, phys_keys[k->from].section, phys_keys[k->from].key);
        else
            snprintf(err, errlen, "%s:%d: firmware.%s: missing key", p->path, p->line[0], k->key);
        return 2;
    }
    return 0;
}

/* The feed-forward's three motor figures as the robot's own keys give them
 * (firmware/motion.c: a wheel's command is its speed / mm_s_per_cmd, plus
 * cmd_friction in the direction it turns, plus cmd_per_mm_s2 per mm/s^2 of
 * its acceleration), for a command step of step_v volts, each with how.
 * A [measured.*] section's fwd_km_mm_s_v and fwd_tm_s (the real robot's
 * characterisation) give the speed and acceleration terms where it has
 * them; [motor.left]'s datasheet figures the rest, as the physics'
 * datasheet model takes them (sim/world/motor.c motor_constants: R the
 * rated voltage over the stall current, N*Ke from the free-running speed
 * less the no-load current's drop, the H-bridge's driver_r_ohm in series;
 * each wheel pushes half the robot's mass and its own spin). 0, or 2 with
 * the reason in err. */
static int arc_figure(const prof_t *p, const double v[M_N], double step_v, double r, double kt_r, double *want, char *how,
                      char *err, size_t errlen);

static int motor_figures(const prof_t *p, double step_v, double want[4], char how[4][200], char *err, size_t errlen)
{
    double v[M_N], d_left, d_right;
    for (size_t i = 0; i < M_N; i++) {
        const char *t = *p->mot[i] ? p->mot[i] : mot_keys[i].def;
        v[i] = NAN;
        if (i == M_MODEL || (t && !*t)) continue; /* the model is a word; [measured.*] optional */
        if (t && real(t, &v[i]) && v[i] >= 0) continue;
        snprintf(err, errlen, "%s: firmware.mm_s_per_cmd, cmd_friction, cmd_per_mm_s2 are checked against [%s] %s: %s",
                 p->path, mot_keys[i].section, mot_keys[i].key, t ? "not a number >= 0" : "missing");
        return 2;
    }
    if (strcmp(p->mot[M_MODEL], "datasheet") != 0 || v[M_STALL_A] <= v[M_I0] || v[M_RATED_V] <= 0) {
        snprintf(err, errlen, "%s: firmware.mm_s_per_cmd, cmd_friction, cmd_per_mm_s2 are checked against a [motor.left] "
                 "of model datasheet with no_load_a below stall_a", p->path);
        return 2;
    }
    if (!real(p->phys[FW_FROM_WHEELS], &d_left) || !real(p->phys_right, &d_right)) {
        snprintf(err, errlen, "%s: firmware.cmd_per_mm_s2 is checked against [chassis] wheel_left_d_mm and "
                 "wheel_right_d_mm: missing or not a number", p->path);
        return 2;
    }
    double r_mm = (d_left + d_right) / 4, r = r_mm / 1000;       /* the mean wheel's radius, mm and m */
    double r_motor = v[M_RATED_V] / v[M_STALL_A], r_circuit = r_motor + v[M_DRIVER_R]; /* ohm */
    double n_ke = (v[M_RATED_V] - v[M_I0] * r_motor) / (v[M_RPM] * 2 * M_PI / 60); /* V*s/rad at the wheel */
    double n_eta_kt = v[M_STALL_T] / (v[M_STALL_A] - v[M_I0]);     /* N*m/A at the wheel */
    double wheel_kg = v[M_WHEEL] / 1000;
    double mass_kg = (v[M_BODY] + 2 * v[M_WHEEL] + v[M_CASTERS] * v[M_CASTER]) / 1000;
    double spin_kg = (v[M_ROTOR] * v[M_GEAR] * v[M_GEAR] + 0.5 * wheel_kg * r * r) / (r * r);
    want[1] = v[M_I0] * r_circuit / step_v;
    snprintf(how[1], sizeof how[1], "[motor.left] no_load_a x (rated_v / stall_a + driver_r_ohm) = %.4g V", v[M_I0] * r_circuit);
    int km = !isnan(v[M_KM]) && v[M_KM] > 0, tm = km && !isnan(v[M_TM]);
    want[0] = km ? v[M_KM] * step_v : step_v / n_ke * r_mm;
    want[2] = tm ? v[M_TM] / v[M_KM] / step_v : (mass_kg / 2 + spin_kg) * 0.001 * r / n_eta_kt * r_circuit / step_v;
    if (km)
        snprintf(how[0], sizeof how[0], "[%.40s] fwd_km_mm_s_v %g mm/s per V", p->measured, v[M_KM]);
    else
        snprintf(how[0], sizeof how[0], "[motor.left] no_load_rpm %g over rated_v less the no-load current's drop", v[M_RPM]);
    if (tm)
        snprintf(how[2], sizeof how[2], "[%.40s] fwd_tm_s %g s / fwd_km_mm_s_v %g", p->measured, v[M_TM], v[M_KM]);
    else
        snprintf(how[2], sizeof how[2], "half the %.4g kg robot and the wheel's spin %.4g kg through [motor.left]'s %.4g N*m/A, %.4g ohm",
                 mass_kg, spin_kg, n_eta_kt, r_circuit);
    /* the wheel's spin in the arc's figure too: kg per (m/s^2) at the rim */
    want[3] = spin_kg;
    return arc_figure(p, v, step_v, r, n_eta_kt / r_circuit, &want[3], how[3], err, errlen);
}

/* The yaw's feed-forward, command steps per mm/s^2 of each wheel's arc in a
 * spin (firmware/motion.c: a_arc x cmd_per_arc_mm_s2): a [measured.*]
 * section's rot_tm_s / (rot_km_deg_s_v as wheel arc on half the track);
 * else the chassis' yaw inertia about the axle's middle as the physics
 * builds it (sim/world/world.c chassis_mass: the body's own,
 * body_yaw_inertia_kgm2 or the box's, at its centre of mass, the skids
 * and the wheels as points) over 2 b^2, plus the wheel's spin (*want on
 * entry), through the motor as cmd_per_mm_s2. kt_r: N*m/A over ohm at the
 * wheel. 0, or 2 with the reason in err. */
static int arc_figure(const prof_t *p, const double v[M_N], double step_v, double r, double kt_r, double *want, char *how,
                      char *err, size_t errlen)
{
    double a[A_N];
    for (size_t i = 0; i < A_N; i++) {
        const char *t = *p->arc[i] ? p->arc[i] : arc_keys[i].def;
        a[i] = NAN;
        if (t && !*t) continue; /* [measured.*] optional */
        if (t && real(t, &a[i])) continue;
        snprintf(err, errlen, "%s: firmware.cmd_per_arc_mm_s2 is checked against [%s] %s: %s", p->path, arc_keys[i].section,
                 arc_keys[i].key, t ? "not a number" : "missing");
        return 2;
    }
    double b = a[A_TRACK] / 2000, spin_kg = *want; /* the half track, m */
    if (!isnan(a[A_ROT_KM]) && a[A_ROT_KM] > 0 && !isnan(a[A_ROT_TM])) {
        *want = a[A_ROT_TM] / (a[A_ROT_KM] * M_PI / 180 * b * 1000) / step_v;
        snprintf(how, 200, "[%.40s] rot_tm_s %g s / rot_km_deg_s_v %g as wheel arc on a %g mm half track", p->measured,
                 a[A_ROT_TM], a[A_ROT_KM], b * 1000);
        return 0;
    }
    double mb = v[M_BODY] / 1000, w = a[A_BODY_W] / 1000, l = a[A_BODY_L] / 1000, ay = a[A_AXLE_Y] / 1000;
    double j = a[A_YAW_J] > 0 ? a[A_YAW_J] : mb * (w * w + l * l) / 12, dy = a[A_COM_Y] / 1000 - ay;
    j += mb * dy * dy + 2 * v[M_WHEEL] / 1000 * b * b; /* kg*m^2 about the axle's middle */
    for (int k = 0; k < v[M_CASTERS] && k < 2; k++) {
        double cy = a[k ? A_CASTER2_Y : A_CASTER_Y] / 1000 - ay;
        j += v[M_CASTER] / 1000 * cy * cy;
    }
    *want = (j / (2 * b * b) + spin_kg) * 0.001 * r / kt_r / step_v;
    snprintf(how, 200, "the chassis' %.4g kg*m^2 about the axle over 2 x (%g mm)^2 and the wheel's spin %.4g kg through [motor.left]",
             j, b * 1000, spin_kg);
    return 0;
}

/* the line of key in [section] of path, 0 if none (the file parsed already) */
static int key_line(const char *path, const char *section, const char *key)
{
    FILE *f = fopen(path, "r");
    char buf[INIFILE_MAX_LINE + 3], sec[VAL_MAX] = "";
    int line = 0, found = 0;
    size_t n = strlen(key);
    while (f && !found && fgets(buf, sizeof buf, f)) {
        line++;
        if (buf[0] == '[') sscanf(buf, "[%199[^]]", sec);
        else if (!strcmp(sec, section) && !strncmp(buf, key, n) && strchr(" \t=:", buf[n])) found = line;
    }
    if (f) fclose(f);
    return found;
}

/* the figure of key (nominal want) in each section giving it against want:
 * within 0.5 % (the figures are written to 3-4 digits from the same keys,
 * rounding by less than 0.1 %; another gearbox, wheel or winding moves them
 * by several percent) or tol_abs; 0, or 2 with err at the key's line */
static int within(const prof_t *p, const char *key, double want, double tol_abs, const char *how, char *err, size_t errlen)
{
    const fw_key_t *k = fw_key_find(key);
    for (int s = 0; s < 2; s++) {
        const char *t = p->val[s][k - fw_keys];
        double got;
        if (!*t || !num(t, &got)) continue;
        double apart = fabs(got - want), tol = fmax(0.005 * fabs(want), tol_abs);
        if (apart <= tol) continue;
        const char *sec = s ? "firmware.avr" : "firmware";
        int line = key_line(p->path, sec, key);
        snprintf(err, errlen, "%s:%d: %s.%s = %s, the robot's keys give %.4g (%s): %.1f %% apart, more than %s", p->path,
                 line ? line : p->line[s], sec, key, t, want, how, 100 * apart / fabs(want),
                 tol > 0.005 * fabs(want) ? "half a command step" : "0.5 %");
        return 2;
    }
    return 0;
}

/* [firmware]'s feed-forward figures against the robot's motor keys, for
 * the command step cmd_max_v / cmd_max: 0, or 2 with err */
static int check_motor(const prof_t *p, char *err, size_t errlen)
{
    double full_v, cmd_max, want[4];
    char how[4][200];
    if (!num(p->val[0][fw_key_find("cmd_max_v") - fw_keys], &full_v) || !num(p->val[0][fw_key_find("cmd_max") - fw_keys], &cmd_max)
        || full_v <= 0 || cmd_max <= 0) {
        snprintf(err, errlen, "%s:%d: firmware.cmd_max_v, cmd_max: missing or not above 0 (the command step they make "
                 "checks mm_s_per_cmd, cmd_friction, cmd_per_mm_s2)", p->path, p->line[0]);
        return 2;
    }
    double step_v = full_v / cmd_max;
    if (motor_figures(p, step_v, want, how, err, errlen)) return 2;
    if (within(p, "mm_s_per_cmd", want[0], 0, how[0], err, errlen)) return 2;
    /* the friction within half a command step too: the files write it in whole steps */
    if (within(p, "cmd_friction", want[1], 0.5, how[1], err, errlen)) return 2;
    if (within(p, "cmd_per_mm_s2", want[2], 0, how[2], err, errlen)) return 2;
    return within(p, "cmd_per_arc_mm_s2", want[3], 0, how[3], err, errlen);
}

static void upper(const char *s, char *out, size_t n)
{
    size_t i = 0;
    for (; s[i] && i + 1 < n; i++) out[i] = (char)(s[i] >= 'a' && s[i] <= 'z' ? s[i] - 'a' + 'A' : s[i]);
    out[i] = '\0';
}

/* every key's #define into f: 0, or 2 with err */
static int write_profile(const prof_t *p, FILE *f, char *err, size_t errlen)
{
    fprintf(f, "/* robot_profile.h - generated by mkprofile from %s ([firmware], [firmware.avr]):\n"
               " * do not edit; change the robot file (docs/ROBOTS.md). */\n"
               "#ifndef ROBOT_PROFILE_H\n#define ROBOT_PROFILE_H\n\n",
            p->path);
    for (size_t i = 0; i < fw_nkeys; i++) {
        char name[64], all[VAL_MAX + 64], avr[VAL_MAX + 64];
        upper(fw_keys[i].key, name, sizeof name);
        if (value(p, i, 0, all, sizeof all, err, errlen) || value(p, i, 1, avr, sizeof avr, err, errlen)) return 2;
        if (!strcmp(all, avr))
            fprintf(f, "#define RC_%s %s\n", name, all);
        else
            fprintf(f, "#ifdef __AVR__\n#define RC_%s %s\n#else\n#define RC_%s %s\n#endif\n", name, avr, name, all);
    }
    fprintf(f, "\n#endif\n");
    return 0;
}

int main(int argc, char **argv)
{
    if (argc != 3) {
        fprintf(stderr, "usage: mkprofile ROBOT.ini OUT.h\n");
        return EXIT_BAD_INPUT;
    }
    static prof_t p;
    char err[INIFILE_ERR_MAX];
    if (fw_nkeys > FW_MAX) return EXIT_EXTERNAL; /* FW_MAX below the table's size */
    p.path = argv[1];
    const inifile_t r = { on_section, on_key, &p, "want key = value or [section]" };
    if (inifile_load(&r, argv[1], ROBOT_MAX_BYTES, err, sizeof err) != 0) {
        fprintf(stderr, "%s\n", err);
        return EXIT_BAD_INPUT;
    }
    if (!p.line[0]) {
        fprintf(stderr, "%s: no [firmware] section (the firmware's profile: docs/ROBOTS.md)\n", argv[1]);
        return EXIT_BAD_INPUT;
    }
    if (check_motor(&p, err, sizeof err) != 0) {
        fprintf(stderr, "%s\n", err);
        return EXIT_BAD_INPUT;
    }
    outfile_t o;
    if (outfile_open(&o, argv[2], err, sizeof err) != 0) {
        fprintf(stderr, "mkprofile: %s\n", err);
        return EXIT_EXTERNAL;
    }
    if (write_profile(&p, o.f, err, sizeof err) != 0) {
        outfile_abort(&o);
        fprintf(stderr, "%s\n", err);
        return EXIT_BAD_INPUT;
    }
    if (outfile_commit(&o, err, sizeof err) != 0) {
        fprintf(stderr, "mkprofile: %s\n", err);
        return EXIT_EXTERNAL;
    }
    return EXIT_OK;
}

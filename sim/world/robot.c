/* robot.c - the robot file: components, their schemas, loading through
 * the INI reader (inifile.h), checks and printing (see robot.h). */
#include "robot.h"

#include <ctype.h>
#include <stdarg.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "fwprofile.h"
#include "inifile.h"
#include "keytab.h"
#include "world.h"
#include "world/sensors/sensor.h"
#include "world/sensors/tof.h"

extern const char robot_paper_ini[]; /* robots/paper.ini, built in (Makefile) */

static const char *const motor_models[] = { "paper", "datasheet" };
static const char *const starts[] = { "centre", "back_to_wall" };

/* ---- the schemas of the robot's fixed parts ---- */

#define C(name, field, per, min, max, unit, src) \
    { NULL, #name, offsetof(simcfg_robot_t, field), KEYTAB_REQUIRED, min, max, unit, src, NULL, 0, per, 0, KEYTAB_DOUBLE, 0, NULL }
static const keytab_t chassis_keys[] = {
    C(body_w_mm, body_w_m, 1000, 10, 300, "mm", "the body's width"),
    C(body_l_mm, body_l_m, 1000, 10, 300, "mm", "the body's length"),
    C(body_h_mm, body_h_m, 1000, 2, 100, "mm", "the body's height (sensors sit within it)"),
    C(body_mass_g, body_mass_kg, 1000, 1, 2000, "g", "the body's mass, without wheels and caster"),
    C(body_clearance_mm, body_clearance_m, 1000, 0.5, 50, "mm", "floor to the body's underside"),
    C(wheel_track_mm, wheel_x_m, 2000, 10, 300, "mm", "tyre centre to tyre centre"),
    C(wheel_left_d_mm, wheel_left_d_m, 1000, 5, 100, "mm", "left tyre's diameter"),
    C(wheel_right_d_mm, wheel_right_d_m, 1000, 5, 100, "mm", "right tyre's diameter"),
    C(wheel_w_mm, wheel_w_m, 1000, 1, 50, "mm", "tyre width"),
    C(wheel_mass_g, wheel_mass_kg, 1000, 0.5, 500, "g", "one wheel with its tyre"),
    C(axle_y_mm, axle_y_m, 1000, -100, 100, "mm", "the axle ahead of the body's centre"),
    C(caster_r_mm, caster_r_m, 1000, 1, 50, "mm", "caster sphere's radius"),
    C(caster_mass_g, caster_mass_kg, 1000, 0.5, 500, "g", "caster's mass"),
    C(caster_y_mm, caster_y_m, 1000, -200, 200, "mm", "caster ahead of the body's centre (negative: behind)"),
    { NULL, "casters", offsetof(simcfg_robot_t, casters), 1, 1, 2, "1", "1, or 2: a second skid at caster2_y_mm, as the first",
      NULL, 0, 0, 0, KEYTAB_INT, 0, NULL },
    { NULL, "caster2_y_mm", offsetof(simcfg_robot_t, caster2_y_m), 0, -200, 200, "mm", "the second skid ahead of the body's centre",
      NULL, 0, 1000, 0, KEYTAB_DOUBLE, 0, NULL },
    { NULL, "skid_mu", offsetof(simcfg_robot_t, skid_mu), 0, 0, 3, "1",
      "Coulomb friction, caster (skid) sliding on the floor; 0 = frictionless", NULL, 0, 0, 0, KEYTAB_DOUBLE, 0, NULL },
    C(tyre_mu, tyre_mu, 0, 0.01, 3, "1", "Coulomb friction, tyre on floor"),
    C(tyre_mu_dynamic, tyre_mu_dynamic, 0, 0.01, 3, "1", "sliding friction, <= tyre_mu"),
    C(tyre_slip_m_s, tyre_slip_m_s, 0, 0, 1, "m/s", "slip speed above which tyre_mu_dynamic applies"),
    { NULL, "start", offsetof(simcfg_robot_t, start), 0, 0, 1, "word",
      "centre: in the start cell's centre; back_to_wall: its rear against the cell's back wall (UKMARSBOT)", starts, 0, 0, 0, KEYTAB_INT, 0, NULL },
    { NULL, "body_com_y_mm", offsetof(simcfg_robot_t, body_com_y_m), 0, -100, 100, "mm",
      "the body's centre of mass ahead of its centre (0 = at the box's centre)", NULL, 0, 1000, 0, KEYTAB_DOUBLE, 0, NULL },
    { NULL, "body_drag_n_s_m", offsetof(simcfg_robot_t, body_drag_n_s_m), 0, 0, 10, "N*s/m",
      "a load against the robot's translation (the axle midpoint's horizontal velocity), none in a spin in place; 0 = none",
      NULL, 0, 0, 0, KEYTAB_DOUBLE, 0, NULL },
    { NULL, "body_yaw_inertia_kgm2", offsetof(simcfg_robot_t, body_yaw_inertia_kgm2), 0, 0, 0.1, "kg*m^2",
      "the body's own about its vertical axis through its centre; 0 = a uniform box's", NULL, 0, 0, 0, KEYTAB_DOUBLE, 0, NULL },
};

#define D(name, def, min, max, unit, src) \
    { NULL, #name, offsetof(drive_spec_t, name), def, min, max, unit, src, NULL, 0, 0, 0, KEYTAB_DOUBLE, 0, NULL }
static const keytab_t motor_keys[] = {
    { NULL, "model", offsetof(drive_spec_t, motor_model), KEYTAB_REQUIRED, 0, 1, "word",
      "datasheet: losses and rotor inertia; paper: the paper's eq. 1-5", motor_models, 0, 0, 0, KEYTAB_INT, 0, NULL },
    D(rated_v, KEYTAB_REQUIRED, 0.5, 50, "V", "the datasheet's figures below are at this voltage"),
    D(no_load_rpm, KEYTAB_REQUIRED, 1, 100000, "rpm", "output shaft, at rated_v"),
    D(no_load_a, KEYTAB_REQUIRED, 0, 10, "A", "at rated_v"),
    D(stall_torque_nm, KEYTAB_REQUIRED, 1e-5, 10, "N*m", "output shaft, at rated_v"),
    D(stall_a, KEYTAB_REQUIRED, 0.001, 100, "A", "at rated_v"),
    D(l_h, KEYTAB_REQUIRED, 1e-7, 1, "H", "armature inductance"),
    D(gear_ratio, KEYTAB_REQUIRED, 1, 1000, "1", "motor turns per wheel turn"),
    D(rotor_inertia_kgm2, 0, 0, 1e-3, "kg*m^2", "at the motor shaft (x N^2 at the wheel); 0 = ignored"),
    D(driver_r_ohm, 0, 0, 100, "ohm", "the H-bridge's on-resistance, in series with the motor"),
    D(friction_load_a, 0, 0, 10, "A", "the friction's rise under load, in amperes of motor current (motor.h); 0 = constant"),
};
static const keytab_t encoder_keys[] = {
    D(encoder_ppr, KEYTAB_REQUIRED, 1, 100000, "counts/motor rev", "counts per motor-shaft turn, every edge counted"),
    { NULL, "channels", offsetof(drive_spec_t, encoder_channels), 2, 1, 2, "1", "1: pulses only; 2: quadrature (direction)", NULL, 0, 0, 0, KEYTAB_INT, 0, NULL },
};
#define BT(name, def, min, max, unit, src) \
    { NULL, #name, offsetof(battery_spec_t, name), def, min, max, unit, src, NULL, 0, 0, 0, KEYTAB_DOUBLE, 0, NULL }
static const keytab_t battery_keys[] = {
    { NULL, "ocv_v", offsetof(battery_spec_t, ocv_v), KEYTAB_REQUIRED, 0.5, 60, "V",
      "open-circuit voltage, empty to full in even steps of charge (one value: constant)", NULL, 0, 0, BATTERY_OCV_MAX, KEYTAB_DOUBLE,
      offsetof(battery_spec_t, ocv_n), NULL },
    BT(r_ohm, KEYTAB_REQUIRED, 0, 100, "ohm", "internal resistance"),
    BT(capacity_mah, KEYTAB_REQUIRED, 1, 1e6, "mAh", "capacity"),
    BT(divider, 1, 0.01, 1, "1", "what the robot's ADC sees of the battery voltage"),
};
#define M(name, unit, src) \
    { NULL, #name, offsetof(robot_measured_t, name), -1, -1, 1e6, unit, src, NULL, 0, 0, 0, KEYTAB_DOUBLE, 0, NULL }
static const keytab_t measured_keys[] = {
    M(fwd_km_mm_s_v, "mm/s/V", "forward: slope of steady speed against motor voltage"),
    M(fwd_tm_s, "s", "forward: time constant of a voltage step"),
    M(rot_km_deg_s_v, "deg/s/V", "rotation: slope of steady spin rate against motor voltage (+V/-V)"),
    M(rot_tm_s, "s", "rotation: time constant of a voltage step"),
    M(counts_500mm_left, "counts", "left encoder over 500 mm of straight travel"),
    M(counts_500mm_right, "counts", "right encoder over 500 mm of straight travel"),
};
#define P(name, field, def, min, max, per, unit, src) \
    { NULL, #name, offsetof(robot_part_t, field), def, min, max, unit, src, NULL, 0, per, 0, KEYTAB_DOUBLE, 0, NULL }
static const keytab_t pose_keys[] = {
    P(x_mm, x_m, KEYTAB_REQUIRED, -200, 200, 1000, "mm", "to the right of the body's centre"),
    P(y_mm, y_m, KEYTAB_REQUIRED, -200, 200, 1000, "mm", "ahead of the body's centre"),
    P(z_mm, z_m, KEYTAB_REQUIRED, 0, 200, 1000, "mm", "above the floor"),
    P(yaw_deg, yaw_deg, KEYTAB_REQUIRED, -180, 180, 0, "deg", "counter-clockwise from straight ahead"),
    P(pitch_deg, pitch_deg, 0, -90, 90, 0, "deg", "up from level"),
};
#define N(t) (sizeof t / sizeof t[0])

/* ---- the file's sections ---- */

#define MAX_SECTIONS (ROBOT_MAX_PARTS + 8)
#define MAX_KEYS 64 /* keys of one schema (masks) */

typedef struct {
    char kind[16], name[ROBOT_NAME_MAX];
    int line;
    const sensor_kind_t *sensor; /* a sensor's kind, NULL for the fixed parts */
    const keytab_t *keys[2];     /* pose keys (sensors), the kind's */
    size_t nkeys[2];
    void *target[2];
    uint64_t seen[2];
} sect_t;

typedef struct {
    simcfg_t *c;
    simcfg_t work; /* the robot being loaded: c changes only if the whole file is good */
    const char *name;
    sect_t s[MAX_SECTIONS];
    int n;
    char reason[240];
    int err_line;         /* the line of a section's or a check's error, 0: none */
} load_t;

static int side_of(const char *name) { return !strcmp(name, "left") ? 0 : !strcmp(name, "right") ? 1 : -1; }

/* The load's error: its line (0: none) and reason; returns -1. */
static int fail(load_t *l, int line, const char *fmt, ...) __attribute__((format(printf, 3, 4)));
static int fail(load_t *l, int line, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    l->err_line = line;
    vsnprintf(l->reason, sizeof l->reason, fmt, ap);
    va_end(ap);
    return -1;
}

/* The section [kind.name] at line: its schema and where it writes. */
static int add_section(load_t *l, const char *kind, const char *name, int line)
{
    simcfg_t *c = l->c;
    sect_t *s = &l->s[l->n];
    memset(s, 0, sizeof *s);
    snprintf(s->kind, sizeof s->kind, "%s", kind);
    snprintf(s->name, sizeof s->name, "%.15s", name); /* checked: at most 15 */
    s->line = line;
    int side = side_of(name);
    if (!strcmp(kind, "chassis")) {
        s->keys[1] = chassis_keys, s->nkeys[1] = N(chassis_keys), s->target[1] = &c->robot;
        snprintf(c->robot.chassis_name, sizeof c->robot.chassis_name, "%.15s", name); /* checked: at most 15 */
    } else if (!strcmp(kind, "motor") || !strcmp(kind, "encoder")) {
        if (side < 0) return fail(l, line, "%s.%s: the %s is named left or right", kind, name, kind);
        int motor = !strcmp(kind, "motor");
        s->keys[1] = motor ? motor_keys : encoder_keys, s->nkeys[1] = motor ? N(motor_keys) : N(encoder_keys);
        s->target[1] = &c->robot.drive[side];
    } else if (!strcmp(kind, "measured")) {
        s->keys[1] = measured_keys, s->nkeys[1] = N(measured_keys), s->target[1] = &c->robot.measured;
        snprintf(c->robot.measured_name, sizeof c->robot.measured_name, "%.15s", name); /* checked: at most 15 */
    } else if (!strcmp(kind, "battery")) {
        s->keys[1] = battery_keys, s->nkeys[1] = N(battery_keys), s->target[1] = &c->robot.battery;
        snprintf(c->robot.battery_name, sizeof c->robot.battery_name, "%.15s", name); /* checked: at most 15 */
    } else {
        const sensor_kind_t *k = sensor_kind(kind);
        if (!k) return fail(l, line, "%s.%s: unknown kind (chassis motor encoder battery measured tof ir gyro)", kind, name);
        if (c->robot.nparts == ROBOT_MAX_PARTS) return fail(l, line, "%s.%s: more than 16 sensors", kind, name);
        robot_part_t *p = &c->robot.part[c->robot.nparts++];
        memset(p, 0, sizeof *p);
        p->kind = k;
        p->line = line;
        snprintf(p->name, sizeof p->name, "%.15s", name); /* checked: at most 15 */
        s->sensor = k;
        s->keys[0] = pose_keys, s->nkeys[0] = N(pose_keys), s->target[0] = p;
        s->keys[1] = k->keys, s->nkeys[1] = k->nkeys, s->target[1] = p->spec;
    }
    for (int i = 0; i < 2; i++)
        if (s->keys[i]) keytab_defaults(s->keys[i], s->nkeys[i], s->target[i]);
    l->n++;
    return 0;
}

static int name_ok(const char *s)
{
    if (!*s) return 0;
    for (; *s; s++)
        if (!isalnum((unsigned char)*s) && *s != '_' && *s != '-') return 0;
    return 1;
}

/* One [section] line (the text between the brackets): the component it
 * starts, checked. */
static int header(load_t *l, const char *sec, int line)
{
    char kind[16], name[64];
    if (strlen(sec) >= 64) return fail(l, line, "[%.40s...]: section name too long", sec);
    const char *dot = strchr(sec, '.');
    if (!dot || (size_t)(dot - sec) >= sizeof kind)
        return fail(l, line, "[%s]: want [KIND.NAME], e.g. [ir.left_front]", sec);
    memcpy(kind, sec, (size_t)(dot - sec));
    kind[dot - sec] = '\0';
    snprintf(name, sizeof name, "%s", dot + 1);
    if (!name_ok(name) || strlen(name) >= ROBOT_NAME_MAX)
        return fail(l, line, "[%s]: a name is 1 to 15 letters, digits, _ or -", sec);
    int fixed = !strcmp(kind, "chassis") || !strcmp(kind, "motor") || !strcmp(kind, "encoder") || !strcmp(kind, "battery") ||
                !strcmp(kind, "measured");
    for (int i = 0; i < l->n; i++) {
        int both_sensors = !fixed && l->s[i].sensor;
        if (!strcmp(l->s[i].kind, kind) && !strcmp(l->s[i].name, name))
            return fail(l, line, "%s.%s: a second [%s] (two components with one name)", kind, name, sec);
        if (both_sensors && !strcmp(l->s[i].name, name))
            return fail(l, line, "%s.%s: two sensors with one name (%s is taken)", kind, name, l->s[i].kind);
        if (fixed && strcmp(kind, "motor") && strcmp(kind, "encoder") && !strcmp(l->s[i].kind, kind))
            return fail(l, line, "%s.%s: a robot has one %s", kind, name, kind);
    }
    if (l->n == MAX_SECTIONS) return fail(l, line, "%s.%s: too many sections", kind, name);
    return add_section(l, kind, name, line);
}

/* The reader's section callback: every [section] before any key. */
static int on_section(void *user, const char *section, int line, char *why, size_t len)
{
    load_t *l = user;
    if (fw_section(section)) return 0; /* the firmware's profile: its keys checked in on_key */
    if (header(l, section, line) == 0) return 0;
    snprintf(why, len, "%s", l->reason);
    return -1;
}

static sect_t *find(load_t *l, const char *section)
{
    for (int i = 0; i < l->n; i++) {
        char full[40];
        snprintf(full, sizeof full, "%s.%s", l->s[i].kind, l->s[i].name);
        if (!strcmp(full, section)) return &l->s[i];
    }
    return NULL;
}

static int on_key(void *user, const char *section, const char *key, const char *val, char *why, size_t len)
{
    load_t *l = user;
    if (fw_section(section)) {
        const fw_key_t *k = fw_key_find(key);
        if (k) return fw_value_check(k, section, val, why, len);
        snprintf(why, len, "%s.%s: unknown key (the firmware's keys: docs/ROBOTS.md)", section, key);
        return -1;
    }
    sect_t *s = find(l, section);
    if (!s) {
        snprintf(why, len, "%s: a key outside any [KIND.NAME] section", key);
        return -1;
    }
    for (int t = 0; t < 2; t++) {
        if (!s->keys[t]) continue;
        const keytab_t *k = keytab_find(s->keys[t], s->nkeys[t], NULL, key);
        if (!k) continue;
        if (keytab_set(k, s->target[t], section, val, why, len) != 0) return -1;
        s->seen[t] |= 1ull << (k - s->keys[t]);
        return 0;
    }
    int n = snprintf(why, len, "%s.%s: unknown key (a %s has:", section, key, s->kind);
    for (int t = 0; t < 2; t++)
        for (size_t i = 0; s->keys[t] && i < s->nkeys[t] && n > 0 && (size_t)n < len; i++)
            n += snprintf(why + n, len - (size_t)n, " %s", s->keys[t][i].key);
    if (n > 0 && (size_t)n < len) snprintf(why + n, len - (size_t)n, ")");
    return -1;
}

/* ---- checks after parsing ---- */

static int missing_keys(load_t *l)
{
    for (int i = 0; i < l->n; i++) {
        sect_t *s = &l->s[i];
        for (int t = 0; t < 2; t++) {
            const keytab_t *k = s->keys[t] ? keytab_missing(s->keys[t], s->nkeys[t], s->seen[t]) : NULL;
            if (k) return fail(l, s->line, "%s.%s.%s: missing key", s->kind, s->name, k->key);
        }
    }
    return 0;
}

static int has(load_t *l, const char *kind, const char *name)
{
    for (int i = 0; i < l->n; i++)
        if (!strcmp(l->s[i].kind, kind) && (!name || !strcmp(l->s[i].name, name))) return 1;
    return 0;
}

static int required_parts(load_t *l)
{
    static const char *const need[][2] = { { "chassis", NULL }, { "motor", "left" }, { "motor", "right" },
                                           { "encoder", "left" }, { "encoder", "right" }, { "battery", NULL } };
    for (size_t i = 0; i < N(need); i++)
        if (!has(l, need[i][0], need[i][1]))
            return fail(l, 0, "no [%s.%s] section: a robot has a chassis, motor and encoder left and right, and a battery",
                        need[i][0], need[i][1] ? need[i][1] : "NAME");
    if (robot_count(l->c, "tof") > WORLD_TOF_COUNT)
        return fail(l, 0, "more than %d tof sensors (the HAL has left, front, right)", WORLD_TOF_COUNT);
    if (robot_count(l->c, "ir") > ROBOT_MAX_IR) return fail(l, 0, "more than 8 ir sensors (hal.h HAL_IR_MAX)");
    return 0;
}

/* Keys a sensor's section left to another of its keys (a ToF's ranging
 * profile sets its period, range and noise unless the file gives them). */
static int complete_parts(load_t *l)
{
    for (int i = 0; i < l->n; i++)
        if (l->s[i].sensor) tof_complete(l->s[i].target[0], l->s[i].seen[1]);
    return 0;
}

static int part_checks(load_t *l)
{
    const simcfg_t *c = l->c;
    double top = c->robot.body_clearance_m + c->robot.body_h_m;
    for (int i = 0; i < c->robot.nparts; i++) {
        const robot_part_t *p = &c->robot.part[i];
        const char *k = p->kind->name, *key = NULL;
        if (fabs(p->x_m) > c->robot.body_w_m / 2) key = "x_mm";
        else if (fabs(p->y_m) > c->robot.body_l_m / 2) key = "y_mm";
        else if (p->z_m > top) key = "z_mm";
        if (key)
            return fail(l, p->line, "%s.%s.%s: pose outside the chassis (body %g x %g mm, %g mm high above the floor)", k,
                        p->name, key, c->robot.body_w_m * 1000, c->robot.body_l_m * 1000, top * 1000);
        char why[160];
        if (p->kind->check && p->kind->check(p, why, sizeof why) != 0)
            return fail(l, p->line, "%s.%s.%s", k, p->name, why);
    }
    return 0;
}

static int physics_checks(load_t *l)
{
    simcfg_t *c = l->c;
    if (c->robot.tyre_mu_dynamic > c->robot.tyre_mu)
        return fail(l, 0, "chassis.%s.tyre_mu_dynamic: %g is above tyre_mu %g", c->robot.chassis_name, c->robot.tyre_mu_dynamic,
                    c->robot.tyre_mu);
    for (int s = 0; s < 2; s++)
        if (c->robot.drive[s].no_load_a >= c->robot.drive[s].stall_a)
            return fail(l, 0, "motor.%s.no_load_a: not below stall_a", s ? "right" : "left");
        else if (c->robot.drive[s].no_load_a + c->robot.drive[s].friction_load_a >= c->robot.drive[s].stall_a)
            return fail(l, 0, "motor.%s.friction_load_a: no_load_a + friction_load_a not below stall_a", s ? "right" : "left");
    return 0;
}

int robot_fits(const simcfg_t *c, char *reason, size_t len)
{
    double wide = 2 * c->robot.wheel_x_m + c->robot.wheel_w_m, corridor = c->world.cell_m - c->world.wall_thick_m;
    if (wide < corridor) return 0;
    snprintf(reason, len, "world.cell_m: the robot is wider than a corridor (%g mm over its tyres, the corridor %g mm)",
             wide * 1000, corridor * 1000);
    return -1;
}

/* ---- loading ---- */

/* The robot from text (NULL: the file at name) into c; c changes only if
 * the whole file is good. */
static int load(simcfg_t *c, const char *text, const char *name, char *err, size_t errlen)
{
    load_t *l = calloc(1, sizeof *l);
    if (!l) {
        snprintf(err, errlen, "%s: out of memory", name);
        return -1;
    }
    l->work = *c;
    l->work.robot.nparts = 0;
    l->work.robot.measured_name[0] = '\0';
    keytab_defaults(measured_keys, N(measured_keys), &l->work.robot.measured);
    l->c = &l->work;
    l->name = name;
    const inifile_t r = { on_section, on_key, l, "want key = value or [KIND.NAME]" };
    int rc = text ? inifile_parse(&r, text, strlen(text), name, err, errlen) : inifile_load(&r, name, ROBOT_MAX_BYTES, err, errlen);
    if (rc == 0 && missing_keys(l) == 0 && required_parts(l) == 0 && complete_parts(l) == 0 && part_checks(l) == 0 &&
        physics_checks(l) == 0) {
        snprintf(l->work.robot.path, sizeof l->work.robot.path, "%s", name);
        *c = l->work;
    } else if (rc == 0) {
        if (l->err_line > 0) snprintf(err, errlen, "%s:%d: %s", name, l->err_line, l->reason);
        else snprintf(err, errlen, "%s: %s", name, l->reason);
        rc = -1;
    }
    free(l);
    return rc;
}

int robot_load(simcfg_t *c, const char *path, char *err, size_t errlen) { return load(c, NULL, path, err, errlen); }

int robot_load_string(simcfg_t *c, const char *text, const char *name, char *err, size_t errlen)
{
    return load(c, text, name, err, errlen);
}

void robot_defaults(simcfg_t *c)
{
    char err[300];
    if (robot_load_string(c, robot_paper_ini, "robots/paper.ini", err, sizeof err) != 0) {
        fprintf(stderr, "built-in robot: %s\n", err);
        abort();
    }
}

/* ---- printing and queries ---- */

static void print_keys(const keytab_t *k, size_t n, const void *target, FILE *out)
{
    for (size_t i = 0; i < n; i++) keytab_print(&k[i], target, out);
}

void robot_print(const simcfg_t *c, FILE *out)
{
    static const char *const sides[2] = { "left", "right" };
    fprintf(out, "; robot: %s\n[chassis.%s]\n", c->robot.path, c->robot.chassis_name);
    print_keys(chassis_keys, N(chassis_keys), &c->robot, out);
    for (int s = 0; s < 2; s++) {
        fprintf(out, "\n[motor.%s]\n", sides[s]);
        print_keys(motor_keys, N(motor_keys), &c->robot.drive[s], out);
        fprintf(out, "\n[encoder.%s]\n", sides[s]);
        print_keys(encoder_keys, N(encoder_keys), &c->robot.drive[s], out);
    }
    fprintf(out, "\n[battery.%s]\n", c->robot.battery_name);
    print_keys(battery_keys, N(battery_keys), &c->robot.battery, out);
    if (c->robot.measured_name[0]) {
        fprintf(out, "\n[measured.%s]\n", c->robot.measured_name);
        print_keys(measured_keys, N(measured_keys), &c->robot.measured, out);
    }
    for (int i = 0; i < c->robot.nparts; i++) {
        const robot_part_t *p = &c->robot.part[i];
        fprintf(out, "\n[%s.%s]\n", p->kind->name, p->name);
        print_keys(pose_keys, N(pose_keys), p, out);
        print_keys(p->kind->keys, p->kind->nkeys, p->spec, out);
    }
}

int robot_section(const char *section)
{
    static const char *const old[] = { "robot", "motor", "drivetrain", "encoder", "tof", "chassis", "battery", "measured" };
    char kind[32];
    snprintf(kind, sizeof kind, "%s", section);
    char *dot = strchr(kind, '.');
    if (dot) *dot = '\0';
    for (size_t i = 0; i < N(old); i++)
        if (!strcmp(kind, old[i])) return 1;
    return sensor_kind(kind) != NULL;
}

int robot_part_of_kind(const simcfg_t *c, const char *kind, unsigned i)
{
    for (int k = 0; k < c->robot.nparts; k++)
        if (!strcmp(c->robot.part[k].kind->name, kind) && i-- == 0) return k;
    return -1;
}

unsigned robot_count(const simcfg_t *c, const char *kind)
{
    unsigned n = 0;
    for (int k = 0; k < c->robot.nparts; k++) n += !strcmp(c->robot.part[k].kind->name, kind);
    return n;
}

double robot_tof_range_m(const simcfg_t *c)
{
    int k = robot_part_of_kind(c, "tof", 0);
    return k < 0 ? 1.2 : ((const tof_spec_t *)c->robot.part[k].spec)->range_m;
}

/* ---- the key list (tests) ---- */

/* The i-th key of the list robot.h describes, and its kind; NULL past the end. */
static const keytab_t *key_at(size_t i, const char **kind)
{
    static const struct {
        const char *kind;
        const keytab_t *keys;
        size_t n;
    } fixed[] = { { "chassis", chassis_keys, N(chassis_keys) },
                  { "motor", motor_keys, N(motor_keys) },
                  { "encoder", encoder_keys, N(encoder_keys) },
                  { "battery", battery_keys, N(battery_keys) } };
    for (size_t f = 0; f < N(fixed); f++) {
        if (i < fixed[f].n) {
            *kind = fixed[f].kind;
            return &fixed[f].keys[i];
        }
        i -= fixed[f].n;
    }
    const sensor_kind_t *k;
    for (unsigned s = 0; (k = sensor_kind_at(s)) != NULL; s++) {
        *kind = k->name;
        if (i < N(pose_keys)) return &pose_keys[i];
        i -= N(pose_keys);
        if (i < k->nkeys) return &k->keys[i];
        i -= k->nkeys;
    }
    return NULL;
}

size_t robot_key_count(void)
{
    size_t n = 0;
    const char *kind;
    while (key_at(n, &kind)) n++;
    return n;
}

int robot_key_info(size_t i, const char **kind, const char **key, double *min, double *max)
{
    const char *k_kind;
    const keytab_t *k = key_at(i, &k_kind);
    if (!k) return -1;
    *kind = k_kind;
    *key = k->key;
    *min = k->min;
    *max = k->max;
    return 0;
}

const char *robot_key_word(size_t i, double v)
{
    const char *kind;
    const keytab_t *k = key_at(i, &kind);
    if (!k || !k->choices || v < 0 || v > k->max) return NULL;
    return k->choices[(int)v];
}

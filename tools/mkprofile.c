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

typedef struct {
    const char *path;
    char val[2][FW_MAX][VAL_MAX]; /* [0] [firmware], [1] [firmware.avr]; "" none */
    int line[2];                  /* of the sections, 0: none */
    char phys[N(phys_keys)][VAL_MAX], phys_right[VAL_MAX], phys_gear[VAL_MAX];
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

static int on_key(void *user, const char *section, const char *key, const char *val, char *why, size_t len)
{
    prof_t *p = user;
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
        if (!strcmp(key, phys_keys[i].key) && (strchr(phys_keys[i].section, '.') ? !strcmp(section, phys_keys[i].section)
                                                                                  : kind_is(section, phys_keys[i].section)))
            snprintf(p->phys[i], VAL_MAX, "%s", val);
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

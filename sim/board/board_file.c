/* board_file.c - the board file (board.h's board_spec_t): INI, one section
 * per part, read through the INI reader (world/inifile.h) with its keys in
 * keytab tables (world/keytab.h). Every key is required; a bad value is
 * "FILE:LINE: section.key: reason", a missing key "FILE:LINE: section.key:
 * missing" (the section's line), or "FILE: section.key: missing (no
 * [section] section)". A board file may
 * name its mainboard's parts file ([board] mainboard = parts/NAME.ini, from
 * the board file's folder): the parts one mainboard has whatever sensor
 * board is on it (motors, encoders, switches, battery, A4/A5), read after
 * the board file; each key is given in one of the two files only, so a
 * mainboard's figure has one place. */
#include "board.h"

#include <ctype.h>
#include <dirent.h>
#include <stdarg.h>
#include <stdlib.h>
#include <string.h>

#include "world/inifile.h"
#include "world/inisec.h"
#include "world/keytab.h"
#include "world/robot.h"
#include "world/sensors/ir.h"
#include "io/datadir.h"

/* "D7", "A0" (Arduino Nano names) or "PB1" into a board_pin_t */
static int parse_pin(const char *v, void *field, char *why, size_t len)
{
    board_pin_t *p = field;
    char *end;
    if ((v[0] == 'D' || v[0] == 'A') && isdigit((unsigned char)v[1])) {
        long n = strtol(v + 1, &end, 10);
        if (*end) n = -1;
        if (v[0] == 'A' && n >= 0 && n <= 5) { /* A6/A7 are analogue inputs only */
            *p = (board_pin_t){ 'C', (uint8_t)n };
            return 0;
        }
        if (v[0] == 'D' && n >= 0 && n <= 7) {
            *p = (board_pin_t){ 'D', (uint8_t)n };
            return 0;
        }
        if (v[0] == 'D' && n >= 8 && n <= 13) {
            *p = (board_pin_t){ 'B', (uint8_t)(n - 8) };
            return 0;
        }
    } else if (v[0] == 'P' && (v[1] == 'B' || v[1] == 'C' || v[1] == 'D') && v[2] >= '0' && v[2] <= '7' && !v[3]) {
        *p = (board_pin_t){ v[1], (uint8_t)(v[2] - '0') };
        return 0;
    }
    snprintf(why, len, "expected a pin D0-D13, A0-A5 or PB0-PD7, got '%s'", v);
    return -1;
}

/* "open" or a voltage in V (0..vcc_v, checked with the rest) into a board_analog_t */
static int parse_analog(const char *v, void *field, char *why, size_t len)
{
    board_analog_t *a = field;
    char *end;
    if (!strcmp(v, "open")) {
        *a = (board_analog_t){ 0, 0.0 };
        return 0;
    }
    double x = strtod(v, &end);
    if (end == v || *end || !(x >= 0 && x <= 5.5)) {
        snprintf(why, len, "expected 'open' or a voltage 0-5.5 V, got '%s'", v);
        return -1;
    }
    *a = (board_analog_t){ 1, x };
    return 0;
}

static const char *const leads[] = { "b_leads", "a_leads" }; /* the index is enc_a_leads */

#define OFF(f) offsetof(board_spec_t, f)
#define TEXT(sec, key, f, src) \
    { sec, key, OFF(f), KEYTAB_REQUIRED, 0, 0, "text", src, NULL, 0, 0, 0, KEYTAB_TEXT, sizeof ((board_spec_t *)0)->f, NULL }
#define NUM(sec, key, type, f, min, max, unit, src) \
    { sec, key, OFF(f), KEYTAB_REQUIRED, min, max, unit, src, NULL, 0, 0, 0, type, 0, NULL }
#define PIN(sec, key, f, src) \
    { sec, key, OFF(f), KEYTAB_REQUIRED, 0, 0, "pin", src, NULL, 0, 0, 0, KEYTAB_PARSED, sizeof(board_pin_t), parse_pin }
#define LEADS(sec, f) \
    { sec, "forward", OFF(f), KEYTAB_REQUIRED, 0, 1, "word", "which channel leads when the wheel turns forward", leads, 1, 0, 0, KEYTAB_INT, 0, NULL }

static const keytab_t keys[] = {
    TEXT("board", "name", name, "the board's name"),
    TEXT("board", "mcu", mcu, "the MCU, as simavr names it"),
    { "board", "default_robot", OFF(default_robot), 0, 0, 0, "name", "the robot file a run uses without --robot: robots/NAME.ini", NULL, 0, 0, 0,
      KEYTAB_TEXT, sizeof ((board_spec_t *)0)->default_robot, NULL },
    { "board", "mainboard", OFF(mainboard), 0, 0, 0, "path", "the mainboard's parts file, from this file's folder", NULL, 0, 0, 0,
      KEYTAB_TEXT, sizeof ((board_spec_t *)0)->mainboard, NULL },
    NUM("board", "f_cpu_hz", KEYTAB_U32, f_cpu, 1e6, 32e6, "Hz", "the MCU's clock"),
    NUM("board", "vcc_v", KEYTAB_DOUBLE, vcc_v, 1.8, 5.5, "V", "VCC = AVCC = AREF"),
    PIN("motor.left", "dir_pin", motor_dir[0], "the H-bridge's direction input"),
    PIN("motor.left", "pwm_pin", motor_pwm[0], "the H-bridge's PWM input: a Timer1 output"),
    NUM("motor.left", "forward_level", KEYTAB_INT, motor_fwd_level[0], 0, 1, "0/1", "the direction level that turns the wheel forward"),
    PIN("motor.right", "dir_pin", motor_dir[1], "the H-bridge's direction input"),
    PIN("motor.right", "pwm_pin", motor_pwm[1], "the H-bridge's PWM input: a Timer1 output"),
    NUM("motor.right", "forward_level", KEYTAB_INT, motor_fwd_level[1], 0, 1, "0/1", "the direction level that turns the wheel forward"),
    PIN("encoder.left", "int_pin", enc_int[0], "A xor B: an external-interrupt pin"),
    PIN("encoder.left", "b_pin", enc_b[0], "channel B"),
    LEADS("encoder.left", enc_a_leads[0]),
    PIN("encoder.right", "int_pin", enc_int[1], "A xor B: an external-interrupt pin"),
    PIN("encoder.right", "b_pin", enc_b[1], "channel B"),
    LEADS("encoder.right", enc_a_leads[1]),
    NUM("switches", "adc_channel", KEYTAB_INT, sw_channel, 0, 7, "1", "the ladder's ADC channel"),
    NUM("switches", "r_top_ohm", KEYTAB_DOUBLE, sw_r_top_ohm, 1, 1e7, "ohm", "VCC to the ADC pin"),
    { "switches", "r_ohm", OFF(sw_r_ohm), KEYTAB_REQUIRED, 0.001, 1e7, "ohm", "the ladder's four resistors, bit 0 to bit 3", NULL, 0, 0, 4,
      KEYTAB_DOUBLES, 0, NULL },
    NUM("switches", "r_ground_ohm", KEYTAB_DOUBLE, sw_r_ground_ohm, 0, 1e7, "ohm", "in series when every switch is closed"),
    NUM("battery", "adc_channel", KEYTAB_INT, bat_channel, 0, 7, "1", "the divider's ADC channel"),
    NUM("battery", "r_top_ohm", KEYTAB_DOUBLE, bat_r_top_ohm, 0, 1e7, "ohm", "battery to the ADC pin"),
    NUM("battery", "r_bottom_ohm", KEYTAB_DOUBLE, bat_r_bottom_ohm, 1, 1e7, "ohm", "the ADC pin to ground"),
    { "battery", "diode_drop_v", OFF(bat_diode_drop_v), 0.0, 0, 2, "V", "a series diode's forward drop before the divider (0: none)",
      NULL, 0, 0, 0, KEYTAB_DOUBLE, 0, NULL },
    { "analog", "a4", OFF(analog[0]), 0.0, 0, 0, "open|V", "what A4 is wired to when no IR sensor is: open (floating) or a fixed voltage",
      NULL, 0, 0, 0, KEYTAB_PARSED, sizeof(board_analog_t), parse_analog },
    { "analog", "a5", OFF(analog[1]), 0.0, 0, 0, "open|V", "what A5 is wired to when no IR sensor is: open (floating) or a fixed voltage",
      NULL, 0, 0, 0, KEYTAB_PARSED, sizeof(board_analog_t), parse_analog },
};
#define N(t) (sizeof t / sizeof t[0])
static const char *const fixed[] = { "board", "motor.left", "motor.right", "encoder.left", "encoder.right", "switches", "battery", "analog" };

/* [emitter.NAME] and [led.NAME]: as many as the board has */
typedef struct {
    char name[16];
    int line;          /* its section's */
    board_pin_t pin;
    int group;         /* an emitter's */
    uint64_t seen;     /* its keys given */
} part_t;

static const keytab_t emitter_keys[] = {
    { NULL, "pin", offsetof(part_t, pin), KEYTAB_REQUIRED, 0, 0, "pin", "lights the emitter group", NULL, 0, 0, 0, KEYTAB_PARSED,
      sizeof(board_pin_t), parse_pin },
    { NULL, "group", offsetof(part_t, group), KEYTAB_REQUIRED, 0, SIM_EMITTER_GROUPS - 1, "1", "the robot file's [ir.*] emitter number",
      NULL, 0, 0, 0, KEYTAB_INT, 0, NULL },
};
#define LED_KEYS 1 /* of emitter_keys: pin only */

typedef struct {
    inisec_t ini;       /* the file being read, its fixed sections' lines, the error */
    const char *board_path; /* the board file's (ini.path is the mainboard file's while that is read) */
    int in_mainboard;
    board_spec_t work;
    uint64_t seen;     /* keys[] given */
    const char *sec_path[N(fixed)]; /* each fixed section's file, NULL: not given */
    char mb_path[sizeof ((board_spec_t *)0)->path + 128]; /* the mainboard file's path */
    part_t emitter[SIM_EMITTER_GROUPS], led[BOARD_LEDS_MAX];
    int nemitters, nleds;
    char *err;
    size_t errn;
} bload_t;

/* The named part of section ("emitter.NAME", "led.NAME"), NULL if none;
 * *led: which kind the section names (-1: neither). */
static part_t *named(bload_t *l, const char *section, int *led)
{
    *led = !strncmp(section, "led.", 4) ? 1 : !strncmp(section, "emitter.", 8) ? 0 : -1;
    if (*led < 0) return NULL;
    const char *nm = section + (*led ? 4 : 8);
    part_t *p = *led ? l->led : l->emitter;
    for (int i = 0, n = *led ? l->nleds : l->nemitters; i < n; i++)
        if (!strcmp(p[i].name, nm)) return &p[i];
    return NULL;
}

static int on_section(void *user, const char *section, int line, char *why, size_t len)
{
    bload_t *l = user;
    if (l->in_mainboard && (!strcmp(section, "board") || !strncmp(section, "emitter.", 8) || !strncmp(section, "led.", 4))) {
        snprintf(why, len, "[%s]: not a mainboard part (motor.*, encoder.*, switches, battery, analog): it goes in the board file",
                 section);
        return -1;
    }
    int i = inisec_section(&l->ini, section, line);
    if (i >= 0) {
        if (!l->sec_path[i]) l->sec_path[i] = l->ini.path;
        return 0;
    }
    int led;
    if (named(l, section, &led) || led < 0) {
        if (led >= 0) return 0; /* the part's section again */
        snprintf(why, len, "[%s]: unknown section (board, motor.left, motor.right, encoder.left, encoder.right, switches, battery, analog, "
                 "emitter.NAME, led.NAME)", section);
        return -1;
    }
    const char *nm = section + (led ? 4 : 8);
    int *n = led ? &l->nleds : &l->nemitters, max = led ? BOARD_LEDS_MAX : SIM_EMITTER_GROUPS;
    if (*n >= max || !*nm || strlen(nm) >= sizeof l->led[0].name) {
        snprintf(why, len, "[%s]: at most %d %s sections, names of 1-15 characters", section, max, led ? "led" : "emitter");
        return -1;
    }
    part_t *p = &(led ? l->led : l->emitter)[(*n)++];
    snprintf(p->name, sizeof p->name, "%s", nm);
    p->line = line;
    return 0;
}

static int on_key(void *user, const char *section, const char *key, const char *val, char *why, size_t len)
{
    bload_t *l = user;
    int led;
    part_t *p = named(l, section, &led);
    const keytab_t *k = p ? inisec_key(section, key, emitter_keys, led ? LED_KEYS : N(emitter_keys), NULL, why, len)
                          : inisec_key(section, key, keys, N(keys), section, why, len);
    if (!k) return -1;
    if (!p && (l->seen >> (k - keys) & 1u)) {
        snprintf(why, len, "%s.%s: given in %s too: a figure of the mainboard has one place", section, key, l->board_path);
        return -1;
    }
    if (keytab_set(k, p ? (void *)p : (void *)&l->work, section, val, why, len) != 0) return -1;
    if (p) p->seen |= 1ull << (k - emitter_keys);
    else l->seen |= 1ull << (k - keys);
    return 0;
}

/* inisec_line's section's file (the board file's when it has none) */
static const char *path_of(const bload_t *l, const char *section)
{
    for (size_t i = 0; i < N(fixed); i++)
        if (!strcmp(section, fixed[i]) && l->sec_path[i]) return l->sec_path[i];
    return l->board_path;
}

/* The section's line, its file made the one inisec_fail() names. */
static int at(bload_t *l, const char *section)
{
    l->ini.path = path_of(l, section);
    return inisec_line(&l->ini, section);
}

/* Every key given; the named parts into the spec. */
static int missing(bload_t *l)
{
    const keytab_t *k = keytab_missing(keys, N(keys), l->seen);
    if (k && inisec_line(&l->ini, k->section)) return inisec_fail(&l->ini, at(l, k->section), "%s.%s: missing", k->section, k->key);
    l->ini.path = l->board_path;
    if (k) return inisec_fail(&l->ini, 0, "%s.%s: missing (no [%s] section)", k->section, k->key, k->section);
    board_spec_t *sp = &l->work;
    for (int i = 0; i < l->nemitters; i++) {
        part_t *p = &l->emitter[i];
        if ((k = keytab_missing(emitter_keys, N(emitter_keys), p->seen)) != NULL)
            return inisec_fail(&l->ini, p->line, "emitter.%s.%s: missing", p->name, k->key);
        sp->emitter_pin[i] = p->pin;
        sp->emitter_group[i] = p->group;
        snprintf(sp->emitter_name[i], sizeof sp->emitter_name[i], "%s", p->name);
        sp->emitter_line[i] = p->line;
    }
    for (int i = 0; i < l->nleds; i++) {
        part_t *p = &l->led[i];
        if ((k = keytab_missing(emitter_keys, LED_KEYS, p->seen)) != NULL) return inisec_fail(&l->ini, p->line, "led.%s.%s: missing", p->name, k->key);
        sp->led_pin[i] = p->pin;
        snprintf(sp->led_name[i], sizeof sp->led_name[i], "%s", p->name);
    }
    sp->nemitters = l->nemitters;
    sp->nleds = l->nleds;
    return 0;
}

/* the pins of the board, each with its section: no pin twice */
static int check_pins(bload_t *l)
{
    const board_spec_t *sp = &l->work;
    board_pin_t pins[8 + SIM_EMITTER_GROUPS + BOARD_LEDS_MAX];
    char secs[N(pins)][24];
    int lines[N(pins)], n = 0;
    const char *paths[N(pins)];
    static const char *const side[2] = { "left", "right" };
    for (int m = 0; m < 2; m++) {
        board_pin_t mine[4] = { sp->motor_dir[m], sp->motor_pwm[m], sp->enc_int[m], sp->enc_b[m] };
        for (int j = 0; j < 4; j++, n++) {
            snprintf(secs[n], sizeof secs[n], "%s.%s", j < 2 ? "motor" : "encoder", side[m]);
            lines[n] = inisec_line(&l->ini, secs[n]);
            paths[n] = path_of(l, secs[n]);
            pins[n] = mine[j];
        }
    }
    for (int i = 0; i < l->nemitters; i++, n++)
        snprintf(secs[n], sizeof secs[n], "emitter.%s", l->emitter[i].name), pins[n] = sp->emitter_pin[i], lines[n] = l->emitter[i].line,
            paths[n] = l->board_path;
    for (int i = 0; i < l->nleds; i++, n++)
        snprintf(secs[n], sizeof secs[n], "led.%s", l->led[i].name), pins[n] = sp->led_pin[i], lines[n] = l->led[i].line,
            paths[n] = l->board_path;
    for (int i = 0; i < n; i++)
        for (int j = 0; j < i; j++)
            if (pins[j].port == pins[i].port && pins[j].bit == pins[i].bit && (l->ini.path = paths[i]) != NULL)
                return inisec_fail(&l->ini, lines[i], "%s: a pin already wired to another part (%s)", secs[i], secs[j]);
    return 0;
}

static int check(bload_t *l)
{
    board_spec_t *sp = &l->work;
    static const char *mcus[] = { "atmega48", "atmega48p", "atmega88", "atmega88p", "atmega168", "atmega168p", "atmega328", "atmega328p" };
    int known = 0;
    for (size_t i = 0; i < N(mcus); i++) known |= !strcmp(sp->mcu, mcus[i]);
    if (!known)
        return inisec_fail(&l->ini, at(l, "board"), "board.mcu: '%s': the board emulation knows the ATmega48/88/168/328 registers only", sp->mcu);
    for (int m = 0; m < 2; m++) {
        board_pin_t p = sp->motor_pwm[m];
        const char *sec = m ? "motor.right" : "motor.left";
        if (p.port != 'B' || (p.bit != 1 && p.bit != 2))
            return inisec_fail(&l->ini, at(l, sec), "%s.pwm_pin: not a Timer1 output (OC1A = D9, OC1B = D10)", sec);
        sp->motor_oc[m] = p.bit == 2;
    }
    l->ini.path = l->board_path; /* the emitters' lines are the board file's */
    for (int i = 0; i < sp->nemitters; i++)
        for (int j = 0; j < i; j++)
            if (sp->emitter_group[j] == sp->emitter_group[i])
                return inisec_fail(&l->ini, l->emitter[i].line, "emitter.%s.group: another emitter lights that group", l->emitter[i].name);
    if (sp->sw_channel == sp->bat_channel) return inisec_fail(&l->ini, at(l, "battery"), "battery.adc_channel: the switches' channel too");
    for (int i = 0; i < BOARD_ANALOG_N; i++)
        if (sp->analog[i].wired && sp->analog[i].v > sp->vcc_v)
            return inisec_fail(&l->ini, at(l, "analog"), "analog.a%d: %g V is above vcc_v (%g V)", BOARD_ANALOG_FIRST + i, sp->analog[i].v, sp->vcc_v);
    return check_pins(l);
}

/* The mainboard's parts file named by the board file, from its folder: 0, or -1 with err. */
static int load_mainboard(bload_t *l, const inifile_t *r)
{
    const char *slash = strrchr(l->board_path, '/');
    int dir = slash ? (int)(slash - l->board_path) + 1 : 0;
    if (snprintf(l->mb_path, sizeof l->mb_path, "%.*s%s", dir, l->board_path, l->work.mainboard) >= (int)sizeof l->mb_path)
        return snprintf(l->ini.err, l->ini.errn, "%s: board.mainboard: the path is too long", l->board_path), -1;
    l->ini.path = l->mb_path;
    l->in_mainboard = 1;
    int rc = inifile_load(r, l->mb_path, BOARD_MAX_BYTES, l->ini.err, l->ini.errn);
    if (rc != 0 && strstr(l->ini.err, "No such file")) /* say who names it */
        snprintf(l->ini.err, l->ini.errn, "%s: board.mainboard: %s: no such file", l->board_path, l->mb_path);
    l->ini.path = l->board_path;
    return rc;
}

int board_load(board_spec_t *spec, const char *path, char *err, size_t errn)
{
    bload_t *l = calloc(1, sizeof *l);
    if (!l) {
        snprintf(err, errn, "%s: out of memory", path);
        return -1;
    }
    inisec_init(&l->ini, path, err, errn, fixed, N(fixed));
    keytab_defaults(keys, N(keys), &l->work);
    l->board_path = path;
    const inifile_t r = { on_section, on_key, l, "want key = value or [section]" };
    int rc = inifile_load(&r, path, BOARD_MAX_BYTES, err, errn);
    if (rc == 0 && l->work.mainboard[0]) rc = load_mainboard(l, &r);
    if (rc == 0 && missing(l) == 0 && check(l) == 0) {
        snprintf(l->work.path, sizeof l->work.path, "%s", path);
        *spec = l->work;
    } else {
        rc = -1;
    }
    free(l);
    return rc;
}

int board_fits_robot(const board_spec_t *sp, const simcfg_t *c, char *err, size_t errn)
{
    int lights[SIM_EMITTER_GROUPS] = { 0 }; /* the robot's IR sensors per emitter group */
    for (unsigned i = 0, n = robot_count(c, "ir"); i < n; i++) {
        int k = robot_part_of_kind(c, "ir", i), e = 0;
        const robot_part_t *p = &c->robot.part[k];
        int g = (int)((const ir_part_spec_t *)(const void *)p->spec)->emitter;
        while (e < sp->nemitters && sp->emitter_group[e] != g) e++;
        if (e == sp->nemitters) {
            snprintf(err, errn, "%s:%d: ir.%s.emitter %d: the board %s (%s) has no emitter pin for group %d: this robot's sensors "
                     "are not on that board (docs/ROBOTS.md: which robot file fits which board)", c->robot.path, p->line, p->name, g,
                     sp->name, sp->path, g);
            return -1;
        }
        lights[g]++;
    }
    for (int e = 0; e < sp->nemitters; e++)
        if (!lights[sp->emitter_group[e]]) {
            snprintf(err, errn, "%s:%d: emitter.%s.group %d: the robot %s has no [ir.*] sensor with emitter = %d: the board's "
                     "sensors are not on this robot (docs/ROBOTS.md: which robot file fits which board)", sp->path,
                     sp->emitter_line[e], sp->emitter_name[e], sp->emitter_group[e], c->robot.path, sp->emitter_group[e]);
            return -1;
        }
    return 0;
}

static int cmp_str(const void *a, const void *b) { return strcmp(*(char *const *)a, *(char *const *)b); }

/* The board file NAME.ini (the file's own name, --board ukmarsbot-v1.3) or
 * else NAME-VERSION.ini in dir/boards that sorts first into best, or "". VERSION has no '-': boards/ukmarsbot-basic-v1.3.ini is the board
 * ukmarsbot-basic's, never --board ukmarsbot's. */
static void find_in(const char *dir, const char *name, char *best, size_t bestn)
{
    char path[DATADIR_PATH_MAX + 8];
    best[0] = '\0';
    if (snprintf(path, sizeof path, "%s%sboards", dir, dir[0] ? "/" : "") >= (int)sizeof path) return;
    DIR *d = opendir(path);
    size_t n = strlen(name);
    struct dirent *e;
    while (d && (e = readdir(d)) != NULL) {
        size_t k = strlen(e->d_name);
        if (k == n + 4 && !strncmp(e->d_name, name, n) && !strcmp(e->d_name + n, ".ini")) { /* the file's own name */
            snprintf(best, bestn, "%s", e->d_name);
            break;
        }
        if (strncmp(e->d_name, name, n) || e->d_name[n] != '-' || k < n + 6 || strcmp(e->d_name + k - 4, ".ini")) continue;
        if (memchr(e->d_name + n + 1, '-', k - 4 - (n + 1))) continue; /* a longer NAME's board */
        const char *c = e->d_name;
        if (!best[0] || cmp_str(&c, &(const char *){ best }) < 0) snprintf(best, bestn, "%s", e->d_name);
    }
    if (d) closedir(d);
}

/* The boards in dir/boards appended to list ("NAME-VERSION, ..." sorted by
 * readdir's order, no repeats), cut to stay one line. */
static void list_in(const char *dir, char *list, size_t listn)
{
    char path[DATADIR_PATH_MAX + 8];
    if (snprintf(path, sizeof path, "%s%sboards", dir, dir[0] ? "/" : "") >= (int)sizeof path) return;
    DIR *d = opendir(path);
    struct dirent *e;
    while (d && (e = readdir(d)) != NULL) {
        size_t k = strlen(e->d_name), w = strlen(list);
        if (k < 5 || e->d_name[0] == '.' || strcmp(e->d_name + k - 4, ".ini")) continue;
        char stem[256];
        snprintf(stem, sizeof stem, "%.*s", (int)(k - 4), e->d_name);
        const char *at = strstr(list, stem);
        if (at && (at == list || at[-1] == ' ') && (at[strlen(stem)] == ',' || !at[strlen(stem)])) continue;
        if (snprintf(list + w, listn - w, "%s%s", w ? ", " : "", stem) >= (int)(listn - w)) list[w] = '\0';
    }
    if (d) closedir(d);
}

int board_find(const char *name, char *out, size_t outn, char *err, size_t errn)
{
    if (strchr(name, '/') || strstr(name, ".ini")) { /* a path */
        snprintf(out, outn, "%s", name);
        return 0;
    }
    char dirs[DATADIR_MAX][DATADIR_PATH_MAX], best[256], where[600] = "";
    int nd = datadir_list(dirs);
    for (int i = 0; i < nd; i++) {
        find_in(dirs[i], name, best, sizeof best);
        if (best[0]) {
            if (snprintf(out, outn, "%s%sboards/%s", dirs[i], dirs[i][0] ? "/" : "", best) < (int)outn) return 0;
            snprintf(err, errn, "--board %s: the path of %s in %s is too long", name, best, dirs[i]);
            return -1;
        }
        size_t w = strlen(where);
        if (snprintf(where + w, sizeof where - w, "%s%s%sboards", i ? ", " : "", dirs[i], dirs[i][0] ? "/" : "") >=
            (int)(sizeof where - w))
            where[sizeof where - 1] = '\0'; /* cut: the message stays one line */
    }
    char boards[600] = "";
    for (int i = 0; i < nd; i++) list_in(dirs[i], boards, sizeof boards);
    snprintf(err, errn, "--board %s: no %s.ini or %s-VERSION.ini in %s; the boards there: %s (--board NAME or NAME-VERSION,"
             " or the board file's path)", name, name, name, where, boards[0] ? boards : "none");
    return -1;
}

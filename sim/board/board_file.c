/* board_file.c - the board file (board.h's board_spec_t): INI, one section
 * per part. Every key is required; a bad value is "FILE:LINE: section.key:
 * reason", a missing key "FILE:LINE: section.key: missing" (the section's
 * line; line 0 = no such section). */
#include "board.h"

#include <ctype.h>
#include <dirent.h>
#include <stdlib.h>
#include <string.h>

#include <ini.h>

#include "io/infile.h"
#include "world/config.h"

enum { K_STR, K_NUM, K_U32, K_INT, K_PIN, K_LEVEL, K_LEADS, K_OHMS4 };

typedef struct {
    const char *section, *key;
    int kind;
    double lo, hi;
    size_t off;
    int seen;
} bkey_t;

#define OFF(f) offsetof(board_spec_t, f)

typedef struct {
    board_spec_t *sp;
    bkey_t *keys;
    int nkeys;
    char reason[300];
    int emitters_seen[SIM_EMITTER_GROUPS]; /* [emitter.*] sections in order: their index */
    char emitter_names[SIM_EMITTER_GROUPS][32];
    char led_names[BOARD_LEDS_MAX][32];
} bload_t;

/* "D7", "A0" (Arduino Nano names) or "PB1" */
static int parse_pin(const char *v, board_pin_t *p)
{
    char *end;
    if ((v[0] == 'D' || v[0] == 'A') && isdigit((unsigned char)v[1])) {
        long n = strtol(v + 1, &end, 10);
        if (*end) return -1;
        if (v[0] == 'A') {
            if (n > 5) return -1; /* A6/A7 are analogue inputs only */
            *p = (board_pin_t){ 'C', (uint8_t)n };
        } else if (n <= 7) *p = (board_pin_t){ 'D', (uint8_t)n };
        else if (n <= 13) *p = (board_pin_t){ 'B', (uint8_t)(n - 8) };
        else return -1;
        return 0;
    }
    if (v[0] == 'P' && (v[1] == 'B' || v[1] == 'C' || v[1] == 'D') && v[2] >= '0' && v[2] <= '7' && !v[3]) {
        *p = (board_pin_t){ v[1], (uint8_t)(v[2] - '0') };
        return 0;
    }
    return -1;
}

static int set_num(bload_t *l, const bkey_t *k, const char *v, double *out)
{
    char *end;
    double x = strtod(v, &end);
    if (end == v || *end || !(x >= k->lo && x <= k->hi)) {
        snprintf(l->reason, sizeof l->reason, "%s.%s: expected a number from %g to %g, got '%s'", k->section, k->key, k->lo,
                 k->hi, v);
        return -1;
    }
    *out = x;
    return 0;
}

static int set_value(bload_t *l, const bkey_t *k, const char *v, char *base)
{
    double x;
    switch (k->kind) {
    case K_STR:
        if (!*v || strlen(v) >= 32) return snprintf(l->reason, sizeof l->reason, "%s.%s: expected a name of 1-31 characters", k->section, k->key), -1;
        snprintf(base + k->off, 32, "%s", v);
        return 0;
    case K_NUM:
        if (set_num(l, k, v, &x)) return -1;
        *(double *)(void *)(base + k->off) = x;
        return 0;
    case K_U32:
        if (set_num(l, k, v, &x)) return -1;
        *(uint32_t *)(void *)(base + k->off) = (uint32_t)x;
        return 0;
    case K_INT:
    case K_LEVEL:
        if (set_num(l, k, v, &x)) return -1;
        if (x != (int)x) return snprintf(l->reason, sizeof l->reason, "%s.%s: expected a whole number, got '%s'", k->section, k->key, v), -1;
        *(int *)(void *)(base + k->off) = (int)x;
        return 0;
    case K_PIN:
        if (parse_pin(v, (board_pin_t *)(void *)(base + k->off)) == 0) return 0;
        return snprintf(l->reason, sizeof l->reason, "%s.%s: expected a pin D0-D13, A0-A5 or PB0-PD7, got '%s'", k->section, k->key, v), -1;
    case K_LEADS:
        if (!strcmp(v, "a_leads") || !strcmp(v, "b_leads")) {
            *(int *)(void *)(base + k->off) = v[0] == 'a';
            return 0;
        }
        return snprintf(l->reason, sizeof l->reason, "%s.%s: expected a_leads or b_leads, got '%s'", k->section, k->key, v), -1;
    default: { /* K_OHMS4: four resistances */
        double *r = (double *)(void *)(base + k->off);
        char *end;
        const char *s = v;
        for (int i = 0; i < 4; i++) {
            r[i] = strtod(s, &end);
            if (end == s || !(r[i] > 0 && r[i] <= 1e7)) break;
            s = end;
            if (i == 3 && !*s) return 0;
        }
        return snprintf(l->reason, sizeof l->reason, "%s.%s: expected four resistances in ohm (bit 0 to bit 3), got '%s'", k->section, k->key, v), -1;
    }
    }
}

static const bkey_t KEYS[] = {
    { "board", "name", K_STR, 0, 0, OFF(name), 0 },
    { "board", "mcu", K_STR, 0, 0, OFF(mcu), 0 },
    { "board", "f_cpu_hz", K_U32, 1e6, 32e6, OFF(f_cpu), 0 },
    { "board", "vcc_v", K_NUM, 1.8, 5.5, OFF(vcc_v), 0 },
    { "motor.left", "dir_pin", K_PIN, 0, 0, OFF(motor_dir[0]), 0 },
    { "motor.left", "pwm_pin", K_PIN, 0, 0, OFF(motor_pwm[0]), 0 },
    { "motor.left", "forward_level", K_LEVEL, 0, 1, OFF(motor_fwd_level[0]), 0 },
    { "motor.right", "dir_pin", K_PIN, 0, 0, OFF(motor_dir[1]), 0 },
    { "motor.right", "pwm_pin", K_PIN, 0, 0, OFF(motor_pwm[1]), 0 },
    { "motor.right", "forward_level", K_LEVEL, 0, 1, OFF(motor_fwd_level[1]), 0 },
    { "encoder.left", "int_pin", K_PIN, 0, 0, OFF(enc_int[0]), 0 },
    { "encoder.left", "b_pin", K_PIN, 0, 0, OFF(enc_b[0]), 0 },
    { "encoder.left", "forward", K_LEADS, 0, 0, OFF(enc_a_leads[0]), 0 },
    { "encoder.right", "int_pin", K_PIN, 0, 0, OFF(enc_int[1]), 0 },
    { "encoder.right", "b_pin", K_PIN, 0, 0, OFF(enc_b[1]), 0 },
    { "encoder.right", "forward", K_LEADS, 0, 0, OFF(enc_a_leads[1]), 0 },
    { "switches", "adc_channel", K_INT, 0, 7, OFF(sw_channel), 0 },
    { "switches", "r_top_ohm", K_NUM, 1, 1e7, OFF(sw_r_top_ohm), 0 },
    { "switches", "r_ohm", K_OHMS4, 0, 0, OFF(sw_r_ohm), 0 },
    { "switches", "r_ground_ohm", K_NUM, 0, 1e7, OFF(sw_r_ground_ohm), 0 },
    { "battery", "adc_channel", K_INT, 0, 7, OFF(bat_channel), 0 },
    { "battery", "r_top_ohm", K_NUM, 0, 1e7, OFF(bat_r_top_ohm), 0 },
    { "battery", "r_bottom_ohm", K_NUM, 1, 1e7, OFF(bat_r_bottom_ohm), 0 },
};
#define NKEYS (int)(sizeof KEYS / sizeof KEYS[0])

/* [emitter.NAME] (pin, group) and [led.NAME] (pin): as many as the board has */
static int named_part(bload_t *l, const char *section, const char *name, const char *v)
{
    board_spec_t *sp = l->sp;
    int led = !strncmp(section, "led.", 4);
    const char *nm = section + (led ? 4 : 8);
    char (*names)[32] = led ? l->led_names : l->emitter_names;
    int *n = led ? &sp->nleds : &sp->nemitters, max = led ? BOARD_LEDS_MAX : SIM_EMITTER_GROUPS, i;
    for (i = 0; i < *n && strcmp(names[i], nm); i++) {}
    if (i == *n) {
        if (*n >= max || !*nm || strlen(nm) >= 16)
            return snprintf(l->reason, sizeof l->reason, "%s: at most %d %s sections, names of 1-15 characters", section, max, led ? "led" : "emitter"), -1;
        snprintf(names[i], 32, "%s", nm);
        (*n)++;
        if (led) snprintf(sp->led_name[i], sizeof sp->led_name[i], "%s", nm), sp->led_pin[i].port = 0;
        else sp->emitter_pin[i].port = 0, sp->emitter_group[i] = -1;
    }
    bkey_t k = { section, name, K_PIN, 0, SIM_EMITTER_GROUPS - 1, 0, 0 };
    if (!strcmp(name, "pin")) {
        k.off = led ? OFF(led_pin[i]) : OFF(emitter_pin[i]);
        return set_value(l, &k, v, (char *)sp);
    }
    if (!led && !strcmp(name, "group")) {
        k.kind = K_INT;
        k.off = OFF(emitter_group[i]);
        return set_value(l, &k, v, (char *)sp);
    }
    return snprintf(l->reason, sizeof l->reason, "%s.%s: unknown key", section, name), -1;
}

static int on_key(void *user, const char *section, const char *name, const char *v)
{
    bload_t *l = user;
    if (!strncmp(section, "led.", 4) || !strncmp(section, "emitter.", 8)) return named_part(l, section, name, v) == 0;
    for (int i = 0; i < l->nkeys; i++)
        if (!strcmp(l->keys[i].section, section) && !strcmp(l->keys[i].key, name)) {
            if (l->keys[i].seen++) return snprintf(l->reason, sizeof l->reason, "%s.%s: given twice", section, name), 0;
            return set_value(l, &l->keys[i], v, (char *)l->sp) == 0;
        }
    snprintf(l->reason, sizeof l->reason, "%s.%s: unknown key", section, name);
    return 0;
}

/* the line of [section] in text, 0 if none */
static int section_line(const char *text, const char *section)
{
    int line = 1;
    size_t n = strlen(section);
    for (const char *p = text; *p; line++) {
        while (*p == ' ' || *p == '\t') p++;
        if (*p == '[' && !strncmp(p + 1, section, n) && p[1 + n] == ']') return line;
        p = strchr(p, '\n');
        if (!p) break;
        p++;
    }
    return 0;
}

static int fail(bload_t *l, const char *text, const char *section, const char *fmt, const char *a)
{
    char r[200];
    snprintf(r, sizeof r, fmt, a);
    snprintf(l->reason, sizeof l->reason, "%d: %s", section_line(text, section), r);
    return -1;
}

/* the pins of the board, each with its section: no pin twice */
static int check_pins(bload_t *l, const char *text)
{
    board_spec_t *sp = l->sp;
    board_pin_t pins[32];
    char secs[32][40];
    int n = 0;
    static const char *side[2] = { "left", "right" };
    for (int m = 0; m < 2; m++) {
        snprintf(secs[n], 40, "motor.%s", side[m]), pins[n++] = sp->motor_dir[m];
        snprintf(secs[n], 40, "motor.%s", side[m]), pins[n++] = sp->motor_pwm[m];
        snprintf(secs[n], 40, "encoder.%s", side[m]), pins[n++] = sp->enc_int[m];
        snprintf(secs[n], 40, "encoder.%s", side[m]), pins[n++] = sp->enc_b[m];
    }
    for (int i = 0; i < sp->nemitters; i++) snprintf(secs[n], 40, "emitter.%s", l->emitter_names[i]), pins[n++] = sp->emitter_pin[i];
    for (int i = 0; i < sp->nleds; i++) snprintf(secs[n], 40, "led.%s", l->led_names[i]), pins[n++] = sp->led_pin[i];
    for (int i = 0; i < n; i++) {
        if (!pins[i].port) return fail(l, text, secs[i], "%s.pin: missing", secs[i]);
        for (int j = 0; j < i; j++)
            if (pins[j].port == pins[i].port && pins[j].bit == pins[i].bit)
                return fail(l, text, secs[i], "%s: a pin already wired to another part", secs[i]);
    }
    return 0;
}

static int check(bload_t *l, const char *text)
{
    board_spec_t *sp = l->sp;
    for (int i = 0; i < l->nkeys; i++)
        if (!l->keys[i].seen) {
            char sk[80];
            snprintf(sk, sizeof sk, "%s.%s", l->keys[i].section, l->keys[i].key);
            return fail(l, text, l->keys[i].section, "%s: missing", sk);
        }
    static const char *mcus[] = { "atmega48", "atmega48p", "atmega88", "atmega88p", "atmega168", "atmega168p", "atmega328", "atmega328p" };
    int known = 0;
    for (size_t i = 0; i < sizeof mcus / sizeof mcus[0]; i++) known |= !strcmp(sp->mcu, mcus[i]);
    if (!known) return fail(l, text, "board", "board.mcu: '%s': the board emulation knows the ATmega48/88/168/328 registers only", sp->mcu);
    for (int m = 0; m < 2; m++) {
        board_pin_t p = sp->motor_pwm[m];
        if (p.port != 'B' || (p.bit != 1 && p.bit != 2))
            return fail(l, text, m ? "motor.right" : "motor.left", "%s.pwm_pin: not a Timer1 output (OC1A = D9, OC1B = D10)", m ? "motor.right" : "motor.left");
        sp->motor_oc[m] = p.bit == 2;
    }
    for (int i = 0; i < sp->nemitters; i++) {
        char sec[40];
        snprintf(sec, sizeof sec, "emitter.%s", l->emitter_names[i]);
        if (sp->emitter_group[i] < 0) return fail(l, text, sec, "%s.group: missing", sec);
        for (int j = 0; j < i; j++)
            if (sp->emitter_group[j] == sp->emitter_group[i]) return fail(l, text, sec, "%s.group: another emitter lights that group", sec);
    }
    if (sp->sw_channel == sp->bat_channel) return fail(l, text, "battery", "%s", "battery.adc_channel: the switches' channel too");
    return check_pins(l, text);
}

int board_load(board_spec_t *spec, const char *path, char *err, size_t errn)
{
    size_t len;
    char *text = infile_read(path, BOARD_MAX_BYTES, &len, err, errn);
    if (!text) return -1;
    bload_t *l = calloc(1, sizeof *l);
    bkey_t *keys = malloc(sizeof KEYS);
    board_spec_t work;
    memset(&work, 0, sizeof work);
    int rc = -1;
    if (!l || !keys) snprintf(err, errn, "%s: out of memory", path);
    else if (config_scan_lines(text, len, path, err, errn) == 0) {
        memcpy(keys, KEYS, sizeof KEYS);
        l->sp = &work;
        l->keys = keys;
        l->nkeys = NKEYS;
        int ini = ini_parse_string(text, on_key, l);
        if (ini > 0) snprintf(err, errn, "%s:%d: %s", path, ini, l->reason[0] ? l->reason : "syntax error (want key = value or [section])");
        else if (ini < 0) snprintf(err, errn, "%s: out of memory", path);
        else if (check(l, text) != 0) snprintf(err, errn, "%s:%s", path, l->reason);
        else {
            snprintf(work.path, sizeof work.path, "%s", path);
            *spec = work;
            rc = 0;
        }
    }
    free(keys);
    free(l);
    free(text);
    return rc;
}

static int cmp_str(const void *a, const void *b) { return strcmp(*(char *const *)a, *(char *const *)b); }

int board_find(const char *name, char *out, size_t outn, char *err, size_t errn)
{
    if (strchr(name, '/') || strstr(name, ".ini")) { /* a path */
        snprintf(out, outn, "%s", name);
        return 0;
    }
    DIR *d = opendir("boards");
    char best[256] = "";
    size_t n = strlen(name);
    struct dirent *e;
    while (d && (e = readdir(d)) != NULL) {
        size_t k = strlen(e->d_name);
        if (strncmp(e->d_name, name, n) || e->d_name[n] != '-' || k < 5 || strcmp(e->d_name + k - 4, ".ini")) continue;
        const char *c = e->d_name;
        if (!best[0] || cmp_str(&c, &(const char *){ best }) < 0) snprintf(best, sizeof best, "%s", e->d_name);
    }
    if (d) closedir(d);
    if (!best[0]) {
        snprintf(err, errn, "--board %s: no boards/%s-*.ini here (give the board file's path)", name, name);
        return -1;
    }
    snprintf(out, outn, "boards/%s", best);
    return 0;
}

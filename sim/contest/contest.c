/* contest.c - contest files (contest.h): the key table, the reading path
 * (inifile.h) with each error's line and column, printing, and applying a
 * profile to the config, the maze and the results. */
#include "contest.h"

#include <ctype.h>
#include <math.h>
#include <stdarg.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "io/datadir.h"
#include "io/infile.h"
#include "world/inifile.h"
#include "world/keytab.h"

static const char *const headings[] = { "north", "east", "south", "west" }; /* TRUEMAZE_NORTH.. */
static const char *const rules_words[] = { "best_run", "run_plus_search" };   /* SCORE_* */

/* "X,Y": two whole numbers 0..255 into int[2] */
static int parse_cell(const char *val, void *field, char *why, size_t len)
{
    int *v = field, n = 0;
    if (sscanf(val, "%d,%d%n", &v[0], &v[1], &n) != 2 || val[n] || v[0] < 0 || v[1] < 0 || v[0] > 255 || v[1] > 255) {
        snprintf(why, len, "expected a cell X,Y (whole numbers 0..255, e.g. 0,0), got '%s'", val);
        return -1;
    }
    return 0;
}

/* "X0,Y0 X1,Y1": two corner cells into int[4], ordered x0 <= x1, y0 <= y1 */
static int parse_rect(const char *val, void *field, char *why, size_t len)
{
    int *v = field, n = 0;
    if (sscanf(val, "%d,%d %d,%d%n", &v[0], &v[1], &v[2], &v[3], &n) != 4 || val[n]) {
        snprintf(why, len, "expected two corner cells X0,Y0 X1,Y1 (e.g. 7,7 8,8), got '%s'", val);
        return -1;
    }
    for (int i = 0; i < 4; i++)
        if (v[i] < 0 || v[i] > 255) {
            snprintf(why, len, "cell coordinate %d outside 0..255 in '%s'", v[i], val);
            return -1;
        }
    if (v[0] > v[2]) { int t = v[0]; v[0] = v[2]; v[2] = t; }
    if (v[1] > v[3]) { int t = v[1]; v[1] = v[3]; v[3] = t; }
    return 0;
}

#define OFF(f) offsetof(contest_t, f)
#define REQ KEYTAB_REQUIRED
/* a number in the file's unit (per: file units per stored unit) */
#define N(sec, name, field, min, max, unit, per) \
    { sec, name, OFF(field), REQ, min, max, unit, "the contest file", NULL, 0, per, 0, KEYTAB_DOUBLE, 0, NULL }
#define I(sec, name, field, def, min, max, unit) \
    { sec, name, OFF(field), def, min, max, unit, "the contest file", NULL, 1, 0, 0, KEYTAB_INT, 0, NULL }
#define W(sec, name, field, words) \
    { sec, name, OFF(field), REQ, 0, sizeof words / sizeof words[0] - 1, "word", "the contest file", words, 0, 0, 0, KEYTAB_INT, 0, NULL }
#define P(sec, name, field, fn) \
    { sec, name, OFF(field), REQ, 0, 0, "cells", "the contest file", NULL, 0, 0, 0, KEYTAB_PARSED, sizeof ((contest_t *)0)->field, fn }

/* ranges: the config's [world] and [sim] ranges (config.c), in the file's units */
static const keytab_t keys[] = {
    I("maze", "max_width", max_width, REQ, 1, TRUEMAZE_MAX_SIZE, "cells"),
    I("maze", "max_height", max_height, REQ, 1, TRUEMAZE_MAX_SIZE, "cells"),
    N("maze", "cell_mm", cell_m, 50, 500, "mm", 1000),
    N("maze", "wall_thick_mm", wall_thick_m, 1, 50, "mm", 1000),
    N("maze", "wall_height_mm", wall_height_m, 5, 200, "mm", 1000),
    N("maze", "post_mm", post_m, 1, 50, "mm", 1000),
    I("maze", "centre_post", centre_post, REQ, 0, 1, "0/1"),
    P("maze", "start", start, parse_cell),
    W("maze", "heading", heading, headings),
    P("maze", "goal", goal, parse_rect),
    N("rules", "time_limit_s", time_limit_s, 1, 86400, "s", 1),
    I("rules", "runs", rules.runs, REQ, 0, SCORE_MAX_RUNS, "1"),
    W("rules", "scoring", rules.rule, rules_words),
    { "rules", "search_divisor", OFF(rules.search_divisor), 0, 1, 1000, "1", "the contest file", NULL, 0, 0, 0, KEYTAB_DOUBLE, 0, NULL },
    { "rules", "touch_penalty_s", OFF(rules.touch_penalty_s), 0, 0, 600, "s", "the contest file", NULL, 0, 0, 0, KEYTAB_DOUBLE, 0, NULL },
};
#define NKEYS (sizeof keys / sizeof keys[0])
_Static_assert(NKEYS <= CONTEST_KEYS, "contest_t.source has a row per key");

int contest_find(const char *arg, char *path, size_t pathlen, char *err, size_t errlen)
{
    char rel[300];
    if (strchr(arg, '/') || strstr(arg, ".ini")) {
        snprintf(path, pathlen, "%s", arg);
        return 0;
    }
    if (!*arg || snprintf(rel, sizeof rel, "contests/%s.ini", arg) >= (int)sizeof rel || datadir_find(rel, path, pathlen) != 0) {
        snprintf(err, errlen, "--contest %s: no contests/NAME.ini of that name here, installed or in the source tree (give the contest file's path)", arg);
        return -1;
    }
    return 0;
}

/* The reader's state: the profile being filled, the keys given, and the
 * key whose handler failed (its line and column are found in the text). */
typedef struct {
    contest_t *c;
    uint64_t seen;          /* bit i: keys[i] was given */
    int failed;             /* 1: unknown key, 2: bad value */
    char section[64], key[64];
} reader_t;

static int on_section(void *user, const char *section, int line, char *why, size_t len)
{
    if (!strcmp(section, "maze") || !strcmp(section, "rules")) return 0;
    snprintf(why, len, "[%s]: unknown section (a contest file has [maze] and [rules])", section);
    return -1;
}

static int on_key(void *user, const char *section, const char *name, const char *val, char *why, size_t len)
{
    reader_t *r = user;
    const keytab_t *k = keytab_find(keys, NKEYS, section, name);
    snprintf(r->section, sizeof r->section, "%s", section);
    snprintf(r->key, sizeof r->key, "%s", name);
    if (!k) {
        r->failed = 1;
        snprintf(why, len, "%s.%s: unknown key", section, name);
        return -1;
    }
    if (keytab_set(k, r->c, section, val, why, len) != 0) {
        r->failed = 2;
        return -1;
    }
    r->seen |= 1ull << (k - keys);
    return 0;
}

/* The 1-based line and columns (of the key, of its value) of key in
 * [section] of text; 0 if absent. A line scan as inifile's: blanks before
 * the key, '=' or ':' after it. */
static int find_key(const char *text, const char *section, const char *key, int *key_col, int *val_col)
{
    char sec[64] = "";
    int line = 1;
    for (const char *p = text; *p; line++) {
        const char *end = strchr(p, '\n'), *s = p;
        size_t n = end ? (size_t)(end - p) : strlen(p);
        while (s < p + n && isspace((unsigned char)*s)) s++;
        if (*s == '[') {
            const char *close = memchr(s, ']', n - (size_t)(s - p));
            if (close) snprintf(sec, sizeof sec, "%.*s", (int)(close - s - 1), s + 1);
        } else if (!strcmp(sec, section) && !strncmp(s, key, strlen(key))) {
            const char *q = s + strlen(key);
            while (*q == ' ' || *q == '\t') q++;
            if (*q == '=' || *q == ':') {
                for (q++; *q == ' ' || *q == '\t'; q++) {}
                *key_col = (int)(s - p) + 1;
                *val_col = (int)(q - p) + 1;
                return line;
            }
        }
        if (!end) break;
        p = end + 1;
    }
    return 0;
}

/* The column of line's first non-blank character (1 if none). */
static int line_col(const char *text, int line)
{
    const char *p = text;
    for (int l = 1; l < line && p; l++) {
        p = strchr(p, '\n');
        if (p) p++;
    }
    if (!p) return 1;
    const char *s = p;
    while (*s == ' ' || *s == '\t') s++;
    return (int)(s - p) + 1;
}

/* err ("PATH:LINE: reason" from the reader) with the column added. */
static void add_column(const reader_t *r, const char *text, const char *path, char *err, size_t errlen)
{
    char reason[400];
    int line = 0, kc = 1, vc = 1, at = 0;
    size_t pl = strlen(path);
    if (strncmp(err, path, pl) != 0 || sscanf(err + pl, ":%d: %n", &line, &at) != 1 || at == 0) return;
    snprintf(reason, sizeof reason, "%s", err + pl + at);
    int col = line_col(text, line);
    if (r->failed && find_key(text, r->section, r->key, &kc, &vc) == line) col = r->failed == 1 ? kc : vc;
    snprintf(err, errlen, "%s:%d:%d: %s", path, line, col, reason);
}

/* One error line at key's value in the text (its line and column), the
 * reason printf-style. Returns -1. */
static int fail_at(const char *text, const char *path, const char *section, const char *key, char *err, size_t errlen,
                   const char *fmt, ...) __attribute__((format(printf, 7, 8)));
static int fail_at(const char *text, const char *path, const char *section, const char *key, char *err, size_t errlen,
                   const char *fmt, ...)
{
    char why[300];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(why, sizeof why, fmt, ap);
    va_end(ap);
    int kc = 1, vc = 1, line = find_key(text, section, key, &kc, &vc);
    if (line > 0) snprintf(err, errlen, "%s:%d:%d: %s.%s: %s", path, line, vc, section, key, why);
    else snprintf(err, errlen, "%s: %s.%s: %s", path, section, key, why);
    return -1;
}

/* The `; source:` text in the comment lines right above line (1-based) of
 * text into out; 0, or -1 if they have none. */
static int source_above(const char *text, int line, char *out, size_t n)
{
    const char *starts[64];
    int count = 0, l = 1;
    for (const char *p = text; *p && l < line; l++) { /* the starts of the up to 64 lines before line */
        starts[count++ % 64] = p;
        const char *e = strchr(p, '\n');
        if (!e) break;
        p = e + 1;
    }
    for (int i = 1; i <= count && i <= 64; i++) {
        const char *s = starts[(count - i) % 64];
        while (*s == ' ' || *s == '\t') s++;
        if (*s != ';' && *s != '#') return -1; /* the comment block above the key has ended */
        const char *t = s + 1;
        while (*t == ' ' || *t == '\t') t++;
        if (!strncmp(t, "source:", 7)) {
            for (t += 7; *t == ' ' || *t == '\t'; t++) {}
            size_t k = strcspn(t, "\r\n");
            snprintf(out, n, "%.*s", (int)(k < n ? k : n - 1), t);
            return 0;
        }
    }
    return -1;
}

/* Every key given has its source (contests/README.md); kept for contest_print. */
static int check_sources(const reader_t *r, const char *text, const char *path, char *err, size_t errlen)
{
    for (size_t i = 0; i < NKEYS; i++) {
        if (!((r->seen >> i) & 1)) continue;
        int kc = 1, vc = 1, line = find_key(text, keys[i].section, keys[i].key, &kc, &vc);
        if (line > 0 && source_above(text, line, r->c->source[i], sizeof r->c->source[i]) != 0) {
            snprintf(err, errlen, "%s:%d:%d: %s.%s: no '; source:' line above it (contests/README.md: every key says where its"
                     " figure comes from, or \"not found\")", path, line, kc, keys[i].section, keys[i].key);
            return -1;
        }
    }
    return 0;
}

/* The checks between keys, once every key is read: 0, or -1 after one line. */
static int check(const reader_t *r, const char *text, const char *path, char *err, size_t errlen)
{
    const contest_t *c = r->c;
    const keytab_t *miss = keytab_missing(keys, NKEYS, r->seen);
    if (miss) {
        snprintf(err, errlen, "%s: %s.%s: missing (a contest file gives every key but search_divisor and touch_penalty_s)", path,
                 miss->section, miss->key);
        return -1;
    }
    if (c->post_m < c->wall_thick_m)
        return fail_at(text, path, "maze", "post_mm", err, errlen, "posts thinner than the walls (wall_thick_mm %g)", c->wall_thick_m * 1000);
    if (c->start[0] >= c->max_width || c->start[1] >= c->max_height)
        return fail_at(text, path, "maze", "start", err, errlen, "cell %d,%d is outside the %dx%d maze", c->start[0], c->start[1],
                       c->max_width, c->max_height);
    if (c->goal[2] >= c->max_width || c->goal[3] >= c->max_height)
        return fail_at(text, path, "maze", "goal", err, errlen, "cells %d,%d %d,%d reach outside the %dx%d maze", c->goal[0], c->goal[1],
                       c->goal[2], c->goal[3], c->max_width, c->max_height);
    int given = (r->seen >> (size_t)(keytab_find(keys, NKEYS, "rules", "search_divisor") - keys)) & 1;
    if (c->rules.rule == SCORE_RUN_PLUS_SEARCH && !given)
        return fail_at(text, path, "rules", "scoring", err, errlen, "run_plus_search needs search_divisor (the search time's share is 1/search_divisor)");
    if (c->rules.rule != SCORE_RUN_PLUS_SEARCH && given)
        return fail_at(text, path, "rules", "search_divisor", err, errlen, "only with scoring = run_plus_search");
    return 0;
}

/* The file's name without its folder and ".ini". */
static void stem(const char *path, char *out, size_t n)
{
    const char *base = strrchr(path, '/');
    base = base ? base + 1 : path;
    size_t len = strlen(base);
    if (len > 4 && !strcmp(base + len - 4, ".ini")) len -= 4;
    snprintf(out, n, "%.*s", (int)len, base);
}

int contest_load(contest_t *out, const char *path, char *err, size_t errlen)
{
    size_t len;
    char *text = infile_read(path, CONTEST_MAX_BYTES, &len, err, errlen);
    if (!text) return -1;
    static contest_t work; /* the caller's only if the whole file is good */
    memset(&work, 0, sizeof work);
    keytab_defaults(keys, NKEYS, &work);
    reader_t r = { &work, 0, 0, "", "" };
    const inifile_t ini = { on_section, on_key, &r, "want key = value or [section]" };
    int rc = inifile_parse(&ini, text, len, path, err, errlen);
    if (rc != 0) add_column(&r, text, path, err, errlen);
    else rc = check(&r, text, path, err, errlen);
    if (rc == 0) rc = check_sources(&r, text, path, err, errlen);
    free(text);
    if (rc != 0) return -1;
    stem(path, work.name, sizeof work.name);
    snprintf(work.path, sizeof work.path, "%s", path);
    *out = work;
    return 0;
}

/* "; source: TEXT\n" of the key, as the file gave it; a key the file left to
 * its default says so. */
static void print_source(const contest_t *c, const char *section, const char *key, FILE *out)
{
    const keytab_t *k = keytab_find(keys, NKEYS, section, key);
    const char *src = k ? c->source[k - keys] : "";
    fprintf(out, "; source: %s\n", src[0] ? src : "not in the file: the default");
}

void contest_print(const contest_t *c, FILE *out)
{
    fprintf(out, "; contest %s (%s): the profile as resolved, each key with the source its file gives\n[maze]\n", c->name, c->path);
    print_source(c, "maze", "max_width", out);
    fprintf(out, "max_width = %d\n", c->max_width);
    print_source(c, "maze", "max_height", out);
    fprintf(out, "max_height = %d\n", c->max_height);
    print_source(c, "maze", "cell_mm", out);
    fprintf(out, "cell_mm = %.9g\n", c->cell_m * 1000);
    print_source(c, "maze", "wall_thick_mm", out);
    fprintf(out, "wall_thick_mm = %.9g\n", c->wall_thick_m * 1000);
    print_source(c, "maze", "wall_height_mm", out);
    fprintf(out, "wall_height_mm = %.9g\n", c->wall_height_m * 1000);
    print_source(c, "maze", "post_mm", out);
    fprintf(out, "post_mm = %.9g\n", c->post_m * 1000);
    print_source(c, "maze", "centre_post", out);
    fprintf(out, "centre_post = %d\n", c->centre_post);
    print_source(c, "maze", "start", out);
    fprintf(out, "start = %d,%d\n", c->start[0], c->start[1]);
    print_source(c, "maze", "heading", out);
    fprintf(out, "heading = %s\n", headings[c->heading]);
    print_source(c, "maze", "goal", out);
    fprintf(out, "goal = %d,%d %d,%d\n\n[rules]\n", c->goal[0], c->goal[1], c->goal[2], c->goal[3]);
    print_source(c, "rules", "time_limit_s", out);
    fprintf(out, "time_limit_s = %.9g\n", c->time_limit_s);
    print_source(c, "rules", "runs", out);
    fprintf(out, "runs = %d\n", c->rules.runs);
    print_source(c, "rules", "scoring", out);
    fprintf(out, "scoring = %s\n", rules_words[c->rules.rule]);
    if (c->rules.rule == SCORE_RUN_PLUS_SEARCH) {
        print_source(c, "rules", "search_divisor", out);
        fprintf(out, "search_divisor = %.9g\n", c->rules.search_divisor);
    }
    print_source(c, "rules", "touch_penalty_s", out);
    fprintf(out, "touch_penalty_s = %.9g\n", c->rules.touch_penalty_s);
}

void contest_apply_config(const contest_t *c, simcfg_t *cfg)
{
    cfg->world.cell_m = c->cell_m;
    cfg->world.wall_thick_m = c->wall_thick_m;
    cfg->world.wall_height_m = c->wall_height_m;
    cfg->world.post_m = c->post_m;
    cfg->world.centre_post = c->centre_post;
    cfg->sim.time_limit_s = c->time_limit_s;
}

/* The profile's heading where the start cell is open that way, else the
 * first open side (north, east, south, west), as the maze reader picks. */
static void start_heading(const contest_t *c, truemaze_t *m)
{
    if (truemaze_open(m, m->start, (uint8_t)c->heading)) {
        m->start_heading = (uint8_t)c->heading;
        return;
    }
    for (uint8_t d = 0; d < 4; d++)
        if (truemaze_open(m, m->start, d)) {
            m->start_heading = d;
            return;
        }
}

int contest_apply_maze(const contest_t *c, truemaze_t *m, const mazefile_info_t *info, const char *maze_path, char *err,
                       size_t errlen)
{
    if (m->width > c->max_width || m->height > c->max_height) {
        snprintf(err, errlen, "%s: a %ux%u maze, larger than contest %s's %dx%d", maze_path, m->width, m->height, c->name,
                 c->max_width, c->max_height);
        return -1;
    }
    if (!info->has_start) {
        if (c->start[0] >= m->width || c->start[1] >= m->height) {
            snprintf(err, errlen, "%s: contest %s's start %d,%d is outside the %ux%u maze", maze_path, c->name, c->start[0],
                     c->start[1], m->width, m->height);
            return -1;
        }
        m->start = truemaze_cell(m, (uint8_t)c->start[0], (uint8_t)c->start[1]);
        start_heading(c, m);
    }
    if (info->has_goal) return 0; /* the file's 'G' marks */
    if (c->goal[2] >= m->width || c->goal[3] >= m->height) {
        snprintf(err, errlen, "%s: contest %s's goal %d,%d %d,%d reaches outside the %ux%u maze (and the file marks no 'G')",
                 maze_path, c->name, c->goal[0], c->goal[1], c->goal[2], c->goal[3], m->width, m->height);
        return -1;
    }
    truemaze_clear_goals(m);
    for (int y = c->goal[1]; y <= c->goal[3]; y++)
        for (int x = c->goal[0]; x <= c->goal[2]; x++) truemaze_set_goal(m, truemaze_cell(m, (uint8_t)x, (uint8_t)y), 1);
    return 0;
}

static double ms3(double s) { return round(s * 1000.0) / 1000.0; }

/* The race's laps as scored runs (figures rounded to 1 ms as the JSON's);
 * returns how many. */
static int score_runs(const race_t *race, const double *lift_t_s, int n_lifts, score_run_t *runs)
{
    int n = race->nlaps < SCORE_MAX_RUNS ? race->nlaps : SCORE_MAX_RUNS;
    for (int i = 0; i < n; i++) {
        const race_lap_t *l = &race->laps[i];
        runs[i].run_s = ms3(l->end_s - l->start_s);
        runs[i].search_s = ms3(l->start_s);
        runs[i].over_time = l->over_time;
        runs[i].touches = 0;
        for (int k = 0; k < n_lifts; k++) runs[i].touches += lift_t_s[k] < race->global_start_s + l->start_s;
    }
    return n;
}

json_t *contest_json(const contest_t *c, const race_t *race, const double *lift_t_s, int n_lifts)
{
    score_run_t runs[SCORE_MAX_RUNS] = { { 0 } };
    int n = score_runs(race, lift_t_s, n_lifts, runs);
    double score = 0;
    int best = score_best(&c->rules, runs, n, &score);
    json_t *arr = json_array();
    for (int i = 0; i < n; i++)
        json_array_append_new(arr, json_pack("{s:i, s:f, s:f, s:i, s:b, s:f}", "lap", i + 1, "run_s", runs[i].run_s, "search_s",
                                             runs[i].search_s, "touches", runs[i].touches, "counts",
                                             score_counts(&c->rules, runs, i), "score_s", score_run(&c->rules, &runs[i])));
    json_t *j = json_pack("{s:s, s:s, s:i, s:f, s:f, s:f, s:o}", "name", c->name, "scoring", rules_words[c->rules.rule],
                          "runs", c->rules.runs, "search_divisor", c->rules.search_divisor, "touch_penalty_s",
                          c->rules.touch_penalty_s, "time_limit_s", race->limit_s, "run_scores", arr);
    json_object_set_new(j, "score_s", best >= 0 ? json_real(score) : json_null());
    json_object_set_new(j, "score_lap", best >= 0 ? json_integer(best + 1) : json_null());
    return j;
}

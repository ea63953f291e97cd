/* plots.c - the run report's page of plots against time (see plots.h). */
#include "plots.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "font.h"
#include "world/sensors/sensor.h"

/* The series: fixed ones, then one per robot part, then the watches. */
enum { CH_SPEED, CH_YAW, CH_VOLT_L, CH_VOLT_R, CH_AMP_L, CH_AMP_R, CH_WHEEL_L, CH_WHEEL_R, CH_BATT, CH_PART0 };
#define CH_WATCH0 (CH_PART0 + ROBOT_MAX_PARTS)
#define NCH (CH_WATCH0 + PLOTS_WATCH_MAX)
#define CONTACTS_MAX 1024 /* contact marks kept; more are counted, not marked */

enum { B_MIN, B_MAX, B_LAST };

struct plots {
    int nparts;
    int part_col[ROBOT_MAX_PARTS];   /* which of a part's values is plotted */
    char part_unit[ROBOT_MAX_PARTS][24]; /* that value's name (its kind's units word) */
    double (*b)[NCH][3];             /* buckets: each series' min, max, last */
    double *bt;                      /* each bucket's first sample time, s */
    size_t nb;                       /* buckets used */
    uint64_t per;                    /* samples a full bucket holds */
    uint64_t in_last;                /* samples in the last bucket */
    uint64_t nsamples;
    unsigned seen;                   /* world_collisions at the last step */
    double contact_t[CONTACTS_MAX];  /* when each contact began, s */
    int ncontacts;
};

/* The value a part's kind names `want` among its units ("dark lit
 * lit_minus_dark"), else its first: its index, its name into unit. */
static int pick_value(const char *units, const char *want, char *unit, size_t len)
{
    char buf[128];
    snprintf(buf, sizeof buf, "%s", units ? units : "value");
    int k = 0, found = -1;
    char *save = NULL;
    for (char *w = strtok_r(buf, " ", &save); w; w = strtok_r(NULL, " ", &save), k++) {
        if (k == 0 || !strcmp(w, want)) snprintf(unit, len, "%s", w);
        if (!strcmp(w, want)) found = k;
    }
    return found < 0 ? 0 : found;
}

plots_t *plots_new(const sim_state_t *s)
{
    plots_t *p = calloc(1, sizeof *p);
    if (!p) return NULL;
    p->b = malloc(PLOTS_BUCKETS * sizeof *p->b);
    p->bt = malloc(PLOTS_BUCKETS * sizeof *p->bt);
    if (!p->b || !p->bt) {
        plots_free(p);
        return NULL;
    }
    p->per = 1;
    p->nparts = s->model->cfg->robot.nparts;
    for (int i = 0; i < p->nparts; i++)
        p->part_col[i] = pick_value(s->model->cfg->robot.part[i].kind->units, "lit_minus_dark", p->part_unit[i],
                                    sizeof p->part_unit[i]);
    p->seen = world_collisions(s->world);
    plots_sample(p, s, 0, NULL);
    return p;
}

void plots_free(plots_t *p)
{
    if (!p) return;
    free(p->b);
    free(p->bt);
    free(p);
}

void plots_contacts(plots_t *p, const sim_state_t *s)
{
    unsigned n = world_collisions(s->world);
    for (; p->seen < n; p->seen++)
        if (p->ncontacts < CONTACTS_MAX) p->contact_t[p->ncontacts++] = sim_time_s(s);
}

/* Buckets full: neighbours merged in pairs, each now twice the samples. */
static void merge(plots_t *p)
{
    for (size_t j = 0; j < p->nb / 2; j++) {
        double (*a)[3] = p->b[2 * j], (*b)[3] = p->b[2 * j + 1], (*o)[3] = p->b[j];
        for (int c = 0; c < NCH; c++) {
            double mn = fmin(a[c][B_MIN], b[c][B_MIN]), mx = fmax(a[c][B_MAX], b[c][B_MAX]), last = b[c][B_LAST];
            o[c][B_MIN] = mn;
            o[c][B_MAX] = mx;
            o[c][B_LAST] = last;
        }
        p->bt[j] = p->bt[2 * j];
    }
    p->nb /= 2;
    p->per *= 2;
    p->in_last = p->per;
}

static void add(plots_t *p, double t, const double v[NCH])
{
    p->nsamples++;
    if (p->nb && p->in_last < p->per) {
        double (*o)[3] = p->b[p->nb - 1];
        for (int c = 0; c < NCH; c++) {
            o[c][B_MIN] = fmin(o[c][B_MIN], v[c]); /* fmin/fmax skip a NaN (no value yet) */
            o[c][B_MAX] = fmax(o[c][B_MAX], v[c]);
            o[c][B_LAST] = v[c];
        }
        p->in_last++;
        return;
    }
    if (p->nb == PLOTS_BUCKETS) merge(p);
    for (int c = 0; c < NCH; c++) p->b[p->nb][c][B_MIN] = p->b[p->nb][c][B_MAX] = p->b[p->nb][c][B_LAST] = v[c];
    p->bt[p->nb++] = t;
    p->in_last = 1;
}

void plots_sample(plots_t *p, const sim_state_t *s, int n, const double *watch)
{
    double v[NCH], w;
    world_velocity(s->world, &v[CH_SPEED], &w);
    v[CH_YAW] = w * 180.0 / M_PI;
    for (int i = 0; i < 2; i++) {
        v[CH_VOLT_L + i] = motor_terminal_v(&s->motor[i]);
        v[CH_AMP_L + i] = s->motor[i].i_a;
        v[CH_WHEEL_L + i] = world_wheel_rate(s->world, i);
    }
    v[CH_BATT] = sim_battery_v(s);
    for (int i = 0; i < ROBOT_MAX_PARTS; i++) {
        double vals[SENSOR_VALUES];
        int got = i < p->nparts ? sim_part_values(s, i, vals) : 0;
        v[CH_PART0 + i] = p->part_col[i] < got ? vals[p->part_col[i]] : NAN;
    }
    for (int i = 0; i < PLOTS_WATCH_MAX; i++) v[CH_WATCH0 + i] = i < n ? watch[i] : NAN;
    add(p, sim_time_s(s), v);
}

/* ---- the page ---- */

#define X0_PX 110                     /* plot boxes' left edge */
#define X1_PX (PLOTS_W_PX - 20)       /* and right edge */
#define BOX_TOP_PX 22                 /* box top below the panel's top (its title line above) */
#define BOX_H_PX 120                  /* box height */
#define C_BG 0xFFFFFFu
#define C_TEXT 0x101010u
#define C_FRAME 0x909090u
#define C_ZERO 0xC8C8C8u
#define C_LAP 0xE4EEFAu               /* a lap's span */
#define C_LAP2 0xD2E2F6u              /* every second lap's, so laps that touch stay two */
#define C_CONTACT 0xE02020u           /* a wall contact's mark */
#define PANEL_SERIES ROBOT_MAX_PARTS
static const uint32_t palette[] = { 0x1F77B4, 0xFF7F0E, 0x2CA02C, 0x9467BD, 0x8C564B, 0xE377C2, 0x17BECF, 0xBCBD22 };

typedef struct {
    char title[64];
    char unit[24];
    int n, zero;              /* series; 1: the axis includes 0 */
    double span;              /* the axis' least span, in its unit (a still robot's 1e-12 A is drawn flat) */
    int ch[PANEL_SERIES];
    char names[PANEL_SERIES][24];
} panel_t;

static void panel_add(panel_t *pn, int ch, const char *name)
{
    if (pn->n == PANEL_SERIES) return;
    pn->ch[pn->n] = ch;
    snprintf(pn->names[pn->n++], sizeof pn->names[0], "%s", name);
}

static panel_t *panel_new(panel_t *list, int *np, const char *title, const char *unit, int zero, double span)
{
    panel_t *pn = &list[(*np)++];
    memset(pn, 0, sizeof *pn);
    snprintf(pn->title, sizeof pn->title, "%s", title);
    snprintf(pn->unit, sizeof pn->unit, "%s", unit);
    pn->zero = zero;
    pn->span = span;
    return pn;
}

/* The panels this run has, into list: their count. */
static int panels_make(const plots_t *p, const sim_state_t *s, int nw, const char *const *names, panel_t *list)
{
    int np = 0;
    panel_add(panel_new(list, &np, "speed", "m/s", 1, 0.1), CH_SPEED, "speed");
    panel_add(panel_new(list, &np, "yaw rate", "deg/s", 1, 10), CH_YAW, "yaw rate");
    static const char *const title[3] = { "motor volts", "motor current", "wheel speed" }, *const unit[3] = { "V", "A", "rad/s" };
    static const double span[3] = { 1, 0.1, 1 }; /* V, A, rad/s */
    for (int k = 0; k < 3; k++) {
        panel_t *pn = panel_new(list, &np, title[k], unit[k], 1, span[k]);
        panel_add(pn, CH_VOLT_L + 2 * k, "left");
        panel_add(pn, CH_VOLT_L + 2 * k + 1, "right");
    }
    int has_batt = 0;
    for (size_t i = 0; i < p->nb; i++) has_batt |= p->b[i][CH_BATT][B_MAX] > 0;
    if (has_batt) panel_add(panel_new(list, &np, "battery", "V", 0, 0.1), CH_BATT, "battery");
    int done[ROBOT_MAX_PARTS] = { 0 };
    for (int i = 0; i < p->nparts; i++) { /* one panel per kind, a curve per sensor */
        if (done[i]) continue;
        const robot_part_t *a = &s->model->cfg->robot.part[i];
        panel_t *pn = panel_new(list, &np, a->kind->name, p->part_unit[i], !strcmp(a->kind->name, "gyro"), 1);
        for (int j = i; j < p->nparts; j++)
            if (s->model->cfg->robot.part[j].kind == a->kind) {
                panel_add(pn, CH_PART0 + j, s->model->cfg->robot.part[j].name);
                done[j] = 1;
            }
    }
    for (int i = 0; i < nw && i < PLOTS_WATCH_MAX; i++)
        panel_add(panel_new(list, &np, names[i], "", 0, 0), CH_WATCH0 + i, names[i]);
    return np;
}

/* A tick label: digits enough for its size. */
static void tick_label(double v, char *out, size_t len)
{
    double a = fabs(v);
    if (a >= 100) snprintf(out, len, "%.0f", v);
    else if (a >= 10) snprintf(out, len, "%.1f", v);
    else if (a >= 0.1 || a == 0) snprintf(out, len, "%.2f", v);
    else snprintf(out, len, "%.2g", v);
}

typedef struct {
    int x0, x1, top, bot;  /* box, px (rows top..bot, both drawn) */
    double lo, hi, t_end;  /* axis: value at bot, at top; time at x1, s */
} axis_t;

static int col_of(const axis_t *a, double t) { return a->x0 + (int)lround(t / a->t_end * (a->x1 - a->x0)); }
static int row_of(const axis_t *a, double v) { return a->bot - (int)lround((v - a->lo) / (a->hi - a->lo) * (a->bot - a->top)); }

/* The panel's value range over the run (0 included when it asks). */
static void panel_range(const plots_t *p, const panel_t *pn, axis_t *a)
{
    double lo = pn->zero ? 0 : NAN, hi = lo;
    for (int k = 0; k < pn->n; k++)
        for (size_t i = 0; i < p->nb; i++) {
            lo = fmin(lo, p->b[i][pn->ch[k]][B_MIN]);
            hi = fmax(hi, p->b[i][pn->ch[k]][B_MAX]);
        }
    if (isnan(lo)) lo = 0, hi = 1; /* nothing recorded */
    if (!(hi > lo) && !(pn->span > 0)) lo -= 1, hi += 1; /* flat: the line in the middle */
    if (hi - lo < pn->span) { /* widened about the middle, from 0 when 0 is an end */
        double mid = lo == 0 ? pn->span / 2 : hi == 0 ? -pn->span / 2 : (lo + hi) / 2;
        lo = mid - pn->span / 2;
        hi = mid + pn->span / 2;
    }
    a->lo = lo;
    a->hi = hi;
}

/* One series: each bucket's min..max span, joined to the next's last value. */
static void draw_series(image_t *im, const plots_t *p, const axis_t *a, int ch, uint32_t rgb)
{
    double px = 0, py = 0;
    int have = 0;
    for (size_t i = 0; i < p->nb; i++) {
        const double *b = p->b[i][ch];
        double x = col_of(a, p->bt[i]) + 0.5;
        if (isnan(b[B_MIN])) {
            have = 0;
            continue;
        }
        image_line(im, x, row_of(a, b[B_MIN]) + 0.5, x, row_of(a, b[B_MAX]) + 0.5, 1.5, rgb);
        double y = row_of(a, b[B_LAST]) + 0.5;
        if (have) image_line(im, px, py, x, y, 1.5, rgb);
        px = x, py = y, have = 1;
    }
}

/* The panel's frame, laps, zero line, curves, contacts, ticks and title. */
static void draw_panel(image_t *im, const plots_t *p, const sim_state_t *s, const panel_t *pn, const axis_t *a)
{
    const race_t *rc = &s->race;
    for (int i = 0; i < rc->nlaps; i++)
        image_rect(im, col_of(a, rc->laps[i].start_s), a->top, col_of(a, rc->laps[i].end_s) + 1, a->bot + 1,
                   i % 2 ? C_LAP2 : C_LAP);
    if (a->lo < 0 && a->hi > 0) image_rect(im, a->x0, row_of(a, 0), a->x1 + 1, row_of(a, 0) + 1, C_ZERO);
    image_rect(im, a->x0 - 1, a->top - 1, a->x1 + 2, a->top, C_FRAME);
    image_rect(im, a->x0 - 1, a->bot + 1, a->x1 + 2, a->bot + 2, C_FRAME);
    image_rect(im, a->x0 - 1, a->top - 1, a->x0, a->bot + 2, C_FRAME);
    image_rect(im, a->x1 + 1, a->top - 1, a->x1 + 2, a->bot + 2, C_FRAME);
    for (int k = 0; k < pn->n; k++)
        draw_series(im, p, a, pn->ch[k], palette[k % (int)(sizeof palette / sizeof palette[0])]);
    for (int i = 0; i < p->ncontacts; i++) {
        int x = col_of(a, p->contact_t[i]);
        image_rect(im, x - 1, a->bot - 8, x + 1, a->bot + 1, C_CONTACT);
    }
    char buf[96];
    double tick[2] = { a->lo, a->hi };
    int row[2] = { a->bot, a->top };
    for (int k = 0; k < 2; k++) {
        tick_label(tick[k], buf, sizeof buf);
        image_rect(im, a->x0 - 7, row[k], a->x0 - 1, row[k] + 1, C_FRAME);
        image_text(im, a->x0 - 10 - font_text_width(buf, 2), row[k] - FONT_H, 2, C_TEXT, buf);
    }
    snprintf(buf, sizeof buf, pn->unit[0] ? "%s (%s)" : "%s", pn->title, pn->unit);
    int x = a->x0;
    image_text(im, x, a->top - BOX_TOP_PX + 2, 2, C_TEXT, buf);
    x += font_text_width(buf, 2) + 24;
    for (int k = 0; k < pn->n && pn->n > 1; k++) { /* legend: each series' name in its colour */
        image_text(im, x, a->top - BOX_TOP_PX + 2, 2, palette[k % (int)(sizeof palette / sizeof palette[0])], pn->names[k]);
        x += font_text_width(pn->names[k], 2) + 16;
    }
}

static json_t *panel_json(const panel_t *pn, const axis_t *a)
{
    char lo[32], hi[32];
    tick_label(a->lo, lo, sizeof lo);
    tick_label(a->hi, hi, sizeof hi);
    json_t *names = json_array();
    for (int k = 0; k < pn->n; k++) json_array_append_new(names, json_string(pn->names[k]));
    json_t *j = json_pack("{s:s, s:s, s:o, s:[i,i,i,i], s:f, s:f, s:s, s:s}", "title", pn->title, "unit", pn->unit,
                          "series", names, "box_px", a->x0, a->top, a->x1, a->bot, "y_lo", a->lo, "y_hi", a->hi,
                          "label_lo", lo, "label_hi", hi);
    if (j) json_object_set_new(j, "zero_row_px", a->lo <= 0 && a->hi >= 0 ? json_integer(row_of(a, 0)) : json_null());
    return j;
}

/* The page's title band and the shared time axis under the last panel. */
static void draw_frame(image_t *im, const plots_t *p, const axis_t *a, const char *title)
{
    char buf[200];
    image_text(im, 20, 8, 2, C_TEXT, title);
    snprintf(buf, sizeof buf, "shaded: laps   red marks: wall contacts (%d)", p->ncontacts);
    image_text(im, 20, 30, 2, C_TEXT, buf);
    int y = a->bot + 2;
    image_rect(im, a->x0, y, a->x0 + 1, y + 6, C_FRAME);
    image_rect(im, a->x1, y, a->x1 + 1, y + 6, C_FRAME);
    image_text(im, a->x0, y + 10, 2, C_TEXT, "0 s");
    snprintf(buf, sizeof buf, "%.2f s", a->t_end);
    image_text(im, a->x1 + 1 - font_text_width(buf, 2), y + 10, 2, C_TEXT, buf);
    const char *lab = "time (s, simulation)";
    image_text(im, (a->x0 + a->x1 - font_text_width(lab, 2)) / 2, y + 10, 2, C_TEXT, lab);
}

int plots_draw(const plots_t *p, const sim_state_t *s, int n, const char *const *names, const char *title, image_t *im,
               json_t **desc)
{
    static panel_t list[9 + ROBOT_MAX_PARTS + PLOTS_WATCH_MAX];
    int np = panels_make(p, s, n, names, list);
    if (image_init(im, PLOTS_W_PX, PLOTS_TOP_PX + np * PLOTS_PANEL_PX + PLOTS_BOTTOM_PX, C_BG) != 0) return -1;
    json_t *panels = json_array();
    double t_end = sim_time_s(s) > 0 ? sim_time_s(s) : 1e-3;
    axis_t a = { 0 };
    for (int i = 0; i < np; i++) {
        a = (axis_t){ X0_PX, X1_PX, PLOTS_TOP_PX + i * PLOTS_PANEL_PX + BOX_TOP_PX, 0, 0, 0, t_end };
        a.bot = a.top + BOX_H_PX - 1;
        panel_range(p, &list[i], &a);
        draw_panel(im, p, s, &list[i], &a);
        json_array_append_new(panels, panel_json(&list[i], &a));
    }
    draw_frame(im, p, &a, title);
    *desc = json_pack("{s:o, s:f, s:I, s:I, s:i}", "panels", panels, "t_end_s", t_end, "samples",
                      (json_int_t)p->nsamples, "bucket_samples", (json_int_t)p->per, "contacts", p->ncontacts);
    if (!*desc) {
        image_free(im);
        return -1;
    }
    return 0;
}

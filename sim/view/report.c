/* report.c - run reports (see report.h). One drawing routine paints onto a
 * small canvas interface that either rasterises (PNG) or prints SVG
 * elements, so both files show the same picture. */
#include "report.h"

#include <jansson.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "font.h"
#include "mms/mms.h"
#include "image.h"
#include "io/outfile.h"
#include "plots.h"
#include "maze/solve.h"

typedef struct {
    float x, y, v; /* body centre, m; speed along the heading, m/s */
    double t;      /* sim time, s */
} sample_t;

struct report {
    const truemaze_t *maze;
    double cell_m;
    uint64_t every; /* physics steps per sample */
    sample_t *s;
    size_t n, cap;
    double vmax;    /* highest |speed| seen, m/s */
    uint8_t visited[TRUEMAZE_MAX_CELLS];
    char colour[TRUEMAZE_MAX_CELLS]; /* report_set_cells: mms colour letters */
    char text[TRUEMAZE_MAX_CELLS][12];
    int watch_n;                      /* report_watch: variables (0 none) */
    const char *const *watch_names;
    double watch_now[REPORT_WATCH_MAX]; /* their latest values */
    double *wrows;                    /* per sample: t, x, y, heading, then the values */
    size_t wn, wcap;                  /* rows kept, rows allocated */
    plots_t *plots;                   /* the page of plots against time */
};

report_t *report_new(const sim_state_t *s)
{
    report_t *r = calloc(1, sizeof *r);
    if (!r) return NULL;
    r->maze = s->maze;
    r->cell_m = s->model->cfg->world.cell_m;
    r->every = (uint64_t)llround(REPORT_SAMPLE_S / s->model->cfg->sim.step_s);
    if (r->every == 0) r->every = 1;
    r->visited[s->maze->start] = 1;
    r->plots = plots_new(s);
    if (!r->plots) {
        free(r);
        return NULL;
    }
    return r;
}

void report_free(report_t *r)
{
    if (!r) return;
    free(r->s);
    free(r->wrows);
    plots_free(r->plots);
    free(r);
}

void report_set_cells(report_t *r, const char *colours, const char *texts, size_t text_stride)
{
    for (uint16_t k = 0; k < truemaze_cells(r->maze); k++) {
        r->colour[k] = colours[k];
        snprintf(r->text[k], sizeof r->text[k], "%s", texts + k * text_stride);
    }
}

void report_watch(report_t *r, int n, const char *const *names, const double *values)
{
    r->watch_n = n < 0 ? 0 : n > REPORT_WATCH_MAX ? REPORT_WATCH_MAX : n;
    r->watch_names = names;
    memcpy(r->watch_now, values, (size_t)r->watch_n * sizeof *values);
}

/* One row of the watch table: the time, the true pose, the variables. */
static void watch_row(report_t *r, double t, double x, double y, double h)
{
    size_t cols = 4 + (size_t)r->watch_n;
    if (r->wn == r->wcap) {
        size_t cap = r->wcap ? r->wcap * 2 : 4096;
        double *p = realloc(r->wrows, cap * cols * sizeof *p);
        if (!p) return; /* out of memory: the table just stops */
        r->wrows = p;
        r->wcap = cap;
    }
    double *row = r->wrows + r->wn++ * cols;
    row[0] = t;
    row[1] = x;
    row[2] = y;
    row[3] = h;
    memcpy(row + 4, r->watch_now, (size_t)r->watch_n * sizeof *row);
}

void report_step(report_t *r, const sim_state_t *s)
{
    plots_contacts(r->plots, s);
    if (s->step % r->every) return;
    plots_sample(r->plots, s, r->watch_n, r->watch_now);
    if (r->n == r->cap) {
        size_t cap = r->cap ? r->cap * 2 : 4096;
        sample_t *p = realloc(r->s, cap * sizeof *p);
        if (!p) return; /* out of memory: the trajectory just stops */
        r->s = p;
        r->cap = cap;
    }
    double x, y, h, v, w;
    world_pose(s->world, &x, &y, &h);
    world_velocity(s->world, &v, &w);
    r->s[r->n++] = (sample_t){ (float)x, (float)y, (float)v, sim_time_s(s) };
    if (r->watch_n) watch_row(r, sim_time_s(s), x, y, h);
    if (fabs(v) > r->vmax) r->vmax = fabs(v);
    double fx = floor(x / r->cell_m), fy = floor(y / r->cell_m);
    if (fx >= 0 && fy >= 0 && fx < r->maze->width && fy < r->maze->height)
        r->visited[truemaze_cell(r->maze, (uint8_t)fx, (uint8_t)fy)] = 1;
}

void report_sibling(const char *png_path, const char *ext, char *out, size_t len)
{
    size_t n = strlen(png_path);
    if (n >= 4 && !strcmp(png_path + n - 4, ".png")) n -= 4;
    snprintf(out, len, "%.*s%s", (int)n, png_path, ext);
}

/* ---- canvas: raster or SVG ---- */

typedef struct {
    image_t *im; /* raster, or NULL */
    FILE *svg;   /* SVG, or NULL */
} canvas_t;

static void svg_colour(char out[8], uint32_t rgb) { snprintf(out, 8, "#%06x", (unsigned)(rgb & 0xFFFFFF)); }

static void c_rect(canvas_t *c, double x0, double y0, double x1, double y1, uint32_t rgb)
{
    if (c->im) image_rect(c->im, (int)lround(x0), (int)lround(y0), (int)lround(x1), (int)lround(y1), rgb);
    if (c->svg) {
        char col[8];
        svg_colour(col, rgb);
        fprintf(c->svg, "<rect x=\"%.1f\" y=\"%.1f\" width=\"%.1f\" height=\"%.1f\" fill=\"%s\"/>\n", x0, y0, x1 - x0,
                y1 - y0, col);
    }
}

static void c_line(canvas_t *c, double x0, double y0, double x1, double y1, double w, uint32_t rgb)
{
    if (c->im) image_line(c->im, x0, y0, x1, y1, w, rgb);
    if (c->svg) {
        char col[8];
        svg_colour(col, rgb);
        fprintf(c->svg,
                "<line x1=\"%.1f\" y1=\"%.1f\" x2=\"%.1f\" y2=\"%.1f\" stroke=\"%s\" stroke-width=\"%.1f\" "
                "stroke-linecap=\"round\"/>\n",
                x0, y0, x1, y1, col, w);
    }
}

static void c_disc(canvas_t *c, double x, double y, double r, uint32_t rgb)
{
    if (c->im) image_disc(c->im, x, y, r, rgb);
    if (c->svg) {
        char col[8];
        svg_colour(col, rgb);
        fprintf(c->svg, "<circle cx=\"%.1f\" cy=\"%.1f\" r=\"%.1f\" fill=\"%s\"/>\n", x, y, r, col);
    }
}

/* Polyline through n points (x, y pairs). */
static void c_polyline(canvas_t *c, const double *p, size_t n, double w, uint32_t rgb)
{
    if (c->im)
        for (size_t i = 1; i < n; i++) image_line(c->im, p[2 * i - 2], p[2 * i - 1], p[2 * i], p[2 * i + 1], w, rgb);
    if (c->svg) {
        char col[8];
        svg_colour(col, rgb);
        fputs("<polyline points=\"", c->svg);
        for (size_t i = 0; i < n; i++) fprintf(c->svg, "%s%.1f,%.1f", i ? " " : "", p[2 * i], p[2 * i + 1]);
        fprintf(c->svg, "\" fill=\"none\" stroke=\"%s\" stroke-width=\"%.1f\" stroke-linejoin=\"round\" "
                        "stroke-linecap=\"round\"/>\n", col, w);
    }
}

/* Text at scale 2 of the built-in font; SVG gets monospace text of the same size. */
#define TEXT_SCALE 2
#define LINE_PX (FONT_LINE * TEXT_SCALE)

static void c_text_at(canvas_t *c, double x, double y, int scale, uint32_t rgb, const char *s);
static void c_text(canvas_t *c, double x, double y, uint32_t rgb, const char *s) { c_text_at(c, x, y, TEXT_SCALE, rgb, s); }

static void c_text_at(canvas_t *c, double x, double y, int scale, uint32_t rgb, const char *s)
{
    if (c->im) image_text(c->im, (int)x, (int)y, scale, rgb, s);
    if (c->svg) {
        char col[8];
        svg_colour(col, rgb);
        fprintf(c->svg,
                "<text x=\"%.1f\" y=\"%.1f\" fill=\"%s\" font-family=\"monospace\" font-size=\"%d\" "
                "xml:space=\"preserve\">",
                x, y + FONT_H * scale, col, (FONT_H + 3) * scale);
        for (const char *p = s; *p; p++) {
            if (*p == '<') fputs("&lt;", c->svg);
            else if (*p == '>') fputs("&gt;", c->svg);
            else if (*p == '&') fputs("&amp;", c->svg);
            else fputc(*p, c->svg);
        }
        fputs("</text>\n", c->svg);
    }
}

/* ---- the picture ---- */

#define C_BG 0xFFFFFFu
#define C_CELL 0xF2F2F2u
#define C_VISITED 0xCFE4FAu
#define C_START 0xA8E0A8u
#define C_GOAL 0xFFDD80u
#define C_TRUE_WALL 0xB4B4B4u  /* true wall the mouse did not learn */
#define C_LEARNED 0x202020u    /* wall the mouse learned, and it is there */
#define C_WRONG 0xE000E0u      /* the mouse's wall state disagrees with the truth */
#define C_POST 0x606060u
#define C_PATH 0xD9B8F0u       /* final run path, under the trajectory */
#define C_TEXT 0x101010u
#define MARGIN_PX 20
#define SPEED_LEVELS 16 /* colour steps of the speed scale */

/* Speed colour: blue (0) - cyan - green - yellow - red (vmax). */
static uint32_t speed_colour(double f)
{
    static const double stops[5][3] = { { 32, 64, 255 }, { 0, 200, 220 }, { 40, 200, 40 }, { 250, 210, 0 }, { 230, 30, 20 } };
    if (!(f > 0)) f = 0;
    if (f > 1) f = 1;
    double p = f * 4;
    int i = (int)p;
    if (i > 3) i = 3;
    double u = p - i;
    uint32_t out = 0;
    for (int k = 0; k < 3; k++) out = out << 8 | (uint32_t)lround(stops[i][k] + (stops[i + 1][k] - stops[i][k]) * u);
    return out;
}

typedef struct {
    double cp;       /* pixels per cell */
    double ox, oy;   /* pixel of the maze's south-west corner (oy = its bottom) */
    int w, h;        /* image size */
    int text_y;      /* top of the text panel */
    char *table;     /* lap table text */
    int table_lines;
} layout_t;

static double px_x(const layout_t *L, double cells) { return L->ox + cells * L->cp; }
static double px_y(const layout_t *L, double cells) { return L->oy - cells * L->cp; }

/* The cells (start, goal, visited, the algorithm's colours) and the final
 * run's path (NULL: the run has none). */
static void draw_cells(canvas_t *c, const layout_t *L, const report_t *r, const solve_path_t *path)
{
    const truemaze_t *m = r->maze;
    double cp = L->cp;
    for (uint8_t y = 0; y < m->height; y++)
        for (uint8_t x = 0; x < m->width; x++) {
            truemaze_cell_t k = truemaze_cell(m, x, y);
            uint32_t col = k == m->start ? C_START : truemaze_is_goal(m, k) ? C_GOAL : r->visited[k] ? C_VISITED : C_CELL;
            if (r->colour[k]) col = mms_colour_rgb(r->colour[k]);
            c_rect(c, px_x(L, x), px_y(L, y + 1), px_x(L, x + 1), px_y(L, y), col);
        }

    /* final run path (NULL: the run has none) */
    if (path)
        for (int i = 0; i + 1 < path->len; i++) {
            truemaze_cell_t a = path->path[i], b = path->path[i + 1];
            c_line(c, px_x(L, truemaze_x(m, a) + 0.5), px_y(L, truemaze_y(m, a) + 0.5), px_x(L, truemaze_x(m, b) + 0.5),
                   px_y(L, truemaze_y(m, b) + 0.5), cp * 0.4, C_PATH);
        }
}

/* The walls (south and west of every cell, plus the outer north and east)
 * as the mouse learned them against the truth, the algorithm's cell texts,
 * the posts. */
static void draw_walls(canvas_t *c, const layout_t *L, const report_t *r, const maze_t *learned)
{
    const truemaze_t *m = r->maze;
    double cp = L->cp;
    double wall_px = fmax(2.0, cp * 0.08);
    for (uint8_t y = 0; y < m->height; y++)
        for (uint8_t x = 0; x < m->width; x++) {
            truemaze_cell_t k = truemaze_cell(m, x, y);
            for (uint8_t d = 0; d < 4; d++) {
                if ((d == TRUEMAZE_NORTH && y != m->height - 1) || (d == TRUEMAZE_EAST && x != m->width - 1)) continue;
                int truth = truemaze_wall(m, k, d);
                uint8_t known = learned ? maze_wall(learned, (maze_cell_t)k, d) : MAZE_WALL_UNKNOWN;
                uint32_t col;
                if (known == MAZE_WALL_UNKNOWN) {
                    if (!truth) continue;
                    col = C_TRUE_WALL;
                } else if ((known == MAZE_WALL_CLOSED) != truth) {
                    col = C_WRONG;
                } else if (truth) {
                    col = C_LEARNED;
                } else {
                    continue; /* known open, truly open */
                }
                double x0 = x, y0 = y, x1 = x, y1 = y;
                if (d == TRUEMAZE_SOUTH) x1 = x + 1;
                if (d == TRUEMAZE_NORTH) y0 = y1 = y + 1, x1 = x + 1;
                if (d == TRUEMAZE_WEST) y1 = y + 1;
                if (d == TRUEMAZE_EAST) x0 = x1 = x + 1, y1 = y + 1;
                c_line(c, px_x(L, x0), px_y(L, y0), px_x(L, x1), px_y(L, y1), wall_px, col);
            }
        }
    /* the algorithm's cell texts (mms setText), as much as fits */
    for (uint16_t k = 0; k < truemaze_cells(m); k++) {
        char t[12];
        int fit = (int)((cp - wall_px - 2) / (FONT_W + 1));
        if (!r->text[k][0] || fit < 1) continue;
        snprintf(t, sizeof t, "%.*s", fit < 11 ? fit : 11, r->text[k]);
        uint32_t bg = r->colour[k] ? mms_colour_rgb(r->colour[k]) : C_CELL;
        int dark = ((bg >> 16) & 255) + ((bg >> 8) & 255) + (bg & 255) < 300;
        c_text_at(c, px_x(L, truemaze_x(m, k)) + wall_px / 2 + 1, px_y(L, truemaze_y(m, k) + 1) + wall_px / 2 + 1, 1,
                  dark ? 0xFFFFFFu : C_TEXT, t);
    }
    for (int y = 0; y <= m->height; y++)
        for (int x = 0; x <= m->width; x++)
            c_rect(c, px_x(L, x) - wall_px / 2, px_y(L, y) - wall_px / 2, px_x(L, x) + wall_px / 2,
                   px_y(L, y) + wall_px / 2, C_POST);
}

/* The trajectory coloured by speed, the last lap thicker; the robot's last
 * position as a dot. */
static void draw_trajectory(canvas_t *c, const layout_t *L, const report_t *r, const sim_state_t *s)
{
    double cp = L->cp, cell_m = r->cell_m;
    const race_t *rc = &s->race;
    double lap0 = rc->nlaps ? rc->laps[rc->nlaps - 1].start_s : -1, lap1 = rc->nlaps ? rc->laps[rc->nlaps - 1].end_s : -1;
    double vmax = r->vmax > 0.05 ? r->vmax : 0.05, k = cp / cell_m;
    /* runs of equal colour (speed in SPEED_LEVELS steps) as one polyline each */
    double *pts = malloc((r->n + 1) * 2 * sizeof *pts);
    for (int pass = 0; pass < 2 && pts; pass++) {
        size_t np = 0;
        int run_q = -1;
        for (size_t i = 1; i < r->n; i++) {
            const sample_t *a = &r->s[i - 1], *b = &r->s[i];
            int last = b->t >= lap0 && b->t <= lap1;
            int q = (int)lround(fabs(b->v) / vmax * (SPEED_LEVELS - 1));
            if (last != pass || q != run_q) {
                if (np > 1) c_polyline(c, pts, np, pass ? 4.0 : 1.5, speed_colour((double)run_q / (SPEED_LEVELS - 1)));
                np = 0;
                run_q = -1;
                if (last != pass) continue;
                run_q = q;
                pts[0] = L->ox + a->x * k;
                pts[1] = L->oy - a->y * k;
                np = 1;
            }
            pts[2 * np] = L->ox + b->x * k;
            pts[2 * np + 1] = L->oy - b->y * k;
            np++;
        }
        if (np > 1) c_polyline(c, pts, np, pass ? 4.0 : 1.5, speed_colour((double)run_q / (SPEED_LEVELS - 1)));
    }
    free(pts);
    if (r->n) {
        const sample_t *e = &r->s[r->n - 1];
        c_disc(c, L->ox + e->x * k, L->oy - e->y * k, fmax(3.0, cp * 0.12), 0x000000);
    }
}

/* "Watch at the end: NAME=VALUE ..." (mmsim --watch) in lines of at most
 * WATCH_LINE_CHARS (the panel's narrowest width), a name that does not fit
 * beginning the next: the number of lines (0 without a watch). */
#define WATCH_LINE_CHARS 62
#define WATCH_LINES_MAX (REPORT_WATCH_MAX + 1)
static int watch_lines(const report_t *r, char lines[WATCH_LINES_MAX][WATCH_LINE_CHARS + 1])
{
    if (!r->watch_n) return 0;
    int n = 0;
    snprintf(lines[0], WATCH_LINE_CHARS + 1, "Watch at the end:");
    for (int i = 0; i < r->watch_n; i++) {
        char item[WATCH_LINE_CHARS + 1];
        snprintf(item, sizeof item, " %s=%.6g", r->watch_names[i], r->watch_now[i]);
        size_t used = strlen(lines[n]);
        if (used + strlen(item) > WATCH_LINE_CHARS && n + 1 < WATCH_LINES_MAX) {
            n++;
            used = 0;
            lines[n][0] = '\0';
        }
        snprintf(lines[n] + used, WATCH_LINE_CHARS + 1 - used, "%s", item);
    }
    return n + 1;
}

/* The text panel: title, lap table, totals, watched variables, legend, speed scale. */
static void draw_panel(canvas_t *c, const layout_t *L, const report_t *r, const sim_state_t *s, const maze_t *learned,
                       const solve_path_t *path, const char *title)
{
    const race_t *rc = &s->race;
    double vmax = r->vmax > 0.05 ? r->vmax : 0.05;
    int ty = L->text_y;
    c_text(c, MARGIN_PX, ty, C_TEXT, title);
    ty += LINE_PX + LINE_PX / 2;
    char *save = NULL, *tab = strdup(L->table ? L->table : "");
    for (char *line = strtok_r(tab, "\n", &save); line; line = strtok_r(NULL, "\n", &save)) {
        c_text(c, MARGIN_PX, ty, C_TEXT, line);
        ty += LINE_PX;
    }
    free(tab);
    char buf[160];
    snprintf(buf, sizeof buf, "Sim time %.3f s  laps %d  collisions %u  top speed %.2f m/s", sim_time_s(s), rc->nlaps,
             world_collisions(s->world), r->vmax);
    ty += LINE_PX / 2;
    c_text(c, MARGIN_PX, ty, C_TEXT, buf);
    char wl[WATCH_LINES_MAX][WATCH_LINE_CHARS + 1];
    for (int i = 0, n = watch_lines(r, wl); i < n; i++) {
        ty += LINE_PX;
        c_text(c, MARGIN_PX, ty, C_TEXT, wl[i]);
    }
    ty += LINE_PX + LINE_PX / 2;
    const struct { uint32_t col; const char *name; } legend[] = {
        { C_VISITED, "visited" }, { C_LEARNED, "learned wall" }, { C_TRUE_WALL, learned ? "unlearned wall" : "wall" },
        { C_WRONG, "wrong wall" }, { C_PATH, "final path" },
    };
    int lx = MARGIN_PX;
    for (size_t i = 0; i < sizeof legend / sizeof legend[0]; i++) {
        if (!learned && (legend[i].col == C_LEARNED || legend[i].col == C_WRONG)) continue;
        if (!path && legend[i].col == C_PATH) continue;
        int item = 20 + font_text_width(legend[i].name, TEXT_SCALE);
        if (lx > MARGIN_PX && lx + item > L->w - MARGIN_PX) { /* wrap */
            lx = MARGIN_PX;
            ty += LINE_PX + 4;
        }
        c_rect(c, lx, ty, lx + 14, ty + 14, legend[i].col);
        c_text(c, lx + 20, ty, C_TEXT, legend[i].name);
        lx += 20 + font_text_width(legend[i].name, TEXT_SCALE) + 16;
    }
    ty += LINE_PX + 4;
    c_text(c, MARGIN_PX, ty, C_TEXT, "speed 0");
    int bx = MARGIN_PX + font_text_width("speed 0 ", TEXT_SCALE), bw = 200;
    for (int i = 0; i < bw; i++) c_rect(c, bx + i, ty, bx + i + 1, ty + 14, speed_colour((double)i / (bw - 1)));
    snprintf(buf, sizeof buf, "%.2f m/s", vmax);
    c_text(c, bx + bw + 8, ty, C_TEXT, buf);
}

static void draw(canvas_t *c, const layout_t *L, const report_t *r, const sim_state_t *s, const maze_t *learned,
                 const solve_path_t *path, const char *title)
{
    c_rect(c, 0, 0, L->w, L->h, C_BG);
    draw_cells(c, L, r, path);
    draw_walls(c, L, r, learned);
    draw_trajectory(c, L, r, s);
    draw_panel(c, L, r, s, learned, path, title);
}

static int layout_make(layout_t *L, const report_t *r, const sim_state_t *s, const char *title)
{
    const truemaze_t *m = r->maze;
    int side = m->width > m->height ? m->width : m->height;
    L->cp = floor(640.0 / side);
    if (L->cp < 16) L->cp = 16;
    if (L->cp > 96) L->cp = 96;
    /* the lap table, exactly as the CLI prints it */
    size_t len = 0;
    L->table = NULL;
    FILE *f = open_memstream(&L->table, &len);
    if (!f) return -1;
    race_print_table(&s->race, f);
    fclose(f);
    L->table_lines = 0;
    int widest = 0, cur = 0;
    for (const char *p = L->table; *p; p++) {
        if (*p == '\n') {
            L->table_lines++;
            if (cur > widest) widest = cur;
            cur = 0;
        } else {
            cur++;
        }
    }
    int mw = (int)(m->width * L->cp), mh = (int)(m->height * L->cp);
    int text_w = widest * FONT_ADVANCE * TEXT_SCALE;
    if (text_w < 62 * FONT_ADVANCE * TEXT_SCALE) text_w = 62 * FONT_ADVANCE * TEXT_SCALE; /* totals line */
    if (text_w < font_text_width(title, TEXT_SCALE)) text_w = font_text_width(title, TEXT_SCALE);
    L->w = (mw > text_w ? mw : text_w) + 2 * MARGIN_PX;
    L->ox = (L->w - mw) / 2;
    L->oy = MARGIN_PX + mh;
    L->text_y = MARGIN_PX + mh + MARGIN_PX;
    char wl[WATCH_LINES_MAX][WATCH_LINE_CHARS + 1];
    L->h = L->text_y + (L->table_lines + 8 + watch_lines(r, wl)) * LINE_PX + MARGIN_PX;
    return 0;
}

/* {"columns": ["t_s", "x_m", "y_m", "heading_rad", NAME...], "rows": [[...], ...]} */
static json_t *watch_json(const report_t *r)
{
    static const char *const pose[] = { "t_s", "x_m", "y_m", "heading_rad" };
    size_t cols = 4 + (size_t)r->watch_n;
    json_t *c = json_array(), *rows = json_array();
    for (size_t k = 0; k < cols; k++)
        json_array_append_new(c, json_string(k < 4 ? pose[k] : r->watch_names[k - 4]));
    for (size_t i = 0; i < r->wn; i++) {
        json_t *row = json_array();
        for (size_t k = 0; k < cols; k++) json_array_append_new(row, json_real(r->wrows[i * cols + k]));
        json_array_append_new(rows, row);
    }
    return json_pack("{s:o, s:o}", "columns", c, "rows", rows);
}

/* The JSON file into f: 0, or -1. */
static int write_json(const report_t *r, const sim_state_t *s, const solve_path_t *final, FILE *f, const char *png,
                      const char *svg, json_t *plots, const char *title)
{
    const race_t *rc = &s->race;
    json_t *laps = json_array();
    for (int i = 0; i < rc->nlaps; i++)
        json_array_append_new(laps, json_pack("{s:i, s:f, s:f, s:f, s:b}", "lap", i + 1, "start_s", rc->laps[i].start_s,
                                              "end_s", rc->laps[i].end_s, "run_s",
                                              rc->laps[i].end_s - rc->laps[i].start_s, "over_time", rc->laps[i].over_time));
    int visited = 0;
    for (uint16_t k = 0; k < truemaze_cells(r->maze); k++) visited += r->visited[k];
    json_t *j = json_pack("{s:s, s:f, s:o, s:i, s:f, s:s, s:s, s:i}", "title", title, "sim_time_s", sim_time_s(s),
                          "laps", laps, "visited_cells", visited, "top_speed_m_s", r->vmax, "png", png, "svg", svg,
                          "trajectory_samples", (int)r->n);
    json_object_set_new(j, "final_path_cells", final ? json_integer(final->len) : json_null()); /* null: none drawn */
    json_object_set_new(j, "best_run_s", rc->best >= 0 ? json_real(rc->laps[rc->best].end_s - rc->laps[rc->best].start_s)
                                                       : json_null());
    if (r->watch_n) json_object_set_new(j, "watch", watch_json(r));
    if (j) json_object_set(j, "plots", plots);
    int rcode = j && json_dumpf(j, f, JSON_INDENT(2) | JSON_REAL_PRECISION(10)) == 0 && fputc('\n', f) != EOF ? 0 : -1;
    json_decref(j);
    return rcode;
}

/* The page of plots drawn into im (image_free it) and what it shows into
 * *desc (the JSON's "plots", with its file's name): 0, or -1 with one line in err. */
static int plots_page(const char *name, const report_t *r, const sim_state_t *s, const char *title, image_t *im,
                      json_t **desc, char *err, size_t errlen)
{
    *desc = NULL;
    if (plots_draw(r->plots, s, r->watch_n, r->watch_names, title, im, desc) != 0) {
        snprintf(err, errlen, "%s: out of memory", name);
        return -1;
    }
    json_object_set_new(*desc, "png", json_string(name));
    json_object_set_new(*desc, "sample_s", json_real(REPORT_SAMPLE_S));
    return 0;
}

/* The four files' temporaries written and closed, the plots page last (its
 * PNG the largest): 0, or -1 with one line in err. */
static int write_four(outfile_t *o, const report_t *r, const sim_state_t *s, const maze_t *learned,
                      const solve_path_t *path, const char *title, char *err, size_t errlen)
{
    layout_t L;
    if (layout_make(&L, r, s, title) != 0) {
        snprintf(err, errlen, "%s: out of memory", o[0].path);
        return -1;
    }
    image_t im, page = { 0, 0, NULL };
    if (image_init(&im, L.w, L.h, C_BG) != 0) {
        snprintf(err, errlen, "%s: out of memory", o[0].path);
        free(L.table);
        return -1;
    }
    canvas_t cv = { &im, NULL };
    draw(&cv, &L, r, s, learned, path, title);
    int rc = image_write_png_file(&im, o[0].f, o[0].path, err, errlen);
    image_free(&im);
    if (rc == 0) {
        fprintf(o[1].f, "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"%d\" height=\"%d\" viewBox=\"0 0 %d %d\">\n",
                L.w, L.h, L.w, L.h);
        canvas_t sv = { NULL, o[1].f };
        draw(&sv, &L, r, s, learned, path, title);
        fputs("</svg>\n", o[1].f);
        json_t *plots = NULL;
        rc = plots_page(o[3].path, r, s, title, &page, &plots, err, errlen);
        if (rc == 0 && write_json(r, s, path, o[2].f, o[0].path, o[1].path, plots, title) != 0) {
            snprintf(err, errlen, "%s: cannot write", o[2].path);
            rc = -1;
        }
        json_decref(plots);
    }
    free(L.table);
    for (int i = 0; i < 3 && rc == 0; i++) rc = outfile_finish(&o[i], err, errlen);
    if (rc == 0) rc = image_write_png_file(&page, o[3].f, o[3].path, err, errlen);
    image_free(&page);
    if (rc == 0) rc = outfile_finish(&o[3], err, errlen);
    return rc;
}

int report_write(const report_t *r, const sim_state_t *s, const maze_t *learned, const truemaze_t *path_on, const char *png_path,
                 const char *title, char *err, size_t errlen)
{
    static solve_path_t best;
    const solve_path_t *path = path_on && solve_best(path_on, &best) == 0 ? &best : NULL;
    char paths[REPORT_FILES][4096];
    outfile_t o[REPORT_FILES];
    int n = 0;
    snprintf(paths[0], sizeof paths[0], "%s", png_path);
    report_sibling(png_path, ".svg", paths[1], sizeof paths[1]);
    report_sibling(png_path, ".json", paths[2], sizeof paths[2]);
    report_sibling(png_path, "-plots.png", paths[3], sizeof paths[3]);
    while (n < REPORT_FILES && outfile_open(&o[n], paths[n], err, errlen) == 0) n++;
    int rc = n == REPORT_FILES ? write_four(o, r, s, learned, path, title, err, errlen) : -1;
    /* all four written before any is renamed: all four files, or none */
    for (int i = 0; i < REPORT_FILES && rc == 0; i++) rc = outfile_rename(&o[i], err, errlen);
    for (int i = 0; i < n; i++) outfile_abort(&o[i]); /* what is left after a failure */
    return rc;
}

/* hud.c - the viewer's 2D overlay (see hud.h). */
#include "hud.h"

#include <GL/gl.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "font.h"

#define PAD 8         /* pixels between things */
#define BTN_H 28      /* button height, pixels */
#define CHAR_PX (FONT_ADVANCE * HUD_TEXT_SCALE)

static const char *const labels[HUD_BTN_COUNT] = {
    "1 Bird", "2 Follow", "3 Top", "Overlay", "-", "Pause", "Step", "+", "Toggle post", "Connect", "Reset",
};

static int panel_k(int W);
static int info_bottom(int W);

static int btn_w(const char *label) { return (int)strlen(label) * CHAR_PX + 2 * PAD; }

void hud_layout(int W, int H, hud_button_t b[HUD_BTN_COUNT])
{
    for (int i = 0; i < HUD_BTN_COUNT; i++) {
        b[i].label = labels[i];
        b[i].w = btn_w(labels[i]);
        b[i].h = BTN_H;
        b[i].y = H - PAD - BTN_H;
    }
    /* lower left: cameras and overlay */
    int x = PAD;
    for (int i = HUD_BTN_BIRD; i <= HUD_BTN_OVERLAY; i++) {
        b[i].x = x;
        x += b[i].w + PAD / 2;
    }
    /* bottom centre: run controls */
    int total = 0;
    for (int i = HUD_BTN_SLOWER; i <= HUD_BTN_FASTER; i++) total += b[i].w + PAD / 2;
    x = (W - total) / 2;
    int left_end = b[HUD_BTN_OVERLAY].x + b[HUD_BTN_OVERLAY].w + PAD;
    if (x < left_end) x = left_end;
    for (int i = HUD_BTN_SLOWER; i <= HUD_BTN_FASTER; i++) {
        b[i].x = x;
        x += b[i].w + PAD / 2;
    }
    /* lower right: toggle post; above it if the row is full */
    b[HUD_BTN_POST].x = W - PAD - b[HUD_BTN_POST].w;
    if (b[HUD_BTN_POST].x < x + PAD) b[HUD_BTN_POST].y -= BTN_H + PAD;
    /* mms Reset: above Toggle post */
    b[HUD_BTN_RESET].x = W - PAD - b[HUD_BTN_RESET].w;
    b[HUD_BTN_RESET].y = b[HUD_BTN_POST].y - BTN_H - PAD;
    /* in the side panel under the info lines: Connect, under the port and baud fields */
    b[HUD_BTN_CONNECT].x = PAD / 2;
    b[HUD_BTN_CONNECT].y = info_bottom(W) + 2 * (FONT_LINE * panel_k(W) + PAD);
}

void hud_fields(int W, int H, hud_button_t f[HUD_FIELDS])
{
    (void)H;
    int lh = FONT_LINE * panel_k(W);
    for (int i = 0; i < HUD_FIELDS; i++) {
        f[i].label = i == HUD_FIELD_PORT ? "Port" : "Baud";
        f[i].x = PAD / 2;
        f[i].w = hud_panel_w(W, 0) - PAD;
        f[i].h = lh + PAD / 2;
        f[i].y = info_bottom(W) + i * (lh + PAD);
    }
}

int hud_field_hit(int W, int H, double x, double y)
{
    hud_button_t f[HUD_FIELDS];
    hud_fields(W, H, f);
    for (int i = 0; i < HUD_FIELDS; i++)
        if (x >= f[i].x && x < f[i].x + f[i].w && y >= f[i].y && y < f[i].y + f[i].h) return i;
    return -1;
}

#define SLIDER_H 18 /* slider bar height, pixels */

void hud_slider(int W, int H, hud_button_t *out)
{
    hud_button_t b[HUD_BTN_COUNT];
    hud_layout(W, H, b);
    int top = b[HUD_BTN_POST].y < b[HUD_BTN_BIRD].y ? b[HUD_BTN_POST].y : b[HUD_BTN_BIRD].y;
    out->label = "";
    out->x = PAD;
    out->w = W - 2 * PAD > 1 ? W - 2 * PAD : 1;
    out->h = SLIDER_H;
    out->y = top - PAD - SLIDER_H;
}

int hud_slider_hit(int W, int H, double x, double y)
{
    hud_button_t sl;
    hud_slider(W, H, &sl);
    return x >= sl.x && x < sl.x + sl.w && y >= sl.y && y < sl.y + sl.h;
}

double hud_slider_time(int W, int H, double x, double end_s)
{
    hud_button_t sl;
    hud_slider(W, H, &sl);
    double f = (x - sl.x) / sl.w;
    f = f < 0 ? 0 : f > 1 ? 1 : f;
    return f * end_s;
}

int hud_hit(int W, int H, double x, double y)
{
    hud_button_t b[HUD_BTN_COUNT];
    hud_layout(W, H, b);
    for (int i = 0; i < HUD_BTN_COUNT; i++)
        if (x >= b[i].x && x < b[i].x + b[i].w && y >= b[i].y && y < b[i].y + b[i].h) return i;
    return -1;
}

/* ---- the side panel and the bottom bar ---- */

static const char *const board_labels[HUD_BOARD_COUNT] = { "1", "2", "4", "8", "Button", "Reset" };

#define CONSOLE_COLS_MAX 40
#define PANEL_CHARS 18        /* the info lines' longest text, characters */
#define PANEL_MAX_PCT 45      /* the side panel takes at most this % of the window's width */
#define PANEL_BG 0x0C0D10u    /* the panel's and the bar's colour (opaque) */
#define PANEL_EDGE 0x3A3F4Au  /* the line between the panel and the scene */

/* Screen pixels per font pixel in the side panel: 2, or 1 in a small window. */
static int panel_k(int W) { return W >= 640 ? 2 : 1; }

/* The board's controls in one row, pixels. */
static int ctl_row_w(void)
{
    int w = 0;
    for (int i = 0; i < HUD_BOARD_COUNT; i++) w += btn_w(board_labels[i]) + (i == HUD_BOARD_SW3 ? PAD : PAD / 2);
    return w - PAD / 2;
}

int hud_panel_w(int W, int board)
{
    int w = PANEL_CHARS * FONT_ADVANCE * panel_k(W) + 2 * PAD;
    if (board && w < ctl_row_w() + 2 * PAD) w = ctl_row_w() + 2 * PAD;
    if (board && w < CONSOLE_COLS_MAX * FONT_ADVANCE + 2 * PAD) w = CONSOLE_COLS_MAX * FONT_ADVANCE + 2 * PAD;
    return w > W * PANEL_MAX_PCT / 100 ? W * PANEL_MAX_PCT / 100 : w;
}

/* The status line's top in a W x H window: above the slider in a replay,
 * in the slider's place in a live run. */
static int status_y(int W, int H, int replay)
{
    hud_button_t sl;
    hud_slider(W, H, &sl);
    return replay ? sl.y - FONT_LINE * HUD_TEXT_SCALE - PAD : sl.y;
}

/* The bottom bar's top: the same in a live run and a replay (the scene the
 * same size in both), over the status line, the slider, the buttons and an
 * mms run's Reset. */
static int bar_top(int W, int H)
{
    hud_button_t b[HUD_BTN_COUNT];
    hud_layout(W, H, b);
    int y = status_y(W, H, 1);
    if (b[HUD_BTN_RESET].y < y) y = b[HUD_BTN_RESET].y;
    y -= PAD / 2;
    return y < 0 ? 0 : y;
}

void hud_scene_rect(int W, int H, int board, hud_button_t *out)
{
    int pw = hud_panel_w(W, board), h = bar_top(W, H);
    *out = (hud_button_t){ pw, 0, W - pw > 1 ? W - pw : 1, h > 1 ? h : 1, "" };
}

/* Below the info lines. */
static int info_bottom(int W) { return PAD + HUD_INFO_LINES * FONT_LINE * panel_k(W) + PAD; }

void hud_board_layout(int W, int H, hud_board_layout_t *o)
{
    memset(o, 0, sizeof *o);
    int pw = hud_panel_w(W, 1), x = PAD, y = info_bottom(W), kc = panel_k(W);
    int bh = kc == HUD_TEXT_SCALE ? BTN_H : FONT_LINE * kc + PAD; /* the buttons' height: smaller in a small window */
    o->ctl_scale = kc;
    for (int i = 0; i < HUD_BOARD_COUNT; i++) { /* in rows as wide as the panel */
        hud_button_t *c = &o->ctl[i];
        c->label = board_labels[i];
        c->w = (int)strlen(c->label) * FONT_ADVANCE * kc + 2 * PAD;
        if (i > 0 && x + c->w > pw - PAD / 2) {
            x = PAD;
            y += bh + PAD / 2;
        }
        c->x = x;
        c->y = y;
        c->h = bh;
        x += c->w + (i == HUD_BOARD_SW3 ? PAD : PAD / 2); /* a gap after the switches */
    }
    o->leds = (hud_button_t){ PAD, y + bh + PAD / 2, pw - 2 * PAD, FONT_LINE * kc, "" };
    /* the console: the panel's width, rows down to the bottom bar */
    int k = pw - 2 * PAD >= CONSOLE_COLS_MAX * FONT_ADVANCE * 2 ? 2 : 1, cw = FONT_ADVANCE * k, lh = FONT_LINE * k;
    int top = o->leds.y + o->leds.h + PAD / 2, bottom = bar_top(W, H);
    o->console_scale = k;
    o->cols = (pw - 2 * PAD) / cw;
    if (o->cols > CONSOLE_COLS_MAX) o->cols = CONSOLE_COLS_MAX;
    if (o->cols < 1) o->cols = 1;
    o->rows = (bottom - top - PAD) / lh;
    if (o->rows > HUD_CONSOLE_LINES) o->rows = HUD_CONSOLE_LINES;
    if (o->rows < 0) o->rows = 0;
    o->console = (hud_button_t){ PAD / 2, top, o->cols * cw + PAD, o->rows * lh + PAD, "" };
}

int hud_board_hit(int W, int H, double x, double y)
{
    hud_board_layout_t l;
    hud_board_layout(W, H, &l);
    for (int i = 0; i < HUD_BOARD_COUNT; i++) {
        const hud_button_t *c = &l.ctl[i];
        if (x >= c->x && x < c->x + c->w && y >= c->y && y < c->y + c->h) return i;
    }
    return -1;
}

#define ROWS_MAX (2 * HUD_CONSOLE_LINES)
#define LINE_BACK_MAX 16384 /* bytes looked back for the start of the first line */

int hud_console_rows(const char *c, size_t n, int cols, int rows, char out[][129])
{
    if (cols > 128) cols = 128;
    if (rows > ROWS_MAX) rows = ROWS_MAX;
    if (cols < 1 || rows < 1 || !c) return 0;
    /* enough of the tail for `rows` rows: each takes at most cols characters and a CR LF */
    size_t want = (size_t)rows * (size_t)(cols + 2) + 2, i = n > want ? n - want : 0;
    for (size_t back = 0; i > 0 && c[i - 1] != '\n' && back < LINE_BACK_MAX; back++) i--; /* from a line's start: wraps as drawn */
    int filled = 0, cur = 0, len = 0; /* rows started, the current one (ring index), its length */
    for (; i < n; i++) {
        char ch = c[i];
        if (ch == '\r') continue;
        if (!filled || (ch != '\n' && len == cols)) { /* a row starts: the first, or a wrap */
            cur = filled++ % rows;
            out[cur][len = 0] = '\0';
        }
        if (ch == '\n') {
            if (i + 1 < n) { /* a newline at the very end starts no row */
                cur = filled++ % rows;
                out[cur][len = 0] = '\0';
            }
            continue;
        }
        out[cur][len++] = ch == '\t' ? ' ' : ch >= ' ' && ch <= '~' ? ch : '?';
        out[cur][len] = '\0';
    }
    if (filled <= rows) return filled;
    char tmp[ROWS_MAX][129]; /* the ring, oldest row first */
    for (int r = 0; r < rows; r++) memcpy(tmp[r], out[(filled + r) % rows], sizeof tmp[0]);
    memcpy(out, tmp, (size_t)rows * sizeof tmp[0]);
    return rows;
}

static void mmss(double s, char out[16])
{
    long ms = lround(s * 1000.0);
    if (ms < 0) ms = 0;
    snprintf(out, 16, "%ld:%02ld.%03ld", ms / 60000 % 1000, (ms / 1000) % 60, ms % 1000);
}

void hud_timers(const snap_t *s, char global[16], char lap[16], int *over_time)
{
    const race_t *r = &s->race;
    double t = s->time_s, g = race_global_s(r, t), l = 0;
    if (r->in_run) l = t - r->run_start_s;
    else if (r->nlaps) l = r->laps[r->nlaps - 1].end_s - r->laps[r->nlaps - 1].start_s;
    mmss(g, global);
    mmss(l, lap);
    *over_time = r->over_time || g > r->limit_s;
}

static void col(uint32_t rgb, float a)
{
    glColor4f((float)((rgb >> 16) & 255) / 255.f, (float)((rgb >> 8) & 255) / 255.f, (float)(rgb & 255) / 255.f, a);
}

static void rect(int x, int y, int w, int h, uint32_t rgb, float a)
{
    col(rgb, a);
    glBegin(GL_QUADS);
    glVertex2i(x, y), glVertex2i(x + w, y), glVertex2i(x + w, y + h), glVertex2i(x, y + h);
    glEnd();
}

static void text_k(int x, int y, uint32_t rgb, const char *s, int k)
{
    col(rgb, 1);
    glBegin(GL_QUADS);
    for (; *s; s++, x += FONT_ADVANCE * k)
        for (int row = 0; row < FONT_H; row++) {
            int bits = font_row(*s, row);
            for (int c = 0; c < FONT_W; c++)
                if (bits & (1 << (FONT_W - 1 - c))) {
                    int px = x + c * k, py = y + row * k;
                    glVertex2i(px, py), glVertex2i(px + k, py), glVertex2i(px + k, py + k), glVertex2i(px, py + k);
                }
        }
    glEnd();
}

static void text(int x, int y, uint32_t rgb, const char *s) { text_k(x, y, rgb, s, HUD_TEXT_SCALE); }

#define LINE (FONT_LINE * HUD_TEXT_SCALE)

/* The board's switches, button, reset, LEDs and console (hud.h). */
static void draw_board(const hud_board_t *bd, int W, int H)
{
    hud_board_layout_t l;
    hud_board_layout(W, H, &l);
    for (int i = 0; i < HUD_BOARD_COUNT; i++) {
        const hud_button_t *c = &l.ctl[i];
        int on = i <= HUD_BOARD_SW3 ? (bd->switches >> i) & 1u : i == HUD_BOARD_BUTTON && bd->button;
        rect(c->x, c->y, c->w, c->h, on ? 0x3070D0u : 0x404040u, 1);
        text_k(c->x + (c->w - font_text_width(c->label, l.ctl_scale)) / 2, c->y + (c->h - FONT_H * l.ctl_scale) / 2, 0xFFFFFFu,
               c->label, l.ctl_scale);
    }
    int x = l.leds.x, n = bd->nleds < HUD_BOARD_LEDS ? bd->nleds : HUD_BOARD_LEDS, lh = l.leds.h;
    for (int i = 0; i < n; i++) { /* a lamp and its name */
        const char *name = bd->led_name[i] ? bd->led_name[i] : "LED";
        int w = lh + PAD / 2 + font_text_width(name, l.ctl_scale) + PAD;
        rect(x - PAD / 2, l.leds.y, w, lh, 0x000000u, 1);
        rect(x + 2, l.leds.y + 2, lh - 4, lh - 4, bd->led[i] ? HUD_LED_LIT : HUD_LED_DARK, 1);
        text_k(x + lh + PAD / 2, l.leds.y + (lh - FONT_H * l.ctl_scale) / 2, 0xFFFFFFu, name, l.ctl_scale);
        x += w + PAD / 2;
    }
    if (l.rows < 1) return;
    char rows[HUD_CONSOLE_LINES][129];
    int k = l.console_scale, nr = hud_console_rows(bd->console, bd->console_len, l.cols, l.rows, rows);
    rect(l.console.x, l.console.y, l.console.w, (nr > 0 ? nr : 1) * FONT_LINE * k + PAD, 0x000000u, 1); /* as tall as the text */
    for (int r = 0; r < nr; r++) text_k(l.console.x + PAD / 2, l.console.y + PAD / 2 + r * FONT_LINE * k, HUD_CONSOLE_TEXT, rows[r], k);
}

/* The firmware's state (mouse.h's MOUSE_* in order), as the panel names it. */
static const char *const state_names[] = { "Searching", "At start", "Speed run", "Returning", "Done", "No goal", "Crashed" };

/* The state line: the firmware's own, else (none published, or command
 * mode: an mms algorithm or a link drives) what the contest clock knows. */
static const char *state_text(const snap_t *s, int st)
{
    if (st >= 0 && st < (int)(sizeof state_names / sizeof state_names[0])) return state_names[st];
    const race_t *r = &s->race;
    return r->in_run ? "On a run" : r->started ? "Between runs" : "Not started";
}

int hud_lap_rows(const race_t *r, char out[][32])
{
    char t[16];
    int n = 0, first = r->nlaps > HUD_LAP_ROWS ? r->nlaps - HUD_LAP_ROWS : 0;
    snprintf(out[n++], 32, "Lap  Run time");
    for (int i = first; i < r->nlaps; i++) {
        mmss(r->laps[i].end_s - r->laps[i].start_s, t);
        snprintf(out[n++], 32, "%2d  %s%s", i + 1, t, i == r->best ? " *" : r->laps[i].over_time ? " !" : "");
    }
    if (r->best >= 0 && r->best < r->nlaps) {
        mmss(r->laps[r->best].end_s - r->laps[r->best].start_s, t);
        snprintf(out[n++], 32, "Best %s", t);
    } else {
        snprintf(out[n++], 32, "Best -");
    }
    return n;
}

/* The side panel's info lines: timers, time and speed factor, the robot's
 * speed, the mouse's state, the lap table. */
static void draw_info(const snap_t *s, const hud_info_t *in, int W)
{
    int k = panel_k(W), lh = FONT_LINE * k, y = PAD;
    char g[16], l[16], line[96], laps[HUD_LAP_ROWS + 2][32];
    int over;
    hud_timers(s, g, l, &over);
    uint32_t tc = over ? 0xFF3030u : 0xFFFFFFu;
    snprintf(line, sizeof line, "Global %s", g);
    text_k(PAD, y, tc, line, k);
    snprintf(line, sizeof line, "Lap    %s", l);
    text_k(PAD, y += lh, tc, line, k);
    if (in->replay) snprintf(line, sizeof line, "Log %.2f/%.2f", in->replay_s, in->replay_end_s);
    else snprintf(line, sizeof line, "Sim %.3f s", s->time_s);
    text_k(PAD, y += lh, 0xB0B0B0u, line, k);
    snprintf(line, sizeof line, "x%g%s  %.2f m/s", in->speed, in->paused ? " ||" : "", in->v_m_s);
    text_k(PAD, y += lh, 0xB0B0B0u, line, k);
    text_k(PAD, y += lh, 0x80D0FFu, state_text(s, in->mouse_state), k);
    int n = hud_lap_rows(&s->race, laps);
    for (int i = 0; i < n; i++) text_k(PAD, y += lh, i == 0 ? 0xB0B0B0u : 0xFFFFFFu, laps[i], k);
}

/* Port and baud fields (the tail of a long port name; a cursor and a
 * lighter box while typing) and Connect, on opaque boxes. */
static void draw_fields(const hud_info_t *in, int W, int H)
{
    hud_button_t f[HUD_FIELDS];
    hud_fields(W, H, f);
    for (int i = 0; i < HUD_FIELDS; i++) {
        char val[64], shown[80];
        int ed = in->editing == i;
        if (i == HUD_FIELD_PORT) snprintf(val, sizeof val, "%s%s", in->port && *in->port ? in->port : ed ? "" : "(none)", ed ? "_" : "");
        else if (in->baud_text) snprintf(val, sizeof val, "%s%s", in->baud_text, ed ? "_" : "");
        else snprintf(val, sizeof val, "%ld", in->baud);
        int k = panel_k(W), fit = (f[i].w - 2 * PAD) / (FONT_ADVANCE * k) - 5; /* characters after the label */
        size_t n = strlen(val), room = fit > 1 ? (size_t)fit : 1;
        snprintf(shown, sizeof shown, "%s %s", f[i].label, n > room ? val + n - room : val);
        rect(f[i].x, f[i].y, f[i].w, f[i].h, ed ? 0x505868u : 0x303030u, 1);
        text_k(f[i].x + PAD, f[i].y + PAD / 2, 0xFFFFFFu, shown, k);
    }
}

/* The buttons (Reset in mms runs only, Connect where a link can be made)
 * and the replay's slider. */
static void draw_buttons(const snap_t *s, const hud_info_t *in, int W, int H)
{
    hud_button_t b[HUD_BTN_COUNT];
    hud_layout(W, H, b);
    for (int i = 0; i < HUD_BTN_COUNT; i++) {
        if ((i == HUD_BTN_RESET && !in->mms) || (i == HUD_BTN_CONNECT && !in->link_ok)) continue;
        int on = (i <= HUD_BTN_TOP && in->camera == i + 1) || (i == HUD_BTN_OVERLAY && in->overlay) ||
                 (i == HUD_BTN_PAUSE && in->paused) || (i == HUD_BTN_POST && s->centre_post);
        rect(b[i].x, b[i].y, b[i].w, b[i].h, on ? 0x3070D0u : 0x404040u, 1);
        text(b[i].x + PAD, b[i].y + (BTN_H - FONT_H * HUD_TEXT_SCALE) / 2, 0xFFFFFFu, b[i].label);
    }
    hud_button_t sl;
    hud_slider(W, H, &sl);
    if (in->replay) { /* bar, the part played, a knob */
        double frac = in->replay_end_s > 0 ? in->replay_s / in->replay_end_s : 0;
        int kx = sl.x + (int)lround((frac < 0 ? 0 : frac > 1 ? 1 : frac) * sl.w);
        rect(sl.x, sl.y + sl.h / 3, sl.w, sl.h / 3, 0x404040u, 1);
        rect(sl.x, sl.y + sl.h / 3, kx - sl.x, sl.h / 3, 0x3070D0u, 1);
        rect(kx - 4, sl.y, 8, sl.h, 0xF0F0F0u, 1);
    }
}

void hud_draw(const snap_t *s, const hud_info_t *in, int W, int H)
{
    glViewport(0, 0, W, H);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(0, W, H, 0, -1, 1);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_LIGHTING);
    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    /* the side panel and the bottom bar, opaque: the scene stays in its rectangle */
    hud_button_t sc;
    hud_scene_rect(W, H, in->board != NULL, &sc);
    rect(0, 0, sc.x, H, PANEL_BG, 1);
    rect(sc.x - 1, 0, 1, sc.h, PANEL_EDGE, 1);
    rect(0, sc.h, W, H - sc.h, PANEL_BG, 1);
    draw_info(s, in, W);
    if (in->link_ok) draw_fields(in, W, H);
    draw_buttons(s, in, W, H);
    if (in->board) draw_board(in->board, W, H);
    if (in->status && *in->status)
        text(PAD, status_y(W, H, in->replay), 0xFFE080u, in->status);
    glDisable(GL_BLEND);
}

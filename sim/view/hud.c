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
    /* upper right: connect, under the port and baud fields */
    b[HUD_BTN_CONNECT].x = W - PAD - b[HUD_BTN_CONNECT].w;
    b[HUD_BTN_CONNECT].y = PAD + 2 * (FONT_LINE * HUD_TEXT_SCALE + PAD);
}

#define FIELD_CHARS 19 /* "Port " + 14 characters */

void hud_fields(int W, int H, hud_button_t f[HUD_FIELDS])
{
    (void)H;
    int fw = FIELD_CHARS * CHAR_PX + 2 * PAD, fx = W - PAD - fw;
    for (int i = 0; i < HUD_FIELDS; i++) {
        f[i].label = i == HUD_FIELD_PORT ? "Port" : "Baud";
        f[i].x = fx;
        f[i].w = fw;
        f[i].h = FONT_LINE * HUD_TEXT_SCALE + PAD / 2;
        f[i].y = PAD / 2 + i * (FONT_LINE * HUD_TEXT_SCALE + PAD);
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

/* ---- a board's panel, under the timers ---- */

static const char *const board_labels[HUD_BOARD_COUNT] = { "1", "2", "4", "8", "Button", "Reset" };

#define TIMERS_BOTTOM (3 * FONT_LINE * HUD_TEXT_SCALE + 2 * PAD) /* below the timers' box */
#define CONSOLE_COLS_MAX 40

void hud_board_layout(int W, int H, hud_board_layout_t *o)
{
    memset(o, 0, sizeof *o);
    int x = PAD, y = TIMERS_BOTTOM;
    for (int i = 0; i < HUD_BOARD_COUNT; i++) {
        hud_button_t *c = &o->ctl[i];
        c->label = board_labels[i];
        c->x = x;
        c->y = y;
        c->w = btn_w(c->label);
        c->h = BTN_H;
        x += c->w + (i == HUD_BOARD_SW3 ? PAD : PAD / 2); /* a gap after the switches */
    }
    o->leds = (hud_button_t){ PAD, y + BTN_H + PAD / 2, x - PAD, FONT_LINE * HUD_TEXT_SCALE, "" };
    /* the console: big text in a big window; rows down to the status line above the bottom row */
    int k = W >= 800 && H >= 560 ? 2 : 1, cw = FONT_ADVANCE * k, lh = FONT_LINE * k;
    int top = o->leds.y + o->leds.h + PAD / 2, bottom = H - PAD - BTN_H - FONT_LINE * HUD_TEXT_SCALE - 2 * PAD;
    o->console_scale = k;
    o->cols = (W - 4 * PAD) / cw;
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
        rect(c->x, c->y, c->w, c->h, on ? 0x3070D0u : 0x404040u, 0.85f);
        text(c->x + PAD, c->y + (BTN_H - FONT_H * HUD_TEXT_SCALE) / 2, 0xFFFFFFu, c->label);
    }
    int x = l.leds.x, n = bd->nleds < HUD_BOARD_LEDS ? bd->nleds : HUD_BOARD_LEDS;
    for (int i = 0; i < n; i++) { /* a lamp and its name */
        const char *name = bd->led_name[i] ? bd->led_name[i] : "LED";
        int w = LINE + PAD / 2 + font_text_width(name, HUD_TEXT_SCALE) + PAD;
        rect(x - PAD / 2, l.leds.y, w, l.leds.h, 0x000000u, 0.55f);
        rect(x + 2, l.leds.y + 2, LINE - 4, LINE - 4, bd->led[i] ? HUD_LED_LIT : HUD_LED_DARK, 1);
        text(x + LINE + PAD / 2, l.leds.y + (LINE - FONT_H * HUD_TEXT_SCALE) / 2, 0xFFFFFFu, name);
        x += w + PAD / 2;
    }
    if (l.rows < 1) return;
    char rows[HUD_CONSOLE_LINES][129];
    int k = l.console_scale, nr = hud_console_rows(bd->console, bd->console_len, l.cols, l.rows, rows);
    rect(l.console.x, l.console.y, l.console.w, (nr > 0 ? nr : 1) * FONT_LINE * k + PAD, 0x000000u, 0.6f); /* as tall as the text */
    for (int r = 0; r < nr; r++) text_k(l.console.x + PAD / 2, l.console.y + PAD / 2 + r * FONT_LINE * k, HUD_CONSOLE_TEXT, rows[r], k);
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

    /* upper left: timers */
    char g[16], l[16], line[96];
    int over;
    hud_timers(s, g, l, &over);
    uint32_t tc = over ? 0xFF3030u : 0xFFFFFFu;
    rect(PAD / 2, PAD / 2, 30 * CHAR_PX, 3 * LINE + PAD, 0x000000u, 0.55f);
    snprintf(line, sizeof line, "Global %s", g);
    text(PAD, PAD, tc, line);
    snprintf(line, sizeof line, "Lap    %s", l);
    text(PAD, PAD + LINE, tc, line);
    if (in->replay)
        snprintf(line, sizeof line, "Log %.3f/%.3f x%g%s", in->replay_s, in->replay_end_s, in->speed,
                 in->paused ? " paused" : "");
    else
        snprintf(line, sizeof line, "Sim %.3f s  x%g%s", s->time_s, in->speed, in->paused ? "  paused" : "");
    text(PAD, PAD + 2 * LINE, 0xB0B0B0u, line);

    /* upper right: serial port and baud fields (the tail of a long port
     * name; a cursor and a lighter box while typing) */
    hud_button_t f[HUD_FIELDS];
    hud_fields(W, H, f);
    for (int i = 0; i < HUD_FIELDS; i++) {
        char val[64], shown[80];
        int ed = in->editing == i;
        if (i == HUD_FIELD_PORT) snprintf(val, sizeof val, "%s%s", in->port && *in->port ? in->port : ed ? "" : "(none)", ed ? "_" : "");
        else if (in->baud_text) snprintf(val, sizeof val, "%s%s", in->baud_text, ed ? "_" : "");
        else snprintf(val, sizeof val, "%ld", in->baud);
        size_t n = strlen(val), room = FIELD_CHARS - 5;
        snprintf(shown, sizeof shown, "%s %s", f[i].label, n > room ? val + n - room : val);
        rect(f[i].x, f[i].y, f[i].w, f[i].h, ed ? 0x505868u : 0x303030u, 0.85f);
        text(f[i].x + PAD, f[i].y + PAD / 2, 0xFFFFFFu, shown);
    }

    /* buttons */
    hud_button_t b[HUD_BTN_COUNT];
    hud_layout(W, H, b);
    for (int i = 0; i < HUD_BTN_COUNT; i++) {
        if (i == HUD_BTN_RESET && !in->mms) continue;
        int on = (i <= HUD_BTN_TOP && in->camera == i + 1) || (i == HUD_BTN_OVERLAY && in->overlay) ||
                 (i == HUD_BTN_PAUSE && in->paused) || (i == HUD_BTN_POST && s->centre_post);
        rect(b[i].x, b[i].y, b[i].w, b[i].h, on ? 0x3070D0u : 0x404040u, 0.85f);
        text(b[i].x + PAD, b[i].y + (BTN_H - FONT_H * HUD_TEXT_SCALE) / 2, 0xFFFFFFu, b[i].label);
    }
    hud_button_t sl;
    hud_slider(W, H, &sl);
    if (in->replay) { /* bar, the part played, a knob */
        double frac = in->replay_end_s > 0 ? in->replay_s / in->replay_end_s : 0;
        int kx = sl.x + (int)lround((frac < 0 ? 0 : frac > 1 ? 1 : frac) * sl.w);
        rect(sl.x, sl.y + sl.h / 3, sl.w, sl.h / 3, 0x404040u, 0.85f);
        rect(sl.x, sl.y + sl.h / 3, kx - sl.x, sl.h / 3, 0x3070D0u, 0.95f);
        rect(kx - 4, sl.y, 8, sl.h, 0xF0F0F0u, 1);
    }
    if (in->board) draw_board(in->board, W, H);
    if (in->status && *in->status) {
        int y = (in->replay ? sl.y : b[HUD_BTN_BIRD].y) - LINE - PAD;
        rect(PAD / 2, y - PAD / 2, (int)strlen(in->status) * CHAR_PX + PAD, LINE + PAD / 2, 0x000000u, 0.55f);
        text(PAD, y, 0xFFE080u, in->status);
    }
    glDisable(GL_BLEND);
}

/* mms.c - the mms text API served to a child process (mms.h). */
#include "mms.h"

#include <errno.h>
#include <fcntl.h>
#include <jansson.h>
#include <limits.h>
#include <stdarg.h>
#include <math.h>
#include <poll.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

#include "io/escape.h"
#include "mouse.h"
#include "world/sim.h"
#include "world/world.h"

/* what the simulation steps for; MOVE_WAIT: an idle algorithm's wasReset, answered when Reset is pressed */
enum { MOVE_NONE = 0, MOVE_SENSE, MOVE_FORWARD, MOVE_TURN, MOVE_RESET, MOVE_WAIT };

/* ---- stats (mms Stats.cpp semantics) ---- */

void mms_stats_init(mms_stats_t *s) { memset(s, 0, sizeof *s); }

void mms_stats_start_run(mms_stats_t *s)
{
    s->cur_halves = s->cur_turns = 0;
    s->cur_eff = s->penalty;
    s->total_eff += s->penalty;
    s->penalty = 0;
    s->in_run = 1;
}

void mms_stats_distance(mms_stats_t *s, int halves)
{
    float cells = halves / 2.0f;
    float eff = cells > 2 ? cells / 2.0f + 1.0f : cells;
    s->total_halves += halves;
    s->total_eff += eff;
    if (s->in_run) {
        s->cur_halves += halves;
        s->cur_eff += eff;
    }
}

void mms_stats_turn(mms_stats_t *s)
{
    s->total_turns++;
    if (s->in_run) s->cur_turns++;
}

void mms_stats_finish_run(mms_stats_t *s)
{
    s->in_run = 0;
    s->solved = 1;
    float cur = s->cur_turns + s->cur_eff, best = s->best_turns + s->best_eff;
    if (!s->has_best || cur < best) {
        s->has_best = 1;
        s->best_turns = s->cur_turns;
        s->best_halves = s->cur_halves;
        s->best_eff = s->cur_eff;
    }
}

void mms_stats_end_unfinished(mms_stats_t *s) { s->in_run = 0; }
void mms_stats_reset_penalty(mms_stats_t *s) { s->penalty = 15.0f; }

float mms_stats_score(const mms_stats_t *s)
{
    if (!s->solved) return 2000.0f;
    return s->best_eff + s->best_turns + 0.1f * (s->total_eff + s->total_turns);
}

int mms_stats_get(const mms_stats_t *s, const char *name, char *out, size_t len)
{
    static const char *const names[] = { "total-distance", "total-turns", "best-run-distance", "best-run-turns",
                                         "current-run-distance", "current-run-turns", "total-effective-distance",
                                         "best-run-effective-distance", "current-run-effective-distance", "score" };
    int k = -1;
    for (int i = 0; i < 10; i++)
        if (!strcmp(name, names[i])) k = i;
    if (k < 0) return -1;
    int best = k == 2 || k == 3 || k == 7;
    if (best && !s->has_best) {
        snprintf(out, len, "-1");
        return 0;
    }
    switch (k) {
    case 0: snprintf(out, len, "%d", s->total_halves / 2); break;
    case 1: snprintf(out, len, "%d", s->total_turns); break;
    case 2: snprintf(out, len, "%d", s->best_halves / 2); break;
    case 3: snprintf(out, len, "%d", s->best_turns); break;
    case 4: snprintf(out, len, "%d", s->cur_halves / 2); break;
    case 5: snprintf(out, len, "%d", s->cur_turns); break;
    case 6: snprintf(out, len, "%g", (double)s->total_eff); break;
    case 7: snprintf(out, len, "%g", (double)s->best_eff); break;
    case 8: snprintf(out, len, "%g", (double)s->cur_eff); break;
    default: snprintf(out, len, "%g", (double)mms_stats_score(s)); break;
    }
    return 0;
}

uint32_t mms_colour_rgb(char letter)
{
    static const char letters[] = "kbacgorwyBCAGRY";
    static const uint32_t rgb[] = { 0x000000, 0x0000FF, 0xA0A0A4, 0x00FFFF, 0x00FF00, 0xFFA500, 0xFF0000, 0xFFFFFF,
                                    0xFFFF00, 0x000080, 0x008080, 0x808080, 0x008000, 0x800000, 0x808000 };
    const char *p = letter ? strchr(letters, letter) : NULL;
    return p ? rgb[p - letters] : 0;
}

/* ---- commands ---- */

void mms_init(mms_t *m, const mms_opts_t *o, const truemaze_t *truth)
{
    memset(m, 0, sizeof *m);
    m->o = *o;
    m->truth = truth;
    m->to_child = m->from_child = m->err_fd = -1;
    guard_init(&m->guard);
    m->exit_code = -1;
    m->reason = "running";
    const char *c = o->command ? o->command : "";
    io_escape(m->shown, sizeof m->shown, c, strnlen(c, 64));
    mms_stats_init(&m->stats);
}

/* wasReset: true once Reset was pressed, until ackReset. An algorithm that
 * asks MMS_IDLE_POLLS times without a move idles (it waits for Reset): then
 * Reset is pressed now (reset_on_idle), or the answer waits while the clock
 * runs (MOVE_WAIT: to the reset time, or the viewer's button), or nobody
 * will press it and the run ends (m->idle). Returns 1 when the answer waits. */
static int answer_was_reset(mms_t *m, struct sim_state_s *s, char *resp, size_t len)
{
    if (!m->was_reset && ++m->idle_polls >= MMS_IDLE_POLLS) {
        if (m->o.reset_on_idle) {
            m->was_reset = 1;
        } else if (s && (m->o.reset_at_s >= 0 || m->o.idle_wait)) {
            m->pending = MOVE_WAIT;
            return 1;
        } else if (s) {
            m->idle = 1;
            resp[0] = '\0';
            return 0;
        }
    }
    snprintf(resp, len, "%s", m->was_reset ? "true" : "false");
    return 0;
}

/* Qt's QString::toInt as mms uses it: the whole token a base-10 integer,
 * else 0 with ok = 0. */
static int to_int(const char *t, int *ok)
{
    char *end;
    errno = 0;
    long v = strtol(t, &end, 10);
    if (errno || end == t || *end || v < INT_MIN || v > INT_MAX) {
        *ok = 0;
        return 0;
    }
    return (int)v;
}

static int dir_of(const char *t)
{
    if (strlen(t) != 1) return -1;
    switch (t[0]) {
    case 'n': case 'N': return TRUEMAZE_NORTH;
    case 'e': case 'E': return TRUEMAZE_EAST;
    case 's': case 'S': return TRUEMAZE_SOUTH;
    case 'w': case 'W': return TRUEMAZE_WEST;
    default: return -1;
    }
}

static int in_maze(const mms_t *m, int x, int y)
{
    return x >= 0 && y >= 0 && x < m->truth->width && y < m->truth->height;
}

/* Is there a wall on side d of cell (x, y): the maze file or the robot's
 * map (unknown = no wall: mms assumes none until seen). */
static int wall_at(const mms_t *m, int x, int y, uint8_t d)
{
    truemaze_cell_t c = truemaze_cell(m->truth, (uint8_t)x, (uint8_t)y);
    if (m->o.ideal_walls) return !truemaze_open(m->truth, c, d);
    return maze_wall(mouse_map(), (maze_cell_t)c, d) == MAZE_WALL_CLOSED;
}

/* Positions and directions as mms's SemiPosition/SemiDirection: a cell's
 * centre is (2x+1, 2y+1), the boundary on its east side (2x+2, 2y+1);
 * directions in eighths of a turn clockwise from north (N = 0, NE = 1). */
enum { S_N = 0, S_NE, S_E, S_SE, S_S, S_SW, S_W, S_NW };

/* Where the robot stands: a cell centre or, after an odd number of half
 * steps, a boundary (mouse_cmd_edge). */
static void semi_pos(const mms_t *m, int *sx, int *sy)
{
    static const int dx[4] = { 0, 1, 0, -1 }, dy[4] = { 1, 0, -1, 0 };
    const mouse_status_t *st = mouse_status();
    uint8_t e = mouse_cmd_edge();
    *sx = 2 * truemaze_x(m->truth, st->cell) + 1 + (e ? dx[e - 1] : 0);
    *sy = 2 * truemaze_y(m->truth, st->cell) + 1 + (e ? dy[e - 1] : 0);
}

/* The cell mms counts a position in (toMazeLocation: x / 2, y / 2; on a
 * boundary that is the cell north or east of it). */
static truemaze_cell_t semi_cell(const mms_t *m, int sx, int sy)
{
    return truemaze_cell(m->truth, (uint8_t)(sx / 2), (uint8_t)(sy / 2));
}

/* mms's isWall(position, direction): from a centre, the cell's wall (a
 * diagonal aims at a post); on a boundary, along it a post, across it
 * the open middle of a cell, diagonally the wall of the neighbouring cell
 * it aims at (none outside the maze). */
static int semi_wall(const mms_t *m, int x, int y, int d8)
{
    int w2 = 2 * m->truth->width, h2 = 2 * m->truth->height;
    if (x < 0 || y < 0 || x > w2 || y > h2) return 1; /* outside (mms asserts): a wall */
    int cx = x / 2, cy = y / 2;
    if (x % 2 && y % 2) return d8 % 2 ? 1 : wall_at(m, cx, cy, (uint8_t)(d8 / 2));
    if (x % 2 == 0 && y % 2 == 0) return 1; /* a post (never reached) */
    if (x % 2 == 0) { /* on a boundary between west and east */
        switch (d8) {
        case S_N: case S_S: return 1;
        case S_E: case S_W: return 0;
        case S_NE: return x == w2 ? 0 : wall_at(m, cx, cy, TRUEMAZE_NORTH);
        case S_SE: return x == w2 ? 0 : wall_at(m, cx, cy, TRUEMAZE_SOUTH);
        case S_NW: return x == 0 ? 0 : wall_at(m, cx - 1, cy, TRUEMAZE_NORTH);
        default: return x == 0 ? 0 : wall_at(m, cx - 1, cy, TRUEMAZE_SOUTH);
        }
    }
    switch (d8) { /* on a boundary between south and north */
    case S_E: case S_W: return 1;
    case S_N: case S_S: return 0;
    case S_NE: return y == h2 ? 0 : wall_at(m, cx, cy, TRUEMAZE_EAST);
    case S_NW: return y == h2 ? 0 : wall_at(m, cx, cy, TRUEMAZE_WEST);
    case S_SE: return y == 0 ? 0 : wall_at(m, cx, cy - 1, TRUEMAZE_EAST);
    default: return y == 0 ? 0 : wall_at(m, cx, cy - 1, TRUEMAZE_WEST);
    }
}

/* mms's isWall(position, direction, halfStepsAhead): a wall at this
 * position or at any of the next `ahead` half steps along d8. */
static int semi_wall_ahead(const mms_t *m, int x, int y, int d8, long ahead)
{
    static const int dx[8] = { 0, 1, 1, 1, 0, -1, -1, -1 }, dy[8] = { 1, 1, 0, -1, -1, -1, 0, 1 };
    if (semi_wall(m, x, y, d8)) return 1;
    for (long i = 1; i <= ahead; i++) { /* ends at the latest outside the maze */
        x += dx[d8];
        y += dy[d8];
        if (semi_wall(m, x, y, d8)) return 1;
    }
    return 0;
}

/* wallFront & co: rel in eighths of a turn clockwise from the heading,
 * `away` half steps (mms: 1 = the wall right there). */
static int wall_query(const mms_t *m, int rel, int away)
{
    int x, y;
    semi_pos(m, &x, &y);
    return semi_wall_ahead(m, x, y, (mouse_cmd_heading8() + rel) & 7, (long)away - 1);
}

static void place_at_start(const mms_t *m, struct sim_state_s *s)
{
    const truemaze_t *t = m->truth;
    double cell = s->model->cfg->world.cell_m;
    world_place(s->world, (truemaze_x(t, t->start) + 0.5) * cell, (truemaze_y(t, t->start) + 0.5) * cell,
                M_PI / 2 - t->start_heading * (M_PI / 2), NULL);
}

/* Bytes of the UTF-8 character at t (mms reads its input as UTF-8 and
 * puts one '?' per character it cannot draw); 1 for a byte that starts no
 * valid sequence. */
static size_t utf8_length(const unsigned char *t)
{
    size_t n = *t >= 0xF0 && *t <= 0xF4 ? 4 : *t >= 0xE0 && *t <= 0xEF ? 3 : *t >= 0xC2 && *t <= 0xDF ? 2 : 1;
    for (size_t i = 1; i < n; i++)
        if ((t[i] & 0xC0) != 0x80) return 1;
    return n;
}

/* Split on spaces (empty parts skipped) into at most n tokens; returns the
 * count, n + 1 if there were more. */
static int split(char *line, char **tok, int n)
{
    int k = 0;
    for (char *p = strtok(line, " "); p; p = strtok(NULL, " ")) {
        if (k == n) return n + 1;
        tok[k++] = p;
    }
    return k;
}

/* A forward move of `halves` half steps (moveForward N: 2N; mms's
 * moveForward(numHalfSteps)), along the heading or, facing a diagonal,
 * from boundary middle to boundary middle (mms 1.2's diagonal half steps):
 * refused with crash, nothing moving, if N < 1 or a wall (the robot's map
 * or, ideal, the maze file) is on the way as mms's wallFront N would see
 * it (a diagonal from a cell centre aims at a post). */
static int start_forward(mms_t *m, long halves, char *resp, size_t len)
{
    int x, y;
    semi_pos(m, &x, &y);
    if (halves > 510) halves = 510; /* 255 cells: more than any maze */
    if (halves < 1 || semi_wall_ahead(m, x, y, mouse_cmd_heading8(), halves - 1) ||
        mouse_cmd_forward((uint16_t)halves) != 0) {
        snprintf(resp, len, "crash");
        return 0;
    }
    if (semi_cell(m, x, y) == m->truth->start) mms_stats_start_run(&m->stats);
    m->pending = MOVE_FORWARD;
    return 1;
}

/* ---- the commands: each handler answers into resp and returns 0, 1 when
 * it started a move (the answer comes when the move ends), -1 when the
 * command is invalid (mms answers nothing) ---- */

/* What a handler is given: the tokens, the number argument (the second
 * token of a command that takes one; 1 without it) and its table entry's
 * parameter. */
typedef struct {
    mms_t *m;
    struct sim_state_s *s;
    char **tok;
    int arg, param;
    char *resp;
    size_t len;
} cmd_call_t;

/* setText X Y TEXT: the text may hold spaces; p is what follows "setText ". */
static int set_text(mms_t *m, char *p)
{
    char *sp1 = strchr(p, ' ');
    if (!sp1) return -1;
    *sp1 = '\0';
    char *q = sp1 + 1, *sp2 = strchr(q, ' ');
    const char *text = "";
    if (sp2) {
        *sp2 = '\0';
        text = sp2 + 1;
    }
    int ok = 1, x = to_int(p, &ok), y = to_int(q, &ok);
    if (!ok || !in_maze(m, x, y)) return -1;
    char *dst = m->text[truemaze_cell(m->truth, (uint8_t)x, (uint8_t)y)];
    size_t k = 0;
    for (const unsigned char *t = (const unsigned char *)text; *t && k < MMS_TEXT_MAX; k++) {
        dst[k] = *t >= 32 && *t < 127 ? (char)*t : '?';
        t += utf8_length(t);
    }
    dst[k] = '\0';
    return 0;
}

/* setWall / clearWall X Y D (param 1: set): the drawn wall on both sides. */
static int cmd_draw_wall(const cmd_call_t *c)
{
    mms_t *m = c->m;
    int ok = 1, x = to_int(c->tok[1], &ok), y = to_int(c->tok[2], &ok), d = dir_of(c->tok[3]);
    if (!ok || d < 0 || !in_maze(m, x, y)) return -1;
    truemaze_cell_t cell = truemaze_cell(m->truth, (uint8_t)x, (uint8_t)y), nb;
    if (c->param) m->drawn_walls[cell] |= (uint8_t)(1u << d);
    else m->drawn_walls[cell] &= (uint8_t)~(1u << d);
    if (truemaze_neighbour(m->truth, cell, (uint8_t)d, &nb)) {
        uint8_t bit = (uint8_t)(1u << ((d + 2) & 3));
        if (c->param) m->drawn_walls[nb] |= bit;
        else m->drawn_walls[nb] &= (uint8_t)~bit;
    }
    return 0;
}

/* setColor X Y C */
static int cmd_set_color(const cmd_call_t *c)
{
    char **tok = c->tok;
    int ok = 1, x = to_int(tok[1], &ok), y = to_int(tok[2], &ok);
    if (!ok || strlen(tok[3]) != 1 || !strchr("kbacgorwyBCAGRY", tok[3][0]) || !in_maze(c->m, x, y)) return -1;
    c->m->color[truemaze_cell(c->m->truth, (uint8_t)x, (uint8_t)y)] = tok[3][0];
    return 0;
}

/* clearColor / clearText X Y (param 0: the colour, 1: the text) */
static int cmd_clear_cell(const cmd_call_t *c)
{
    int ok = 1, x = to_int(c->tok[1], &ok), y = to_int(c->tok[2], &ok);
    if (!ok || !in_maze(c->m, x, y)) return -1;
    truemaze_cell_t cell = truemaze_cell(c->m->truth, (uint8_t)x, (uint8_t)y);
    if (c->param == 0) c->m->color[cell] = 0;
    else c->m->text[cell][0] = '\0';
    return 0;
}

/* clearAllColor / clearAllText (param 0: the colours, 1: the texts) */
static int cmd_clear_all(const cmd_call_t *c)
{
    if (c->param == 0) memset(c->m->color, 0, sizeof c->m->color);
    else memset(c->m->text, 0, sizeof c->m->text);
    return 0;
}

/* mazeWidth / mazeHeight (param 0 / 1) */
static int cmd_size(const cmd_call_t *c)
{
    snprintf(c->resp, c->len, "%d", c->param ? c->m->truth->height : c->m->truth->width);
    return 0;
}

/* wallFront & co (param: eighths of a turn clockwise from the heading) */
static int cmd_wall(const cmd_call_t *c)
{
    snprintf(c->resp, c->len, "%s", wall_query(c->m, c->param, c->arg) ? "true" : "false");
    return 0;
}

/* moveForward N (param 2: N cells) / moveForwardHalf N (param 1: N halves) */
static int cmd_forward(const cmd_call_t *c)
{
    long halves = c->param == 2 ? (c->arg > 255 ? 510 : 2L * c->arg) : c->arg;
    return start_forward(c->m, halves, c->resp, c->len);
}

/* turnRight / turnLeft (param 1 / -1: a quarter turn clockwise / not);
 * turnRight45 / turnLeft45 (param 2 / -2: an eighth). mms counts every
 * turn, an eighth too, as one turn in its stats. */
static int cmd_turn(const cmd_call_t *c)
{
    int q = c->param;
    if ((q == 1 || q == -1 ? mouse_cmd_turn((int8_t)q) : mouse_cmd_turn45((int8_t)(q / 2))) != 0) {
        snprintf(c->resp, c->len, "crash");
        return 0;
    }
    mms_stats_turn(&c->m->stats);
    c->m->pending = MOVE_TURN;
    return 1;
}

static int cmd_was_reset(const cmd_call_t *c)
{
    return answer_was_reset(c->m, c->s, c->resp, c->len);
}

/* ackReset: the robot back at the start (without a simulation, only "ack") */
static int cmd_ack_reset(const cmd_call_t *c)
{
    mms_t *m = c->m;
    m->was_reset = 0;
    m->idle_polls = 0;
    m->resets++;
    mms_stats_reset_penalty(&m->stats);
    mms_stats_end_unfinished(&m->stats);
    if (!c->s) {
        snprintf(c->resp, c->len, "ack");
        return 0;
    }
    place_at_start(m, c->s);
    mouse_cmd_reset();
    m->pending = MOVE_RESET;
    return 1;
}

/* getStat NAME */
static int cmd_get_stat(const cmd_call_t *c)
{
    return mms_stats_get(&c->m->stats, c->tok[1], c->resp, c->len) != 0 ? -1 : 0;
}

/* A command's tokens, the name included: exactly that many, or TOK_ARG:
 * the name and an optional number (mms: not a number = 0). */
enum { TOK_ARG = -1 };

static const struct {
    const char *name;
    int (*run)(const cmd_call_t *c);
    int param;
    int tokens;
} commands[] = {
    { "setWall", cmd_draw_wall, 1, 4 },
    { "clearWall", cmd_draw_wall, 0, 4 },
    { "setColor", cmd_set_color, 0, 4 },
    { "clearColor", cmd_clear_cell, 0, 3 },
    { "clearText", cmd_clear_cell, 1, 3 },
    { "clearAllColor", cmd_clear_all, 0, 1 },
    { "clearAllText", cmd_clear_all, 1, 1 },
    { "mazeWidth", cmd_size, 0, 1 },
    { "mazeHeight", cmd_size, 1, 1 },
    { "wallFront", cmd_wall, 0, TOK_ARG },
    { "wallRight", cmd_wall, 2, TOK_ARG },
    { "wallBack", cmd_wall, 4, TOK_ARG },
    { "wallLeft", cmd_wall, 6, TOK_ARG },
    { "wallFrontLeft", cmd_wall, -1, TOK_ARG },
    { "wallFrontRight", cmd_wall, 1, TOK_ARG },
    { "wallBackLeft", cmd_wall, -3, TOK_ARG },
    { "wallBackRight", cmd_wall, 3, TOK_ARG },
    { "moveForward", cmd_forward, 2, TOK_ARG },
    { "moveForwardHalf", cmd_forward, 1, TOK_ARG },
    { "turnRight", cmd_turn, 1, 1 },
    { "turnRight90", cmd_turn, 1, 1 },
    { "turnLeft", cmd_turn, -1, 1 },
    { "turnLeft90", cmd_turn, -1, 1 },
    { "turnRight45", cmd_turn, 2, 1 },
    { "turnLeft45", cmd_turn, -2, 1 },
    { "wasReset", cmd_was_reset, 0, 1 },
    { "ackReset", cmd_ack_reset, 0, 1 },
    { "getStat", cmd_get_stat, 0, 2 },
};

int mms_execute(mms_t *m, struct sim_state_s *s, const char *line_in, char *resp, size_t len)
{
    char line[MMS_LINE_MAX + 1], *tok[5];
    resp[0] = '\0';
    snprintf(line, sizeof line, "%s", line_in);
    m->commands++;
    m->since_move++;

    int r = -1;
    if (!strncmp(line, "setText ", 8)) {
        r = set_text(m, line + 8);
    } else {
        int n = split(line, tok, 4);
        for (size_t i = 0; n >= 1 && n <= 4 && i < sizeof commands / sizeof commands[0]; i++) {
            if (strcmp(tok[0], commands[i].name)) continue;
            int t = commands[i].tokens;
            if (t == TOK_ARG ? n > 2 : n != t) break;
            int ok = 1;
            cmd_call_t c = { m, s, tok, t == TOK_ARG && n == 2 ? to_int(tok[1], &ok) : 1, commands[i].param, resp, len };
            r = commands[i].run(&c);
            break;
        }
    }
    if (r < 0) {
        resp[0] = '\0';
        m->invalid++;
        return 0;
    }
    return r;
}

/* ---- the child process ---- */

static double now_s(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + ts.tv_nsec * 1e-9;
}

static int pipe_cloexec(int fd[2])
{
    if (pipe(fd) != 0) return -1;
    fcntl(fd[0], F_SETFD, FD_CLOEXEC);
    fcntl(fd[1], F_SETFD, FD_CLOEXEC);
    return 0;
}

static void set_nonblock(int fd) { fcntl(fd, F_SETFL, fcntl(fd, F_GETFL) | O_NONBLOCK); }

int mms_start(mms_t *m, const mms_opts_t *o, const truemaze_t *truth, char *err, size_t len)
{
    int p[3][2], n = 0; /* the algorithm's stdin, stdout, stderr */
    mms_init(m, o, truth);
    signal(SIGPIPE, SIG_IGN); /* a closed pipe is an error return, never a signal */
    while (n < 3 && pipe_cloexec(p[n]) == 0) n++;
    int rc = n == 3 ? guard_start(&m->guard, o->command, p[0][0], p[1][1], p[2][1], err, len) : -1;
    if (n < 3) snprintf(err, len, "mms: pipe: %s", strerror(errno));
    for (int i = 0; i < n; i++) { /* the child's ends are the guardian's now; ours stay if it started */
        close(i == 0 ? p[i][0] : p[i][1]);
        if (rc != 0) close(i == 0 ? p[i][1] : p[i][0]);
    }
    if (rc != 0) return -1;
    m->to_child = p[0][1];
    m->from_child = p[1][0];
    m->err_fd = p[2][0];
    set_nonblock(m->to_child);
    set_nonblock(m->from_child);
    set_nonblock(m->err_fd);
    m->pending = MOVE_SENSE; /* the firmware senses the start cell first */
    return 0;
}

/* The whole lines in errbuf (all: also the rest; a full buffer counts as
 * a line) onto our stderr as "algo: LINE", control bytes escaped
 * (sim/io/escape.h): the algorithm cannot forge or hide a line of ours. */
static void flush_stderr_lines(mms_t *m, int all)
{
    static char esc[IO_ESCAPE_MAX(sizeof m->errbuf)];
    for (;;) {
        char *nl = memchr(m->errbuf, '\n', m->errlen);
        if (!nl && m->errlen < sizeof m->errbuf && !(all && m->errlen)) return;
        size_t line = nl ? (size_t)(nl - m->errbuf) : m->errlen, used = line + (nl != NULL);
        io_escape(esc, sizeof esc, m->errbuf, line);
        fprintf(stderr, "algo: %s\n", esc);
        memmove(m->errbuf, m->errbuf + used, m->errlen - used);
        m->errlen -= used;
    }
}

/* What the algorithm wrote on its stderr so far (up to 64 reads). */
static void forward_stderr(mms_t *m)
{
    for (int reads = 0; m->err_fd >= 0 && reads < 64; reads++) {
        ssize_t k = read(m->err_fd, m->errbuf + m->errlen, sizeof m->errbuf - m->errlen);
        if (k > 0) {
            m->errlen += (size_t)k;
            flush_stderr_lines(m, 0);
            continue;
        }
        if (k < 0 && errno == EINTR) continue;
        if (k < 0 && errno == EAGAIN) return;
        close(m->err_fd); /* end of file */
        m->err_fd = -1;
    }
    if (m->err_fd < 0) flush_stderr_lines(m, 1);
}

/* End the run with this reason and one message line (fmt NULL: none). */
static int end_run(mms_t *m, const char *reason, const char *fmt, ...) __attribute__((format(printf, 3, 4)));
static int end_run(mms_t *m, const char *reason, const char *fmt, ...)
{
    m->reason = reason;
    if (fmt) {
        va_list ap;
        va_start(ap, fmt);
        vsnprintf(m->message, sizeof m->message, fmt, ap);
        va_end(ap);
    }
    return MMS_END;
}

/* Has the shell exited? Waits up to wait_s for the guardian's report
 * (guard.h); its status goes into exit_code / exit_signal. */
static int shell_exited(mms_t *m, double wait_s)
{
    int r = guard_shell_ended(&m->guard, wait_s);
    m->exited = m->guard.exited;
    m->exit_code = m->guard.exit_code;
    m->exit_signal = m->guard.exit_signal;
    return r;
}

/* "exited with status N" or "was killed by signal N" */
static const char *how_it_ended(const mms_t *m, char *buf, size_t len)
{
    if (m->exit_signal) snprintf(buf, len, "was killed by signal %d", m->exit_signal);
    else snprintf(buf, len, "exited with status %d", m->exit_code);
    return buf;
}

/* The child closed its output: it has ended (or is about to). Whatever
 * is left of its group is killed by mms_stop. */
static int child_gone(mms_t *m)
{
    char how[64];
    if (!shell_exited(m, m->o.timeout_ms / 1000.0))
        return end_run(m, "mms_failed", "mmsim: mms: the algorithm '%s' closed its output but did not exit", m->shown);
    if (m->exit_code == 0) return end_run(m, "mms_exited", NULL);
    return end_run(m, "mms_failed", "mmsim: mms: the algorithm '%s' %s", m->shown, how_it_ended(m, how, sizeof how));
}

static void trace(const mms_t *m, const struct sim_state_s *s, const char *dir, const char *text)
{
    static char esc[IO_ESCAPE_MAX(MMS_LINE_MAX)]; /* the algorithm's line: escaped (sim/io/escape.h) */
    if (!m->o.trace) return;
    io_escape(esc, sizeof esc, text, strlen(text));
    fprintf(m->o.trace, "mms %9.3f %s %s\n", s ? sim_time_s(s) : 0.0, dir, esc);
}

static int send_line(mms_t *m, const char *resp)
{
    char out[64];
    int n = snprintf(out, sizeof out, "%s\n", resp), off = 0;
    double t0 = now_s();
    while (off < n) {
        ssize_t k = write(m->to_child, out + off, (size_t)(n - off));
        if (k > 0) {
            off += (int)k;
            continue;
        }
        if (k < 0 && errno != EAGAIN && errno != EINTR) return -1;
        double left_ms = m->o.timeout_ms - (now_s() - t0) * 1000.0;
        if (left_ms <= 0) return -2;
        struct pollfd p[2] = { { m->to_child, POLLOUT, 0 }, { m->err_fd, POLLIN, 0 } };
        if (poll(p, 2, (int)ceil(left_ms)) > 0 && p[1].revents) forward_stderr(m); /* it may wait on its stderr */
    }
    return 0;
}

/* The next command line into line; MMS_STEP when there is one, else
 * MMS_END with the reason set. */
static int read_line(mms_t *m, char *line)
{
    double t0 = now_s();
    for (;;) {
        char *nl = memchr(m->buf, '\n', m->len);
        if (nl) {
            size_t k = (size_t)(nl - m->buf);
            memcpy(line, m->buf, k);
            line[k] = '\0';
            if (k && line[k - 1] == '\r') line[k - 1] = '\0'; /* mms drops \r */
            memmove(m->buf, nl + 1, m->len - k - 1);
            m->len -= k + 1;
            return MMS_STEP;
        }
        if (m->len >= MMS_LINE_MAX)
            return end_run(m, "mms_garbage", "mmsim: mms: the algorithm '%s' printed a line longer than %d bytes",
                           m->shown, MMS_LINE_MAX);
        double left_ms = m->o.timeout_ms - (now_s() - t0) * 1000.0;
        if (left_ms <= 0) {
            char how[64];
            if (shell_exited(m, 0)) /* e.g. 'algo & exit 0': a process it started holds the pipe */
                return end_run(m, "mms_timeout",
                               "mmsim: mms: the algorithm '%s' %s, but a process it started keeps its output open "
                               "and sent no command for %d ms", m->shown, how_it_ended(m, how, sizeof how),
                               m->o.timeout_ms);
            return end_run(m, "mms_timeout", "mmsim: mms: the algorithm '%s' sent no command for %d ms",
                           m->shown, m->o.timeout_ms);
        }
        struct pollfd p[2] = { { m->from_child, POLLIN, 0 }, { m->err_fd, POLLIN, 0 } }; /* fd -1: not polled */
        int r = poll(p, 2, (int)ceil(left_ms));
        if (r < 0 && errno != EINTR)
            return end_run(m, "mms_failed", "mmsim: mms: poll on the algorithm '%s' failed: %s", m->shown, strerror(errno));
        if (r > 0 && p[1].revents) forward_stderr(m);
        if (r <= 0 || !p[0].revents) continue;
        ssize_t k = read(m->from_child, m->buf + m->len, MMS_LINE_MAX - m->len);
        if (k == 0) {
            if (m->len) { /* a last line without a newline is still a line */
                m->buf[m->len++] = '\n';
                continue;
            }
            return child_gone(m);
        }
        if (k < 0 && errno != EAGAIN && errno != EINTR)
            return end_run(m, "mms_failed", "mmsim: mms: reading from the algorithm '%s' failed: %s", m->shown, strerror(errno));
        if (k > 0) m->len += (size_t)k;
    }
}

/* What mms_service's helpers return besides MMS_STEP and MMS_END: serve
 * the next command. */
enum { GO_ON = 2 };

/* An idle algorithm (MOVE_WAIT): the clock runs, the robot at rest, until
 * Reset (--mms-reset-at, or the viewer's Reset button sets was_reset);
 * then wasReset's answer, "true". */
static int wait_reset(mms_t *m, struct sim_state_s *s)
{
    if (m->o.reset_at_s >= 0 && sim_time_s(s) >= m->o.reset_at_s) {
        m->was_reset = 1; /* the Reset button, pressed once */
        m->o.reset_at_s = -1;
    }
    if (!m->was_reset) return MMS_STEP;
    m->pending = MOVE_NONE;
    trace(m, s, "<", "true");
    if (send_line(m, "true") != 0) return child_gone(m);
    return GO_ON;
}

/* A move under way: MMS_STEP while it runs; when it ends, its statistics
 * and its answer ("ack" or "crash"), or the end of the run if the robot is
 * stuck. */
static int move_done(mms_t *m, struct sim_state_s *s)
{
    uint8_t st = mouse_cmd_status();
    if (st == MOUSE_CMD_BUSY && sim_time_s(s) - m->move_start_s > MMS_MOVE_MAX_S) {
        m->crashes++;
        send_line(m, "crash");
        snprintf(m->message, sizeof m->message,
                 "mmsim: mms: the robot did not finish a move in %.0f s of simulation time: stuck", MMS_MOVE_MAX_S);
        m->reason = "crash_stop";
        return MMS_END;
    }
    if (st == MOUSE_CMD_BUSY) return MMS_STEP;
    int was = m->pending;
    m->pending = MOVE_NONE;
    if (was == MOVE_FORWARD) {
        mms_stats_distance(&m->stats, mouse_cmd_moved());
        int x, y;
        semi_pos(m, &x, &y);
        truemaze_cell_t c = semi_cell(m, x, y);
        if (truemaze_is_goal(m->truth, c)) mms_stats_finish_run(&m->stats);
        else if (c == m->truth->start) mms_stats_end_unfinished(&m->stats);
        m->moves++;
        m->since_move = m->idle_polls = 0;
    }
    if (was == MOVE_TURN) {
        m->moves++;
        m->since_move = m->idle_polls = 0;
    }
    if (was == MOVE_RESET) m->since_move = 0; /* a reset is not a flood */
    if (st == MOUSE_CMD_CRASHED) {
        if (was != MOVE_SENSE) send_line(m, "crash");
        m->crashes++;
        return end_run(m, "crash_stop", "mmsim: mms: the robot is stuck (motion stall) during a %s: run ended",
                       was == MOVE_FORWARD ? "forward move" : was == MOVE_TURN ? "turn" : "reset");
    }
    if (m->o.reset_at_s >= 0 && sim_time_s(s) >= m->o.reset_at_s) {
        m->was_reset = 1; /* the Reset button, pressed once */
        m->o.reset_at_s = -1;
    }
    if (was != MOVE_SENSE) {
        const char *r = st == MOUSE_CMD_BLOCKED ? "crash" : "ack";
        trace(m, s, "<", r);
        if (st == MOUSE_CMD_BLOCKED) m->crashes++;
        if (send_line(m, r) != 0) return child_gone(m);
    }
    return GO_ON;
}

int mms_service(mms_t *m, struct sim_state_s *s)
{
    char line[MMS_LINE_MAX + 1], resp[64];
    forward_stderr(m);
    for (;;) {
        int r = m->pending == MOVE_WAIT ? wait_reset(m, s) : m->pending ? move_done(m, s) : GO_ON;
        if (r != GO_ON) return r;
        if (m->since_move >= MMS_FLOOD_LIMIT)
            return end_run(m, "mms_flood", "mmsim: mms: the algorithm '%s' sent %ld commands without a move",
                           m->shown, MMS_FLOOD_LIMIT);
        if (read_line(m, line) != MMS_STEP) return MMS_END;
        long inv = m->invalid;
        int move = mms_execute(m, s, line, resp, sizeof resp);
        trace(m, s, m->invalid != inv ? "> (ignored)" : ">", line);
        if (resp[0]) trace(m, s, "<", resp);
        if (m->idle)
            return end_run(m, "mms_idle",
                           "mmsim: mms: the algorithm '%s' waits for Reset (wasReset %d times without a move) and "
                           "none is coming: run ended (--mms-reset-at S or idle presses it)",
                           m->shown, MMS_IDLE_POLLS);
        if (move) { /* a move: answered when done */
            m->move_start_s = sim_time_s(s);
            continue;
        }
        if (resp[0]) {
            if (!strcmp(resp, "crash")) m->crashes++;
            int w = send_line(m, resp);
            if (w == -2)
                return end_run(m, "mms_timeout", "mmsim: mms: the algorithm '%s' does not read its input (%d ms)",
                               m->shown, m->o.timeout_ms);
            if (w != 0) return child_gone(m);
        }
    }
}

void mms_stop(mms_t *m)
{
    /* everything the algorithm started, killed and reaped by its guardian
     * (guard.h), also what left its process group or session; its pipes
     * closed only then, as mms kills its algorithm's process (QProcess::kill)
     * with them open: an algorithm still running never sees a closed pipe
     * (no BrokenPipeError or EOF traceback from it in the run's stderr) */
    guard_stop(&m->guard);
    if (m->to_child >= 0) close(m->to_child);
    if (m->from_child >= 0) close(m->from_child);
    m->to_child = m->from_child = -1;
    shell_exited(m, 0);
    forward_stderr(m); /* its last words, to the end (nothing writes any more) */
    if (m->err_fd >= 0) close(m->err_fd);
    m->err_fd = -1;
    flush_stderr_lines(m, 1);
}

int mms_failed(const mms_t *m)
{
    return !strcmp(m->reason, "mms_failed") || !strcmp(m->reason, "mms_timeout") ||
           !strcmp(m->reason, "mms_garbage") || !strcmp(m->reason, "mms_flood");
}

/* A distance in cells: an integer, or x.5 after an odd number of half steps. */
static json_t *cells_json(int halves)
{
    return halves % 2 ? json_real(halves / 2.0) : json_integer(halves / 2);
}

void *mms_json(const mms_t *m)
{
    const mms_stats_t *s = &m->stats;
    json_t *st = json_pack("{s:o, s:i, s:f, s:o, s:i, s:f, s:f}", "total_distance", cells_json(s->total_halves),
                           "total_turns", s->total_turns, "total_effective_distance", (double)s->total_eff,
                           "current_run_distance", cells_json(s->cur_halves), "current_run_turns", s->cur_turns,
                           "current_run_effective_distance", (double)s->cur_eff, "score",
                           round(mms_stats_score(s) * 1000.0) / 1000.0);
    json_object_set_new(st, "best_run_distance", s->has_best ? cells_json(s->best_halves) : json_null());
    json_object_set_new(st, "best_run_turns", s->has_best ? json_integer(s->best_turns) : json_null());
    json_object_set_new(st, "best_run_effective_distance", s->has_best ? json_real(s->best_eff) : json_null());
    json_t *j = json_pack("{s:s, s:b, s:i, s:I, s:I, s:I, s:I, s:I, s:o}", "command", m->o.command, "ideal_walls",
                          m->o.ideal_walls, "timeout_ms", m->o.timeout_ms, "commands", (json_int_t)m->commands,
                          "invalid_commands", (json_int_t)m->invalid, "moves", (json_int_t)m->moves, "crashes",
                          (json_int_t)m->crashes, "resets", (json_int_t)m->resets, "stats", st);
    json_t *colors = json_object(), *texts = json_object();
    for (uint16_t c = 0; c < truemaze_cells(m->truth); c++) {
        char key[16];
        snprintf(key, sizeof key, "%u,%u", truemaze_x(m->truth, c), truemaze_y(m->truth, c));
        if (m->color[c]) json_object_set_new(colors, key, json_stringn(&m->color[c], 1));
        if (m->text[c][0]) json_object_set_new(texts, key, json_string(m->text[c]));
    }
    json_object_set_new(j, "colors", colors);
    json_object_set_new(j, "texts", texts);
    json_object_set_new(j, "exit_status", m->exit_code >= 0 ? json_integer(m->exit_code) : json_null());
    json_object_set_new(j, "exit_signal", m->exit_signal ? json_integer(m->exit_signal) : json_null());
    return j;
}

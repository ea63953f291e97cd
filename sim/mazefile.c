/* mazefile.c - read and write maze files (see mazefile.h for the formats).
 *
 * The text parser first splits the buffer into lines (LF, CRLF or CR),
 * keeping offsets in a fixed array, then checks every character of every
 * row against the grammar: post rows "o---o   o", cell rows "| S |   |".
 * Every index is checked against the line length, and the buffer is never
 * assumed to end in NUL. */
#include "mazefile.h"

#include <errno.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define MAX_ROWS (2 * MAZE_MAX_H + 1)

typedef struct {
    const char *text;
    size_t len;
    const char *name;
    char *err;
    size_t errlen;
} src_t;

typedef struct {
    size_t off;  /* offset of the line in the buffer */
    size_t len;  /* length without line end and trailing spaces */
    size_t raw;  /* length without line end */
} line_t;

static int fail(const src_t *s, size_t line, size_t col, const char *fmt, ...)
{
    char msg[200];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(msg, sizeof msg, fmt, ap);
    va_end(ap);
    if (s->err && s->errlen) snprintf(s->err, s->errlen, "%s:%zu:%zu: %s", s->name, line, col, msg);
    return -1;
}

/* The line starting at *pos: fills ln, advances *pos past its line end. */
static void next_line(const src_t *s, size_t *pos, line_t *ln)
{
    size_t i = *pos;
    ln->off = i;
    while (i < s->len && s->text[i] != '\n' && s->text[i] != '\r') i++;
    ln->raw = i - ln->off;
    ln->len = ln->raw;
    while (ln->len > 0 && s->text[ln->off + ln->len - 1] == ' ') ln->len--;
    if (i < s->len) /* one line end: "\r\n", "\n" or "\r" */
        i += (s->text[i] == '\r' && i + 1 < s->len && s->text[i + 1] == '\n') ? 2 : 1;
    *pos = i;
}

static char at(const src_t *s, const line_t *ln, size_t col)
{
    return col < ln->len ? s->text[ln->off + col] : ' ';
}

static int is_post(char c) { return c == 'o' || c == '+'; }

/* ---- text format ---- */

/* A post row: posts at 4k, "---" or "   " between. r = 0-based row. */
static int parse_post_row(const src_t *s, const line_t *ln, size_t r, maze_t *m, uint8_t w, uint8_t h)
{
    size_t lineno = r + 1;
    /* the cells south of this row have y = h-1-r/2 (none for the last row) */
    int y_south = (int)h - 1 - (int)(r / 2);
    for (uint8_t k = 0; k <= w; k++) {
        size_t col = (size_t)k * 4;
        char c = at(s, ln, col);
        if (!is_post(c)) {
            if (c == ' ') return fail(s, lineno, col + 1, "missing post");
            if (c == '-' || c == '|') return fail(s, lineno, col + 1, "wall character '%c' at the wrong column (a post goes here)", c);
            return fail(s, lineno, col + 1, "stray character '%c' (a post 'o' goes here)", c);
        }
        if (k == w) break;
        int walls = 0, spaces = 0;
        for (size_t j = 1; j <= 3; j++) {
            char d = at(s, ln, col + j);
            if (d == '-') walls++;
            else if (d == ' ') spaces++;
            else if (d == '|' || is_post(d))
                return fail(s, lineno, col + j + 1, "wall character '%c' at the wrong column", d);
            else
                return fail(s, lineno, col + j + 1, "stray character '%c'", d);
        }
        if (walls && spaces) {
            size_t j = 1;
            while (at(s, ln, col + j) == (walls > spaces ? '-' : ' ')) j++;
            return fail(s, lineno, col + j + 1, "broken wall: expected \"---\" or \"   \"");
        }
        int boundary = (r == 0 || y_south < 0);
        if (boundary && !walls) return fail(s, lineno, col + 2, "boundary not closed");
        if (!boundary)
            maze_set_wall(m, maze_cell(m, k, (uint8_t)y_south), MAZE_NORTH, walls ? MAZE_WALL_CLOSED : MAZE_WALL_OPEN);
    }
    return 0;
}

/* A cell row: '|' or ' ' at 4k, cell interiors " x " between. */
static int parse_cell_row(const src_t *s, const line_t *ln, size_t r, maze_t *m, uint8_t w, uint8_t h,
                          int *n_start, int *n_goal)
{
    size_t lineno = r + 1;
    uint8_t y = (uint8_t)(h - 1 - r / 2);
    for (uint8_t k = 0; k <= w; k++) {
        size_t col = (size_t)k * 4;
        char c = at(s, ln, col);
        int boundary = (k == 0 || k == w);
        if (c == '|') {
            if (!boundary) maze_set_wall(m, maze_cell(m, k, y), MAZE_WEST, MAZE_WALL_CLOSED);
        } else if (c == ' ') {
            if (boundary) return fail(s, lineno, col + 1, "boundary not closed");
            maze_set_wall(m, maze_cell(m, k, y), MAZE_WEST, MAZE_WALL_OPEN);
        } else if (c == '-' || is_post(c)) {
            return fail(s, lineno, col + 1, "wall character '%c' at the wrong column", c);
        } else {
            return fail(s, lineno, col + 1, "stray character '%c'", c);
        }
        if (k == w) break;
        for (size_t j = 1; j <= 3; j++) {
            char d = at(s, ln, col + j);
            if (d == ' ') continue;
            if (j == 2 && (d == 'S' || d == 'G')) {
                maze_cell_t cell = maze_cell(m, k, y);
                if (d == 'S') {
                    if (++*n_start > 1) return fail(s, lineno, col + j + 1, "more than one start 'S'");
                    m->start = cell;
                } else {
                    if (++*n_goal == 1) maze_clear_goals(m);
                    maze_set_goal(m, cell, 1);
                }
                continue;
            }
            if (d == '|' || d == '-' || is_post(d))
                return fail(s, lineno, col + j + 1, "wall character '%c' at the wrong column", d);
            return fail(s, lineno, col + j + 1, "stray character '%c'", d);
        }
    }
    return 0;
}

/* Start heading: north unless closed, then the first open side N,E,S,W. */
static void pick_start_heading(maze_t *m)
{
    m->start_heading = MAZE_NORTH;
    for (uint8_t d = 0; d < 4; d++)
        if (maze_passable(m, m->start, d, 0)) {
            m->start_heading = d;
            return;
        }
}

static int parse_text(const src_t *s, maze_t *m, mazefile_info_t *info)
{
    line_t lines[MAX_ROWS];
    size_t pos = 0, n = 0, lineno = 0;
    int blank_seen = 0;
    size_t blank_line = 0;

    while (pos < s->len) {
        line_t ln;
        next_line(s, &pos, &ln);
        lineno++;
        if (ln.len == 0) {
            if (!blank_seen) blank_line = lineno;
            blank_seen = 1;
            continue;
        }
        if (blank_seen) return fail(s, blank_line, 1, "blank line inside the maze");
        if (n == MAX_ROWS) return fail(s, lineno, 1, "more than %d rows: mazes have at most %d cells a side", MAX_ROWS, MAZE_MAX_H);
        lines[n++] = ln;
    }
    if (n == 0) return fail(s, 1, 1, "empty file");
    if (lines[0].len < 5 || (lines[0].len - 1) % 4 != 0)
        return fail(s, 1, lines[0].len + 1, "first row must be 4*cells+1 characters wide, got %zu", lines[0].len);
    size_t width = (lines[0].len - 1) / 4;
    if (width > MAZE_MAX_W) return fail(s, 1, 1, "%zu cells wide: the maximum is %d", width, MAZE_MAX_W);
    for (size_t r = 1; r < n; r++) {
        /* a short cell row is caught by the boundary check at its column */
        if (lines[r].len < lines[0].len && r % 2 == 0)
            return fail(s, r + 1, lines[r].len + 1, "row shorter than the first (%zu characters, want %zu)", lines[r].len, lines[0].len);
        if (lines[r].len > lines[0].len)
            return fail(s, r + 1, lines[0].len + 1, "row longer than the first (%zu characters, want %zu)", lines[r].len, lines[0].len);
    }
    if (n < 3 || n % 2 == 0)
        return fail(s, n, 1, "the maze must end with a row of posts (%zu rows; want 2*cells+1)", n);
    size_t height = (n - 1) / 2;
    if (maze_init(m, (uint8_t)width, (uint8_t)height) != 0)
        return fail(s, 1, 1, "bad maze size %zux%zu", width, height);

    int n_start = 0, n_goal = 0;
    for (size_t r = 0; r < n; r++) {
        int rc = (r % 2 == 0) ? parse_post_row(s, &lines[r], r, m, (uint8_t)width, (uint8_t)height)
                              : parse_cell_row(s, &lines[r], r, m, (uint8_t)width, (uint8_t)height, &n_start, &n_goal);
        if (rc) return rc;
    }
    pick_start_heading(m);
    if (info) {
        info->has_start = n_start > 0;
        info->has_goal = n_goal > 0;
    }
    return 0;
}

/* ---- mms numeric format ---- */

/* Read an unsigned decimal at *col of the line; returns -1 if none. */
static long read_uint(const src_t *s, const line_t *ln, size_t *col)
{
    while (*col < ln->len && (s->text[ln->off + *col] == ' ' || s->text[ln->off + *col] == '\t')) (*col)++;
    long v = -1;
    while (*col < ln->len && s->text[ln->off + *col] >= '0' && s->text[ln->off + *col] <= '9') {
        v = (v < 0 ? 0 : v) * 10 + (s->text[ln->off + *col] - '0');
        if (v > 100000) v = 100000; /* saturate: reported as out of range */
        (*col)++;
    }
    return v;
}

typedef struct {
    uint8_t walls[MAZE_MAX_CELLS];  /* bit d = wall on side d; 0x80 = seen */
    uint32_t line[MAZE_MAX_CELLS];  /* line that defined the cell */
} mms_cells_t;

static int mms_line(const src_t *s, const line_t *ln, size_t lineno, long v[6])
{
    size_t col = 0;
    for (int k = 0; k < 6; k++) {
        size_t start = col;
        while (start < ln->len && (s->text[ln->off + start] == ' ' || s->text[ln->off + start] == '\t')) start++;
        v[k] = read_uint(s, ln, &col);
        if (v[k] < 0) {
            if (col < ln->len) return fail(s, lineno, col + 1, "stray character '%c' (want 6 numbers: X Y N E S W)", s->text[ln->off + col]);
            return fail(s, lineno, col + 1, "want 6 numbers per line: X Y N E S W");
        }
        if (k >= 2 && v[k] > 1) return fail(s, lineno, start + 1, "wall value must be 0 or 1");
        if (k < 2 && v[k] >= MAZE_MAX_SIZE) return fail(s, lineno, start + 1, "coordinate %ld out of range (maximum %d)", v[k], MAZE_MAX_SIZE - 1);
    }
    while (col < ln->len && (s->text[ln->off + col] == ' ' || s->text[ln->off + col] == '\t')) col++;
    if (col < ln->len) return fail(s, lineno, col + 1, "stray character '%c' after the 6 numbers", s->text[ln->off + col]);
    return 0;
}

static int parse_mms(const src_t *s, maze_t *m, mazefile_info_t *info)
{
    static mms_cells_t cells; /* host side, one parse at a time: keeps 5 KB off the stack */
    size_t pos = 0, lineno = 0;
    long w = 0, h = 0, v[6];

    memset(&cells, 0, sizeof cells);
    /* pass 1: syntax and size */
    while (pos < s->len) {
        line_t ln;
        next_line(s, &pos, &ln);
        lineno++;
        if (ln.len == 0) continue;
        if (mms_line(s, &ln, lineno, v)) return -1;
        if (v[0] + 1 > w) w = v[0] + 1;
        if (v[1] + 1 > h) h = v[1] + 1;
    }
    if (w == 0) return fail(s, 1, 1, "empty file");
    /* pass 2: cells */
    pos = 0;
    lineno = 0;
    while (pos < s->len) {
        line_t ln;
        next_line(s, &pos, &ln);
        lineno++;
        if (ln.len == 0) continue;
        mms_line(s, &ln, lineno, v);
        size_t c = (size_t)v[1] * (size_t)w + (size_t)v[0];
        if (cells.walls[c] & 0x80)
            return fail(s, lineno, 1, "cell (%ld,%ld) given twice (first on line %u)", v[0], v[1], (unsigned)cells.line[c]);
        cells.walls[c] = (uint8_t)(0x80 | v[2] | v[3] << 1 | v[4] << 2 | v[5] << 3);
        cells.line[c] = (uint32_t)lineno;
    }
    maze_init(m, (uint8_t)w, (uint8_t)h);
    for (long y = 0; y < h; y++)
        for (long x = 0; x < w; x++) {
            size_t c = (size_t)y * (size_t)w + (size_t)x;
            if (!(cells.walls[c] & 0x80)) return fail(s, lineno + 1, 1, "cell (%ld,%ld) missing", x, y);
        }
    for (long y = 0; y < h; y++)
        for (long x = 0; x < w; x++) {
            maze_cell_t c = maze_cell(m, (uint8_t)x, (uint8_t)y), nb;
            for (uint8_t d = 0; d < 4; d++) {
                int wall = (cells.walls[c] >> d) & 1;
                if (!maze_neighbour(m, c, d, &nb)) {
                    if (!wall) return fail(s, cells.line[c], 1, "boundary not closed at cell (%ld,%ld)", x, y);
                    continue;
                }
                if (wall != ((cells.walls[nb] >> maze_turn(d, 2)) & 1))
                    return fail(s, cells.line[c], 1, "wall between (%ld,%ld) and (%u,%u) disagrees with line %u", x, y,
                                maze_x(m, nb), maze_y(m, nb), (unsigned)cells.line[nb]);
                maze_set_wall(m, c, d, wall ? MAZE_WALL_CLOSED : MAZE_WALL_OPEN);
            }
        }
    pick_start_heading(m);
    if (info) info->mms_format = 1;
    return 0;
}

int mazefile_parse(maze_t *m, const char *text, size_t len, const char *name, mazefile_info_t *info,
                   char *err, size_t errlen)
{
    src_t s = { text, len, name ? name : "<maze>", err, errlen };
    size_t line = 1, col = 1;
    if (info) memset(info, 0, sizeof *info);
    if (len > MAZEFILE_MAX_BYTES) return fail(&s, 1, 1, "file larger than %u bytes", MAZEFILE_MAX_BYTES);
    /* NUL bytes and the first significant character, with their positions */
    char first = 0;
    size_t fline = 1, fcol = 1;
    for (size_t i = 0; i < len; i++) {
        char c = text[i];
        if (c == '\0') return fail(&s, line, col, "NUL byte");
        if (c == '\n' || c == '\r') {
            if (!(c == '\n' && i > 0 && text[i - 1] == '\r')) line++;
            col = 1;
            continue;
        }
        if (!first && c != ' ' && c != '\t') {
            first = c;
            fline = line;
            fcol = col;
        }
        col++;
    }
    if (!first) return fail(&s, 1, 1, "empty file");
    if (is_post(first)) return parse_text(&s, m, info);
    if (first >= '0' && first <= '9') return parse_mms(&s, m, info);
    return fail(&s, fline, fcol, "stray character '%c': a maze starts with a post 'o' (text) or a number (mms)", first);
}

int mazefile_load(maze_t *m, const char *path, mazefile_info_t *info, char *err, size_t errlen)
{
    int is_stdin = strcmp(path, "-") == 0;
    const char *name = is_stdin ? "<stdin>" : path;
    FILE *f = is_stdin ? stdin : fopen(path, "rb");
    if (!f) {
        snprintf(err, errlen, "%s: cannot open: %s", name, strerror(errno));
        return -1;
    }
    char *buf = malloc(MAZEFILE_MAX_BYTES + 1);
    if (!buf) {
        if (!is_stdin) fclose(f);
        snprintf(err, errlen, "%s: out of memory", name);
        return -1;
    }
    size_t n = fread(buf, 1, MAZEFILE_MAX_BYTES + 1, f);
    int read_error = ferror(f);
    if (!is_stdin) fclose(f);
    int rc;
    if (read_error) {
        snprintf(err, errlen, "%s: cannot read: %s", name, strerror(errno ? errno : EIO));
        rc = -1;
    } else if (n > MAZEFILE_MAX_BYTES) {
        snprintf(err, errlen, "%s:1:1: file larger than %u bytes", name, MAZEFILE_MAX_BYTES);
        rc = -1;
    } else {
        rc = mazefile_parse(m, buf, n, name, info, err, errlen);
    }
    free(buf);
    return rc;
}

/* ---- writers ---- */

typedef struct {
    char *buf;
    size_t cap, n;
} out_t;

static void put(out_t *o, const char *str)
{
    for (; *str; str++, o->n++)
        if (o->n + 1 < o->cap) o->buf[o->n] = *str;
}

static void finish(out_t *o)
{
    if (o->cap) o->buf[o->n < o->cap ? o->n : o->cap - 1] = '\0';
}

/* One letter per cell: a start inside the goal area hides one goal cell.
 * If the goal is the default centre, leaving the G letters out says it
 * exactly; any other goal holding the start cannot be written. */
static int write_goal_letters(const maze_t *m)
{
    maze_t centre;
    if (!maze_is_goal(m, m->start)) return 1;
    maze_init(&centre, m->width, m->height);
    return memcmp(centre.goal, m->goal, sizeof centre.goal) != 0;
}

size_t mazefile_format(const maze_t *m, char *buf, size_t cap)
{
    out_t o = { buf, cap, 0 };
    int letters = write_goal_letters(m);
    for (int r = 0; r <= 2 * m->height; r++) {
        if (r % 2 == 0) {
            /* north walls of row y (y = -1: the south boundary) */
            int y = m->height - 1 - r / 2;
            for (uint8_t x = 0; x < m->width; x++) {
                int wall = y < 0 ? 1 : !maze_passable(m, maze_cell(m, x, (uint8_t)y), MAZE_NORTH, 0);
                put(&o, "o");
                put(&o, wall ? "---" : "   ");
            }
            put(&o, "o\n");
        } else {
            uint8_t y = (uint8_t)(m->height - 1 - r / 2);
            char line[4 * MAZE_MAX_W + 2];
            size_t k = 0;
            for (uint8_t x = 0; x < m->width; x++) {
                maze_cell_t c = maze_cell(m, x, y);
                line[k++] = maze_passable(m, c, MAZE_WEST, 0) ? ' ' : '|';
                line[k++] = ' ';
                line[k++] = c == m->start ? 'S' : (letters && maze_is_goal(m, c)) ? 'G' : ' ';
                line[k++] = ' ';
            }
            line[k++] = '|';
            while (k > 0 && line[k - 1] == ' ') k--;
            line[k] = '\0';
            put(&o, line);
            put(&o, "\n");
        }
    }
    finish(&o);
    return o.n;
}

size_t mazefile_format_mms(const maze_t *m, char *buf, size_t cap)
{
    out_t o = { buf, cap, 0 };
    for (uint8_t x = 0; x < m->width; x++)
        for (uint8_t y = 0; y < m->height; y++) {
            maze_cell_t c = maze_cell(m, x, y);
            char line[40];
            snprintf(line, sizeof line, "%u %u %d %d %d %d\n", x, y, !maze_passable(m, c, MAZE_NORTH, 0),
                     !maze_passable(m, c, MAZE_EAST, 0), !maze_passable(m, c, MAZE_SOUTH, 0),
                     !maze_passable(m, c, MAZE_WEST, 0));
            put(&o, line);
        }
    finish(&o);
    return o.n;
}

/* mazefile.c - read and write maze files (see mazefile.h for the formats).
 *
 * Text format: the buffer is split into lines (LF, CRLF or CR), the rows
 * are kept as offsets in a fixed array, then every character of every row
 * is checked against its column: post rows "o---o   o", cell rows
 * "| S |   |". Errors are reported in file order where that is possible, so
 * the first message points at the first thing that is wrong.
 *
 * Safety: the buffer is not NUL-terminated, so every read goes through a
 * length check; the parser uses fixed arrays on the stack and never
 * allocates (it must stay usable from the fuzzer and from tools that parse
 * many files). */
#include "mazefile.h"

#include <errno.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "io/infile.h"

enum {
    MAX_ROWS = 2 * TRUEMAZE_MAX_SIZE + 1, /* text rows of the largest maze */
    MAX_COLS = 4 * TRUEMAZE_MAX_SIZE + 1  /* characters in its widest row */
};

typedef struct {
    const char *text;
    size_t len;
    const char *name;
    char *err;
    size_t errlen;
} src_t;

typedef struct {
    size_t off;    /* offset of the line in the buffer */
    size_t len;    /* length without line end and trailing spaces */
    size_t raw;    /* length without line end */
    size_t lineno; /* 1-based */
} line_t;

/* ---- errors ---- */

/* Writes "NAME:LINE:COL: message". The name comes from the caller (often a
 * path), so line ends in it are replaced: the message must stay one line. */
static int fail(const src_t *s, size_t line, size_t col, const char *fmt, ...)
{
    char msg[200];
    va_list ap;
    if (!s->err || s->errlen == 0) return -1;
    va_start(ap, fmt);
    vsnprintf(msg, sizeof msg, fmt, ap);
    va_end(ap);
    snprintf(s->err, s->errlen, "%s:%zu:%zu: %s", s->name, line, col, msg);
    for (char *p = s->err; *p; p++)
        if (*p == '\n' || *p == '\r') *p = '?';
    return -1;
}

/* A character for a message: quoted if printable, else as a hex byte, so a
 * tab or a control byte in the input cannot garble the one-line message. */
static const char *describe(char c, char out[12])
{
    unsigned char u = (unsigned char)c;
    if (u >= 0x20 && u < 0x7f) snprintf(out, 12, "'%c'", c);
    else snprintf(out, 12, "byte 0x%02X", u);
    return out;
}

/* ---- lines ---- */

/* The line starting at *pos: fills ln (except lineno), advances *pos past
 * its line end. */
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

/* Line and column of byte off, counting line ends as next_line does. Only
 * used on error paths, so a scan from the start is fine. */
static void pos_of(const src_t *s, size_t off, size_t *line, size_t *col)
{
    size_t pos = 0;
    line_t ln;
    *line = 1;
    for (;;) {
        next_line(s, &pos, &ln);
        if (off <= ln.off + ln.raw || pos >= s->len) break;
        if (off < pos) break; /* inside a CRLF pair: report its CR */
        (*line)++;
    }
    *col = off - ln.off + 1;
}

/* Character at col of the line; spaces past its end (the rows of a maze
 * are compared as if padded, since trailing spaces are allowed). */
static char at(const src_t *s, const line_t *ln, size_t col)
{
    return col < ln->len ? s->text[ln->off + col] : ' ';
}

/* ---- text format ---- */

static int is_post(char c) { return c == 'o' || c == '+'; }

/* Both wall characters count at either kind of wall position: the
 * database's reference reads any mark at a wall position as a wall. */
static int is_wall(char c) { return c == '-' || c == '|'; }

/* What may stand at a column of a row, by position in the 4-column grid. */
typedef enum { AT_POST, AT_WALL, AT_INTERIOR, AT_CENTRE } slot_t;

static slot_t slot_of(int post_row, size_t col)
{
    if (col % 4 == 0) return post_row ? AT_POST : AT_WALL;
    if (post_row) return AT_WALL;
    return col % 4 == 2 ? AT_CENTRE : AT_INTERIOR;
}

/* Checks one character against its slot: the grammar without meaning. */
static int check_char(const src_t *s, const line_t *ln, int post_row, size_t col)
{
    char c = at(s, ln, col), d[12];
    slot_t slot = slot_of(post_row, col);
    size_t line = ln->lineno;
    if (slot == AT_POST) {
        if (is_post(c)) return 0;
        if (c == ' ') return fail(s, line, col + 1, "missing post");
        if (is_wall(c)) return fail(s, line, col + 1, "wall character %s at the wrong column (a post goes here)", describe(c, d));
        return fail(s, line, col + 1, "stray character %s (a post 'o' goes here)", describe(c, d));
    }
    if (c == ' ') return 0;
    if (slot == AT_WALL && is_wall(c)) return 0;
    if (slot == AT_CENTRE && (c == 'S' || c == 'G')) return 0;
    if (is_wall(c)) return fail(s, line, col + 1, "wall character %s at the wrong column", describe(c, d));
    if (is_post(c)) return fail(s, line, col + 1, "post %s at the wrong column", describe(c, d));
    if (c == 'S' || c == 'G') return fail(s, line, col + 1, "letter %s off the centre of its cell", describe(c, d));
    return fail(s, line, col + 1, "stray character %s", describe(c, d));
}

/* The first row sets the width: checked before anything else, with its
 * characters first so that "o--o" names the misplaced post. */
static int text_width(const src_t *s, const line_t *ln, uint8_t *w)
{
    size_t limit = ln->len < MAX_COLS ? ln->len : MAX_COLS;
    for (size_t col = 0; col < limit; col++)
        if (check_char(s, ln, 1, col)) return -1;
    if (ln->len > MAX_COLS)
        return fail(s, ln->lineno, MAX_COLS + 1, "maze wider than %d cells", TRUEMAZE_MAX_SIZE);
    if (ln->len < 5 || (ln->len - 1) % 4 != 0)
        return fail(s, ln->lineno, ln->len + 1, "first row is %zu characters wide: want 4*cells+1, a post every 4 columns", ln->len);
    *w = (uint8_t)((ln->len - 1) / 4);
    return 0;
}

/* A row that ends before the first row's width. raw (not the stripped
 * length) is compared, so that a full-width row whose east boundary is a
 * space gets "boundary not closed" at that column instead. */
static int short_row(const src_t *s, const line_t *ln, size_t width)
{
    return fail(s, ln->lineno, ln->raw + 1, "row shorter than the first (%zu characters, want %zu)", ln->raw, width);
}

static int long_row(const src_t *s, const line_t *ln, size_t width)
{
    return fail(s, ln->lineno, width + 1, "row longer than the first (%zu characters, want %zu)", ln->len, width);
}

/* Geometry shared by the row parsers. */
typedef struct {
    uint8_t w, h;
    size_t width;  /* characters per row: 4w+1 */
    int truncated; /* rows stopped early (blank line, too many): no south boundary */
} grid_t;

/* A post row (0-based index r): posts at 4k, "---" or "   " between. It
 * holds the north walls of the cells below it, y = h-1-r/2. */
static int parse_post_row(const src_t *s, const line_t *ln, size_t r, const grid_t *g, truemaze_t *m)
{
    int y_south = (int)g->h - 1 - (int)(r / 2);
    int boundary = r == 0 || (y_south < 0 && !g->truncated);
    size_t end = ln->raw < g->width ? ln->raw : g->width;
    for (uint8_t k = 0; k <= g->w; k++) {
        size_t col = (size_t)k * 4;
        if (col >= end) return short_row(s, ln, g->width);
        if (check_char(s, ln, 1, col)) return -1;
        if (k == g->w) break;
        int wall = 0; /* any wall character in the segment makes it a wall */
        for (size_t j = 1; j <= 3; j++) {
            if (col + j >= end) return short_row(s, ln, g->width);
            if (check_char(s, ln, 1, col + j)) return -1;
            wall |= is_wall(at(s, ln, col + j));
        }
        if (boundary && !wall) return fail(s, ln->lineno, col + 3, "boundary not closed");
        if (!boundary && y_south >= 0)
            truemaze_set_wall(m, truemaze_cell(m, k, (uint8_t)y_south), TRUEMAZE_NORTH, wall);
    }
    if (ln->len > g->width) return long_row(s, ln, g->width);
    return 0;
}

/* Letters seen so far in the cell rows. */
typedef struct {
    int n_start, n_goal;
    size_t start_line, start_col; /* of the first 'S', for the "more than one" message */
} letters_t;

static int cell_letter(const src_t *s, const line_t *ln, size_t col, truemaze_cell_t cell, truemaze_t *m, letters_t *lt)
{
    char c = at(s, ln, col);
    if (c == 'S') {
        if (lt->n_start++ > 0)
            return fail(s, ln->lineno, col + 1, "more than one start 'S' (the first is at %zu:%zu)", lt->start_line, lt->start_col);
        lt->start_line = ln->lineno;
        lt->start_col = col + 1;
        m->start = cell;
    } else if (c == 'G') {
        if (lt->n_goal++ == 0) truemaze_clear_goals(m); /* marked goals replace the default centre */
        truemaze_set_goal(m, cell, 1);
    }
    return 0;
}

/* A cell row (0-based index r): '|' or ' ' at 4k, interiors " x " between;
 * the cells are at y = h-1-r/2. */
static int parse_cell_row(const src_t *s, const line_t *ln, size_t r, const grid_t *g, truemaze_t *m, letters_t *lt)
{
    uint8_t y = (uint8_t)(g->h - 1 - r / 2);
    size_t end = ln->raw < g->width ? ln->raw : g->width;
    for (uint8_t k = 0; k <= g->w; k++) {
        size_t col = (size_t)k * 4;
        if (col >= end) return short_row(s, ln, g->width);
        if (check_char(s, ln, 0, col)) return -1;
        int wall = is_wall(at(s, ln, col));
        if (k == 0 || k == g->w) {
            if (!wall) return fail(s, ln->lineno, col + 1, "boundary not closed");
        } else {
            truemaze_set_wall(m, truemaze_cell(m, k, y), TRUEMAZE_WEST, wall);
        }
        if (k == g->w) break;
        for (size_t j = 1; j <= 3; j++) {
            if (col + j >= end) return short_row(s, ln, g->width);
            if (check_char(s, ln, 0, col + j)) return -1;
            if (cell_letter(s, ln, col + j, truemaze_cell(m, k, y), m, lt)) return -1;
        }
    }
    if (ln->len > g->width) return long_row(s, ln, g->width);
    return 0;
}

/* Start heading: north unless that side is closed, then the first open
 * side in the order N, E, S, W (north if the cell is closed all round). */
static void pick_start_heading(truemaze_t *m)
{
    m->start_heading = TRUEMAZE_NORTH;
    for (uint8_t d = 0; d < 4; d++)
        if (truemaze_open(m, m->start, d)) {
            m->start_heading = d;
            return;
        }
}

/* Why the rows stopped before the end of the file. */
typedef struct {
    size_t line; /* 0: they did not */
    int too_many;
} stop_t;

/* Collects the non-blank lines. Leading and trailing blank lines are
 * allowed; a blank line between rows or a row past the maximum stops the
 * collection, and the error is reported after the rows before it have
 * been checked (keeping errors in file order). */
static size_t collect_rows(const src_t *s, line_t rows[MAX_ROWS], stop_t *stop)
{
    size_t pos = 0, n = 0, lineno = 0, blank = 0;
    stop->line = 0;
    stop->too_many = 0;
    while (pos < s->len) {
        line_t ln;
        next_line(s, &pos, &ln);
        ln.lineno = ++lineno;
        if (ln.len == 0) {
            if (n > 0 && blank == 0) blank = lineno;
            continue;
        }
        if (blank) {
            stop->line = blank;
            break;
        }
        if (n == MAX_ROWS) {
            stop->line = lineno;
            stop->too_many = 1;
            break;
        }
        rows[n++] = ln;
    }
    return n;
}

static int parse_text(const src_t *s, truemaze_t *m, mazefile_info_t *info)
{
    line_t rows[MAX_ROWS];
    stop_t stop;
    grid_t g = { 0, 0, 0, 0 };
    letters_t lt = { 0, 0, 0, 0 };
    size_t n = collect_rows(s, rows, &stop);

    if (n == 0) return fail(s, 1, 1, "empty file"); /* guard: the caller saw a post, so n >= 1 */
    if (text_width(s, &rows[0], &g.w)) return -1;
    g.width = (size_t)g.w * 4 + 1;
    g.h = (uint8_t)(n / 2); /* cell rows; the row count's parity is checked last */
    g.truncated = stop.line != 0;
    /* Cannot fail: w is 1..TRUEMAZE_MAX_SIZE (text_width) and h at most TRUEMAZE_MAX_SIZE
     * (collect_rows); a lone row of posts is checked on a 1-high grid. */
    truemaze_init(m, g.w, g.h ? g.h : 1);

    for (size_t r = 0; r < n; r++) {
        int rc = (r % 2 == 0) ? parse_post_row(s, &rows[r], r, &g, m) : parse_cell_row(s, &rows[r], r, &g, m, &lt);
        if (rc) return rc;
    }
    if (stop.line && stop.too_many)
        return fail(s, stop.line, 1, "maze taller than %d cells (more than %d rows)", TRUEMAZE_MAX_SIZE, MAX_ROWS);
    if (stop.line) return fail(s, stop.line, 1, "blank line inside the maze");
    if (n == 1) return fail(s, rows[0].lineno + 1, 1, "no cell rows: a maze has 2*cells+1 rows");
    if (n % 2 == 0)
        return fail(s, rows[n - 1].lineno + 1, 1, "the maze must end with a row of posts (%zu rows; want 2*cells+1)", n);

    pick_start_heading(m);
    if (info) {
        info->has_start = lt.n_start > 0;
        info->has_goal = lt.n_goal > 0;
    }
    return 0;
}

/* ---- mms numeric format ---- */

/* The six fields of one line and the 0-based columns where they start. */
typedef struct {
    long v[6];
    size_t col[6];
} mms_fields_t;

static int is_blank(char c) { return c == ' ' || c == '\t'; }

/* Splits a line into 6 unsigned numbers: X Y N E S W. */
static int mms_fields(const src_t *s, const line_t *ln, mms_fields_t *f)
{
    const char *p = s->text + ln->off;
    size_t col = 0;
    char d[12];
    for (int k = 0; k < 6; k++) {
        while (col < ln->len && is_blank(p[col])) col++;
        if (col >= ln->len)
            return fail(s, ln->lineno, col + 1, "want 6 numbers per line: X Y N E S W (got %d)", k);
        if (p[col] < '0' || p[col] > '9')
            return fail(s, ln->lineno, col + 1, "stray character %s (want 6 numbers: X Y N E S W)", describe(p[col], d));
        f->col[k] = col;
        f->v[k] = 0;
        for (; col < ln->len && p[col] >= '0' && p[col] <= '9'; col++)
            if (f->v[k] < 100000) f->v[k] = f->v[k] * 10 + (p[col] - '0'); /* saturates: too large anyway */
        if (col < ln->len && !is_blank(p[col]))
            return fail(s, ln->lineno, col + 1, "stray character %s after a number", describe(p[col], d));
        if (k < 2 && f->v[k] >= TRUEMAZE_MAX_SIZE) /* quoted from the text: the value saturated */
            return fail(s, ln->lineno, f->col[k] + 1, "coordinate %.*s above the maximum %d", (int)(col - f->col[k] < 20 ? col - f->col[k] : 20),
                        p + f->col[k], TRUEMAZE_MAX_SIZE - 1);
        if (k >= 2 && f->v[k] > 1)
            return fail(s, ln->lineno, f->col[k] + 1, "wall value must be 0 or 1");
    }
    while (col < ln->len && is_blank(p[col])) col++;
    if (col < ln->len) return fail(s, ln->lineno, col + 1, "more than 6 fields on the line");
    return 0;
}

/* Cells indexed y * TRUEMAZE_MAX_SIZE + x: the size is known only at the end. */
typedef struct {
    uint8_t walls[TRUEMAZE_MAX_CELLS]; /* bit d = wall on side d; MMS_GIVEN = seen */
    uint32_t off[TRUEMAZE_MAX_CELLS];  /* offset of the line that gave the cell */
} mms_grid_t;

enum { MMS_GIVEN = 0x80 };

static size_t mms_index(long x, long y) { return (size_t)y * TRUEMAZE_MAX_SIZE + (size_t)x; }

/* The field index (2..5) of side d: N E S W follow X Y. */
static int field_of(uint8_t d) { return 2 + d; }

/* Re-reads the line at off to point at one of its fields (error paths). */
static int fail_field(const src_t *s, uint32_t off, int field, const char *msg, long x, long y)
{
    size_t pos = off, line, col;
    line_t ln;
    mms_fields_t f;
    next_line(s, &pos, &ln);
    pos_of(s, off, &line, &col);
    ln.lineno = line;
    mms_fields(s, &ln, &f); /* parsed once already: cannot fail */
    return fail(s, line, f.col[field] + 1, "%s of cell (%ld,%ld)", msg, x, y);
}

/* A new cell against the cells given before it: each wall it shares with
 * a known neighbour must agree, and its west/south boundary be closed. */
static int mms_check_new(const src_t *s, const line_t *ln, const mms_fields_t *f, const mms_grid_t *g)
{
    static const int dx[4] = { 0, 1, 0, -1 }, dy[4] = { 1, 0, -1, 0 };
    long x = f->v[0], y = f->v[1];
    for (uint8_t d = 0; d < 4; d++) {
        long nx = x + dx[d], ny = y + dy[d];
        int wall = (int)f->v[field_of(d)];
        size_t col = f->col[field_of(d)] + 1;
        if (nx < 0 || ny < 0) {
            if (!wall) return fail(s, ln->lineno, col, "boundary not closed: %s wall of cell (%ld,%ld)", d == TRUEMAZE_SOUTH ? "south" : "west", x, y);
            continue;
        }
        if (nx >= TRUEMAZE_MAX_SIZE || ny >= TRUEMAZE_MAX_SIZE) continue; /* checked as a boundary at the end */
        uint8_t nb = g->walls[mms_index(nx, ny)];
        if (!(nb & MMS_GIVEN)) continue;
        if (wall != ((nb >> truemaze_turn(d, 2)) & 1)) {
            size_t line, c;
            pos_of(s, g->off[mms_index(nx, ny)], &line, &c);
            return fail(s, ln->lineno, col, "wall between (%ld,%ld) and (%ld,%ld) disagrees with line %zu", x, y, nx, ny, line);
        }
    }
    return 0;
}

/* Reads every line into g; w and h become the largest X+1 and Y+1. */
static int mms_read(const src_t *s, mms_grid_t *g, long *w, long *h, size_t *last_line)
{
    size_t pos = 0, lineno = 0;
    *w = *h = 0;
    *last_line = 0;
    while (pos < s->len) {
        line_t ln;
        mms_fields_t f;
        next_line(s, &pos, &ln);
        ln.lineno = ++lineno;
        while (ln.len > 0 && is_blank(s->text[ln.off + ln.len - 1])) ln.len--; /* trailing tabs too */
        if (ln.len == 0) continue;
        if (mms_fields(s, &ln, &f)) return -1;
        size_t i = mms_index(f.v[0], f.v[1]);
        if (g->walls[i] & MMS_GIVEN) {
            size_t line, col;
            pos_of(s, g->off[i], &line, &col);
            return fail(s, ln.lineno, f.col[0] + 1, "cell (%ld,%ld) given twice (first on line %zu)", f.v[0], f.v[1], line);
        }
        if (mms_check_new(s, &ln, &f, g)) return -1;
        g->walls[i] = (uint8_t)(MMS_GIVEN | f.v[2] | f.v[3] << 1 | f.v[4] << 2 | f.v[5] << 3);
        g->off[i] = (uint32_t)ln.off; /* < MAZEFILE_MAX_BYTES: fits */
        if (f.v[0] + 1 > *w) *w = f.v[0] + 1;
        if (f.v[1] + 1 > *h) *h = f.v[1] + 1;
        *last_line = lineno;
    }
    return 0;
}

/* North and east boundary, known once the size is: the first offending
 * line in the file is reported. */
static int mms_check_far_boundary(const src_t *s, const mms_grid_t *g, long w, long h)
{
    long bx = -1, by = -1;
    uint8_t bd = 0;
    for (long y = 0; y < h; y++)
        for (long x = 0; x < w; x++) {
            size_t i = mms_index(x, y);
            if (!(g->walls[i] & MMS_GIVEN)) continue; /* reported as missing later */
            for (uint8_t d = TRUEMAZE_NORTH; d <= TRUEMAZE_EAST; d++) {
                int edge = d == TRUEMAZE_NORTH ? y == h - 1 : x == w - 1;
                if (!edge || (g->walls[i] >> d) & 1) continue;
                if (bx < 0 || g->off[i] < g->off[mms_index(bx, by)]) {
                    bx = x;
                    by = y;
                    bd = d;
                }
            }
        }
    if (bx < 0) return 0;
    return fail_field(s, g->off[mms_index(bx, by)], field_of(bd),
                      bd == TRUEMAZE_NORTH ? "boundary not closed: north wall" : "boundary not closed: east wall", bx, by);
}

static int parse_mms(const src_t *s, truemaze_t *m, mazefile_info_t *info)
{
    mms_grid_t g; /* 5 KB on the host stack; no allocation */
    long w, h;
    size_t last_line;

    memset(g.walls, 0, sizeof g.walls);
    if (mms_read(s, &g, &w, &h, &last_line)) return -1;
    if (mms_check_far_boundary(s, &g, w, h)) return -1;
    for (long y = 0; y < h; y++)
        for (long x = 0; x < w; x++)
            if (!(g.walls[mms_index(x, y)] & MMS_GIVEN))
                return fail(s, last_line + 1, 1, "cell (%ld,%ld) missing: every cell of the %ldx%ld maze must appear once", x, y, w, h);
    truemaze_init(m, (uint8_t)w, (uint8_t)h); /* 1..TRUEMAZE_MAX_SIZE: checked per line */
    for (long y = 0; y < h; y++)
        for (long x = 0; x < w; x++) {
            truemaze_cell_t c = truemaze_cell(m, (uint8_t)x, (uint8_t)y);
            /* north and east cover every interior wall once; the two cells'
             * copies were checked to agree as they were read */
            for (uint8_t d = TRUEMAZE_NORTH; d <= TRUEMAZE_EAST; d++)
                truemaze_set_wall(m, c, d, (g.walls[mms_index(x, y)] >> d) & 1);
        }
    pick_start_heading(m);
    if (info) info->mms_format = 1;
    return 0;
}

/* ---- entry points ---- */

int mazefile_parse(truemaze_t *m, const char *text, size_t len, const char *name, mazefile_info_t *info,
                   char *err, size_t errlen)
{
    src_t s = { text, len, name ? name : "<maze>", err, errlen };
    size_t line, col;
    char d[12];

    if (info) memset(info, 0, sizeof *info);
    if (err && errlen) err[0] = '\0';
    if (len > MAZEFILE_MAX_BYTES) {
        pos_of(&s, MAZEFILE_MAX_BYTES, &line, &col);
        return fail(&s, line, col, "file larger than %u bytes", MAZEFILE_MAX_BYTES);
    }
    /* A NUL means a binary or corrupt file: said first, wherever it is. */
    const char *nul = len ? memchr(text, '\0', len) : NULL;
    if (nul) {
        pos_of(&s, (size_t)(nul - text), &line, &col);
        return fail(&s, line, col, "NUL byte");
    }
    size_t i = 0;
    while (i < len && (text[i] == ' ' || text[i] == '\t' || text[i] == '\n' || text[i] == '\r')) i++;
    if (i == len) return fail(&s, 1, 1, "empty file");
    if (is_post(text[i])) return parse_text(&s, m, info);
    if (text[i] >= '0' && text[i] <= '9') return parse_mms(&s, m, info);
    pos_of(&s, i, &line, &col);
    return fail(&s, line, col, "stray character %s: a maze starts with a post 'o' (text) or a number (mms)",
                describe(text[i], d));
}

int mazefile_load(truemaze_t *m, const char *path, mazefile_info_t *info, char *err, size_t errlen)
{
    int is_stdin = strcmp(path, "-") == 0;
    const char *name = is_stdin ? "<stdin>" : path;
    /* a file must be a regular one (a FIFO or a device would hang or
     * never end); its size is bounded by the read below, as stdin's */
    FILE *f = is_stdin ? stdin : infile_open(path, INFILE_NO_LIMIT, NULL, err, errlen);
    if (!f) return -1;
    /* One byte more than allowed: mazefile_parse then reports the size. */
    char *buf = malloc(MAZEFILE_MAX_BYTES + 1);
    if (!buf) {
        if (!is_stdin) fclose(f);
        snprintf(err, errlen, "%s: out of memory", name);
        return -1;
    }
    errno = 0;
    size_t n = fread(buf, 1, MAZEFILE_MAX_BYTES + 1, f);
    int read_errno = ferror(f) ? (errno ? errno : EIO) : 0;
    if (!is_stdin) fclose(f);
    int rc;
    if (read_errno) {
        snprintf(err, errlen, "%s: cannot read: %s", name, strerror(read_errno));
        rc = -1;
    } else {
        rc = mazefile_parse(m, buf, n, name, info, err, errlen);
    }
    free(buf);
    return rc;
}

/* ---- writers ---- */

/* snprintf-style output: counts everything, stores what fits. */
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

static int valid_size(const truemaze_t *m)
{
    return m->width >= 1 && m->width <= TRUEMAZE_MAX_SIZE && m->height >= 1 && m->height <= TRUEMAZE_MAX_SIZE;
}

/* One letter per cell: a start inside the goal area hides one goal cell.
 * If the goal is the default centre, leaving the G letters out says it
 * exactly; any other goal holding the start cannot be written. */
static int write_goal_letters(const truemaze_t *m)
{
    truemaze_t centre;
    if (!truemaze_is_goal(m, m->start)) return 1;
    truemaze_init(&centre, m->width, m->height);
    return memcmp(centre.goal, m->goal, sizeof centre.goal) != 0;
}

/* Post row r (0 = north edge): the north walls of row y = h-1-r/2. */
static void format_post_row(const truemaze_t *m, int r, out_t *o)
{
    int y = m->height - 1 - r / 2; /* -1: the south boundary */
    for (uint8_t x = 0; x < m->width; x++) {
        int wall = y < 0 || !truemaze_open(m, truemaze_cell(m, x, (uint8_t)y), TRUEMAZE_NORTH);
        put(o, wall ? "o---" : "o   ");
    }
    put(o, "o\n");
}

static void format_cell_row(const truemaze_t *m, int r, int letters, out_t *o)
{
    uint8_t y = (uint8_t)(m->height - 1 - r / 2);
    char line[MAX_COLS + 1];
    size_t k = 0;
    for (uint8_t x = 0; x < m->width; x++) {
        truemaze_cell_t c = truemaze_cell(m, x, y);
        line[k++] = truemaze_open(m, c, TRUEMAZE_WEST) ? ' ' : '|';
        line[k++] = ' ';
        line[k++] = c == m->start ? 'S' : (letters && truemaze_is_goal(m, c)) ? 'G' : ' ';
        line[k++] = ' ';
    }
    line[k++] = truemaze_open(m, truemaze_cell(m, (uint8_t)(m->width - 1), y), TRUEMAZE_EAST) ? ' ' : '|';
    while (k > 0 && line[k - 1] == ' ') k--; /* no trailing spaces */
    line[k] = '\0';
    put(o, line);
    put(o, "\n");
}

size_t mazefile_format(const truemaze_t *m, char *buf, size_t cap)
{
    out_t o = { buf, cap, 0 };
    if (valid_size(m)) {
        int letters = write_goal_letters(m);
        for (int r = 0; r <= 2 * m->height; r++) {
            if (r % 2 == 0) format_post_row(m, r, &o);
            else format_cell_row(m, r, letters, &o);
        }
    }
    finish(&o);
    return o.n;
}

/* mms's own writer (Maze::saveMaze) loops x outside, y inside. */
size_t mazefile_format_mms(const truemaze_t *m, char *buf, size_t cap)
{
    out_t o = { buf, cap, 0 };
    if (valid_size(m)) {
        for (uint8_t x = 0; x < m->width; x++)
            for (uint8_t y = 0; y < m->height; y++) {
                truemaze_cell_t c = truemaze_cell(m, x, y);
                char line[40];
                snprintf(line, sizeof line, "%u %u %d %d %d %d\n", x, y, !truemaze_open(m, c, TRUEMAZE_NORTH),
                         !truemaze_open(m, c, TRUEMAZE_EAST), !truemaze_open(m, c, TRUEMAZE_SOUTH),
                         !truemaze_open(m, c, TRUEMAZE_WEST));
                put(&o, line);
            }
    }
    finish(&o);
    return o.n;
}

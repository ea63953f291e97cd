/* test_mazefile.c - maze files: every database maze parses and agrees with
 * the independent reference (size, goal reachability), malformed inputs
 * give NAME:LINE:COL errors, line-end and post variants parse alike,
 * round trips, mms numeric format.
 *
 * The database is read from $SHARED/mazes (default ../shared/mazes, from
 * the repository root); without it the database tests print one
 * "SKIP name: reason" line and skip. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <cmocka.h>

#include <dirent.h>
#include <jansson.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "maze/mazefile.h"

static truemaze_t a, b;
static char err[MAZEFILE_ERR_LEN];
static char text[1 << 16], text2[1 << 16];

/* ---- helpers ---- */

static const char *shared(void)
{
    const char *s = getenv("SHARED");
    return s ? s : "../shared";
}

static int parse(truemaze_t *m, const char *t)
{
    return mazefile_parse(m, t, strlen(t), "t.txt", NULL, err, sizeof err);
}

static void assert_same_maze(const truemaze_t *x, const truemaze_t *y)
{
    assert_int_equal(x->width, y->width);
    assert_int_equal(x->height, y->height);
    assert_memory_equal(x->cell, y->cell, truemaze_cells(x));
    assert_memory_equal(x->goal, y->goal, sizeof x->goal);
    assert_int_equal(x->start, y->start);
    assert_int_equal(x->start_heading, y->start_heading);
}

static int goal_count(const truemaze_t *m)
{
    int n = 0;
    for (uint16_t c = 0; c < truemaze_cells(m); c++) n += truemaze_is_goal(m, (truemaze_cell_t)c);
    return n;
}

/* Breadth-first search from the start over open walls: is a goal cell
 * reachable? Kept here so the test does not depend on the solver. */
static int goal_reachable(const truemaze_t *m)
{
    static truemaze_cell_t queue[TRUEMAZE_MAX_CELLS];
    static uint8_t seen[TRUEMAZE_MAX_CELLS];
    size_t head = 0, tail = 0;
    memset(seen, 0, sizeof seen);
    queue[tail++] = m->start;
    seen[m->start] = 1;
    while (head < tail) {
        truemaze_cell_t c = queue[head++], n;
        if (truemaze_is_goal(m, c)) return 1;
        for (uint8_t d = 0; d < 4; d++)
            if (truemaze_open(m, c, d) && truemaze_neighbour(m, c, d, &n) && !seen[n]) {
                seen[n] = 1;
                queue[tail++] = n;
            }
    }
    return 0;
}

/* Normalise: LF line ends, no trailing spaces, no trailing blank lines. */
static size_t normalise(const char *in, size_t len, char *out)
{
    size_t k = 0;
    for (size_t i = 0; i < len; i++) {
        char c = in[i];
        if (c == '\r') {
            if (i + 1 < len && in[i + 1] == '\n') continue;
            c = '\n';
        }
        if (c == '\n')
            while (k > 0 && out[k - 1] == ' ') k--;
        out[k++] = c;
    }
    while (k > 0 && (out[k - 1] == '\n' || out[k - 1] == ' ')) k--;
    out[k++] = '\n';
    out[k] = '\0';
    return k;
}

static size_t read_file(const char *path, char *buf, size_t cap)
{
    FILE *f = fopen(path, "rb");
    assert_non_null(f);
    size_t n = fread(buf, 1, cap - 1, f);
    fclose(f);
    assert_true(n < cap - 1);
    buf[n] = '\0';
    return n;
}

/* Expect a parse error whose message starts with want ("t.txt:L:C: ..."). */
static void expect_error(const char *t, size_t len, const char *want)
{
    err[0] = '\0';
    assert_int_equal(mazefile_parse(&a, t, len, "t.txt", NULL, err, sizeof err), -1);
    if (strncmp(err, want, strlen(want)) != 0) fail_msg("input \"%s\": got \"%s\", want prefix \"%s\"", t, err, want);
    assert_null(strchr(err, '\n')); /* one line */
}

/* ---- the database ---- */

static const char *const db_dirs[] = { "classic", "halfsize", "training" };

/* Prints the one SKIP line and returns 0 if $SHARED/mazes is missing. */
static int have_database(const char *test)
{
    char path[1024];
    snprintf(path, sizeof path, "%s/mazes", shared());
    DIR *d = opendir(path);
    if (!d) {
        printf("SKIP %s: %s not found (set SHARED)\n", test, path);
        return 0;
    }
    closedir(d);
    return 1;
}

static int ends_with_txt(const char *s)
{
    size_t n = strlen(s);
    return n > 4 && !strcmp(s + n - 4, ".txt");
}

typedef void (*db_fn)(const char *rel, const char *path, void *ctx);

/* Calls fn for every *.txt of the database directories; returns the count. */
static int for_each_db_file(db_fn fn, void *ctx)
{
    char dir[1024], rel[1024], path[2048];
    int files = 0;
    for (size_t i = 0; i < sizeof db_dirs / sizeof db_dirs[0]; i++) {
        snprintf(dir, sizeof dir, "%s/mazes/%s", shared(), db_dirs[i]);
        DIR *d = opendir(dir);
        if (!d) fail_msg("%s: cannot open the directory", dir);
        struct dirent *e;
        while ((e = readdir(d)) != NULL) {
            if (!ends_with_txt(e->d_name)) continue;
            snprintf(rel, sizeof rel, "%s/%s", db_dirs[i], e->d_name);
            snprintf(path, sizeof path, "%s/%s", dir, e->d_name);
            fn(rel, path, ctx);
            files++;
        }
        closedir(d);
    }
    return files;
}

/* reference.jsonl as one object: maze path -> its record. */
static json_t *load_reference(void)
{
    char path[1024], line[4096];
    snprintf(path, sizeof path, "%s/mazes/reference.jsonl", shared());
    FILE *f = fopen(path, "r");
    if (!f) fail_msg("%s: cannot open", path);
    json_t *all = json_object();
    while (fgets(line, sizeof line, f)) {
        json_error_t jerr;
        json_t *r = json_loads(line, 0, &jerr);
        if (!r) fail_msg("%s:%d: %s", path, jerr.line, jerr.text);
        const char *name = json_string_value(json_object_get(r, "maze"));
        assert_non_null(name);
        json_object_set_new(all, name, r);
    }
    fclose(f);
    return all;
}

static void check_against_reference(const char *rel, const char *path, void *ctx)
{
    json_t *ref = json_object_get((json_t *)ctx, rel);
    if (!ref) fail_msg("%s: not in reference.jsonl", rel);
    if (mazefile_load(&a, path, NULL, err, sizeof err) != 0) fail_msg("%s", err);
    if (a.width != json_integer_value(json_object_get(ref, "width")) ||
        a.height != json_integer_value(json_object_get(ref, "height")))
        fail_msg("%s: size %dx%d differs from the reference", rel, a.width, a.height);
    if (goal_reachable(&a) != json_is_true(json_object_get(ref, "goal_reachable")))
        fail_msg("%s: goal reachability differs from the reference", rel);
}

/* Every *.txt of the database parses; size and goal reachability agree
 * with reference.jsonl, which lists every file. */
static void test_database_matches_reference(void **state)
{
    (void)state;
    if (!have_database("test_database_matches_reference")) skip();
    json_t *ref = load_reference();
    int files = for_each_db_file(check_against_reference, ref);
    assert_int_equal((size_t)files, json_object_size(ref));
    assert_true(files >= 534);
    json_decref(ref);
}

typedef struct {
    int exact; /* files compared as text */
} round_trip_t;

static void round_trip_file(const char *rel, const char *path, void *ctx)
{
    round_trip_t *rt = ctx;
    mazefile_info_t info;
    size_t len = read_file(path, text2, sizeof text2);
    if (mazefile_parse(&a, text2, len, rel, &info, err, sizeof err) != 0) fail_msg("%s", err);
    size_t n = mazefile_format(&a, text, sizeof text);
    assert_true(n < sizeof text);
    assert_int_equal(strlen(text), n);
    if (mazefile_parse(&b, text, n, "rt", NULL, err, sizeof err) != 0) fail_msg("%s: written text: %s", rel, err);
    assert_same_maze(&a, &b);
    if (info.has_start && info.has_goal) {
        static char norm[1 << 16];
        normalise(text2, len, norm);
        if (strcmp(norm, text) != 0) fail_msg("%s: written text differs from the input", rel);
        rt->exact++;
    }
}

/* parse -> format -> parse gives the same maze for every database file;
 * for files marking S and G the text is the normalised input. */
static void test_database_round_trip(void **state)
{
    (void)state;
    if (!have_database("test_database_round_trip")) skip();
    round_trip_t rt = { 0 };
    int files = for_each_db_file(round_trip_file, &rt);
    assert_true(files >= 534);
    assert_true(rt.exact > 400); /* most files mark both */
}

static void mms_round_trip_file(const char *rel, const char *path, void *ctx)
{
    mazefile_info_t info;
    truemaze_t centre;
    (void)ctx;
    if (mazefile_load(&a, path, NULL, err, sizeof err) != 0) fail_msg("%s", err);
    size_t n = mazefile_format_mms(&a, text, sizeof text);
    assert_true(n < sizeof text);
    if (mazefile_parse(&b, text, n, "rt.mms", &info, err, sizeof err) != 0) fail_msg("%s: mms text: %s", rel, err);
    assert_true(info.mms_format);
    assert_int_equal(a.width, b.width);
    assert_int_equal(a.height, b.height);
    assert_memory_equal(a.cell, b.cell, truemaze_cells(&a));
    /* the format has no start or goal: the defaults */
    truemaze_init(&centre, a.width, a.height);
    assert_int_equal(b.start, 0);
    assert_memory_equal(b.goal, centre.goal, sizeof b.goal);
    /* and writing it again gives the same text */
    assert_int_equal(mazefile_format_mms(&b, text2, sizeof text2), n);
    assert_string_equal(text, text2);
}

static void test_database_mms_round_trip(void **state)
{
    (void)state;
    if (!have_database("test_database_mms_round_trip")) skip();
    assert_true(for_each_db_file(mms_round_trip_file, NULL) >= 534);
}

/* ---- hand-written mazes ---- */

/* A 3x2 maze with S and G. */
static const char *small =
    "o---o---o---o\n"
    "|       | G |\n"
    "o   o---o   o\n"
    "| S |       |\n"
    "o---o---o---o\n";

static void test_small_maze(void **state)
{
    (void)state;
    mazefile_info_t info;
    assert_int_equal(mazefile_parse(&a, small, strlen(small), "s", &info, err, sizeof err), 0);
    assert_int_equal(a.width, 3);
    assert_int_equal(a.height, 2);
    assert_true(info.has_start && info.has_goal && !info.mms_format);
    assert_int_equal(a.start, truemaze_cell(&a, 0, 0));
    assert_int_equal(a.start_heading, TRUEMAZE_NORTH);
    assert_int_equal(goal_count(&a), 1); /* the default centre was cleared by G */
    assert_true(truemaze_is_goal(&a, truemaze_cell(&a, 2, 1)));
    assert_int_equal(truemaze_wall(&a, truemaze_cell(&a, 0, 0), TRUEMAZE_EAST), 1);
    assert_int_equal(truemaze_wall(&a, truemaze_cell(&a, 0, 0), TRUEMAZE_NORTH), 0);
    assert_int_equal(truemaze_wall(&a, truemaze_cell(&a, 1, 1), TRUEMAZE_EAST), 1);
    assert_int_equal(truemaze_wall(&a, truemaze_cell(&a, 2, 0), TRUEMAZE_NORTH), 0);
    assert_int_equal(truemaze_wall(&a, truemaze_cell(&a, 1, 0), TRUEMAZE_NORTH), 1);
    assert_int_equal(truemaze_wall(&a, truemaze_cell(&a, 0, 1), TRUEMAZE_EAST), 0);
    assert_int_equal(truemaze_wall(&a, truemaze_cell(&a, 2, 1), TRUEMAZE_NORTH), 1);
    /* every inner wall is the same seen from either side */
    for (uint16_t c = 0; c < truemaze_cells(&a); c++)
        for (uint8_t d = 0; d < 4; d++) {
            truemaze_cell_t n;
            if (truemaze_neighbour(&a, c, d, &n))
                assert_int_equal(truemaze_wall(&a, c, d), truemaze_wall(&a, n, truemaze_turn(d, 2)));
        }
    assert_int_equal(mazefile_format(&a, text, sizeof text), strlen(small));
    assert_string_equal(text, small);
}

/* The smallest maze: 1x1, start and goal the same cell. */
static void test_one_cell(void **state)
{
    (void)state;
    assert_int_equal(parse(&a, "o---o\n|   |\no---o\n"), 0);
    assert_int_equal(a.width, 1);
    assert_int_equal(a.height, 1);
    assert_true(truemaze_is_goal(&a, 0));
    assert_int_equal(a.start_heading, TRUEMAZE_NORTH); /* closed all round */
    mazefile_format(&a, text, sizeof text);
    assert_string_equal(text, "o---o\n| S |\no---o\n");
}

/* No letters: start (0,0), goal = the centre; north closed -> east. */
static void test_defaults(void **state)
{
    (void)state;
    mazefile_info_t info;
    const char *t =
        "o---o---o---o---o\n"
        "|               |\n"
        "o   o   o   o   o\n"
        "|               |\n"
        "o   o   o   o   o\n"
        "|               |\n"
        "o---o   o   o   o\n"
        "|               |\n"
        "o---o---o---o---o\n";
    assert_int_equal(mazefile_parse(&a, t, strlen(t), "d", &info, err, sizeof err), 0);
    assert_false(info.has_start || info.has_goal);
    assert_int_equal(a.start, 0);
    assert_int_equal(a.start_heading, TRUEMAZE_EAST);
    assert_int_equal(goal_count(&a), 4);
    assert_true(truemaze_is_goal(&a, truemaze_cell(&a, 1, 1)) && truemaze_is_goal(&a, truemaze_cell(&a, 2, 2)));
    assert_true(truemaze_is_goal(&a, truemaze_cell(&a, 1, 2)) && truemaze_is_goal(&a, truemaze_cell(&a, 2, 1)));
}

/* The start heading is the first open side in the order N, E, S, W. */
static void test_start_heading(void **state)
{
    (void)state;
    static const struct {
        const char *t;
        uint8_t heading;
    } cases[] = {
        { "o---o---o---o\n|           |\no   o---o   o\n|   | S     |\no   o   o   o\n|           |\no---o---o---o\n", TRUEMAZE_EAST },
        { "o---o---o---o\n|           |\no   o---o   o\n|   | S |   |\no   o   o   o\n|           |\no---o---o---o\n", TRUEMAZE_SOUTH },
        { "o---o---o---o\n|           |\no   o---o   o\n|     S |   |\no   o---o   o\n|           |\no---o---o---o\n", TRUEMAZE_WEST },
        { "o---o---o---o\n|           |\no   o---o   o\n|   | S |   |\no   o---o   o\n|           |\no---o---o---o\n", TRUEMAZE_NORTH },
        { "o---o---o---o\n|           |\no   o   o   o\n|   | S |   |\no   o---o   o\n|           |\no---o---o---o\n", TRUEMAZE_NORTH },
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        assert_int_equal(parse(&a, cases[i].t), 0);
        assert_int_equal(a.start, truemaze_cell(&a, 1, 1));
        if (a.start_heading != cases[i].heading) fail_msg("case %zu: heading %d, want %d", i, a.start_heading, cases[i].heading);
    }
}

/* Several G letters make a goal area; a 5x3 maze (odd, non-square). */
static void test_goal_area(void **state)
{
    (void)state;
    const char *t =
        "o---o---o---o---o---o\n"
        "|             G   G |\n"
        "o   o   o   o   o   o\n"
        "|             G   G |\n"
        "o   o   o   o   o   o\n"
        "| S                 |\n"
        "o---o---o---o---o---o\n";
    mazefile_info_t info;
    assert_int_equal(mazefile_parse(&a, t, strlen(t), "g", &info, err, sizeof err), 0);
    assert_true(info.has_goal && info.has_start);
    assert_int_equal(a.width, 5);
    assert_int_equal(a.height, 3);
    assert_int_equal(goal_count(&a), 4);
    assert_false(truemaze_is_goal(&a, truemaze_cell(&a, 2, 1))); /* the default centre is gone */
    for (uint8_t x = 3; x <= 4; x++)
        for (uint8_t y = 1; y <= 2; y++) assert_true(truemaze_is_goal(&a, truemaze_cell(&a, x, y)));
    mazefile_format(&a, text, sizeof text);
    assert_string_equal(text, t);
}

/* CRLF, CR, trailing spaces, trailing blank lines, leading blank lines,
 * no final line end and '+' posts all read as the LF 'o' text does. */
static void test_variants_parse_alike(void **state)
{
    (void)state;
    static const struct {
        const char *eol;
        int plus, blank_after, blank_before;
    } v[] = {
        { "\r\n", 0, 0, 0 }, { "\r", 0, 0, 0 }, { "   \n", 0, 0, 0 }, { "\n", 1, 0, 0 },
        { "\n", 0, 2, 0 },   { "\r\n", 1, 3, 1 }, { " \r", 1, 1, 2 }, { "", 0, 0, 0 },
    };
    char buf[1024];
    assert_int_equal(parse(&a, small), 0);
    for (size_t i = 0; i < sizeof v / sizeof v[0]; i++) {
        size_t k = 0;
        for (int j = 0; j < v[i].blank_before; j++) buf[k++] = '\n';
        for (const char *p = small; *p; p++) {
            if (*p == '\n') {
                /* "" = no line end at all after the last row */
                const char *e = (*v[i].eol == '\0' && p[1] != '\0') ? "\n" : v[i].eol;
                for (; *e; e++) buf[k++] = *e;
            } else {
                buf[k++] = (v[i].plus && *p == 'o') ? '+' : *p;
            }
        }
        for (int j = 0; j < v[i].blank_after; j++) {
            memcpy(buf + k, j % 2 ? "  \r\n" : "\n", j % 2 ? 4 : 1);
            k += j % 2 ? 4 : 1;
        }
        if (mazefile_parse(&b, buf, k, "v", NULL, err, sizeof err) != 0) fail_msg("variant %zu: %s", i, err);
        assert_same_maze(&a, &b);
    }
}

/* Either wall character counts at either wall position, and a segment
 * with any wall character in it is a wall (as the database reference). */
static void test_lenient_walls(void **state)
{
    (void)state;
    const char *lenient =
        "o---o-|-o---o\n"
        "|       - G |\n"
        "o   o|||o   o\n"
        "| S -       |\n"
        "o---o- -o---o\n";
    assert_int_equal(parse(&a, small), 0);
    assert_int_equal(parse(&b, lenient), 0);
    assert_same_maze(&a, &b);
    /* a partly drawn boundary segment closes the boundary too */
    assert_int_equal(parse(&b, "o-  o\n|   |\no  -o\n"), 0);
    assert_int_equal(parse(&a, "o---o\n|   |\no---o\n"), 0);
    assert_same_maze(&a, &b);
}

/* Malformed text: the exact NAME:LINE:COL: prefix and kind of message. */
static void test_text_errors(void **state)
{
    (void)state;
    static const struct {
        const char *text;
        const char *want;
    } cases[] = {
        /* characters */
        { "o---o\n|   |\no---x\n", "t.txt:3:5: stray character 'x' (a post 'o' goes here)" },
        { "o---o---o\n|       |\no---    o\n", "t.txt:3:5: missing post" },
        { "o---o---o\n|   |   |\no---|---o\n", "t.txt:3:5: wall character '|' at the wrong column (a post goes here)" },
        { "o-------o\n|       |\no---o---o\n", "t.txt:1:5: wall character '-' at the wrong column (a post goes here)" },
        { "o---o---o\n|  -    |\no---o---o\n", "t.txt:2:4: wall character '-' at the wrong column" },
        { "o---o---o\n|   |   |\no-o-o---o\n", "t.txt:3:3: post 'o' at the wrong column" },
        { "o---o---o\n| +     |\no---o---o\n", "t.txt:2:3: post '+' at the wrong column" },
        { "o---o---o\n|S      |\no---o---o\n", "t.txt:2:2: letter 'S' off the centre of its cell" },
        { "o---o---o\n|     G |\n|       |\no---o---o\n", "t.txt:3:1: wall character '|' at the wrong column (a post goes here)" },
        { "o---o---o\n|      G|\no---o---o\n", "t.txt:2:8: letter 'G' off the centre of its cell" },
        { "o---o---o\n| S x   |\no---o---o\n", "t.txt:2:5: stray character 'x'" },
        { "o---o---o\n|     s |\no---o---o\n", "t.txt:2:7: stray character 's'" },
        { "o---o\n|\t  |\no---o\n", "t.txt:2:2: stray character byte 0x09" },
        { "o---o\n|   |\no-x-o\n", "t.txt:3:3: stray character 'x'" },
        { "o---o---o\n| S   S |\no---o---o\n", "t.txt:2:7: more than one start 'S' (the first is at 2:3)" },
        /* shape */
        { "o---o---o\n|   |   |\no---o\n", "t.txt:3:6: row shorter than the first (5 characters, want 9)" },
        { "o---o---o\n|   |\no---o---o\n", "t.txt:2:6: row shorter than the first (5 characters, want 9)" },
        { "o---o---o\n|       |\no---o--\n", "t.txt:3:8: row shorter than the first" },
        { "o---o\n|  \no---o\n", "t.txt:2:4: row shorter than the first (3 characters, want 5)" },
        { "o---o\n|   |\no---o---o\n", "t.txt:3:6: row longer than the first (9 characters, want 5)" },
        { "o---o\n|   |   |\no---o\n", "t.txt:2:6: row longer than the first" },
        { "o---o--\n|     |\no---o--\n", "t.txt:1:8: first row is 7 characters wide: want 4*cells+1" },
        { "o\n|\no\n", "t.txt:1:2: first row is 1 characters wide" },
        { "o--o\n|  |\no--o\n", "t.txt:1:4: post 'o' at the wrong column" },
        { "o---o---o\n|       |\n", "t.txt:3:1: the maze must end with a row of posts (2 rows" },
        { "o---o\n", "t.txt:2:1: no cell rows" },
        { "o---o\n|   |\n\no---o\n", "t.txt:3:1: blank line inside the maze" },
        { "o---o\n|   |\no   o\n  \n|   |\no---o\n", "t.txt:4:1: blank line inside the maze" }, /* not a boundary error */
        /* boundary */
        { "o---o   o\n|       |\no---o---o\n", "t.txt:1:7: boundary not closed" },
        { "o---o---o\n|       |\no   o---o\n", "t.txt:3:3: boundary not closed" },
        { "o---o\n    |\no---o\n", "t.txt:2:1: boundary not closed" },
        { "o---o---o\n|        \no---o---o\n", "t.txt:2:9: boundary not closed" },
        /* not a maze at all; line numbers across blank lines and CR ends */
        { "x---o\n", "t.txt:1:1: stray character 'x': a maze starts with a post 'o' (text) or a number (mms)" },
        { "\n \n  # comment\n", "t.txt:3:3: stray character '#'" },
        { "\n\no---o\n|   |\no---x\n", "t.txt:5:5: stray character 'x'" },
        { "o---o\r|   |\ro---x\r", "t.txt:3:5: stray character 'x'" },
        { "o---o\r\n|   |\r\no---x\r\n", "t.txt:3:5: stray character 'x'" },
        /* the first error in the file wins */
        { "o---o---o\n| x     |\no---o\n", "t.txt:2:3: stray character 'x'" },
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) expect_error(cases[i].text, strlen(cases[i].text), cases[i].want);
}

static void test_empty_file(void **state)
{
    (void)state;
    expect_error("", 0, "t.txt:1:1: empty file");
    expect_error("   \n\n  \r\n\t\n", 11, "t.txt:1:1: empty file");
    expect_error("x", 0, "t.txt:1:1: empty file"); /* len 0: nothing is read */
    /* no name and no error buffer are allowed too */
    assert_int_equal(mazefile_parse(&a, "", 0, NULL, NULL, NULL, 0), -1);
    assert_int_equal(mazefile_parse(&a, "", 0, NULL, NULL, err, sizeof err), -1);
    assert_string_equal(err, "<maze>:1:1: empty file");
}

static void test_nul_byte(void **state)
{
    (void)state;
    const char with_nul[] = "o---o\n|\0  |\no---o\n";
    expect_error(with_nul, sizeof with_nul - 1, "t.txt:2:2: NUL byte");
    const char nul_after[] = "o---o\n|   |\no---o\n\0";
    expect_error(nul_after, sizeof nul_after - 1, "t.txt:4:1: NUL byte");
    const char mms_nul[] = "0 0 1 1 1\0 1\n";
    expect_error(mms_nul, sizeof mms_nul - 1, "t.txt:1:10: NUL byte");
}

/* Sizes above TRUEMAZE_MAX_SIZE: 33x33, 33 wide, 33 high; 32x32 is fine. */
static void test_too_large_size(void **state)
{
    (void)state;
    char *p;
    for (int size = 32; size <= 33; size++) {
        for (int wide = 0; wide <= 1; wide++) {
            int w = wide ? size : 1, h = wide ? size : size;
            p = text;
            for (int r = 0; r <= 2 * h; r++) {
                for (int x = 0; x < w; x++) p += sprintf(p, r % 2 ? "|   " : "o---");
                p += sprintf(p, r % 2 ? "|\n" : "o\n");
            }
            int rc = parse(&a, text);
            if (size == 32) {
                assert_int_equal(rc, 0);
                assert_int_equal(a.width, w);
                assert_int_equal(a.height, h);
            } else if (wide) {
                assert_int_equal(rc, -1);
                assert_string_equal(err, "t.txt:1:130: maze wider than 32 cells");
            } else {
                assert_int_equal(rc, -1);
                assert_string_equal(err, "t.txt:66:1: maze taller than 32 cells (more than 65 rows)");
            }
        }
    }
}

/* A buffer above MAZEFILE_MAX_BYTES, directly and through mazefile_load. */
static void test_file_too_large(void **state)
{
    (void)state;
    size_t n = MAZEFILE_MAX_BYTES + 1;
    char *big = malloc(n);
    assert_non_null(big);
    memset(big, '\n', n);
    memcpy(big, "o---o\n|   |\no---o\n", 18);
    expect_error(big, n, "t.txt:1048562:1: file larger than 1048576 bytes");
    char path[] = "/tmp/test_mazefile_big_XXXXXX";
    int fd = mkstemp(path);
    assert_true(fd >= 0);
    FILE *f = fdopen(fd, "wb");
    assert_int_equal(fwrite(big, 1, n, f), n);
    fclose(f);
    assert_int_equal(mazefile_load(&a, path, NULL, err, sizeof err), -1);
    assert_non_null(strstr(err, ":1048562:1: file larger than 1048576 bytes"));
    assert_int_equal(strncmp(err, path, strlen(path)), 0);
    /* exactly the maximum is accepted */
    f = fopen(path, "wb");
    assert_int_equal(fwrite(big, 1, n - 1, f), n - 1);
    fclose(f);
    assert_int_equal(mazefile_load(&a, path, NULL, err, sizeof err), 0);
    remove(path);
    free(big);
}

/* Every prefix of a valid maze, in an exactly sized heap block: ASan sees
 * any read past len. */
static void test_no_read_past_buffer(void **state)
{
    (void)state;
    const char *inputs[] = { small, "0 0 1 1 1 1\n" };
    for (size_t i = 0; i < 2; i++) {
        size_t n = strlen(inputs[i]);
        for (size_t len = 0; len <= n; len++) {
            char *copy = malloc(len ? len : 1);
            memcpy(copy, inputs[i], len);
            int rc = mazefile_parse(&a, copy, len, "p", NULL, err, sizeof err);
            assert_true(rc == 0 || rc == -1);
            if (rc) assert_null(strchr(err, '\n'));
            free(copy);
        }
    }
}

/* The error is always one line, even for a name with line ends, and it
 * is cut to errlen. */
static void test_error_message_form(void **state)
{
    (void)state;
    assert_int_equal(mazefile_parse(&a, "x", 1, "a\nb\rc", NULL, err, sizeof err), -1);
    assert_null(strchr(err, '\n'));
    assert_null(strchr(err, '\r'));
    assert_int_equal(strncmp(err, "a?b?c:1:1: ", 11), 0);
    char tiny[8];
    assert_int_equal(mazefile_parse(&a, "x", 1, "t.txt", NULL, tiny, sizeof tiny), -1);
    assert_string_equal(tiny, "t.txt:1");
}

static void test_load(void **state)
{
    (void)state;
    mazefile_info_t info;
    assert_int_equal(mazefile_load(&a, "/nonexistent/m.txt", NULL, err, sizeof err), -1);
    assert_string_equal(err, "/nonexistent/m.txt: cannot open: No such file or directory");
    assert_int_equal(mazefile_load(&a, "/tmp", NULL, err, sizeof err), -1);
    assert_string_equal(err, "/tmp: not a regular file (a directory)");
    /* a file, and the same file as standard input ("-") */
    char path[] = "/tmp/test_mazefile_XXXXXX";
    int fd = mkstemp(path);
    assert_true(fd >= 0);
    FILE *f = fdopen(fd, "wb");
    fputs(small, f);
    fclose(f);
    assert_int_equal(mazefile_load(&a, path, &info, err, sizeof err), 0);
    assert_true(info.has_start);
    assert_non_null(freopen(path, "rb", stdin));
    assert_int_equal(mazefile_load(&b, "-", NULL, err, sizeof err), 0);
    assert_same_maze(&a, &b);
    /* errors from standard input are named <stdin> */
    f = fopen(path, "wb");
    fputs("o---o\n|   |\no---x\n", f);
    fclose(f);
    assert_non_null(freopen(path, "rb", stdin));
    assert_int_equal(mazefile_load(&b, "-", NULL, err, sizeof err), -1);
    assert_string_equal(err, "<stdin>:3:5: stray character 'x' (a post 'o' goes here)");
    remove(path);
}

/* The writers follow snprintf: the full length is returned, at most cap
 * bytes are written, always NUL-terminated when cap > 0. */
static void test_format_snprintf(void **state)
{
    (void)state;
    assert_int_equal(parse(&a, small), 0);
    size_t need = mazefile_format(&a, NULL, 0);
    assert_int_equal(need, strlen(small));
    char buf[10];
    memset(buf, 'z', sizeof buf);
    assert_int_equal(mazefile_format(&a, buf, sizeof buf), need);
    assert_int_equal(strlen(buf), 9);
    assert_int_equal(strncmp(buf, small, 9), 0);
    buf[0] = 'z';
    assert_int_equal(mazefile_format(&a, buf, 1), need);
    assert_int_equal(buf[0], '\0');
    size_t need_mms = mazefile_format_mms(&a, NULL, 0);
    assert_int_equal(mazefile_format_mms(&a, buf, sizeof buf), need_mms);
    assert_string_equal(buf, "0 0 0 1 1");
    /* a truemaze_t that was never set up writes nothing */
    truemaze_t zero;
    memset(&zero, 0, sizeof zero);
    assert_int_equal(mazefile_format(&zero, buf, sizeof buf), 0);
    assert_string_equal(buf, "");
    assert_int_equal(mazefile_format_mms(&zero, buf, sizeof buf), 0);
}

/* A start inside the default centre goal is written without G letters, so
 * reading it back gives the same goal. */
static void test_start_in_goal_round_trip(void **state)
{
    (void)state;
    const char *t =
        "o---o---o---o---o\n"
        "|               |\n"
        "o   o   o   o   o\n"
        "|     S         |\n"
        "o   o   o   o   o\n"
        "|               |\n"
        "o   o   o   o   o\n"
        "|               |\n"
        "o---o---o---o---o\n";
    assert_int_equal(parse(&a, t), 0);
    assert_true(truemaze_is_goal(&a, a.start));
    mazefile_format(&a, text, sizeof text);
    assert_string_equal(text, t);
    assert_int_equal(parse(&b, text), 0);
    assert_same_maze(&a, &b);
}

/* A start inside any other goal cannot be written (one letter per cell,
 * and S wins): the walls and start survive, the goal becomes the default.
 * Found by the fuzzer; the limitation is documented in mazefile.h. */
static void test_start_in_other_goal(void **state)
{
    (void)state;
    const char *t = "o---o---o---o\n| G |   |   |\no---o---o---o\n";
    assert_int_equal(parse(&a, t), 0);
    assert_true(truemaze_is_goal(&a, a.start));
    assert_int_equal(goal_count(&a), 1);
    mazefile_format(&a, text, sizeof text);
    assert_string_equal(text, "o---o---o---o\n| S |   |   |\no---o---o---o\n");
    assert_int_equal(parse(&b, text), 0);
    assert_memory_equal(a.cell, b.cell, truemaze_cells(&a));
    assert_int_equal(a.start, b.start);
    assert_true(truemaze_is_goal(&b, truemaze_cell(&b, 1, 0)) && goal_count(&b) == 1);
}

/* ---- mms numeric format ---- */

static void test_mms_small(void **state)
{
    (void)state;
    mazefile_info_t info;
    /* the 3x2 maze above, cells in any order, blank lines, tabs, CRLF */
    const char *t =
        "2 1 1 1 0 1\r\n"
        "0 0 0 1 1 1\r\n"
        "\r\n"
        "0 1\t1 0 0 1\r\n"
        "  1 0 1 0 1 1  \r\n"
        "1 1 1 1 1 0\r\n"
        "2 0 0 1 1 0\t\r\n";
    assert_int_equal(mazefile_parse(&b, t, strlen(t), "m", &info, err, sizeof err), 0);
    assert_true(info.mms_format && !info.has_start && !info.has_goal);
    assert_int_equal(parse(&a, small), 0);
    assert_int_equal(b.width, 3);
    assert_int_equal(b.height, 2);
    assert_memory_equal(a.cell, b.cell, truemaze_cells(&a));
    /* start and goal are the defaults: (0,0) facing north, the centre */
    assert_int_equal(b.start, 0);
    assert_int_equal(b.start_heading, TRUEMAZE_NORTH);
    assert_int_equal(goal_count(&b), 2);
    assert_true(truemaze_is_goal(&b, truemaze_cell(&b, 1, 0)) && truemaze_is_goal(&b, truemaze_cell(&b, 1, 1)));
    /* written x outside, y inside, like mms itself */
    size_t n = mazefile_format_mms(&b, text, sizeof text);
    assert_int_equal(n, strlen(text));
    assert_string_equal(text, "0 0 0 1 1 1\n0 1 1 0 0 1\n1 0 1 0 1 1\n1 1 1 1 1 0\n2 0 0 1 1 0\n2 1 1 1 0 1\n");
    assert_int_equal(mazefile_parse(&a, text, n, "m2", NULL, err, sizeof err), 0);
    assert_same_maze(&a, &b);
}

static void test_mms_errors(void **state)
{
    (void)state;
    static const struct {
        const char *text;
        const char *want;
    } cases[] = {
        { "0 0 1 1 1\n", "t.txt:1:10: want 6 numbers per line: X Y N E S W (got 5)" },
        { "0 0 1 1 1 2\n", "t.txt:1:11: wall value must be 0 or 1" },
        { "0 0 1 1 1 1 7\n", "t.txt:1:13: more than 6 fields on the line" },
        { "0,0 1 1 1 1\n", "t.txt:1:2: stray character ',' after a number" },
        { "0 -1 1 1 1 1\n", "t.txt:1:3: stray character '-' (want 6 numbers" },
        { "32 0 1 1 1 1\n", "t.txt:1:1: coordinate 32 above the maximum 31" },
        { "0 99999999999 1 1 1 1\n", "t.txt:1:3: coordinate 99999999999 above the maximum 31" },
        { "0 0 1 1 1 1\n0 0 1 1 1 1\n", "t.txt:2:1: cell (0,0) given twice (first on line 1)" },
        /* a wall seen from both sides must agree: east/west and north/south */
        { "0 0 1 0 1 1\n1 0 1 1 1 1\n", "t.txt:2:11: wall between (1,0) and (0,0) disagrees with line 1" },
        { "1 0 1 1 1 1\n0 0 1 0 1 1\n", "t.txt:2:7: wall between (0,0) and (1,0) disagrees with line 1" },
        { "0 0 0 1 1 1\n0 1 0 1 1 1\n", "t.txt:2:9: wall between (0,1) and (0,0) disagrees with line 1" },
        { "0 1 1 1 0 1\n\n0 0 1 1 1 1\n", "t.txt:3:5: wall between (0,0) and (0,1) disagrees with line 1" },
        /* boundary */
        { "0 0 1 1 1 0\n", "t.txt:1:11: boundary not closed: west wall of cell (0,0)" },
        { "0 0 1 1 0 1\n", "t.txt:1:9: boundary not closed: south wall of cell (0,0)" },
        { "0 0 0 1 1 1\n", "t.txt:1:5: boundary not closed: north wall of cell (0,0)" },
        { "0 0 1 0 1 1\n", "t.txt:1:7: boundary not closed: east wall of cell (0,0)" },
        { "0 1 0 1 0 1\n0 0 0 0 1 1\n", "t.txt:1:5: boundary not closed: north wall of cell (0,1)" }, /* first in the file */
        /* every cell once */
        { "0 0 1 0 1 1\n1 0 0 1 1 0\n1 1 1 1 0 1\n\n", "t.txt:4:1: cell (0,1) missing" },
        /* text after the numbers; a text row in a numeric file */
        { "0 0 1 1 1 1\no---o\n", "t.txt:2:1: stray character 'o' (want 6 numbers" },
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) expect_error(cases[i].text, strlen(cases[i].text), cases[i].want);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_small_maze),
        cmocka_unit_test(test_one_cell),
        cmocka_unit_test(test_defaults),
        cmocka_unit_test(test_start_heading),
        cmocka_unit_test(test_goal_area),
        cmocka_unit_test(test_variants_parse_alike),
        cmocka_unit_test(test_lenient_walls),
        cmocka_unit_test(test_text_errors),
        cmocka_unit_test(test_empty_file),
        cmocka_unit_test(test_nul_byte),
        cmocka_unit_test(test_too_large_size),
        cmocka_unit_test(test_file_too_large),
        cmocka_unit_test(test_no_read_past_buffer),
        cmocka_unit_test(test_error_message_form),
        cmocka_unit_test(test_load),
        cmocka_unit_test(test_format_snprintf),
        cmocka_unit_test(test_start_in_goal_round_trip),
        cmocka_unit_test(test_start_in_other_goal),
        cmocka_unit_test(test_mms_small),
        cmocka_unit_test(test_mms_errors),
        cmocka_unit_test(test_database_matches_reference),
        cmocka_unit_test(test_database_round_trip),
        cmocka_unit_test(test_database_mms_round_trip),
    };
    return cmocka_run_group_tests_name("mazefile", tests, NULL, NULL);
}

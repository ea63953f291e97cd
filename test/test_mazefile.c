/* test_mazefile.c - maze files: the whole database parses and agrees with
 * the independent reference, malformed inputs give FILE:LINE:COL errors,
 * line-end and post variants, round trips, mms numeric format. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <cmocka.h>

#include <dirent.h>
#include <jansson.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "mazefile.h"
#include "solve.h"

static const char *shared(void)
{
    const char *s = getenv("SHARED");
    return s ? s : "../shared";
}

static maze_t a, b;
static char err[MAZEFILE_ERR_LEN];
static char text[1 << 16], text2[1 << 16];

static int parse(maze_t *m, const char *t)
{
    return mazefile_parse(m, t, strlen(t), "t.txt", NULL, err, sizeof err);
}

static void assert_same_maze(const maze_t *x, const maze_t *y)
{
    assert_int_equal(x->width, y->width);
    assert_int_equal(x->height, y->height);
    assert_memory_equal(x->cell, y->cell, maze_cells(x));
    assert_memory_equal(x->goal, y->goal, sizeof x->goal);
    assert_int_equal(x->start, y->start);
    assert_int_equal(x->start_heading, y->start_heading);
}

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
    assert_int_equal(a.start, maze_cell(&a, 0, 0));
    assert_int_equal(a.start_heading, MAZE_NORTH);
    assert_true(maze_is_goal(&a, maze_cell(&a, 2, 1)));
    assert_false(maze_is_goal(&a, maze_cell(&a, 1, 0))); /* default centre cleared by G */
    assert_int_equal(maze_wall(&a, maze_cell(&a, 0, 0), MAZE_EAST), MAZE_WALL_CLOSED);
    assert_int_equal(maze_wall(&a, maze_cell(&a, 0, 0), MAZE_NORTH), MAZE_WALL_OPEN);
    assert_int_equal(maze_wall(&a, maze_cell(&a, 1, 1), MAZE_EAST), MAZE_WALL_CLOSED);
    assert_int_equal(maze_wall(&a, maze_cell(&a, 2, 0), MAZE_NORTH), MAZE_WALL_OPEN);
    assert_int_equal(maze_wall(&a, maze_cell(&a, 1, 0), MAZE_NORTH), MAZE_WALL_CLOSED);
    /* writer gives the same text back */
    assert_int_equal(mazefile_format(&a, text, sizeof text), strlen(small));
    assert_string_equal(text, small);
}

/* No letters: start (0,0) north, goal = centre; closed north -> east. */
static void test_defaults(void **state)
{
    (void)state;
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
    assert_int_equal(parse(&a, t), 0);
    assert_int_equal(a.start, 0);
    assert_int_equal(a.start_heading, MAZE_EAST);
    int goals = 0;
    for (uint16_t c = 0; c < maze_cells(&a); c++) goals += maze_is_goal(&a, (maze_cell_t)c);
    assert_int_equal(goals, 4);
    assert_true(maze_is_goal(&a, maze_cell(&a, 1, 1)) && maze_is_goal(&a, maze_cell(&a, 2, 2)));
}

/* CRLF, CR, trailing spaces, trailing blank lines and '+' posts. */
static void test_variants_parse_alike(void **state)
{
    (void)state;
    assert_int_equal(parse(&a, small), 0);
    /* build the variants from the LF text */
    char buf[512];
    const char *ends[] = { "\r\n", "\r", "  \n", "\n" };
    for (int v = 0; v < 4; v++) {
        size_t k = 0;
        for (const char *p = small; *p; p++) {
            if (*p == '\n') {
                for (const char *e = ends[v]; *e; e++) buf[k++] = *e;
            } else {
                buf[k++] = (v == 3 && *p == 'o') ? '+' : *p;
            }
        }
        if (v == 2) { buf[k++] = '\n'; buf[k++] = '\n'; } /* trailing blank lines */
        buf[k] = '\0';
        assert_int_equal(parse(&b, buf), 0);
        assert_same_maze(&a, &b);
    }
    /* no final line end */
    strcpy(buf, small);
    buf[strlen(buf) - 1] = '\0';
    assert_int_equal(parse(&b, buf), 0);
    assert_same_maze(&a, &b);
}

/* Malformed inputs: the exact FILE:LINE:COL of each message. */
static void test_errors_have_line_and_col(void **state)
{
    (void)state;
    static const struct {
        const char *text;
        const char *where;
    } cases[] = {
        { "", "t.txt:1:1: empty file" },
        { "   \n\n  \n", "t.txt:1:1: empty file" },
        { "o---o\n|   |\no---x\n", "t.txt:3:5: stray character 'x'" },                 /* stray char */
        { "o---o---o\n|   |   |\no---o\n", "t.txt:3:6: row shorter" },                 /* non-rectangular */
        { "o---o\n|   |\no---o---o\n", "t.txt:3:6: row longer" },                     /* non-rectangular */
        { "o---o---o\n|       |\no---    o\n", "t.txt:3:5: missing post" },           /* missing post */
        { "o---o---o\n|        \no---o---o\n", "t.txt:2:9: boundary not closed" },    /* east boundary */
        { "o---o   o\n|       |\no---o---o\n", "t.txt:1:6: boundary not closed" },    /* north boundary */
        { "o---o\n    |\no---o\n", "t.txt:2:1: boundary not closed" },                /* west boundary */
        { "o---o---o\n|   -   |\no---o---o\n", "t.txt:2:5: wall character '-' at the wrong column" },
        { "o---o---o\n| | |   |\no---o---o\n", "t.txt:2:3: wall character '|' at the wrong column" },
        { "o---o---o\n|       |\no-- o---o\n", "t.txt:3:4: broken wall" },
        { "o---o---o\n| S   S |\no---o---o\n", "t.txt:2:7: more than one start 'S'" },
        { "o---o---o\n| S x   |\no---o---o\n", "t.txt:2:5: stray character 'x'" },
        { "o---o---o\n|       |\n", "t.txt:2:1: the maze must end with a row of posts" },
        { "o---o\n|   |\n\no---o\n|   |\no---o\n", "t.txt:3:1: blank line inside the maze" },
        { "o--o\n|  |\no--o\n", "t.txt:1:5: first row must be 4*cells+1" },
        { "x---o\n", "t.txt:1:1: stray character 'x'" },
        { "o---o\n|   |\r\n|   |\ro---o\n|   |\no---o\no---o\n", "t.txt:3:1: wall character '|' at the wrong column" },
        { "0 0 1 1 1\n", "t.txt:1:10: want 6 numbers" },
        { "0 0 1 1 1 2\n", "t.txt:1:11: wall value must be 0 or 1" },
        { "0 0 1 1 1 1\n0 0 1 1 1 1\n", "t.txt:2:1: cell (0,0) given twice" },
        { "0 0 1 0 1 1\n1 0 1 1 1 1\n", "t.txt:1:1: wall between (0,0) and (1,0) disagrees with line 2" },
        { "0 0 1 1 1 1\n1 0 1 1 1 1\n1 1 1 1 1 1\n", "t.txt:4:1: cell (0,1) missing" },
        { "0 0 0 1 1 1\n", "t.txt:1:1: boundary not closed at cell (0,0)" },
        { "0 0 1 1 1 1 7\n", "t.txt:1:13: stray character '7' after the 6 numbers" },
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        err[0] = '\0';
        assert_int_equal(parse(&a, cases[i].text), -1);
        if (strncmp(err, cases[i].where, strlen(cases[i].where)) != 0)
            fail_msg("case %zu: got \"%s\", want prefix \"%s\"", i, err, cases[i].where);
        assert_null(strchr(err, '\n')); /* one line */
    }
}

/* NUL byte, sizes above the maximum, and the buffer is never read past len. */
static void test_nul_size_and_bounds(void **state)
{
    (void)state;
    const char with_nul[] = "o---o\n|\0  |\no---o\n";
    assert_int_equal(mazefile_parse(&a, with_nul, sizeof with_nul - 1, "t.txt", NULL, err, sizeof err), -1);
    assert_string_equal(err, "t.txt:2:2: NUL byte");
    /* 33 cells wide */
    size_t k = 0;
    for (int x = 0; x < 33; x++) k += (size_t)sprintf(text + k, "o---");
    k += (size_t)sprintf(text + k, "o\n");
    text[k] = '\0';
    assert_int_equal(parse(&a, text), -1);
    assert_string_equal(err, "t.txt:1:1: 33 cells wide: the maximum is 32");
    /* 33 cells high */
    k = 0;
    for (int r = 0; r < 67; r++) k += (size_t)sprintf(text + k, r % 2 ? "|   |\n" : "o---o\n");
    assert_int_equal(parse(&a, text), -1);
    assert_non_null(strstr(err, "t.txt:66:1: more than 65 rows"));
    /* every prefix of a valid maze: an error or a maze, never a read past len */
    size_t n = strlen(small);
    for (size_t len = 0; len < n; len++) {
        char *copy = malloc(len ? len : 1); /* exact size: ASan sees any overread */
        memcpy(copy, small, len);
        int rc = mazefile_parse(&a, copy, len, "p", NULL, err, sizeof err);
        assert_true(rc == 0 || rc == -1);
        free(copy);
    }
    /* a file that does not exist */
    assert_int_equal(mazefile_load(&a, "/nonexistent/m.txt", NULL, err, sizeof err), -1);
    assert_string_equal(err, "/nonexistent/m.txt: cannot open: No such file or directory");
}

static void test_mms_format(void **state)
{
    (void)state;
    mazefile_info_t info;
    /* the 3x2 maze above in mms numeric format, written and read back */
    assert_int_equal(parse(&a, small), 0);
    size_t n = mazefile_format_mms(&a, text, sizeof text);
    assert_int_equal(n, strlen(text));
    assert_string_equal(text, "0 0 0 1 1 1\n0 1 1 0 0 1\n1 0 1 0 1 1\n1 1 1 1 1 0\n2 0 0 1 1 0\n2 1 1 1 0 1\n");
    assert_int_equal(mazefile_parse(&b, text, n, "m", &info, err, sizeof err), 0);
    assert_true(info.mms_format);
    /* same walls; start and goal are the format's defaults */
    assert_memory_equal(a.cell, b.cell, maze_cells(&a));
    assert_int_equal(b.start, 0);
    assert_true(maze_is_goal(&b, maze_cell(&b, 1, 0)) && maze_is_goal(&b, maze_cell(&b, 1, 1)));
}

/* A start inside the default centre goal: written without G letters, so
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
    assert_true(maze_is_goal(&a, a.start));
    mazefile_format(&a, text, sizeof text);
    assert_null(strchr(text, 'G'));
    assert_int_equal(parse(&b, text), 0);
    assert_same_maze(&a, &b);
}

static int ends_with_txt(const char *s)
{
    size_t n = strlen(s);
    return n > 4 && !strcmp(s + n - 4, ".txt");
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

/* The whole database: parses, matches reference.jsonl (size, reachability,
 * best cost/cells/turns, fewest cells), and round-trips. */
static void test_database(void **state)
{
    (void)state;
    char path[1024];
    snprintf(path, sizeof path, "%s/mazes/reference.jsonl", shared());
    FILE *ref = fopen(path, "r");
    if (!ref) {
        printf("SKIP test_database: %s not found\n", path);
        skip();
    }
    char line[1024];
    int files = 0, exact = 0;
    static solve_path_t best;
    while (fgets(line, sizeof line, ref)) {
        json_error_t jerr;
        json_t *r = json_loads(line, 0, &jerr);
        assert_non_null(r);
        const char *name = json_string_value(json_object_get(r, "maze"));
        snprintf(path, sizeof path, "%s/mazes/%s", shared(), name);
        mazefile_info_t info;
        if (mazefile_load(&a, path, &info, err, sizeof err) != 0) fail_msg("%s", err);
        assert_int_equal(a.width, json_integer_value(json_object_get(r, "width")));
        assert_int_equal(a.height, json_integer_value(json_object_get(r, "height")));
        int reachable = solve_best(&a, 0, &best) == 0;
        assert_int_equal(reachable, json_is_true(json_object_get(r, "goal_reachable")));
        if (reachable) {
            if (best.cost != json_integer_value(json_object_get(r, "cost")) ||
                best.cells != json_integer_value(json_object_get(r, "cells")) ||
                best.turns != json_integer_value(json_object_get(r, "turns")) ||
                best.min_cells != json_integer_value(json_object_get(r, "min_cells")))
                fail_msg("%s: got %u/%u/%u/%u", name, best.cost, best.cells, best.turns, best.min_cells);
        }
        /* round trip: read -> write -> read gives the same maze */
        size_t n = mazefile_format(&a, text, sizeof text);
        assert_true(n < sizeof text);
        assert_int_equal(mazefile_parse(&b, text, n, "rt", NULL, err, sizeof err), 0);
        assert_same_maze(&a, &b);
        /* files marking S and G: the written text equals the normalised input */
        if (info.has_start && info.has_goal) {
            FILE *f = fopen(path, "rb");
            size_t len = fread(text2, 1, sizeof text2 - 1, f);
            fclose(f);
            static char norm[1 << 16];
            normalise(text2, len, norm);
            if (strcmp(norm, text) != 0) fail_msg("%s: written text differs from the input", name);
            exact++;
        }
        files++;
        json_decref(r);
    }
    fclose(ref);
    assert_true(files > 500);
    assert_true(exact > 400);
}

/* Every *.txt under $SHARED/mazes parses (also files reference.jsonl might miss). */
static void test_every_database_file_parses(void **state)
{
    (void)state;
    const char *sub[] = { "classic", "halfsize", "training" };
    char dir[1024], path[2048];
    int files = 0;
    for (int i = 0; i < 3; i++) {
        snprintf(dir, sizeof dir, "%s/mazes/%s", shared(), sub[i]);
        DIR *d = opendir(dir);
        if (!d) {
            printf("SKIP test_every_database_file_parses: %s not found\n", dir);
            skip();
        }
        struct dirent *e;
        while ((e = readdir(d)) != NULL) {
            if (!ends_with_txt(e->d_name)) continue;
            snprintf(path, sizeof path, "%s/%s", dir, e->d_name);
            if (mazefile_load(&a, path, NULL, err, sizeof err) != 0) fail_msg("%s", err);
            files++;
        }
        closedir(d);
    }
    assert_true(files >= 534);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_small_maze),
        cmocka_unit_test(test_defaults),
        cmocka_unit_test(test_variants_parse_alike),
        cmocka_unit_test(test_errors_have_line_and_col),
        cmocka_unit_test(test_nul_size_and_bounds),
        cmocka_unit_test(test_mms_format),
        cmocka_unit_test(test_start_in_goal_round_trip),
        cmocka_unit_test(test_database),
        cmocka_unit_test(test_every_database_file_parses),
    };
    return cmocka_run_group_tests_name("mazefile", tests, NULL, NULL);
}

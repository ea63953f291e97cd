/* mmmaze - maze files from the command line: check, show, solve, generate,
 * and grid-mode exploration with the firmware's search code.
 *
 * Exit codes: 0 ok, 1 goal not reached, 2 bad input, 3 external failure. */
#include <ctype.h>
#include <errno.h>
#include <getopt.h>
#include <jansson.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "maze/grid.h"
#include "hal_sim.h"
#include "io/stdstream.h"
#include "maze/truemaze.h"
#include "maze/mazedir.h"
#include "maze/mazefile.h"
#include "maze/mazegen.h"
#include "maze/solve.h"

enum { EXIT_OK = 0, EXIT_NOT_REACHED = 1, EXIT_BAD_INPUT = 2, EXIT_EXTERNAL = 3 };

static const char *const heading_name[4] = { "N", "E", "S", "W" };
static truemaze_t maze;   /* the maze being worked on */
static solve_path_t best; /* its best path */

static void usage(FILE *out)
{
    fputs("usage: mmmaze check FILE... [--strict]\n"
          "       mmmaze show FILE [--path]\n"
          "       mmmaze solve FILE [--json]\n"
          "       mmmaze gen (--size N | --width W --height H) [--seed S]\n"
          "       mmmaze explore FILE [--json]\n"
          "       mmmaze explore --all DIR [--json]\n"
          "Maze files: micromouseonline text format or mms numeric format; '-' reads stdin.\n"
          "Exit codes: 0 ok, 1 goal not reached, 2 bad input, 3 external failure.\n",
          out);
}

static int bad_usage(const char *what)
{
    fprintf(stderr, "mmmaze: %s (try 'mmmaze --help')\n", what);
    return EXIT_BAD_INPUT;
}

/* getopt_long returned '?' or ':' for argv[optind - 1]. */
static int bad_option(const char *cmd, char **argv)
{
    fprintf(stderr, "mmmaze: %s: unknown option or missing value: '%s' (try 'mmmaze --help')\n", cmd, argv[optind - 1]);
    return EXIT_BAD_INPUT;
}

/* Parse a whole decimal number in [lo, hi] (digits and an optional '-':
 * no spaces, '+' or hex); on error print one line. */
static int parse_num(const char *opt, const char *s, long lo, long hi, long *out)
{
    char *end;
    errno = 0;
    int plain = isdigit((unsigned char)s[0]) || (s[0] == '-' && isdigit((unsigned char)s[1]));
    long v = plain ? strtol(s, &end, 10) : 0;
    if (!plain || errno || *end != '\0' || v < lo || v > hi) {
        fprintf(stderr, "mmmaze: %s: expected a whole number from %ld to %ld, got '%s'\n", opt, lo, hi, s);
        return -1;
    }
    *out = v;
    return 0;
}

static int load(const char *path)
{
    char err[MAZEFILE_ERR_LEN];
    if (mazefile_load(&maze, path, NULL, err, sizeof err) != 0) {
        fprintf(stderr, "%s\n", err);
        return -1;
    }
    return 0;
}

static void goal_bounds(const truemaze_t *m, int *x0, int *y0, int *x1, int *y1, int *n)
{
    *x0 = *y0 = 255;
    *x1 = *y1 = -1;
    *n = 0;
    for (uint16_t c = 0; c < truemaze_cells(m); c++) {
        if (!truemaze_is_goal(m, (truemaze_cell_t)c)) continue;
        int x = truemaze_x(m, (truemaze_cell_t)c), y = truemaze_y(m, (truemaze_cell_t)c);
        if (x < *x0) *x0 = x;
        if (y < *y0) *y0 = y;
        if (x > *x1) *x1 = x;
        if (y > *y1) *y1 = y;
        (*n)++;
    }
}

static int cmd_check(int argc, char **argv)
{
    static const struct option opts[] = { { "strict", no_argument, 0, 's' }, { 0, 0, 0, 0 } };
    int strict = 0, o, rc = EXIT_OK;
    while ((o = getopt_long(argc, argv, "", opts, NULL)) != -1) {
        if (o == 's') strict = 1;
        else return bad_option("check", argv);
    }
    if (optind >= argc) return bad_usage("check: no FILE given");
    for (int i = optind; i < argc; i++) {
        int x0, y0, x1, y1, n;
        if (load(argv[i]) != 0) {
            rc = EXIT_BAD_INPUT;
            continue;
        }
        goal_bounds(&maze, &x0, &y0, &x1, &y1, &n);
        printf("%s: %ux%u, start (%u,%u) %s, goal (%d,%d)-(%d,%d) %d cell%s\n", argv[i], maze.width,
               maze.height, truemaze_x(&maze, maze.start), truemaze_y(&maze, maze.start),
               heading_name[maze.start_heading], x0, y0, x1, y1, n, n == 1 ? "" : "s");
        if (solve_best(&maze, &best) != 0) {
            fprintf(stderr, "%s: %s: goal unreachable from the start\n", argv[i], strict ? "error" : "warning");
            if (strict) rc = EXIT_BAD_INPUT;
        }
    }
    return rc;
}

/* ASCII render in the database format; path cells marked with '*'. */
static int cmd_show(int argc, char **argv)
{
    static const struct option opts[] = { { "path", no_argument, 0, 'p' }, { 0, 0, 0, 0 } };
    int with_path = 0, o;
    while ((o = getopt_long(argc, argv, "", opts, NULL)) != -1) {
        if (o == 'p') with_path = 1;
        else return bad_option("show", argv);
    }
    if (optind != argc - 1) return bad_usage("show: needs exactly one FILE");
    if (load(argv[optind]) != 0) return EXIT_BAD_INPUT;
    size_t need = mazefile_format(&maze, NULL, 0) + 1;
    char *text = malloc(need);
    if (!text) return EXIT_EXTERNAL;
    mazefile_format(&maze, text, need);
    int reachable = solve_best(&maze, &best) == 0;
    if (with_path && reachable) {
        /* the cell centre of (x,y) is at row 2*(h-1-y)+1, column 4x+2 */
        size_t row_len = (size_t)maze.width * 4 + 2;
        for (uint16_t j = 0; j < best.len; j++) {
            truemaze_cell_t c = best.path[j];
            size_t at = (size_t)(2 * (maze.height - 1 - truemaze_y(&maze, c)) + 1) * row_len +
                        (size_t)truemaze_x(&maze, c) * 4 + 2;
            if (text[at] == ' ') text[at] = '*';
        }
    }
    fputs(text, stdout);
    free(text);
    if (with_path && !reachable) {
        fprintf(stderr, "%s: goal unreachable from the start\n", argv[optind]);
        return EXIT_NOT_REACHED;
    }
    if (with_path)
        printf("cost %u: %u cells, %u turns\n", best.cost, best.cells, best.turns);
    return EXIT_OK;
}

static int print_json(json_t *j)
{
    char *s = json_dumps(j, JSON_COMPACT | JSON_ENSURE_ASCII);
    json_decref(j);
    if (!s) return EXIT_EXTERNAL;
    puts(s);
    free(s);
    return EXIT_OK;
}

static int cmd_solve(int argc, char **argv)
{
    static const struct option opts[] = { { "json", no_argument, 0, 'j' }, { 0, 0, 0, 0 } };
    int json = 0, o;
    while ((o = getopt_long(argc, argv, "", opts, NULL)) != -1) {
        if (o == 'j') json = 1;
        else return bad_option("solve", argv);
    }
    if (optind != argc - 1) return bad_usage("solve: needs exactly one FILE");
    if (load(argv[optind]) != 0) return EXIT_BAD_INPUT;
    int reachable = solve_best(&maze, &best) == 0;
    if (json) {
        json_t *path = json_array();
        for (uint16_t j = 0; j < best.len; j++)
            json_array_append_new(path, json_pack("[ii]", truemaze_x(&maze, best.path[j]), truemaze_y(&maze, best.path[j])));
        json_t *out = json_pack("{s:o, s:b}", "path", path, "goal_reachable", reachable);
        json_object_set_new(out, "cells", reachable ? json_integer(best.cells) : json_null());
        json_object_set_new(out, "turns", reachable ? json_integer(best.turns) : json_null());
        json_object_set_new(out, "cost", reachable ? json_integer(best.cost) : json_null());
        json_object_set_new(out, "min_cells", reachable ? json_integer(best.min_cells) : json_null());
        if (print_json(out) != EXIT_OK) return EXIT_EXTERNAL;
    } else if (reachable) {
        printf("cost %u: %u cells, %u turns (fewest cells of any path: %u)\npath:", best.cost, best.cells,
               best.turns, best.min_cells);
        for (uint16_t j = 0; j < best.len; j++)
            printf(" (%u,%u)", truemaze_x(&maze, best.path[j]), truemaze_y(&maze, best.path[j]));
        putchar('\n');
    } else {
        printf("goal unreachable from the start\n");
    }
    return reachable ? EXIT_OK : EXIT_NOT_REACHED;
}

static int cmd_gen(int argc, char **argv)
{
    static const struct option opts[] = { { "size", required_argument, 0, 'n' },
                                          { "width", required_argument, 0, 'w' },
                                          { "height", required_argument, 0, 'h' },
                                          { "seed", required_argument, 0, 's' },
                                          { 0, 0, 0, 0 } };
    long w = 0, h = 0, seed = 1, v;
    int o;
    while ((o = getopt_long(argc, argv, "", opts, NULL)) != -1) {
        const char *name = o == 'n' ? "--size" : o == 'w' ? "--width" : o == 'h' ? "--height" : "--seed";
        if (o == '?' || o == ':') return bad_option("gen", argv);
        if (o == 's') {
            if (parse_num(name, optarg, 0, 4294967295L, &v) != 0) return EXIT_BAD_INPUT;
            seed = v;
            continue;
        }
        if (parse_num(name, optarg, MAZEGEN_MIN_SIZE, MAZEGEN_MAX_SIZE, &v) != 0) return EXIT_BAD_INPUT;
        if (o == 'n') w = h = v;
        else if (o == 'w') w = v;
        else h = v;
    }
    if (optind != argc) return bad_usage("gen: unexpected argument");
    if (!w || !h) return bad_usage("gen: give --size N or --width W --height H");
    if (mazegen_generate(&maze, (uint8_t)w, (uint8_t)h, (uint32_t)seed) != 0)
        return bad_usage("gen: size out of range");
    size_t need = mazefile_format(&maze, NULL, 0) + 1;
    char *text = malloc(need);
    if (!text) return EXIT_EXTERNAL;
    mazefile_format(&maze, text, need);
    fputs(text, stdout);
    free(text);
    return EXIT_OK;
}

static json_t *explore_json(const grid_result_t *r)
{
    json_t *o = json_pack("{s:I, s:I, s:I, s:I, s:I, s:I, s:b, s:b, s:b}", "steps", (json_int_t)r->steps,
                          "steps_forward", (json_int_t)r->steps_forward, "steps_left", (json_int_t)r->steps_left,
                          "steps_right", (json_int_t)r->steps_right, "steps_back", (json_int_t)r->steps_back,
                          "cells_visited", (json_int_t)r->cells_visited, "final_path_optimal",
                          r->final_path_optimal, "goal_reachable", r->goal_reachable, "ended_at_start",
                          r->ended_at_start);
    json_object_set_new(o, "proven_at_step", r->proven_at_step >= 0 ? json_integer(r->proven_at_step) : json_null());
    json_object_set_new(o, "goal_at_step", r->goal_at_step >= 0 ? json_integer(r->goal_at_step) : json_null());
    json_object_set_new(o, "run_cost", r->proven_at_step >= 0 ? json_integer(r->run_cost) : json_null());
    json_object_set_new(o, "true_cost", r->goal_reachable ? json_integer(r->true_cost) : json_null());
    return o;
}

static void explore_text(const char *name, const grid_result_t *r)
{
    printf("%s: %u steps (%u forward, %u right, %u left, %u back), %u cells visited\n", name,
           (unsigned)r->steps, (unsigned)r->steps_forward, (unsigned)r->steps_right, (unsigned)r->steps_left,
           (unsigned)r->steps_back, (unsigned)r->cells_visited);
    if (!r->goal_reachable) {
        printf("%s: goal unreachable from the start\n", name);
        return;
    }
    if (r->proven_at_step >= 0)
        printf("%s: run path proven at step %d, cost %u; true best cost %u: %s\n", name, r->proven_at_step,
               r->run_cost, r->true_cost, r->final_path_optimal ? "optimal" : "NOT optimal");
    else
        printf("%s: run path never proven\n", name);
}

/* Explore every *.txt file in dir (sorted, not recursive). */
static int explore_all(const char *dir, int json)
{
    char **names;
    long nn = mazedir_list_or_report(dir, &names);
    if (nn < 0) return EXIT_BAD_INPUT;
    size_t n = (size_t)nn;

    int rc = EXIT_OK;
    unsigned long total = 0, explored = 0, unreachable = 0, not_optimal = 0, bad = 0, worst = 0;
    const char *worst_name = "";
    json_t *per = json ? json_object() : NULL;
    for (size_t i = 0; i < n; i++) {
        grid_result_t r;
        fprintf(stderr, "\r[%zu/%zu] %-60.60s", i + 1, n, names[i]);
        if (load(names[i]) != 0) {
            bad++;
            rc = EXIT_BAD_INPUT;
            continue;
        }
        grid_explore(&maze, &r);
        if (per) json_object_set_new(per, names[i], explore_json(&r));
        if (!r.goal_reachable) {
            unreachable++;
            continue;
        }
        explored++;
        total += r.steps;
        if (!r.final_path_optimal) not_optimal++;
        if (r.steps > worst) {
            worst = r.steps;
            worst_name = names[i];
        }
    }
    fputc('\n', stderr);
    double mean = explored ? (double)total / (double)explored : 0.0;
    if (per) {
        json_t *o = json_pack("{s:I, s:I, s:I, s:I, s:I, s:f, s:I, s:s, s:o}", "files", (json_int_t)n, "explored",
                              (json_int_t)explored, "unreachable", (json_int_t)unreachable, "malformed",
                              (json_int_t)bad, "not_optimal", (json_int_t)not_optimal, "mean_steps", mean,
                              "worst_steps", (json_int_t)worst, "worst_maze", worst_name, "mazes", per);
        if (print_json(o) != EXIT_OK) rc = EXIT_EXTERNAL;
    } else {
        printf("%zu files: %lu explored, %lu goal unreachable, %lu malformed\n", n, explored, unreachable, bad);
        printf("mean steps %.1f, worst %lu (%s), final path not the true shortest: %lu\n", mean, worst, worst_name,
               not_optimal);
    }
    mazedir_free(names, nn);
    if (rc == EXIT_OK && not_optimal) rc = EXIT_NOT_REACHED;
    return rc;
}

static int cmd_explore(int argc, char **argv)
{
    static const struct option opts[] = { { "json", no_argument, 0, 'j' },
                                          { "all", required_argument, 0, 'a' },
                                          { 0, 0, 0, 0 } };
    int json = 0, o;
    const char *all = NULL;
    while ((o = getopt_long(argc, argv, "", opts, NULL)) != -1) {
        if (o == 'j') json = 1;
        else if (o == 'a') all = optarg;
        else return bad_option("explore", argv);
    }
    if (all) {
        if (optind != argc) return bad_usage("explore --all DIR takes no FILE");
        return explore_all(all, json);
    }
    if (optind != argc - 1) return bad_usage("explore: needs exactly one FILE");
    if (load(argv[optind]) != 0) return EXIT_BAD_INPUT;
    grid_result_t r;
    int done = grid_explore(&maze, &r) == 0;
    if (json) {
        if (print_json(explore_json(&r)) != EXIT_OK) return EXIT_EXTERNAL;
    } else {
        explore_text(argv[optind], &r);
    }
    return done && r.final_path_optimal ? EXIT_OK : EXIT_NOT_REACHED;
}

static int run_command(int argc, char **argv)
{
    if (argc < 2) {
        usage(stderr);
        return EXIT_BAD_INPUT;
    }
    if (!strcmp(argv[1], "--help") || !strcmp(argv[1], "-h") || !strcmp(argv[1], "help")) {
        usage(stdout);
        return EXIT_OK;
    }
    opterr = 0; /* our own one-line messages instead of getopt's */
    const char *cmd = argv[1];
    /* getopt sees the subcommand as argv[0] */
    argc--;
    argv++;
    if (!strcmp(cmd, "check")) return cmd_check(argc, argv);
    if (!strcmp(cmd, "show")) return cmd_show(argc, argv);
    if (!strcmp(cmd, "solve")) return cmd_solve(argc, argv);
    if (!strcmp(cmd, "gen")) return cmd_gen(argc, argv);
    if (!strcmp(cmd, "explore")) return cmd_explore(argc, argv);
    fprintf(stderr, "mmmaze: unknown command '%s' (try 'mmmaze --help')\n", cmd);
    return EXIT_BAD_INPUT;
}

int main(int argc, char **argv)
{
    io_stdout_open("mmmaze");
    int rc = run_command(argc, argv);
    return io_stdout_close("mmmaze") != 0 ? EXIT_EXTERNAL : rc;
}

/* cli.c - command-line helpers shared by the tools (see cli.h). */
#include "cli.h"

#include <ctype.h>
#include <errno.h>
#include <getopt.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "io/escape.h"
#include "io/number.h"

/* arg as it may be printed in one line: a text with a control character
 * (a newline in --input or --mms text) escaped whole; one without is
 * printed as it is (a message whose foreign parts are escaped already) */
static const char *printable(const char *arg, char *buf, size_t len)
{
    if (!arg) return "";
    for (const unsigned char *p = (const unsigned char *)arg; *p; p++)
        if (*p < 0x20 || *p == 0x7f) {
            io_escape(buf, len, arg, strlen(arg));
            return buf;
        }
    return arg;
}

int cli_bad(const char *prog, const char *fmt, const char *arg)
{
    char buf[1024];
    fprintf(stderr, "%s: ", prog);
    fprintf(stderr, fmt, printable(arg, buf, sizeof buf));
    fprintf(stderr, " (try '%s --help')\n", prog);
    return CLI_BAD_INPUT;
}

int cli_number(const char *prog, const char *opt, const char *s, double lo, double hi, double *out)
{
    double v = NAN;
    if (io_decimal(s, strlen(s), &v) != 0 || !(v >= lo && v <= hi)) {
        char buf[256];
        fprintf(stderr, "%s: %s: expected a number from %g to %g, got '%s'\n", prog, opt, lo, hi, printable(s, buf, sizeof buf));
        return -1;
    }
    *out = v;
    return 0;
}

/* The digits of s up to the character end as a number; -1 if there are
 * none, anything else comes first, or more than 5 digits (no overflow). */
static long size_part(const char *s, char end)
{
    long v = 0;
    int n = 0;
    for (; isdigit((unsigned char)*s); s++, n++) v = v * 10 + (*s - '0');
    if (n == 0 || n > 5 || *s != end) return -1;
    return v;
}

int cli_view_option(const char *prog, const char *name, const char *arg, view_opts_t *vo)
{
    if (!strcmp(name, "camera")) {
        if (strlen(arg) != 1 || arg[0] < '1' || arg[0] > '3')
            return cli_bad(prog, "--camera: expected 1, 2 or 3, got '%s'", arg);
        vo->camera = arg[0] - '0';
    } else if (!strcmp(name, "speed")) {
        if (cli_number(prog, "--speed", arg, 1, VIEW_SPEED_MAX, &vo->speed)) return CLI_BAD_INPUT;
    } else if (!strcmp(name, "size")) {
        long w = size_part(arg, 'x'), h = w < 0 ? -1 : size_part(strchr(arg, 'x') + 1, '\0');
        if (w < 64 || h < 64 || w > 8192 || h > 8192)
            return cli_bad(prog, "--size: expected WxH, 64 to 8192 pixels each, got '%s'", arg);
        vo->width = w;
        vo->height = h;
    } else {
        return cli_bad(prog, "%s: not a viewer option", name);
    }
    return 0;
}

static int cli_store(const char *prog, const cli_opt_t *t, const char *arg, void *opts)
{
    char *field = (char *)opts + t->off, opt[80];
    double v;
    snprintf(opt, sizeof opt, "--%s", t->name);
    switch (t->kind) {
    case CLI_SET: *(int *)field = 1; return 0;
    case CLI_STR: *(const char **)field = arg; return 0;
    case CLI_NUM: return cli_number(prog, opt, arg, t->lo, t->hi, (double *)field) ? CLI_BAD_INPUT : 0;
    case CLI_INT:
        if (cli_number(prog, opt, arg, t->lo, t->hi, &v)) return CLI_BAD_INPUT;
        if (v != floor(v)) {
            char buf[256];
            fprintf(stderr, "%s: %s: expected a whole number from %g to %g, got '%s'\n", prog, opt, t->lo, t->hi, printable(arg, buf, sizeof buf));
            return CLI_BAD_INPUT;
        }
        *(int *)field = (int)v;
        return 0;
    case CLI_FN: return t->fn(prog, opts, arg);
    }
    return CLI_BAD_INPUT;
}

int cli_parse(const char *prog, const cli_opt_t *table, int argc, char **argv, void *opts, int *seen, int *first)
{
    size_t n = 0;
    while (table[n].name) n++;
    struct option *lo = calloc(n + 1, sizeof *lo);
    if (!lo) {
        fprintf(stderr, "%s: out of memory\n", prog);
        return CLI_BAD_INPUT;
    }
    for (size_t i = 0; i < n; i++) {
        cli_kind_t k = table[i].kind;
        lo[i].name = table[i].name;
        int has = k == CLI_SET ? 0 : k == CLI_FN ? table[i].has_arg : 1;
        lo[i].has_arg = has == 0 ? no_argument : has == 2 ? optional_argument : required_argument;
        lo[i].val = 1000 + (int)i;
    }
    int c, rc = 0;
    opterr = 0;
    optind = 1;
    int at = optind; /* the argument getopt_long is on */
    while (!rc && (c = getopt_long(argc, argv, "", lo, NULL)) != -1) {
        if (c < 1000 || c >= 1000 + (int)n) {
            /* a flag that needs a value and has none (optopt names it); else
             * an unknown one: the argument it came in, which getopt has
             * passed (--bogus, a single -v) or, inside a cluster of single
             * letters (-maze, -vv), is still on */
            const char *arg = optind > at ? argv[optind - 1] : argv[optind];
            rc = optopt >= 1000 && optopt < 1000 + (int)n ? cli_bad(prog, "%s: missing its value", arg)
                                                           : cli_bad(prog, "unknown option: '%s'", arg);
            break;
        }
        at = optind;
        if (seen) seen[c - 1000]++;
        rc = cli_store(prog, &table[c - 1000], optarg, opts);
    }
    free(lo);
    *first = optind;
    return rc;
}

int cli_seen(const cli_opt_t *table, const int *seen, const char *name)
{
    for (size_t i = 0; table[i].name; i++)
        if (!strcmp(table[i].name, name)) return seen[i];
    return 0;
}

/* cli.c - command-line helpers shared by the tools (see cli.h). */
#include "cli.h"

#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

int cli_bad(const char *prog, const char *fmt, const char *arg)
{
    fprintf(stderr, "%s: ", prog);
    fprintf(stderr, fmt, arg);
    fprintf(stderr, " (try '%s --help')\n", prog);
    return CLI_BAD_INPUT;
}

int cli_number(const char *prog, const char *opt, const char *s, double lo, double hi, double *out)
{
    char *end;
    errno = 0;
    double v = strtod(s, &end);
    if (errno || end == s || *end || !(v >= lo && v <= hi)) {
        fprintf(stderr, "%s: %s: expected a number from %g to %g, got '%s'\n", prog, opt, lo, hi, s);
        return -1;
    }
    *out = v;
    return 0;
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
        int w, h, n = 0;
        if (sscanf(arg, "%dx%d%n", &w, &h, &n) != 2 || arg[n] || w < 64 || h < 64 || w > 8192 || h > 8192)
            return cli_bad(prog, "--size: expected WxH, 64 to 8192 pixels each, got '%s'", arg);
        vo->width = w;
        vo->height = h;
    } else {
        return cli_bad(prog, "%s: not a viewer option", name);
    }
    return 0;
}

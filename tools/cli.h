/* cli.h - command-line helpers shared by the tools (mmsim, mmview): a
 * table-driven flag parser, one error line per bad flag, numbers in range,
 * the viewer's options. */
#ifndef CLI_H
#define CLI_H

#include <stddef.h>

#include "view/view.h"

enum { CLI_BAD_INPUT = 2 }; /* the exit code of a bad flag */

/* Prints "PROG: " fmt (with arg) " (try 'PROG --help')" as one line;
 * returns CLI_BAD_INPUT. */
int cli_bad(const char *prog, const char *fmt, const char *arg);
/* s, a plain decimal number (digits, an optional '-' and '.'; no spaces,
 * '+', exponent or hex), from lo to hi into *out: 0, or -1 after one error
 * line "PROG: OPT: expected a number from LO to HI, got 'S'". */
int cli_number(const char *prog, const char *opt, const char *s, double lo, double hi, double *out);
/* The viewer's options of every tool that shows a scene: name "camera"
 * (1..3), "speed" (1..VIEW_SPEED_MAX) or "size" (WxH, 64..8192 pixels
 * each) with its argument into vo. 0, or CLI_BAD_INPUT after one error
 * line. */
int cli_view_option(const char *prog, const char *name, const char *arg, view_opts_t *vo);

/* ---- the flag table ---- */
typedef enum {
    CLI_SET,   /* no argument: the int field becomes 1 */
    CLI_STR,   /* the argument (const char *) */
    CLI_NUM,   /* a number from lo to hi (double) */
    CLI_INT,   /* a whole number from lo to hi (int) */
    CLI_FN,    /* fn decides; has_arg: 0 none, 1 required, 2 optional (--lcm[=URL]: arg NULL without one) */
} cli_kind_t;

typedef struct cli_opt_s {
    const char *name; /* "seed" for --seed */
    cli_kind_t kind;
    size_t off;       /* offsetof the field in the options struct */
    double lo, hi;    /* CLI_NUM, CLI_INT */
    /* CLI_FN: store arg; 0, or CLI_BAD_INPUT after one error line */
    int (*fn)(const char *prog, void *opts, const char *arg);
    int has_arg;      /* CLI_FN: 0 no argument, 1 required, 2 optional */
} cli_opt_t;

/* Parses argv's flags by the table (ended by a { NULL } entry) into opts;
 * seen[i] (NULL: not kept) counts table entry i's uses; *first gets the
 * index of the first operand. 0, or CLI_BAD_INPUT after one error line;
 * --help is left to the table (a CLI_SET of the caller). */
int cli_parse(const char *prog, const cli_opt_t *table, int argc, char **argv, void *opts, int *seen, int *first);
/* How often flag name was given (seen from cli_parse). */
int cli_seen(const cli_opt_t *table, const int *seen, const char *name);

#endif

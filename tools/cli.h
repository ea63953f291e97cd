/* cli.h - command-line helpers shared by the tools (mmsim, mmview): one
 * error line per bad flag, numbers in range, the viewer's options. */
#ifndef CLI_H
#define CLI_H

#include "view/view.h"

enum { CLI_BAD_INPUT = 2 }; /* the exit code of a bad flag */

/* Prints "PROG: " fmt (with arg) " (try 'PROG --help')" as one line;
 * returns CLI_BAD_INPUT. */
int cli_bad(const char *prog, const char *fmt, const char *arg);
/* s as a number from lo to hi into *out: 0, or -1 after one error line
 * "PROG: OPT: expected a number from LO to HI, got 'S'". */
int cli_number(const char *prog, const char *opt, const char *s, double lo, double hi, double *out);
/* The viewer's options of every tool that shows a scene: name "camera"
 * (1..3), "speed" (1..VIEW_SPEED_MAX) or "size" (WxH, 64..8192 pixels
 * each) with its argument into vo. 0, or CLI_BAD_INPUT after one error
 * line. */
int cli_view_option(const char *prog, const char *name, const char *arg, view_opts_t *vo);

#endif

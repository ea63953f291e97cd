/* report.h - a picture of every run: a top-down view of the maze with the
 * true walls, the walls the mouse learned, the cells it visited, its
 * trajectory coloured by speed, the final run path (when the run has one) and the lap table as
 * text. Written as PNG (libpng), SVG beside it (same drawing), JSON
 * beside it (the lap table) and a page of plots against time (plots.h:
 * FILE-plots.png beside FILE.png), all four or none.
 *
 * Record during the run with report_step after every physics step; the
 * pose is sampled every REPORT_SAMPLE_S of simulation time. */
#ifndef REPORT_H
#define REPORT_H

#include <stddef.h>

#include "maze.h"
#include "world/sim.h"

#define REPORT_SAMPLE_S 0.005 /* trajectory sample period, s of sim time */
#define REPORT_WATCH_MAX 16   /* the firmware's variables beside the pose (mmsim --watch) */
#define REPORT_FILES 4        /* FILE.png, FILE.svg, FILE.json, FILE-plots.png */

typedef struct report report_t;

/* Start recording the run of s (already initialised). NULL out of memory. */
report_t *report_new(const sim_state_t *s);
void report_free(report_t *r);
/* Call after every sim_step. */
void report_step(report_t *r, const sim_state_t *s);

/* The firmware's variables now (mmsim --watch), before report_step: n
 * names (the caller's strings, valid until report_write) and values. The
 * JSON gets them beside the true pose at every trajectory sample ("watch":
 * columns t_s, x_m, y_m, heading_rad, then the names; one row a sample) and
 * the picture their last values, the plots page a panel each. */
void report_watch(report_t *r, int n, const char *const *names, const double *values);

/* Cell colours and texts to draw (an mms algorithm's setColor/setText):
 * colours[k] is an mms colour letter (kbacgorwyBCAGRY, 0 = none) and
 * texts + k * text_stride a NUL-terminated text, for every cell k; copied. */
void report_set_cells(report_t *r, const char *colours, const char *texts, size_t text_stride);

/* Write png_path, and beside it the same name with .svg, .json and
 * -plots.png (a trailing .png is replaced; the JSON's "plots" describes the
 * plots page: each panel's pixel box, axis range and tick labels). learned = the mouse's map, or NULL when
 * the run has none (an MCU over the link, the scripted driver: true walls
 * only); path_on = the map the final run path is the best path on (the
 * mouse's map; the true maze for the scripted driver, which drives it), or
 * NULL when the run has no final path (an MCU: none is drawn, and the
 * JSON's final_path_cells is null). title is one line of text (maze, seed,
 * driver). Returns 0, or -1 with one line in err; nothing is left half
 * written. */
int report_write(const report_t *r, const sim_state_t *s, const maze_t *learned, const truemaze_t *path_on, const char *png_path,
                 const char *title, char *err, size_t errlen);

/* The .svg / .json / -plots.png path beside png_path, into out. */
void report_sibling(const char *png_path, const char *ext, char *out, size_t len);

#endif

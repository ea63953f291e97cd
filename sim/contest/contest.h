/* contest.h - a contest's rules as a file (contests/NAME.ini, `mmsim
 * --contest NAME|FILE`): the maze's geometry, start, goal, time limit,
 * number of runs and scoring rule, each with its source in the file.
 *
 *   [maze]  max_width, max_height (cells), cell_mm, wall_thick_mm,
 *           wall_height_mm, post_mm, centre_post (0/1), start = X,Y,
 *           heading = north|east|south|west, goal = X0,Y0 X1,Y1 (a
 *           rectangle of cells, corners included)
 *   [rules] time_limit_s, runs (0 = any number), scoring = best_run |
 *           run_plus_search, search_divisor (run_plus_search only),
 *           touch_penalty_s
 *
 * Every key but search_divisor and touch_penalty_s is required. Errors are
 * one line "FILE:LINE:COL: reason" (COL: the key's column for an unknown
 * key, the value's for a bad value), or "FILE: reason" for a missing key.
 *
 * The geometry sets the world's numbers (config [world] cell_m,
 * wall_thick_m, wall_height_m, post_m, centre_post) and the time limit
 * [sim] time_limit_s before the run's model is built; the maze file's own
 * 'S' and 'G' marks, where present, override the profile's start and goal. */
#ifndef CONTEST_H
#define CONTEST_H

#include <jansson.h>
#include <stdio.h>

#include "contest/score.h"
#include "maze/mazefile.h"
#include "world/config.h"
#include "world/race.h"

#define CONTEST_MAX_BYTES (64u * 1024u) /* bytes of a contest file */
#define CONTEST_KEYS 16 /* room for the keys a contest file has (contest.c's table: 15) */

typedef struct contest_s {
    char name[64];          /* the file's name without folder and .ini */
    char path[512];         /* the file as found */
    int max_width, max_height; /* cells: a maze file may be smaller, never larger */
    double cell_m, wall_thick_m, wall_height_m, post_m; /* the file's mm as m */
    int centre_post;        /* 1 = the post in the middle of the goal stands */
    int start[2];           /* start cell x, y */
    int heading;            /* TRUEMAZE_NORTH.. */
    int goal[4];            /* goal rectangle x0, y0, x1, y1 (x0 <= x1, y0 <= y1) */
    double time_limit_s;
    score_rules_t rules;    /* runs, scoring rule, search share, touch penalty */
    char source[CONTEST_KEYS][160]; /* each key's `; source:` text, in the key table's order ("" not given) */
} contest_t;

/* NAME (no '/', no ".ini"): contests/NAME.ini in the working directory,
 * an installed tree or the source tree (io/datadir.h); else the path as
 * given. 0, or -1 with one line in err. */
int contest_find(const char *arg, char *path, size_t pathlen, char *err, size_t errlen);
/* Read the contest file at path into c. 0, or -1 with one line in err: among
 * the reasons, a key given without its `; source:` comment line in the
 * comment lines right above it (contests/README.md: every key has one). */
int contest_load(contest_t *c, const char *path, char *err, size_t errlen);
/* The resolved profile as a contest file (its keys, in the file's units). */
void contest_print(const contest_t *c, FILE *out);
/* The geometry and the time limit into the loaded config. */
void contest_apply_config(const contest_t *c, simcfg_t *cfg);
/* The start and goal onto a loaded maze (its file's 'S'/'G' marks, in
 * info, win): 0, or -1 with one line in err (a maze larger than the
 * contest's, a goal or start outside the maze). */
int contest_apply_maze(const contest_t *c, truemaze_t *m, const mazefile_info_t *info, const char *maze_path, char *err,
                       size_t errlen);
/* The results' "contest" object: name, rule, each run's figures and score,
 * the score. lift_t_s: the sim times of the hands' lifts (touches), n_lifts
 * of them. */
json_t *contest_json(const contest_t *c, const race_t *race, const double *lift_t_s, int n_lifts);

#endif

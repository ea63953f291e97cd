/* score.h - a contest's scoring rule applied to its runs (laps): plain
 * arithmetic on the figures the results JSON publishes, so a reader can
 * check the score from the same JSON.
 *
 * Each run scores
 *   run_s + search_s / search_divisor + touches * touch_penalty_s
 * where run_s is the run's time (start sensor to goal sensor), search_s the
 * contest clock at the run's start (s since the mouse first left the start
 * cell: APEC's "maze time" used before the run), touches the hands' lifts of
 * the mouse before the run's start. SCORE_BEST_RUN takes no search term
 * (search_divisor is 0 there). A run counts when it ended inside the time
 * limit and is among the first `runs` (0: any number). The contest's score
 * is the lowest counted run's. */
#ifndef SCORE_H
#define SCORE_H

enum { SCORE_BEST_RUN = 0, SCORE_RUN_PLUS_SEARCH = 1 };

#define SCORE_MAX_RUNS 64 /* runs a score looks at (race.h's RACE_MAX_LAPS) */

typedef struct {
    int rule;               /* SCORE_BEST_RUN or SCORE_RUN_PLUS_SEARCH */
    double search_divisor;  /* SCORE_RUN_PLUS_SEARCH: the search time's share is 1/this (APEC: 30); 0 otherwise */
    double touch_penalty_s; /* s added per touch before the run (APEC: 2) */
    int runs;               /* runs that count, the first ones; 0 = any number */
} score_rules_t;

/* One run's figures, as the results JSON gives them (s, rounded to 1 ms). */
typedef struct {
    double run_s, search_s;
    int touches;
    int over_time;          /* ended after the time limit */
} score_run_t;

/* Run i's score (s, rounded to 1 ms as the JSON's figures are). */
double score_run(const score_rules_t *r, const score_run_t *run);
/* Does run i (0-based) count? */
int score_counts(const score_rules_t *r, const score_run_t *runs, int i);
/* The index of the counted run with the lowest score (the first of equal
 * ones), or -1 if none counts; its score into *score_s. */
int score_best(const score_rules_t *r, const score_run_t *runs, int n, double *score_s);

#endif

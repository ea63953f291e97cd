/* score.c - a scoring rule applied to a contest's runs (score.h). */
#include "score.h"

#include <math.h>

double score_run(const score_rules_t *r, const score_run_t *run)
{
    double s = run->run_s + run->touches * r->touch_penalty_s;
    if (r->rule == SCORE_RUN_PLUS_SEARCH && r->search_divisor > 0) s += run->search_s / r->search_divisor;
    return round(s * 1000.0) / 1000.0; /* ms, as the run's own figures */
}

int score_counts(const score_rules_t *r, const score_run_t *runs, int i)
{
    return i >= 0 && !runs[i].over_time && (r->runs <= 0 || i < r->runs);
}

int score_best(const score_rules_t *r, const score_run_t *runs, int n, double *score_s)
{
    int best = -1;
    double low = 0;
    for (int i = 0; i < n && i < SCORE_MAX_RUNS; i++) {
        if (!score_counts(r, runs, i)) continue;
        double s = score_run(r, &runs[i]);
        if (best < 0 || s < low) {
            best = i;
            low = s;
        }
    }
    if (best >= 0) *score_s = low;
    return best;
}

/* race.c - contest timers and the lap table. */
#include "race.h"

#include <math.h>

void race_init(race_t *r, const truemaze_t *m, double cell_m, double limit_s)
{
    r->maze = m;
    r->cell_m = cell_m;
    r->limit_s = limit_s;
    r->started = 0;
    r->global_start_s = 0.0;
    r->in_run = 0;
    r->armed = 1;
    r->run_start_s = 0.0;
    r->nlaps = 0;
    r->best = -1;
    r->over_time = 0;
}

/* The cell under (x, y), or -1 outside the maze. */
static int cell_at(const race_t *r, double x_m, double y_m)
{
    double fx = floor(x_m / r->cell_m), fy = floor(y_m / r->cell_m);
    if (fx < 0 || fy < 0 || fx >= r->maze->width || fy >= r->maze->height) return -1;
    return truemaze_cell(r->maze, (uint8_t)fx, (uint8_t)fy);
}

double race_global_s(const race_t *r, double t_s)
{
    return r->started ? t_s - r->global_start_s : 0.0;
}

int race_update(race_t *r, double t_s, double x_m, double y_m)
{
    int c = cell_at(r, x_m, y_m);
    int at_start = c == r->maze->start;
    if (r->started && t_s - r->global_start_s > r->limit_s) r->over_time = 1;
    if (at_start) {
        r->in_run = 0; /* back at the start: a run not finished is abandoned */
        r->armed = 1;
        return 0;
    }
    if (r->armed) {
        /* just left the start cell */
        r->armed = 0;
        r->in_run = 1;
        r->run_start_s = t_s;
        if (!r->started) {
            r->started = 1;
            r->global_start_s = t_s;
        }
    }
    if (r->in_run && c >= 0 && truemaze_is_goal(r->maze, (truemaze_cell_t)c)) {
        r->in_run = 0;
        if (r->nlaps == RACE_MAX_LAPS) return 0;
        race_lap_t *l = &r->laps[r->nlaps];
        l->start_s = r->run_start_s - r->global_start_s;
        l->end_s = t_s - r->global_start_s;
        l->over_time = l->end_s > r->limit_s;
        if (!l->over_time && (r->best < 0 || l->end_s - l->start_s < r->laps[r->best].end_s - r->laps[r->best].start_s))
            r->best = r->nlaps;
        r->nlaps++;
        return 1;
    }
    return 0;
}

static void mmss(double s, char *out, size_t len)
{
    long ms = lround(s * 1000.0);
    snprintf(out, len, "%ld:%02ld.%03ld", ms / 60000, (ms / 1000) % 60, ms % 1000);
}

void race_print_table(const race_t *r, FILE *out)
{
    fprintf(out, "%-4s  %-10s  %-10s  %-10s\n", "Lap", "Start time", "End time", "Run time");
    for (int i = 0; i < r->nlaps; i++) {
        char a[32], b[32], d[32];
        mmss(r->laps[i].start_s, a, sizeof a);
        mmss(r->laps[i].end_s, b, sizeof b);
        mmss(r->laps[i].end_s - r->laps[i].start_s, d, sizeof d);
        fprintf(out, "%-4d  %-10s  %-10s  %-10s%s%s\n", i + 1, a, b, d, i == r->best ? "  best" : "",
                r->laps[i].over_time ? "  over time" : "");
    }
}

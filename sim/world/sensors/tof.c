/* tof.c - ToF noise and clamps (see tof.h). */
#include "tof.h"

#include <math.h>

void tof_init(tof_t *t, const simcfg_t *c, uint64_t seed, unsigned index)
{
    t->range_m = c->tof_range_m;
    t->blind_m = c->tof_blind_m;
    t->cv = c->tof_cv;
    rng_init(&t->rng, seed, RNG_STREAM_TOF + index);
}

double tof_gauss(tof_t *t) { return rng_gauss(&t->rng); }

tof_reading_t tof_measure(tof_t *t, double true_m)
{
    tof_reading_t out = { t->range_m, 1 };
    if (true_m < 0.0 || true_m >= t->range_m) return out;
    double d = true_m < t->blind_m ? t->blind_m : true_m;
    d += t->cv * d * tof_gauss(t);
    if (d < 0.0) d = 0.0;
    if (d >= t->range_m) return out; /* at or beyond the range: a timeout, as the paper's Unity sensor */
    out.dist_m = d;
    out.timeout = 0;
    return out;
}

/* tof.c - ToF noise and clamps (see tof.h). */
#include "tof.h"

#include <math.h>

/* splitmix64 (Steele, Lea, Flood 2014): one 64-bit state, good mixing. */
static uint64_t next_u64(uint64_t *s)
{
    uint64_t z = (*s += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
}

/* uniform in (0, 1]: never 0, so log() below is finite */
static double uniform(uint64_t *s) { return ((double)(next_u64(s) >> 11) + 1.0) * (1.0 / 9007199254740992.0); }

void tof_init(tof_t *t, const simcfg_t *c, uint64_t seed, unsigned index)
{
    t->range_m = c->tof_range_m;
    t->blind_m = c->tof_blind_m;
    t->cv = c->tof_cv;
    t->rng = seed * 0x2545F4914F6CDD1Dull + (uint64_t)(index + 1) * 0x9E3779B97F4A7C15ull;
    next_u64(&t->rng);
    t->has_spare = 0;
    t->spare = 0.0;
}

double tof_gauss(tof_t *t)
{
    if (t->has_spare) {
        t->has_spare = 0;
        return t->spare;
    }
    double u1 = uniform(&t->rng), u2 = uniform(&t->rng);
    double r = sqrt(-2.0 * log(u1)), a = 2.0 * M_PI * u2;
    t->spare = r * sin(a);
    t->has_spare = 1;
    return r * cos(a);
}

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

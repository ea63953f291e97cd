/* rng.c - seeded noise streams (see rng.h). */
#include "rng.h"

#include <math.h>

static uint64_t next_u64(uint64_t *s)
{
    uint64_t z = (*s += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
}

/* uniform in (0, 1]: never 0, so log() below is finite */
static double uniform(uint64_t *s) { return ((double)(next_u64(s) >> 11) + 1.0) * (1.0 / 9007199254740992.0); }

void rng_init(rng_t *r, uint64_t seed, uint64_t stream)
{
    /* The stream number is hashed before it offsets the seed: splitmix64's
     * state steps by 0x9E37...15, so an offset of stream * 0x9E37...15 made
     * stream s+1 the same sequence as stream s, one draw later (the three
     * ToF sensors' noise was one sequence, shifted). A hashed offset puts
     * each stream at an unrelated point of the 2^64 cycle. */
    uint64_t h = stream;
    r->state = seed * 0x2545F4914F6CDD1Dull ^ next_u64(&h);
    next_u64(&r->state);
    r->has_spare = 0;
    r->spare = 0.0;
}

double rng_gauss(rng_t *r)
{
    if (r->has_spare) {
        r->has_spare = 0;
        return r->spare;
    }
    double u1 = uniform(&r->state), u2 = uniform(&r->state);
    double m = sqrt(-2.0 * log(u1)), a = 2.0 * M_PI * u2;
    r->spare = m * sin(a);
    r->has_spare = 1;
    return m * cos(a);
}

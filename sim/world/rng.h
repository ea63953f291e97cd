/* rng.h - one seeded noise stream: splitmix64 (Steele, Lea, Flood 2014) and
 * Box-Muller normal deviates. Every noise source of a run has its own
 * stream, derived from the run's seed and the source's stream number, so a
 * source's draws never depend on another's. */
#ifndef RNG_H
#define RNG_H

#include <stdint.h>

typedef struct {
    uint64_t state;   /* splitmix64 state */
    int has_spare;    /* Box-Muller makes two deviates at a time */
    double spare;
} rng_t;

/* Stream numbers of the run's noise sources. */
enum { RNG_STREAM_TOF = 1,         /* +sensor index */
       RNG_STREAM_VARIATION = 100, /* the robot's per-seed variation */
       RNG_STREAM_IR = 200,        /* +sensor index (sensors/ir.h) */
       RNG_STREAM_GYRO = 300       /* +gyro index (sensors/gyro.h) */ };

void rng_init(rng_t *r, uint64_t seed, uint64_t stream);
/* A normal deviate, mean 0, standard deviation 1. */
double rng_gauss(rng_t *r);

#endif

/* tof.h - time-of-flight distance sensor model (after the ray cast).
 *
 * The sensor sees through a cone of full angle fov: `rays` rays spread
 * evenly across it in the sensor's horizontal plane (the maze's walls are
 * vertical), and the true distance d is the nearest hit of any of them (the
 * nearest surface in the cone); fov 0 is one ray along the axis (the
 * paper's Unity sensor). A level sensor's cone also meets the floor (at
 * z / tan(fov/2): 68 mm for 15 mm and 25 deg); the model leaves the floor
 * out, as a sensor tilted up by half its cone does.
 * true distance d -> clamp to at least the blind spot ->
 * add Gaussian noise, sigma = cv * d -> clamp to at least 0. Nothing hit
 * within range, or a reading at or beyond the range (before or after the
 * noise) = timeout, reported as a flag (and the range as distance): a
 * reading is always below the range (the paper's Unity simulator sends a
 * reading at or beyond its range as a timeout).
 * Each sensor has its own noise stream (world/rng.h, from the run seed and
 * the sensor index), so adding a sensor or reading one more often never
 * changes another one's noise. */
#ifndef TOF_H
#define TOF_H

#include <stdint.h>
#include "world/config.h"
#include "world/rng.h"

typedef struct {
    double dist_m;    /* what the sensor reports, m */
    int timeout;      /* 1 = nothing within range */
} tof_reading_t;

/* The robot file's [tof.NAME] specification (all doubles: keytab.h). */
typedef struct {
    double range_m, blind_m, cv;
    double period_s;  /* between readings */
    double fov_rad;   /* the cone's full angle, rad (0: one ray) */
    double rays;      /* rays across the cone (a whole number, >= 1) */
} tof_spec_t;

/* One sensor: its spec (the robot file's, kept by pointer: it outlives
 * the sensor) and its noise stream. */
typedef struct {
    const tof_spec_t *spec;
    rng_t rng;
} tof_t;

/* A tof sensor of the robot at run time: the model, its schedule and its
 * latest reading. */
typedef struct {
    tof_t tof;
    uint64_t next_step, period_steps;
    tof_reading_t last;
    double true_m;       /* the ray behind the last reading, m; -1 none */
    uint32_t count;      /* readings taken */
    int enabled;         /* 0: readings paused (a link that sends none) */
    double object_m, object_until_s; /* an object held object_m ahead of it until then, m and s (sim_occlude) */
} tof_state_t;


void tof_init(tof_t *t, const tof_spec_t *s, uint64_t seed, unsigned index);
/* true_m < 0 means the ray hit nothing. */
tof_reading_t tof_measure(tof_t *t, double true_m);
/* A standard normal deviate from the sensor's stream (exposed for tests). */
double tof_gauss(tof_t *t);

#endif

/* tof.h - time-of-flight distance sensor model (after the ray cast).
 *
 * The sensor (ST's VL53L0X) sees through a cone of full angle fov: `rays`
 * rays spread evenly across it in the sensor's horizontal plane (the maze's
 * walls are vertical), and the true distance d is the nearest hit of any of
 * them (the nearest surface in the cone); fov 0 is one ray along the axis
 * (the paper's Unity sensor). A level sensor's cone also meets the floor (at
 * z / tan(fov/2): 68 mm for 15 mm and 25 deg); the model leaves the floor
 * out, as a sensor tilted up by half its cone does.
 *
 * A ranging profile (ST DocID029104 Table 13: default, high accuracy, long
 * range, high speed) sets the period (its timing budget) and the range (how
 * far it detects a white target); cv, the standard deviation as a fraction
 * of the distance, follows from the budget (tof_cv_at); a key the robot
 * file gives wins over the profile's figure (tof_complete).
 * true distance d: nothing hit, or d beyond the range -> a timeout (no
 * return signal: the sensor's range status is not "valid"), reported as a
 * flag and the range as distance; else d clamped to at least the blind
 * spot, plus Gaussian noise of sigma = cv * d, clamped to at least 0 (a
 * reading near the range may come out above it, as a real one does).
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
    double profile;   /* index into the ranging profiles (tof.c), a whole number */
    double range_m;   /* a target farther than this is a timeout, m */
    double blind_m;   /* nearer than this reads as this, m */
    double cv;        /* noise sigma / distance, 1 */
    double period_s;  /* between readings (the timing budget), s */
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


/* A loaded [tof.NAME] part's spec completed: the profile's period, range
 * and cv into the keys the file did not give (given: bit i set = the
 * kind's key i was in the file). Any other part: untouched. */
void tof_complete(robot_part_t *p, uint64_t given);

/* The noise's standard deviation as a fraction of the distance for a
 * timing budget, s: 4 % at 33 ms (DocID029104 Table 12, white target at
 * 120 cm indoors), scaled by sqrt(33 ms / budget), as photon shot noise
 * scales: the spread falls as 1/sqrt(the photons counted), which grow in
 * proportion to the budget. The same fraction at every distance: a target
 * filling the cone returns photons as 1/d^2, so the spread grows as d. */
double tof_cv_at(double budget_s);

void tof_init(tof_t *t, const tof_spec_t *s, uint64_t seed, unsigned index);
/* true_m < 0 means the ray hit nothing. */
tof_reading_t tof_measure(tof_t *t, double true_m);
/* A standard normal deviate from the sensor's stream (exposed for tests). */
double tof_gauss(tof_t *t);

#endif

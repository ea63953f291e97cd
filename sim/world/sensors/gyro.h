/* gyro.h - MEMS z-rate gyroscope model. The robot file's [gyro.*] section
 * sets it up (sensor_gyro in gyro.c, a sensor kind of sensor.h); the
 * simulation samples it with the body's yaw rate every step; the firmware
 * reads it through hal_gyro_mdps.
 *
 * The sensor samples at rate f (Hz); sample k is taken at t_k = k/f and held
 * until t_(k+1) (sample-and-hold). For sample k, with the true rate w (the
 * rate passed to the read that first sees sample k):
 *   b_k = b_(k-1) + rw * sqrt(1/f) * n1      bias random walk (b_0 = bias0)
 *   y_k = (1 + scale_pct/100) * w + b_k + sigma_w * n2
 *   sigma_w = density * sqrt(f / 2)         white noise over the band f/2
 *   y_k clamped to +-full scale, then rounded to a multiple of the LSB.
 * bias0 ~ N(0, bias_dps / bias_typ_sigmas) is drawn once per seed at init
 * (the datasheet's zero-rate level is a spread over parts, not a value of one
 * part). ST's datasheets define the typical zero level TyOff as the standard
 * deviation of the zero levels of a population of sensors (LSM303C DocID
 * 022887 and LSM330 DocID 022697, section 3 "Terminology", "Zero-g level":
 * "The zero-g level tolerance (TyOff) describes the standard deviation of the
 * range of zero-g levels of a population of sensors"); the LSM6DS3's G_TyOff
 * has the same symbol and column (Table 3, "Typ.", footnote 1: "Typical
 * specifications are not guaranteed"), so bias_typ_sigmas = 1 by default:
 * 31.7 % of parts (seeds) beyond +-bias_dps, 4.6 % beyond twice it. Set it
 * to 3 to read the typical figure as a bound 99.7 % of parts meet.
 * n1, n2 are standard normal deviates from the gyro's own stream
 * (RNG_STREAM_GYRO + index); every sample draws both, also samples no one
 * reads, so the noise depends on time only, never on how often it is read.
 * Units: the spec in deg/s (as datasheets give them), gyro_read in rad/s. */
#ifndef GYRO_H
#define GYRO_H

#include <stdint.h>
#include "world/rng.h"

typedef struct {
    double noise_density_dps_rthz; /* white rate noise density, deg/s/sqrt(Hz) */
    double bias_dps;               /* the datasheet's typical zero-rate level, deg/s */
    double bias_typ_sigmas;        /* standard deviations bias_dps stands for (1: ST's TyOff), 1 */
    double bias_rw_dps_rts;        /* bias random walk, deg/s per sqrt(s) */
    double scale_error_pct;        /* sensitivity error, per cent (output = (1 + e/100) * true) */
    double full_scale_dps;         /* saturation, +-deg/s */
    double sample_rate_hz;         /* output data rate, Hz (output held between samples) */
    double lsb_dps;                /* output resolution, deg/s per LSB (0 = not quantised) */
} gyro_spec_t;

typedef struct {
    const gyro_spec_t *spec; /* gyro_init's (the caller's: it outlives the gyro) */
    rng_t rng;
    double bias0_dps;      /* the constant bias drawn at init, deg/s */
    double walk_dps;       /* the random walk's part of the bias now, deg/s */
    int64_t sample;        /* index of the held sample, -1 = none yet */
    double held_rad_s;     /* the held output, rad/s */
} gyro_t;

/* The defaults: an ST LSM6DS3 at +-1000 dps, 833 Hz (values and sources in gyro.c). */
void gyro_spec_default(gyro_spec_t *s);
void gyro_init(gyro_t *g, const gyro_spec_t *s, uint64_t seed, unsigned index);
/* The measured z rate, rad/s, at simulation time t_s (s, >= 0) for the true
 * rate true_rate_rad_s. A time before the held sample's returns the held value. */
double gyro_read(gyro_t *g, double true_rate_rad_s, double t_s);
/* The white noise's standard deviation per sample, deg/s: density * sqrt(f/2). */
double gyro_sigma_dps(const gyro_spec_t *s);

#endif

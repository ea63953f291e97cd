/* gyro.c - MEMS z-rate gyroscope: noise, bias, scale, saturation,
 * sample-and-hold and quantisation (see gyro.h). */
#include "gyro.h"

#include <math.h>

#include "sensor.h"

#define DEG_PER_RAD (180.0 / M_PI)

/* ST LSM6DS3 datasheet, DocID026899 Rev 8 (Feb 2016), Table 3 "Gyroscope
 * mechanical characteristics" unless marked "ours". */
void gyro_spec_default(gyro_spec_t *s)
{
    s->noise_density_dps_rthz = 0.007; /* Rn, 7 mdps/sqrt(Hz) typ, high-performance mode */
    s->bias_dps = 10.0;                /* G_TyOff zero-rate level, +-10 dps typ */
    s->bias_typ_sigmas = 1.0;          /* ST: TyOff is the population's standard deviation (gyro.h) */
    s->bias_rw_dps_rts = 0.01;         /* ours: not in the datasheet; 0.01 deg/s/sqrt(s) gives ~0.08 deg/s
                                        * over a 60 s run, below the ZRL's temperature drift of Table 3 */
    s->scale_error_pct = 1.0;          /* ours: Table 3 gives no initial sensitivity tolerance; 1 % for an
                                        * uncalibrated part (3.6 deg of heading per full turn) */
    s->full_scale_dps = 1000.0;        /* FS = +-1000 dps (a 90 deg micromouse turn peaks near 1000 deg/s) */
    s->sample_rate_hz = 833.0;         /* G_ODR 833 Hz, one of 12.5..1666 Hz; ours: the highest below the 1 kHz step */
    s->lsb_dps = 0.035;                /* G_So at FS +-1000 dps: 35 mdps/LSB */
}

double gyro_sigma_dps(const gyro_spec_t *s)
{
    return s->noise_density_dps_rthz * sqrt(s->sample_rate_hz / 2.0);
}

void gyro_init(gyro_t *g, const gyro_spec_t *s, uint64_t seed, unsigned index)
{
    g->spec = s;
    rng_init(&g->rng, seed, RNG_STREAM_GYRO + index);
    g->bias0_dps = s->bias_dps / s->bias_typ_sigmas * rng_gauss(&g->rng);
    g->walk_dps = 0.0;
    g->sample = -1;
    g->held_rad_s = 0.0;
}

/* The output of one sample from the true rate and the white noise n, deg/s. */
static double sample_out(const gyro_t *g, double true_dps, double n)
{
    const gyro_spec_t *s = g->spec;
    double y = (1.0 + s->scale_error_pct / 100.0) * true_dps + g->bias0_dps + g->walk_dps
             + gyro_sigma_dps(s) * n;
    if (y > s->full_scale_dps) y = s->full_scale_dps;
    if (y < -s->full_scale_dps) y = -s->full_scale_dps;
    if (s->lsb_dps > 0.0) y = s->lsb_dps * round(y / s->lsb_dps);
    return y;
}

double gyro_read(gyro_t *g, double true_rate_rad_s, double t_s)
{
    double f = g->spec->sample_rate_hz;
    int64_t k = (int64_t)floor(t_s * f);
    if (k <= g->sample) return g->held_rad_s;
    double step = g->spec->bias_rw_dps_rts * sqrt(1.0 / f), n = 0.0;
    /* every sample draws its two deviates, read or not: the noise depends on time only */
    for (int64_t i = g->sample + 1; i <= k; i++) {
        double n1 = rng_gauss(&g->rng);
        n = rng_gauss(&g->rng);
        if (i > 0) g->walk_dps += step * n1;
    }
    g->sample = k;
    g->held_rad_s = sample_out(g, true_rate_rad_s * DEG_PER_RAD, n) / DEG_PER_RAD;
    return g->held_rad_s;
}

/* ---- the sensor kind ---- */

#define G(name, def, min, max, unit, src) \
    { NULL, #name, offsetof(gyro_spec_t, name), def, min, max, unit, src, NULL, 0, 0, 0, KEYTAB_DOUBLE, 0, NULL }
static const keytab_t keys[] = {
    G(noise_density_dps_rthz, 0.007, 0, 10, "deg/s/sqrt(Hz)", "LSM6DS3 datasheet Table 3: Rn 7 mdps/sqrt(Hz)"),
    G(bias_dps, 10, 0, 1000, "deg/s", "LSM6DS3 datasheet Table 3: zero-rate level G_TyOff +-10 dps typ"),
    G(bias_typ_sigmas, 1, 0.1, 10, "1", "ST datasheets' Terminology (LSM303C, LSM330): TyOff is the standard deviation over a population of parts"),
    G(bias_rw_dps_rts, 0.01, 0, 10, "deg/s/sqrt(s)", "ours: not in the datasheet"),
    G(scale_error_pct, 1, -50, 50, "%", "ours: an uncalibrated part"),
    G(full_scale_dps, 1000, 1, 10000, "deg/s", "LSM6DS3: FS +-1000 dps"),
    G(sample_rate_hz, 833, 1, 100000, "Hz", "LSM6DS3: ODR 833 Hz"),
    G(lsb_dps, 0.035, 0, 10, "deg/s", "LSM6DS3 datasheet Table 3: 35 mdps/LSB at +-1000 dps"),
};

static void part_init(void *state, const robot_part_t *p, const sim_model_t *md, uint64_t seed, unsigned index, unsigned count)
{
    gyro_init(state, (const gyro_spec_t *)p->spec, seed, index);
}

/* every step: the samples take the true rate of their own time */
static void part_step(void *state, const robot_part_t *p, const sensor_ctx_t *x)
{
    gyro_read(state, x->yaw_rate_rad_s, x->t_s);
}

static int part_read(void *state, const robot_part_t *p, const sensor_ctx_t *x, double v[SENSOR_VALUES])
{
    v[0] = ((const gyro_t *)state)->held_rad_s * DEG_PER_RAD;
    v[1] = x->yaw_rate_rad_s * DEG_PER_RAD;
    return 2;
}

const sensor_kind_t sensor_gyro = {
    "gyro", "MEMS z-rate gyroscope: white noise, bias, bias random walk, scale error, saturation, sample and hold, LSB",
    keys, sizeof keys / sizeof keys[0], NULL, sizeof(gyro_t), part_init, part_step, part_read, "dps true_dps",
};

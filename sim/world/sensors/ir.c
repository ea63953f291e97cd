/* ir.c - IR reflectance wall sensor: the beam's cone of rays, the returned
 * light, the ADC sample (see ir.h). */
#include "ir.h"

#include <math.h>

#ifndef M_PI
#define M_PI 3.14159265358979323846
#endif

void ir_spec_default(ir_spec_t *s)
{
    /* SFH4550 datasheet (docs/datasheets/SFH4550.pdf), characteristics:
     * half angle +-3 deg (that PDF's text is font-encoded, not extractable
     * here: the figure is Osram's published one, to check on the page) */
    s->half_angle_deg = 3.0;
    /* SFH309FA datasheet (docs/datasheets/sfh309-phototransistor.pdf):
     * half angle +-12 deg (the BPW85's is +-25 deg, BPW85 datasheet p. 1) */
    s->det_half_angle_deg = 12.0;
    /* ours: two emitter half angles, where its profile is 1/16 of the axis */
    s->cone_deg = 6.0;
    s->rings = 2;          /* ours: 1 + 2 x 8 = 17 rays */
    s->rays_per_ring = 8;
    s->reflectivity = 0.85; /* ours: matt white wall faces */
    /* counts for reflectivity 1 at 50 mm: mazerunner-core's ORION reads
     * FRONT_REFERENCE = 850 (config-robot-orion.h) centred in a cell facing
     * a wall; ours: that sensor-to-wall distance taken as 50 mm, so
     * 850 / 0.85 */
    s->gain_counts = 1000.0;
    s->ref_m = 0.050;
    /* ours: closer than ~15 mm the emitter's spot leaves the detector's
     * field of view (the pair sits ~10 mm apart); not measured */
    s->near_m = 0.015;
    /* ours: a full wall at 0.5 m returns 1000 * 0.85 * (0.05 / 0.5)^2 = 8.5 counts */
    s->max_m = 0.5;
    /* ours: the detectors sit below the sensor board, shielded from room
     * light (hardware/wall-sensors/wall-sensor-basic/readme.md) */
    s->ambient_counts = 10.0;
    /* docs/analogue-read.md: variance 0.3425 counts^2 over 10000 samples at
     * the default prescaler 128, so sigma = 0.585 counts */
    s->noise_counts = 0.585;
    s->adc_bits = 10; /* ATmega328P ADC: 10 bits, 0..1023 */
}

/* Relative intensity at th_deg off the axis of a Gaussian profile with
 * half its axis value at half_deg. */
static double profile(double th_deg, double half_deg)
{
    double r = th_deg / half_deg;
    return exp(-0.69314718055994531 * r * r) /* ln 2 */;
}

static void add_ray(ir_t *ir, double th_deg, double phi_rad, double solid_sr)
{
    double th = th_deg * M_PI / 180.0;
    int i = ir->nrays++;
    ir->off[i][0] = cos(th);
    ir->off[i][1] = sin(th) * cos(phi_rad);
    ir->off[i][2] = sin(th) * sin(phi_rad);
    ir->weight[i] = profile(th_deg, ir->spec.half_angle_deg) * profile(th_deg, ir->spec.det_half_angle_deg) * solid_sr;
}

void ir_init(ir_t *ir, const ir_spec_t *s, uint64_t seed, unsigned index)
{
    ir->spec = *s;
    ir->nrays = 0;
    int rings = s->rings < 0 ? 0 : s->rings > IR_MAX_RINGS ? IR_MAX_RINGS : s->rings;
    int per = s->rays_per_ring < 1 ? 1 : s->rays_per_ring > IR_MAX_PER_RING ? IR_MAX_PER_RING : s->rays_per_ring;
    double step = rings ? s->cone_deg / rings : 0.0, step_rad = step * M_PI / 180.0;
    /* each ray stands for the solid angle around it: the centre a disc of
     * radius step/2, ring k an annulus of width step shared by its rays */
    add_ray(ir, 0.0, 0.0, rings ? M_PI * step_rad * step_rad / 4 : 1.0);
    for (int k = 1; k <= rings; k++) {
        double th = k * step, solid = 2 * M_PI * sin(th * M_PI / 180.0) * step_rad / per;
        for (int j = 0; j < per; j++) /* odd rings turned half a step */
            add_ray(ir, th, 2 * M_PI * (j + 0.5 * (k & 1)) / per, solid);
    }
    double k0 = 0;
    for (int i = 0; i < ir->nrays; i++) k0 += ir->weight[i] * pow(ir->off[i][0], 3);
    for (int i = 0; i < ir->nrays; i++) ir->weight[i] /= k0;
    rng_init(&ir->rng, seed, RNG_STREAM_IR + index);
}

int ir_full_scale(const ir_t *ir) { return (1 << ir->spec.adc_bits) - 1; }

double ir_received(const ir_t *ir, world_t *w, const double pos_m[3], double dir_rad)
{
    const ir_spec_t *s = &ir->spec;
    double c = cos(dir_rad), sn = sin(dir_rad), sum = 0;
    for (int i = 0; i < ir->nrays; i++) {
        const double *o = ir->off[i];
        double u[3] = { o[0] * c - o[1] * sn, o[0] * sn + o[1] * c, o[2] }, n[3];
        double d = world_ray_normal(w, pos_m, u, s->max_m, n);
        if (d < 0) continue;
        double cosi = -(n[0] * u[0] + n[1] * u[1] + n[2] * u[2]);
        if (cosi <= 0) continue;
        double dd = d < s->near_m ? s->near_m : d;
        sum += ir->weight[i] * s->reflectivity * cosi / (dd * dd);
    }
    return sum;
}

int ir_read(ir_t *ir, world_t *w, const double pos_m[3], double dir_rad, int emitter_on)
{
    const ir_spec_t *s = &ir->spec;
    double v = s->ambient_counts + s->noise_counts * rng_gauss(&ir->rng);
    if (emitter_on) v += s->gain_counts * s->ref_m * s->ref_m * ir_received(ir, w, pos_m, dir_rad);
    double top = ir_full_scale(ir);
    v = floor(v + 0.5);
    return v < 0 ? 0 : v > top ? (int)top : (int)v;
}

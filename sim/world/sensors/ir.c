/* ir.c - IR reflectance wall sensor: the beam's cone of rays, the returned
 * light, the ADC sample (see ir.h). */
#include "ir.h"

#include <math.h>
#include <stdio.h>

#include "sensor.h"

#ifndef M_PI
#define M_PI 3.14159265358979323846
#endif

void ir_spec_default(ir_spec_t *s)
{
    /* SFH4550 datasheet (docs/datasheets/SFH4550.pdf), characteristics:
     * half angle +-3 deg (that PDF's text is font-encoded, not extractable
     * here: the figure is Osram's published one, to check on the page) */
    s->half_angle_deg = 3.0;
    /* SFH4550 datasheet v1.6 p.5, Radiation Characteristics, read from the
     * linear plot (I_rel against angle): 0.04 at 10 deg, 0.022 at 20, 0.015
     * at 30, 0.007 at 40, 0 by 45 deg; a line from 0.04 at 10 deg to 0 at
     * 45 deg stays within 0.007 of it. Integrated over its solid angle the
     * skirt carries about twice the beam's power. */
    s->skirt_rel = 0; /* off unless a robot file gives it: its SFH4550 value is 0.04 */
    s->skirt_deg = 45.0;
    /* ours: 8 x rays_per_ring rays, 4.7 deg apart: ORION's front sums with
     * the skirt move 1.5 % from 6 to 8 rings or from 8 to 16 rays a ring,
     * 4-5 % from 4 rings to 8 */
    s->skirt_rings = 8;
    /* an emitter held clear of its board sends all its skirt out; one lying
     * on the board (UKMARSBOT's wall sensor boards: "the emitters are
     * placed above the board and the detectors are below", UKB
     * hardware/wall-sensors/wall-sensor-basic/readme.md) sends only its
     * upper half: the skirt leaves through the package's body, and the
     * board under the body takes what leaves it downwards. The beam leaves
     * through the lens at the board's edge and is kept whole. */
    s->skirt_below = 1;
    /* SFH309FA datasheet (docs/datasheets/sfh309-phototransistor.pdf):
     * half angle +-12 deg (the BPW85's is +-25 deg, BPW85 datasheet p. 1) */
    s->det_half_angle_deg = 12.0;
    /* ours: two emitter half angles, where its profile is 1/16 of the axis */
    s->cone_deg = 6.0;
    s->rings = 2;          /* ours: 1 + 2 x 8 = 17 rays */
    s->rays_per_ring = 8;
    /* counts for a matt reflectivity-1 wall straight on at 50 mm; ours: of
     * the order of ORION's fitted gains (242 to 1046, robots/ukmarsbot.ini) */
    s->gain_counts = 1000.0;
    s->ref_m = 0.050;
    /* ours: a guard against 1/0 only; the near field comes from the
     * detector's offset and its cone */
    s->near_m = 0.001;
    /* ours: UKMARSBOT's advanced board, emitter above and detector below
     * the board: 5 mm LED's centre 2.5 mm above, 1.6 mm board, 3 mm
     * detector's centre 1.5 mm below */
    s->det_offset_m = -0.0056;
    /* the board between emitter and detector: its underside 1.5 mm above
     * the 3 mm detector's centre; its edge level with the detector (ours:
     * no shield) */
    s->shield_height_m = 0.0015;
    s->shield_setback_m = 0;
    /* ours: a full wall at 0.5 m returns 1000 * 0.85 * (0.05 / 0.5)^2 = 8.5 counts */
    s->max_m = 0.5;
    /* ours: the detectors sit below the sensor board, shielded from room
     * light (hardware/wall-sensors/wall-sensor-basic/readme.md) */
    s->ambient_counts = 10.0;
    /* docs/analogue-read.md: variance 0.3425 counts^2 over 10000 samples at
     * the default prescaler 128, so sigma = 0.585 counts */
    s->noise_counts = 0.585;
    s->adc_bits = 10; /* ATmega328P ADC: 10 bits, 0..1023 */
    s->det_deg_n = s->det_rel_n = 0; /* none: the Gaussian of det_half_angle_deg */
}

/* Relative intensity at th_deg off the axis of a Gaussian profile with
 * half its axis value at half_deg. */
static double profile(double th_deg, double half_deg)
{
    double r = th_deg / half_deg;
    return exp(-0.69314718055994531 * r * r) /* ln 2 */;
}

/* The detector's relative sensitivity at th_deg off its axis: its
 * datasheet's directional characteristic when the spec gives one, else a
 * Gaussian of its half angle. */
static double detector_profile(const ir_spec_t *s, double th_deg)
{
    int n = s->det_deg_n;
    if (n < 2 || s->det_rel_n != n) return profile(th_deg, s->det_half_angle_deg);
    for (int i = 1; i < n; i++)
        if (th_deg <= s->det_deg[i]) {
            double f = (th_deg - s->det_deg[i - 1]) / (s->det_deg[i] - s->det_deg[i - 1]);
            return s->det_rel[i - 1] + f * (s->det_rel[i] - s->det_rel[i - 1]);
        }
    return 0;
}

/* The skirt's knee: where skirt_rel is read (SFH4550 p.5). */
#define SKIRT_KNEE_DEG 10.0

/* The emitter's relative intensity at th_deg off its axis: the beam (a
 * Gaussian of its half angle) or the skirt, whichever is brighter. */
static double emitter_profile(const ir_spec_t *s, double th_deg)
{
    double g = profile(th_deg, s->half_angle_deg), k = 0;
    if (s->skirt_rel > 0 && s->skirt_deg > SKIRT_KNEE_DEG && th_deg < s->skirt_deg)
        k = s->skirt_rel * (th_deg <= SKIRT_KNEE_DEG ? 1 : (s->skirt_deg - th_deg) / (s->skirt_deg - SKIRT_KNEE_DEG));
    return g > k ? g : k;
}

static void add_ray(ir_t *ir, double th_deg, double phi_rad, double solid_sr)
{
    double th = th_deg * M_PI / 180.0;
    int i = ir->nrays++;
    ir->off[i][0] = cos(th);
    ir->off[i][1] = sin(th) * cos(phi_rad);
    ir->off[i][2] = sin(th) * sin(phi_rad);
    /* the detector's profile is taken where it sees each spot (ray_return) */
    ir->weight[i] = emitter_profile(ir->spec, th_deg) * solid_sr;
}

void ir_init(ir_t *ir, const ir_spec_t *s, double reflectivity, uint64_t seed, unsigned index)
{
    ir->spec = s;
    ir->reflectivity = reflectivity;
    ir->gloss = 0, ir->gloss_exp = 1;
    ir->nrays = 0;
    /* a cone of 0 degrees is the axis alone, however many rings are asked for */
    int rings = s->rings < 0 || s->cone_deg <= 0 ? 0 : s->rings > IR_MAX_RINGS ? IR_MAX_RINGS : (int)s->rings;
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
    /* the skirt: annuli from the beam's last (half a step beyond its
     * outer ring) out to skirt_deg, a ring of rays at each one's middle */
    int sk = s->skirt_rel <= 0 || s->skirt_rings < 1 ? 0 : s->skirt_rings > IR_MAX_SKIRT_RINGS ? IR_MAX_SKIRT_RINGS : (int)s->skirt_rings;
    double s0 = s->cone_deg + step / 2, sstep = sk && s->skirt_deg > s0 ? (s->skirt_deg - s0) / sk : 0;
    for (int k = 1; sstep > 0 && k <= sk; k++) {
        double th = s0 + (k - 0.5) * sstep, solid = 2 * M_PI * sin(th * M_PI / 180.0) * sstep * M_PI / 180.0 / per;
        for (int j = 0; j < per; j++) {
            add_ray(ir, th, 2 * M_PI * (j + 0.5 * ((rings + k) & 1)) / per, solid);
            if (ir->off[ir->nrays - 1][2] < 0) ir->weight[ir->nrays - 1] *= s->skirt_below; /* the board under it */
        }
    }
    double k0 = 0; /* a matt plane straight on in the far field: the detector sees ray i at th_i */
    for (int i = 0; i < ir->nrays; i++)
        k0 += ir->weight[i] * detector_profile(s, acos(ir->off[i][0]) * 180.0 / M_PI) * pow(ir->off[i][0], 3);
    for (int i = 0; i < ir->nrays; i++) ir->weight[i] /= k0;
    rng_init(&ir->rng, seed, RNG_STREAM_IR + index);
}

int ir_full_scale(const ir_t *ir) { return (1 << (int)ir->spec->adc_bits) - 1; }

void ir_set_finish(ir_t *ir, double gloss, double gloss_exp)
{
    ir->gloss = gloss;
    ir->gloss_exp = gloss_exp < 1 ? 1 : gloss_exp;
}

/* The fraction of the detector's aperture (DET_APERTURE_M tall, centred
 * on it) that sees a spot x_m ahead of it and z_m above it past the board's
 * edge, shield_setback_m ahead and shield_height_m above the detector: the
 * line from the spot over the edge meets the detector's plane at z0. */
#define DET_APERTURE_M 0.003 /* SFH309FA: a 3 mm package (datasheet p.1 outline) */
static double board_shade(const ir_spec_t *s, double x_m, double z_m)
{
    double sb = s->shield_setback_m, h = s->shield_height_m;
    if (sb <= 0 || z_m <= h) return 1;
    if (x_m <= sb) return 0;
    double z0 = h - (z_m - h) * sb / (x_m - sb), f = (z0 + DET_APERTURE_M / 2) / DET_APERTURE_M;
    return f < 0 ? 0 : f > 1 ? 1 : f;
}

static double dot3(const double a[3], const double b[3]) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

/* What one ray (unit u from the emitter at e) returns to the detector at
 * det (looking along axis) from a spot d along it on a surface of normal n
 * (towards the ray), reflectivity rho and gloss: q_i of ir.h without w_i. */
static double ray_return(const ir_t *ir, const double e[3], const double u[3], double d, const double n[3],
                         const double det[3], const double axis[3], const double up[3], double rho, double gloss)
{
    double q[3], m[3], un = dot3(u, n);
    if (un >= 0) return 0; /* the surface's back */
    for (int k = 0; k < 3; k++) q[k] = det[k] - (e[k] + d * u[k]), m[k] = u[k] - 2 * un * n[k];
    double shade = board_shade(ir->spec, -dot3(q, axis), -dot3(q, up));
    if (shade <= 0) return 0;
    double r = sqrt(dot3(q, q));
    if (r <= 0) return 0;
    for (int k = 0; k < 3; k++) q[k] /= r;
    double cos_o = dot3(n, q), cos_b = -dot3(axis, q);
    if (cos_o <= 0 || cos_b <= 0) return 0; /* the detector behind the surface or looking away */
    double beta_deg = acos(cos_b > 1 ? 1 : cos_b) * 180.0 / M_PI;
    double cos_a = dot3(m, q), f = rho;
    if (gloss > 0 && cos_a > 0) f += gloss * (ir->gloss_exp + 2) / 2 * pow(cos_a, ir->gloss_exp);
    double rr = r < ir->spec->near_m ? ir->spec->near_m : r;
    return shade * f * cos_o * detector_profile(ir->spec, beta_deg) / (rr * rr);
}

/* The detector's place: det_offset_m along up from the emitter at pos. */
static void detector_at(const ir_t *ir, const double pos[3], const double up[3], double det[3])
{
    for (int k = 0; k < 3; k++) det[k] = pos[k] + ir->spec->det_offset_m * up[k];
}

double ir_received_hits(const ir_t *ir, const sim_pose_t *at, const world_hit_t *hit)
{
    double sum = 0, det[3];
    detector_at(ir, at->pos_m, at->up, det);
    for (int i = 0; i < ir->nrays; i++) {
        if (hit[i].d_m < 0) continue;
        sum += ir->weight[i] * ray_return(ir, at->pos_m, hit[i].dir, hit[i].d_m, hit[i].normal, det, at->axis, at->up,
                                          ir->reflectivity, ir->gloss);
    }
    return sum;
}

double ir_received_frame(const ir_t *ir, world_t *w, const double pos_m[3], const double axis[3], const double left[3],
                         const double up[3])
{
    sim_pose_t at;
    world_hit_t hit[IR_MAX_RAYS];
    for (int k = 0; k < 3; k++) at.pos_m[k] = pos_m[k], at.axis[k] = axis[k], at.left[k] = left[k], at.up[k] = up[k];
    world_cast(w, &at, ir->nrays, (const double (*)[3])ir->off, ir->spec->max_m, hit);
    return ir_received_hits(ir, &at, hit);
}

double ir_received_plane(const ir_t *ir, double d_m, double tilt_rad, double rho, double gloss)
{
    return ir_received_band(ir, d_m, tilt_rad, rho, gloss, -INFINITY, INFINITY);
}

double ir_received_band(const ir_t *ir, double d_m, double tilt_rad, double rho, double gloss, double z_lo_m, double z_hi_m)
{
    /* the sensor's own frame: x along the axis, y left, z up; the emitter at the origin */
    static const double e[3] = { 0, 0, 0 }, axis[3] = { 1, 0, 0 }, up[3] = { 0, 0, 1 };
    double n[3] = { -cos(tilt_rad), -sin(tilt_rad), 0 }, det[3] = { 0, 0, ir->spec->det_offset_m };
    double sum = 0, c = -d_m * cos(tilt_rad); /* the plane: x . n = c */
    for (int i = 0; i < ir->nrays; i++) {
        double un = dot3(ir->off[i], n);
        if (un >= 0) continue;
        double d = c / un;
        if (d <= 0 || d > ir->spec->max_m) continue;
        if (d * ir->off[i][2] < z_lo_m || d * ir->off[i][2] > z_hi_m) continue; /* over or under the band */
        sum += ir->weight[i] * ray_return(ir, e, ir->off[i], d, n, det, axis, up, rho, gloss);
    }
    return sum;
}

/* A level sensor's frame looking along dir_rad. */
static void level_frame(double dir_rad, double axis[3], double left[3], double up[3])
{
    double c = cos(dir_rad), sn = sin(dir_rad);
    axis[0] = c, axis[1] = sn, axis[2] = 0;
    left[0] = -sn, left[1] = c, left[2] = 0;
    up[0] = 0, up[1] = 0, up[2] = 1;
}

double ir_received(const ir_t *ir, world_t *w, const double pos_m[3], double dir_rad)
{
    double a[3], l[3], u[3];
    level_frame(dir_rad, a, l, u);
    return ir_received_frame(ir, w, pos_m, a, l, u);
}

int ir_counts(ir_t *ir, double received)
{
    const ir_spec_t *s = ir->spec;
    double v = s->ambient_counts + s->noise_counts * rng_gauss(&ir->rng);
    v += s->gain_counts * s->ref_m * s->ref_m * received;
    double top = ir_full_scale(ir);
    v = floor(v + 0.5);
    return v < 0 ? 0 : v > top ? (int)top : (int)v;
}

int ir_read_frame(ir_t *ir, world_t *w, const double pos_m[3], const double axis[3], const double left[3], const double up[3],
                  int emitter_on)
{
    return ir_counts(ir, emitter_on ? ir_received_frame(ir, w, pos_m, axis, left, up) : 0);
}

int ir_read_object(ir_t *ir, double d_m, int emitter_on)
{
    return ir_counts(ir, emitter_on ? ir_received_plane(ir, d_m, 0, 1, 0) : 0);
}

int ir_read(ir_t *ir, world_t *w, const double pos_m[3], double dir_rad, int emitter_on)
{
    double a[3], l[3], u[3];
    level_frame(dir_rad, a, l, u);
    return ir_read_frame(ir, w, pos_m, a, l, u, emitter_on);
}

/* ---- the sensor kind ---- */

/* A robot file's section is parsed into robot_part_t.spec: it must fit. */
typedef char ir_part_spec_fits[sizeof(ir_part_spec_t) <= sizeof(((robot_part_t *)0)->spec) ? 1 : -1];

#define I(name, field, def, min, max, per, whole, unit, src) \
    { NULL, #name, offsetof(ir_part_spec_t, field), def, min, max, unit, src, NULL, whole, per, 0, KEYTAB_DOUBLE, 0, NULL }
static const keytab_t keys[] = {
    I(emitter, emitter, KEYTAB_REQUIRED, 0, 3, 0, 1, "group", "the emitter group that lights it (hal_emitter)"),
    I(adc_channel, adc_channel, -1, -1, 15, 0, 1, "channel", "the ADC channel of its detector (-1: none; board emulation)"),
    I(measured_centred, measured_centred, -1, -1, 1023, 0, 0, "counts", "the real robot's lit-minus-dark reading centred between side walls, no wall ahead (mmsim --validate)"),
    I(measured_backed, measured_backed, -1, -1, 1023, 0, 0, "counts", "the real robot's lit-minus-dark reading backed against a rear wall, a wall ahead (mmsim --validate)"),
    I(measured_facing_sum, measured_facing_sum, -1, -1, 10000, 0, 0, "1", "the real pair's normalised front sum centred facing a wall (mmsim --validate: predicted)"),
    I(measured_turn_sum, measured_turn_sum, -1, -1, 10000, 0, 0, "1", "the real pair's normalised front sum with the wall ahead 154 mm from the axle, no side walls (mmsim --validate: predicted)"),
    I(measured_turn_wall_adjust, measured_turn_wall_adjust, 0, 0, 10000, 0, 0, "1", "what each side wall adds to that front sum on the real robot (mazerunner-core's EXTRA_WALL_ADJUST)"),
    I(measured_facing_ratio, measured_facing_ratio, -1, -1, 1000, 0, 0, "1", "the real robot's lit minus dark centred facing a wall over backed against the rear wall (mmsim --validate: predicted)"),
    I(gain_counts, model.gain_counts, 1000, 0, 1e6, 0, 0, "counts", "lit minus dark for a reflectivity-1 wall straight on at ref_mm; fit it to your robot's readings"),
    I(ref_mm, model.ref_m, 50, 1, 1000, 1000, 0, "mm", "the gain's reference distance"),
    I(half_angle_deg, model.half_angle_deg, 3, 0.5, 60, 0, 0, "deg", "SFH4550 datasheet: +-3 deg half angle"),
    I(skirt_rel, model.skirt_rel, 0, 0, 1, 0, 0, "1", "the emitter's skirt at 10 deg off the axis, of the axis intensity (SFH4550 datasheet p.5: 0.04; 0: none)"),
    I(skirt_deg, model.skirt_deg, 45, 10, 90, 0, 0, "deg", "SFH4550 datasheet p.5: the skirt ends by 45 deg"),
    I(skirt_below, model.skirt_below, 1, 0, 1, 0, 0, "1", "the share of the skirt below the emitter's axis that leaves (0: the emitter lies on its board, which takes it)"),
    I(skirt_rings, model.skirt_rings, 8, 0, IR_MAX_SKIRT_RINGS, 0, 1, "1", "ours: rings of rays in the skirt (8: converged within 1.5 %)"),
    I(shield_setback_mm, model.shield_setback_m, 0, 0, 50, 1000, 0, "mm", "the board's edge ahead of the detector's centre (0: no shield)"),
    I(shield_height_mm, model.shield_height_m, 1.5, 0, 50, 1000, 0, "mm", "the board's underside above the detector's centre: a 3 mm detector under the board"),
    I(det_half_angle_deg, model.det_half_angle_deg, 12, 0.5, 90, 0, 0, "deg", "SFH309FA datasheet: +-12 deg half angle"),
    { NULL, "det_deg", offsetof(ir_part_spec_t, model.det_deg), 0, 0, 90, "deg", "the detector's directional characteristic: angles off its axis, increasing from 0 (its datasheet; one value: none, the Gaussian of det_half_angle_deg)", NULL, 0, 0, IR_MAX_DET_POINTS, KEYTAB_DOUBLE, offsetof(ir_part_spec_t, model.det_deg_n), NULL },
    { NULL, "det_rel", offsetof(ir_part_spec_t, model.det_rel), 1, 0, 1, "1", "the detector's relative sensitivity at each det_deg (its datasheet's directional characteristic)", NULL, 0, 0, IR_MAX_DET_POINTS, KEYTAB_DOUBLE, offsetof(ir_part_spec_t, model.det_rel_n), NULL },
    I(cone_deg, model.cone_deg, 6, 0, 60, 0, 0, "deg", "ours: the outermost ring at two emitter half angles"),
    I(rings, model.rings, 2, 0, IR_MAX_RINGS, 0, 1, "1", "ours: rings of rays about the axis"),
    I(rays_per_ring, model.rays_per_ring, 8, 1, IR_MAX_PER_RING, 0, 1, "1", "ours: 1 + 2 x 8 = 17 rays"),
    I(near_mm, model.near_m, 1, 0.1, 200, 1000, 0, "mm", "ours: a guard against 1/0; the near field comes from det_offset_mm"),
    I(det_offset_mm, model.det_offset_m, -5.6, -50, 50, 1000, 0, "mm", "ours: the detector below the emitter: 5 mm LED, 1.6 mm board, 3 mm detector"),
    I(max_mm, model.max_m, 500, 10, 2000, 1000, 0, "mm", "ours: the rays' length (a wall at 0.5 m returns ~8 counts)"),
    I(ambient_counts, model.ambient_counts, 10, 0, 1023, 0, 0, "counts", "ours: the dark reading, shielded from room light"),
    I(noise_counts, model.noise_counts, 0.585, 0, 100, 0, 0, "counts", "ukmarsbot docs/analogue-read.md: variance 0.3425 counts^2"),
    I(adc_bits, model.adc_bits, 10, 1, 16, 0, 1, "bits", "ATmega328P: 10-bit ADC"),
};

static void part_init(void *state, const robot_part_t *p, const sim_model_t *md, uint64_t seed, unsigned index, unsigned count)
{
    ir_state_t *st = state;
    ir_init(&st->ir, &((const ir_part_spec_t *)p->spec)->model, md->arena.wall_reflectivity, seed, index);
    ir_set_finish(&st->ir, md->arena.wall_gloss, md->arena.wall_gloss_exp);
    st->last[0] = st->last[1] = -1;
    st->count = 0;
}

/* Telemetry: the latest samples (reading draws noise, so it is the
 * firmware's to do: ir_sample). */
static int part_read(void *state, const robot_part_t *p, const sensor_ctx_t *x, double v[SENSOR_VALUES])
{
    const ir_state_t *st = state;
    v[0] = st->last[0];
    v[1] = st->last[1];
    v[2] = st->last[0] >= 0 && st->last[1] >= 0 ? st->last[1] - st->last[0] : -1;
    return 3;
}

int ir_sample(void *state, const robot_part_t *p, const sensor_ctx_t *x)
{
    ir_state_t *st = state;
    int on = x->emitter[(int)((const ir_part_spec_t *)p->spec)->emitter & 3] != 0;
    double received = 0;
    if (on && x->t_s < st->object_until_s) {
        received = ir_received_plane(&st->ir, st->object_m, 0, 1, 0);
    } else if (on) { /* with the emitter off no ray is cast */
        sim_pose_t at;
        world_hit_t hit[IR_MAX_RAYS];
        world_body_cast(x->world, sensor_pose(x->model, p), st->ir.nrays, (const double (*)[3])st->ir.off,
                        st->ir.spec->max_m, &at, hit);
        received = ir_received_hits(&st->ir, &at, hit);
    }
    int v = ir_counts(&st->ir, received);
    st->last[on] = v;
    st->count++;
    return v;
}

static int part_check(const robot_part_t *p, char *reason, size_t len)
{
    const ir_spec_t *m = &((const ir_part_spec_t *)p->spec)->model;
    if (m->det_deg_n != m->det_rel_n) {
        snprintf(reason, len, "det_rel: %d values for %d det_deg angles", m->det_rel_n, m->det_deg_n);
        return -1;
    }
    for (int i = 0; i < m->det_deg_n; i++)
        if (i == 0 ? m->det_deg[0] != 0 : m->det_deg[i] <= m->det_deg[i - 1]) {
            snprintf(reason, len, "det_deg: %g deg: the angles start at 0 and increase", m->det_deg[i]);
            return -1;
        }
    if (m->near_m >= m->max_m) {
        snprintf(reason, len, "near_mm: %g mm is not below max_mm %g mm", m->near_m * 1000, m->max_m * 1000);
        return -1;
    }
    return 0;
}

const sensor_kind_t sensor_ir = {
    "ir", "IR reflectance wall sensor: emitter and offset phototransistor, a cone of rays, Lambertian paint with a gloss lobe, the detector's cone, ambient, 10-bit ADC",
    keys, sizeof keys / sizeof keys[0], part_check, sizeof(ir_state_t), part_init, NULL, part_read, "dark lit lit_minus_dark",
};

/* ir.h - IR reflectance wall sensor model: an emitter LED, a
 * phototransistor beside it and a 10-bit ADC, as on UKMARSBOT's wall sensor
 * boards (SFH4550 emitter, SFH309FA or BPW85 detector, the Nano's ADC).
 *
 * The beam is a cone of rays about the emitter's axis (a centre ray and
 * rings of rays), cast in the ODE world, so a post or a wall end is seen as
 * the beam sees it: each ray returns what it hits. The detector sits
 * det_offset_m from the emitter along the sensor's up axis, looking along
 * the same axis. Ray i, at angle th_i off the axis, lights a spot P_i on a
 * surface of normal n; the spot is r_i from the detector, seen by it at
 * beta_i off its axis, and the light leaves towards it at o_i off the
 * normal, at alpha_i off the mirror direction of the ray. It returns
 *
 *   q_i = w_i * (rho + gloss * (m + 2) / 2 * cos^m(alpha_i))
 *             * cos(o_i) * D(beta_i) / max(r_i, near_m)^2
 *
 * (a Lambertian paint of reflectivity rho with a Phong gloss lobe of
 * reflectance gloss straight on and exponent m: the world's wall finish;
 * the detector's profile D: a Gaussian of the datasheet's half angle, or
 * the datasheet's directional characteristic when given). The weights w_i
 * are the emitter's profile (its Gaussian beam and its skirt, the skirt's
 * lower half taken by a board under the emitter when skirt_below is 0)
 * times the solid angle each ray stands for. Close to a wall the lit spot leaves the detector's cone
 * (beta grows as det_offset / d): the reading peaks and falls off; the
 * gloss lobe leaves it too, and with any tilt of the wall (alpha grows as
 * twice the tilt). The sum is normalised by k0 = sum w_i D(th_i) cos^3(th_i),
 * what a matt plane straight on returns in the far field, so that
 *
 *   received = sum q_i / k0      [1/m^2]; a matt wall straight on, far: rho/d^2.
 *
 * One ADC sample, in counts:
 *
 *   counts = clamp(round(ambient + (emitter on ? gain * ref_m^2 * received
 *                                              : 0) + sigma * N(0,1)),
 *                  0, 2^bits - 1)
 *
 * gain = the lit-minus-dark counts of a wall of reflectivity 1 straight on
 * at ref_m. The reading depends on the emitter's state at the moment of the
 * sample; the firmware (mazerunner-core's sensors.h) samples dark (emitter
 * off), then lit (emitter on), and uses lit minus dark. Every sample draws
 * one deviate from the sensor's own noise stream (rng.h, RNG_STREAM_IR +
 * index), lit or dark, so the sequence depends only on the seed, the index
 * and the number of samples.
 *
 * A robot file's [ir.NAME] sections place them (ir_part_spec_t); the
 * firmware samples them through sim_ir_read (hal_ir_raw); telemetry
 * publishes their latest samples on MM_PARTS (lcm/parts_t.lcm) and the
 * viewer draws each beam (sim/view/scene.c). */
#ifndef IR_H
#define IR_H

#include <stdint.h>
#include "world/rng.h"
#include "world/world.h"
#include "world/sensors/sensor.h"

#define IR_MAX_RINGS 4
#define IR_MAX_SKIRT_RINGS 8
#define IR_MAX_PER_RING 16
#define IR_MAX_DET_POINTS 14
#define IR_MAX_RAYS (1 + (IR_MAX_RINGS + IR_MAX_SKIRT_RINGS) * IR_MAX_PER_RING)

/* The model's numbers (plain data; ir_spec_default gives UKMARSBOT's). */
typedef struct {
    double half_angle_deg;     /* emitter: half-intensity angle, deg */
    /* The emitter's skirt: the light its lens does not gather into the
     * beam, skirt_rel of the axis intensity at SKIRT_KNEE_DEG, falling
     * linearly to 0 at skirt_deg (0: none), cast as skirt_rings rings of
     * rays_per_ring rays from cone_deg out to skirt_deg. */
    double skirt_rel;          /* relative intensity at 10 deg, 0..1 */
    double skirt_deg;          /* where it ends, deg */
    double skirt_rings;        /* rings of rays in it, 0..IR_MAX_SKIRT_RINGS */
    double skirt_below;        /* the share of its rays below the axis that leave, 0..1 (0: a board under the emitter takes them) */
    double det_half_angle_deg; /* detector: half-sensitivity angle, deg (its Gaussian profile) */
    /* The detector's directional characteristic from its datasheet, when
     * given (2 or more points): relative sensitivity det_rel[i] at
     * det_deg[i] off its axis, increasing angles from 0, linear between
     * them, 0 past the last; it replaces the Gaussian. */
    double det_deg[IR_MAX_DET_POINTS];
    int det_deg_n;
    double det_rel[IR_MAX_DET_POINTS];
    int det_rel_n;
    double cone_deg;           /* the outermost ring's angle off the axis, deg */
    double rings;              /* rings of rays about the centre ray, 0..IR_MAX_RINGS */
    double rays_per_ring;      /* 1..IR_MAX_PER_RING */
    double gain_counts;        /* lit minus dark, counts, for reflectivity 1 straight on at ref_m */
    double ref_m;              /* the gain's reference distance, m */
    double near_m;             /* a guard: a spot closer to the detector counts as this far, m */
    double det_offset_m;       /* the detector from the emitter along the sensor's up axis, m (negative: below) */
    double shield_setback_m;   /* the board's edge ahead of the detector's centre, m (0: no shield) */
    double shield_height_m;    /* the board's underside above the detector's centre, m */
    double max_m;              /* the rays' length, m */
    double ambient_counts;     /* the dark reading, counts */
    double noise_counts;       /* standard deviation of one sample, counts */
    double adc_bits;           /* 10: full scale 1023 */
} ir_spec_t;

/* One sensor: its spec (the robot file's, never copied: it outlives the
 * sensor), the walls' reflectivity it sees (the world's), the rays derived
 * from the spec, and its noise stream. */
typedef struct {
    const ir_spec_t *spec;
    double reflectivity;       /* of the walls and posts, 0..1 ([world] wall_reflectivity) */
    double gloss, gloss_exp;   /* their finish ([world] wall_gloss, wall_gloss_exp); ir_init: 0 (matt) */
    int nrays;
    double off[IR_MAX_RAYS][3]; /* ray directions in the sensor's frame: x along the axis, y left, z up */
    double weight[IR_MAX_RAYS]; /* normalised: a plane straight on in the far field sums to 1 */
    rng_t rng;
} ir_t;

/* The robot file's [ir.NAME]: the model and where it is wired. */
typedef struct {
    ir_spec_t model;           /* the walls' reflectivity is the world's ([world] wall_reflectivity) */
    double emitter;            /* the emitter group that lights it, 0..3 (hal_emitter) */
    double adc_channel;        /* the MCU's ADC channel its detector feeds (a board's business) */
    double measured_centred;   /* lit minus dark on the real robot centred in a cell between side walls, no wall ahead; -1 none */
    double measured_backed;    /* lit minus dark with its back against a cell's rear wall, a wall ahead; -1 none */
    /* The forward pair's sum, each sensor normalised to 100 at its
     * measured_backed (mazerunner-core's get_front_sum), given on each
     * sensor of the pair; -1 none: */
    double measured_facing_sum; /* centred in a cell facing its wall ahead (FRONT_REFERENCE) */
    double measured_turn_sum;  /* the axle 20 mm past a cell boundary, the wall ahead 154 mm from it, no side walls (TURN_THRESHOLD_SS90E) */
    double measured_turn_wall_adjust; /* what each side wall adds to the turn's sum (EXTRA_WALL_ADJUST); 0 none */
    double measured_facing_ratio; /* its own lit minus dark centred facing a wall over backed against the rear wall; -1 none */
} ir_part_spec_t;

/* An [ir.NAME] sensor at run time: the model and its latest samples. */
typedef struct {
    ir_t ir;
    int last[2];               /* the latest sample with its emitter off [0] and on [1], counts; -1 none */
    uint32_t count;            /* samples taken */
    double object_m, object_until_s; /* an object held object_m ahead of it until then (sim_occlude) */
} ir_state_t;

/* UKMARSBOT's sensor (values and sources in ir.c). */
void ir_spec_default(ir_spec_t *s);
/* The sensor with spec s (kept by pointer: s must outlive ir) among walls
 * of this reflectivity (0..1), its noise stream from the run's seed and
 * the sensor's index. */
void ir_init(ir_t *ir, const ir_spec_t *s, double reflectivity, uint64_t seed, unsigned index);
/* The walls' gloss (reflectance straight on, 0..1) and its exponent (>= 1). */
void ir_set_finish(ir_t *ir, double gloss, double gloss_exp);
/* The light returned with the emitter on, 1/m^2, from a plane of
 * reflectivity rho and gloss (the exponent the sensor's) d_m ahead of the emitter along
 * its axis, its normal turned tilt_rad about the sensor's up axis (0:
 * straight on), with no world: the model of ir.h for an ideal plane. */
double ir_received_plane(const ir_t *ir, double d_m, double tilt_rad, double rho, double gloss);
/* The same for a band of that plane from z_lo_m to z_hi_m along the
 * sensor's up axis (a wall of finite height: its foot and top relative to
 * the emitter); ir_received_plane is the band from -inf to +inf. */
double ir_received_band(const ir_t *ir, double d_m, double tilt_rad, double rho, double gloss, double z_lo_m, double z_hi_m);
/* The light returned to the detector with the emitter on, 1/m^2 (see
 * above: about rho/d^2 for a matt wall straight on in the far field), for a sensor at
 * pos_m (world, m) looking horizontally along dir_rad. */
double ir_received(const ir_t *ir, world_t *w, const double pos_m[3], double dir_rad);
/* The same for a sensor whose frame is given: where it looks (axis), its
 * left and up (unit vectors, world frame). */
double ir_received_frame(const ir_t *ir, world_t *w, const double pos_m[3], const double axis[3], const double left[3],
                         const double up[3]);
/* The light returned to the detector, 1/m^2, given what the sensor's rays
 * (ir->off, ir->spec->max_m) hit from its place `at` (world_cast): the
 * model alone, no world. */
double ir_received_hits(const ir_t *ir, const sim_pose_t *at, const world_hit_t *hit);
/* One ADC sample with this light returned to the detector (1/m^2; 0 with
 * the emitter off): ambient, gain, one noise deviate, the ADC's rails. */
int ir_counts(ir_t *ir, double received);
/* One ADC sample at this frame (emitter on 1 or off 0). */
int ir_read_frame(ir_t *ir, world_t *w, const double pos_m[3], const double axis[3], const double left[3], const double up[3],
                  int emitter_on);

/* One ADC sample, counts 0..2^bits - 1, with the emitter on (1) or off (0)
 * at the moment of the sample. With the emitter off no ray is cast. */
int ir_read(ir_t *ir, world_t *w, const double pos_m[3], double dir_rad, int emitter_on);
/* An [ir.NAME] sensor's ADC sample now, with its emitter group as the
 * context says (ir_state_t; the HAL's hal_ir_raw). */
int ir_sample(void *state, const robot_part_t *p, const sensor_ctx_t *x);

/* One ADC sample with a white object straight on at d_m in front of the
 * sensor (a hand held before it): ir_received_plane at d_m, a matt
 * reflectivity 1. */
int ir_read_object(ir_t *ir, double d_m, int emitter_on);

/* The ADC's top count, 2^bits - 1. */
int ir_full_scale(const ir_t *ir);

#endif

/* encoder.h - incremental wheel encoder, the paper's eq. 6-7:
 * delta_pulses = delta_theta / (2*pi) * PPR, PPR on the motor shaft, so
 * counts per wheel turn = PPR * gear ratio (12 * 29.86 = 358.32). The
 * fractional remainder is kept, so no pulse is lost or invented; counts are
 * signed. */
#ifndef ENCODER_H
#define ENCODER_H

#include <stdint.h>

typedef struct {
    double counts_per_rad; /* counts per radian of wheel rotation */
    double last_rad;       /* last wheel angle seen, rad (wrapped or not) */
    double frac;           /* fractional count carried over */
    int32_t count;         /* signed accumulated counts */
} encoder_t;

void encoder_init(encoder_t *e, double counts_per_wheel_rev, double angle_rad);
/* A new wheel angle in radians; angles may wrap at +-pi (as
 * world_wheel_angle does): a jump over pi is taken as the short way round. */
void encoder_update(encoder_t *e, double angle_rad);

#endif

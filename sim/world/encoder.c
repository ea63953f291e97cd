/* encoder.c - incremental encoder with the remainder kept. */
#include "encoder.h"

#include <math.h>

void encoder_init(encoder_t *e, double counts_per_wheel_rev, double angle_rad)
{
    e->counts_per_rad = counts_per_wheel_rev / (2.0 * M_PI);
    e->last_rad = angle_rad;
    e->frac = 0.0;
    e->count = 0;
}

void encoder_update(encoder_t *e, double angle_rad)
{
    double d = angle_rad - e->last_rad;
    if (d > M_PI) d -= 2.0 * M_PI;
    if (d < -M_PI) d += 2.0 * M_PI;
    e->last_rad = angle_rad;
    e->frac += d * e->counts_per_rad;
    double whole = trunc(e->frac);
    e->count += (int32_t)whole;
    e->frac -= whole;
}

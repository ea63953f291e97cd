/* odom.h - odometry from the wheel encoders: distance travelled, heading,
 * speeds. Heading is in radians, counter-clockwise positive, 0 at start. */
#ifndef ODOM_H
#define ODOM_H

#include <stdint.h>

typedef struct {
    int32_t last_l, last_r; /* encoder counts at the previous update */
    float ds_mm, dtheta_rad; /* the last update's increments */
    float dist_mm;          /* forward distance since init */
    float theta_rad;        /* heading since init */
    float x_mm, y_mm;       /* position in the start frame (x right, y ahead) */
    float v_mm_s, w_rad_s;  /* filtered speeds */
} odom_t;

void odom_init(odom_t *o, int32_t left, int32_t right);
/* New encoder counts after dt_s seconds. */
void odom_update(odom_t *o, int32_t left, int32_t right, float dt_s);

#endif

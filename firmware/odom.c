/* odom.c - differential-drive odometry. */
#include "odom.h"

#include <math.h>

#include "robot_config.h"

/* each wheel's mm per count: RC_MM_PER_COUNT_LEFT, _RIGHT (robot_config.h) */

void odom_init(odom_t *o, int32_t left, int32_t right)
{
    o->last_l = left;
    o->last_r = right;
    o->ds_mm = o->dtheta_rad = 0;
    o->dist_mm = o->theta_rad = 0;
    o->x_mm = o->y_mm = 0;
    o->v_mm_s = o->w_rad_s = 0;
}

void odom_update(odom_t *o, int32_t left, int32_t right, float dt_s)
{
    float dl = (float)(left - o->last_l) * RC_MM_PER_COUNT_LEFT;
    float dr = (float)(right - o->last_r) * RC_MM_PER_COUNT_RIGHT;
    o->last_l = left;
    o->last_r = right;
    o->ds_mm = 0.5f * (dl + dr);
    o->dtheta_rad = (dr - dl) / RC_ODOM_TRACK_MM;
    float mid = o->theta_rad + 0.5f * o->dtheta_rad; /* midpoint heading */
    o->x_mm -= o->ds_mm * sinf(mid);
    o->y_mm += o->ds_mm * cosf(mid);
    o->dist_mm += o->ds_mm;
    o->theta_rad += o->dtheta_rad;
    /* one count per 1 ms tick is 280 mm/s: smooth over ~10 ticks */
    o->v_mm_s += 0.1f * (o->ds_mm / dt_s - o->v_mm_s);
    o->w_rad_s += 0.1f * (o->dtheta_rad / dt_s - o->w_rad_s);
}

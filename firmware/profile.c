/* profile.c - trapezoidal speed profile. */
#include "profile.h"

#include <math.h>

void profile_reset(profile_t *p)
{
    p->pos = p->speed = p->target = 0;
    p->v_max = p->v_end = p->accel = p->accel_now = 0;
    p->active = 0;
}

void profile_start(profile_t *p, float distance, float v_max, float v_end, float accel)
{
    float sign = distance < 0 ? -1.0f : 1.0f;
    p->pos = 0;
    p->target = distance;
    p->v_max = sign * fabsf(v_max);
    p->v_end = sign * fabsf(v_end);
    p->accel = fabsf(accel);
    p->active = distance != 0;
    if (!p->active) p->speed = p->v_end;
}

void profile_update(profile_t *p, float dt_s) { profile_update_capped(p, dt_s, INFINITY); }

void profile_update_capped(profile_t *p, float dt_s, float a_up)
{
    float before = p->speed;
    if (!p->active) {
        p->accel_now = 0;
        return;
    }
    float sign = p->target < 0 ? -1.0f : 1.0f;
    float remaining = (p->target - p->pos) * sign; /* >= 0 while moving */
    /* the fastest speed from which we can still brake to v_end */
    float v_brake = sqrtf(p->v_end * p->v_end + 2.0f * p->accel * (remaining > 0 ? remaining : 0));
    float v_goal = fminf(fabsf(p->v_max), v_brake) * sign;
    float dv = p->accel * dt_s;
    float dv_up = (a_up < p->accel ? (a_up > 0 ? a_up : 0) : p->accel) * dt_s;
    /* brake up to twice as hard when the end moved closer (front-wall
     * alignment shortens a move under way) */
    float dv_brake = fabsf(p->speed) > fabsf(v_goal) + dv ? 2.0f * dv : dv;
    if (p->speed < v_goal) {
        float step = sign > 0 ? dv_up : dv_brake;
        p->speed = p->speed + step < v_goal ? p->speed + step : v_goal;
    } else if (p->speed > v_goal) {
        float step = sign > 0 ? dv_brake : dv_up;
        p->speed = p->speed - step > v_goal ? p->speed - step : v_goal;
    }
    p->pos += p->speed * dt_s;
    if ((p->target - p->pos) * sign <= 0 || (fabsf(p->speed) < 1e-3f && remaining < 0.05f)) {
        p->pos = p->target;
        p->speed = p->v_end;
        p->active = 0;
    }
    p->accel_now = (p->speed - before) / dt_s;
    /* arriving a little fast (the end moved): no feed-forward spike */
    if (p->accel_now > 2.0f * p->accel) p->accel_now = 2.0f * p->accel;
    if (p->accel_now < -2.0f * p->accel) p->accel_now = -2.0f * p->accel;
}

float profile_remaining(const profile_t *p) { return p->target - p->pos; }

void profile_set_remaining(profile_t *p, float remaining) { p->target = p->pos + remaining; }

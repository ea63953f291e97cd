/* profile.h - trapezoidal speed profile: accelerate to v_max, cruise,
 * brake to arrive at the target with v_end. Units are the caller's (mm and
 * mm/s for moves, degrees and deg/s for turns). */
#ifndef PROFILE_H
#define PROFILE_H

#include <stdint.h>

typedef struct {
    float pos, speed;       /* along the move, from its start */
    float target;           /* where the move ends */
    float v_max, v_end, accel;
    float accel_now;        /* the last update's acceleration (for feed-forward) */
    uint8_t active;         /* 0 once the target is reached */
} profile_t;

void profile_reset(profile_t *p);
/* Start a move of distance (may be negative) from the current speed. */
void profile_start(profile_t *p, float distance, float v_max, float v_end, float accel);
/* Advance by dt seconds. */
void profile_update(profile_t *p, float dt_s);
/* The same, speeding up at no more than a_up (>= 0; braking keeps accel):
 * a motor's torque to spare falls as its speed rises. */
void profile_update_capped(profile_t *p, float dt_s, float a_up);
float profile_remaining(const profile_t *p);
/* Move the end of the current move so that `remaining` is left to go. */
void profile_set_remaining(profile_t *p, float remaining);

#endif

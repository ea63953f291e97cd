/* motion.h - moves and the wheel controller, run from the control tick.
 *
 * Two profiles run at once: forward (mm) and rotation (degrees). Each tick
 * the setpoints advance, the errors between where the profiles say the
 * robot should be and where odometry says it is are accumulated (forward in
 * mm; rotation in mm of wheel arc), and each wheel gets
 *   feed-forward (motor model: speed and acceleration) + PD on the errors.
 * While driving straight, the heading is held to the move's heading and
 * wall centring adds a steering rate (motion_set_steer).
 * Stuck (forward error above RC_STALL_MM for RC_STALL_MS) = crash: the
 * motors stop and stay off. */
#ifndef MOTION_H
#define MOTION_H

#include <stdint.h>

#include "odom.h"
#include "profile.h"

typedef struct {
    odom_t odom;
    profile_t fwd, rot;
    float fwd_err_mm, rot_err_mm;       /* accumulated errors */
    float fwd_err_prev, rot_err_prev;
    float heading_rad;                  /* the heading straight moves hold */
    float steer_rad_s;                  /* from wall centring, this tick */
    uint16_t stall_ms;
    uint8_t crashed;
    uint8_t enabled;
    int16_t cmd[2];                     /* last motor commands */
} motion_t;

void motion_init(motion_t *m);
/* Forward move of distance_mm, cruising at v_max, ending at v_end. */
void motion_forward(motion_t *m, float distance_mm, float v_max, float v_end);
/* The same with a given acceleration (mm/s^2). */
void motion_forward_accel(motion_t *m, float distance_mm, float v_max, float v_end, float accel);
/* In-place turn, degrees counter-clockwise (negative = clockwise). */
void motion_turn(motion_t *m, float degrees);
int motion_busy(const motion_t *m);
void motion_stop(motion_t *m);
/* One control tick of dt_s: odometry, profiles, controller, motors. */
void motion_tick(motion_t *m, float dt_s);

#endif

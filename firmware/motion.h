/* motion.h - moves and the wheel controller, run from the control tick.
 *
 * Two profiles run at once: forward (mm) and rotation (degrees). Each tick
 * the setpoints advance, the errors between where the profiles say the
 * robot should be and where odometry says it is are accumulated (forward in
 * mm; rotation in mm of wheel arc), and each wheel gets
 *   feed-forward (motor model: speed and acceleration) + PD on the errors.
 * While driving straight, the heading is held to the move's heading; wall
 * centring (lateral_mm, set by the caller from the side sensors) turns the
 * robot towards the centre line in proportion to the offset (P) and slowly
 * corrects the held heading itself (I): the walls are the truth, odometry's
 * heading drifts about a degree per metre.
 * Stuck (forward error above RC_STALL_MM for RC_STALL_MS) = crash: the
 * motors stop and stay off. */
#ifndef MOTION_H
#define MOTION_H

#include <stdint.h>

#include "odom.h"
#include "profile.h"

/* 1: motion_t holds the feed-forward's cap (ff_max_cmd), which the
 * planner's speed runs raise (slalomrun.c, plan.h PLAN_ENABLED); 0: the cap is
 * RC_CMD_FF_MAX alone. The AVR builds have no planner and keep 0 (the
 * cap as a variable costs the UKMARSBOT image 86 B of flash and 23 B of stack
 * headroom); a target that enables the planner defines it 1 as well. */
#ifndef MOTION_FF_CAP
#if !defined(__AVR__)
#define MOTION_FF_CAP 1
#else
#define MOTION_FF_CAP 0
#endif
#endif

typedef struct motion_s {
    odom_t odom;
    profile_t fwd, rot;
    float fwd_err_mm, rot_err_mm;       /* accumulated errors */
    float fwd_err_prev, rot_err_prev;
    float heading_rad;                  /* the heading straight moves hold */
    float lateral_mm;                   /* wall centring: how far right of the centre line */
    uint8_t lateral_valid;              /* lateral_mm was measured (a side wall is there) */
    uint16_t stall_ms;
    uint8_t crashed;
    uint8_t enabled;
    int16_t cmd[2];                     /* last motor commands */
#if MOTION_FF_CAP
    float ff_max_cmd;                   /* the feed-forward's cap: RC_CMD_FF_MAX, a speed run's own */
#endif
} motion_t;

void motion_init(motion_t *m);
/* Forward move of distance_mm, cruising at v_max, ending at v_end. */
void motion_forward(motion_t *m, float distance_mm, float v_max, float v_end);
/* The same with a given acceleration (mm/s^2). */
void motion_forward_accel(motion_t *m, float distance_mm, float v_max, float v_end, float accel);
/* In-place turn, degrees counter-clockwise (negative = clockwise). */
void motion_turn(motion_t *m, float degrees);
/* Turn on the spot about a point offset_mm to the left of the robot's
 * centre on its axle line (negative: to the right): the body's corners
 * then sweep a circle about that point. Used to turn about the cell's
 * centre when the robot stopped off the centre line. */
void motion_turn_about(motion_t *m, float degrees, float offset_mm);
/* Smooth turn while moving, degrees counter-clockwise: only the rotation
 * profile (RC_SMOOTH_*); the forward profile keeps the speed. */
void motion_turn_smooth(motion_t *m, float degrees);
/* Where a smooth 90-degree turn at v_mm_s goes: it starts *offset_mm
 * before the turn point (the crossing of the two centre lines) and ends
 * *offset_mm past it; *length_mm is its path length. From the same
 * discrete profile the control tick runs. */
void motion_smooth_geometry(float v_mm_s, float *offset_mm, float *length_mm);
/* A slalom: the same while moving at the forward profile's speed, with
 * the turn's own peak rate and acceleration (slalom.c). */
void motion_slalom(motion_t *m, float degrees, float w_deg_s, float accel_deg_s2);
/* Where a slalom of `degrees` (> 0, either side) at constant v_mm_s goes,
 * from the discrete profile the control tick runs with the feed-forward
 * capped at ff_max_cmd (motion_t's): *pre_mm from its start
 * to the crossing of the entry and exit lines, *post_mm from there to its
 * end (more than *pre_mm where the motor caps the speeding up of the
 * rotation but not its braking); for 180 degrees *pre_mm how far to the
 * side it ends, *post_mm how far ahead of its start. *length_mm its path
 * length. */
void motion_slalom_geometry(float v_mm_s, float degrees, float w_deg_s, float accel_deg_s2, float ff_max_cmd, float *pre_mm,
                            float *post_mm, float *length_mm);
/* Standing before a flat wall that both diagonal rays hit (at a cell
 * centre, each cone's inner edge meets the wall ahead 22 mm from its ends):
 * how far the robot is turned counter-clockwise from the wall's normal,
 * rad, from the two readings (mm along each cone's inner edge). Exact for
 * any angle and distance while the inner edge is the ray nearest the
 * wall's normal (turned less than 32.5 degrees). */
float motion_wall_angle(float left_mm, float right_mm);
int motion_busy(const motion_t *m);
void motion_stop(motion_t *m);
/* One control tick of dt_s: odometry, profiles, controller, motors. */
void motion_tick(motion_t *m, float dt_s);

#endif

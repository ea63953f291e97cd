/* motion.c - profiles + feed-forward + PD wheel control (see motion.h). */
#include "motion.h"

#include <math.h>

#include "hal.h"
#include "robot_config.h"

#define DEG_TO_RAD 0.017453293f
#define HALF_TRACK_MM (RC_TRACK_MM / 2)

void motion_init(motion_t *m)
{
    odom_init(&m->odom, hal_encoder(HAL_LEFT), hal_encoder(HAL_RIGHT));
    profile_reset(&m->fwd);
    profile_reset(&m->rot);
    m->fwd_err_mm = m->rot_err_mm = 0;
    m->fwd_err_prev = m->rot_err_prev = 0;
    m->heading_rad = 0;
    m->steer_rad_s = 0;
    m->stall_ms = 0;
    m->crashed = 0;
    m->enabled = 1;
    m->cmd[0] = m->cmd[1] = 0;
}

void motion_forward(motion_t *m, float distance_mm, float v_max, float v_end)
{
    motion_forward_accel(m, distance_mm, v_max, v_end, RC_ACCEL_MM_S2);
}

void motion_forward_accel(motion_t *m, float distance_mm, float v_max, float v_end, float accel)
{
    profile_start(&m->fwd, distance_mm, v_max, v_end, accel);
}

void motion_turn(motion_t *m, float degrees)
{
    profile_start(&m->rot, degrees, RC_TURN_DEG_S, 0, RC_TURN_ACCEL_DEG_S2);
    m->heading_rad += degrees * DEG_TO_RAD;
}

/* Busy until the profiles are done AND the robot has caught up with them:
 * turning on the spot while still rolling puts the body into the walls. */
int motion_busy(const motion_t *m)
{
    if (m->fwd.active || m->rot.active) return 1;
    return fabsf(m->fwd_err_mm) > RC_SETTLE_MM || fabsf(m->rot_err_mm) > RC_SETTLE_MM ||
           fabsf(m->odom.v_mm_s) > RC_SETTLE_MM_S || fabsf(m->odom.w_rad_s) * (RC_TRACK_MM / 2) > RC_SETTLE_MM_S;
}

void motion_stop(motion_t *m)
{
    m->enabled = 0;
    m->cmd[0] = m->cmd[1] = 0;
    hal_motor_set(0, 0);
}

static int16_t clamp_cmd(float c)
{
    if (c > RC_CMD_MAX) return RC_CMD_MAX;
    if (c < -RC_CMD_MAX) return -RC_CMD_MAX;
    return (int16_t)lroundf(c);
}

void motion_tick(motion_t *m, float dt_s)
{
    odom_update(&m->odom, hal_encoder(HAL_LEFT), hal_encoder(HAL_RIGHT), dt_s);
    if (!m->enabled || m->crashed) return;
    profile_update(&m->fwd, dt_s);
    profile_update(&m->rot, dt_s);

    /* rotation setpoint: the turn profile, or hold the heading plus centring */
    float w_set = m->rot.speed * DEG_TO_RAD;
    if (!m->rot.active) {
        /* wall centring turns the heading the robot holds: the walls are
         * the truth, odometry's heading drifts */
        m->heading_rad += m->steer_rad_s * dt_s;
        float heading_err = m->heading_rad - m->odom.theta_rad;
        w_set += RC_KP_HEADING * heading_err + m->steer_rad_s;
    }
    float v_set = m->fwd.speed;
    m->fwd_err_mm += v_set * dt_s - m->odom.ds_mm;
    m->rot_err_mm += (w_set * dt_s - m->odom.dtheta_rad) * HALF_TRACK_MM;

    float fwd_out = RC_KP_FWD * m->fwd_err_mm + RC_KD_FWD * (m->fwd_err_mm - m->fwd_err_prev) / dt_s;
    float rot_out = RC_KP_ROT * m->rot_err_mm + RC_KD_ROT * (m->rot_err_mm - m->rot_err_prev) / dt_s;
    m->fwd_err_prev = m->fwd_err_mm;
    m->rot_err_prev = m->rot_err_mm;

    float w_arc = w_set * HALF_TRACK_MM; /* wheel speed from rotation, mm/s */
    float a_arc = m->rot.accel_now * DEG_TO_RAD * HALF_TRACK_MM;
    float ff_l = (v_set - w_arc) / RC_MM_S_PER_CMD + (m->fwd.accel_now - a_arc) * RC_CMD_PER_MM_S2;
    float ff_r = (v_set + w_arc) / RC_MM_S_PER_CMD + (m->fwd.accel_now + a_arc) * RC_CMD_PER_MM_S2;
    m->cmd[HAL_LEFT] = clamp_cmd(ff_l + fwd_out - rot_out);
    m->cmd[HAL_RIGHT] = clamp_cmd(ff_r + fwd_out + rot_out);

    /* stuck against something: stop rather than push forever */
    if (fabsf(m->fwd_err_mm) > RC_STALL_MM) {
        m->stall_ms = (uint16_t)(m->stall_ms + (uint16_t)(dt_s * 1000.0f + 0.5f));
        if (m->stall_ms > RC_STALL_MS) {
            m->crashed = 1;
            m->cmd[0] = m->cmd[1] = 0;
            hal_log("motion: stuck, motors off");
        }
    } else {
        m->stall_ms = 0;
    }
    hal_motor_set(m->cmd[HAL_LEFT], m->cmd[HAL_RIGHT]);
}

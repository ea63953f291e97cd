/* motion.c - profiles + feed-forward + PD wheel control (see motion.h). */
#include "motion.h"

#include <math.h>

#include "hal.h"
#include "robot_config.h"

#define DEG_TO_RAD 0.017453293f
#define HALF_TRACK_MM (RC_TRACK_MM / 2)
/* the feed-forward's cap: motion_t's, or a turn's given one (MOTION_FF_CAP
 * 1); RC_CMD_FF_MAX (0) */
#if MOTION_FF_CAP
#define FF_MAX_CMD(m) ((m)->ff_max_cmd)
#define FF_MAX_GIVEN(cmd) (cmd)
#else
#define FF_MAX_CMD(m) RC_CMD_FF_MAX
#define FF_MAX_GIVEN(cmd) ((void)(cmd), RC_CMD_FF_MAX)
#endif

void motion_init(motion_t *m)
{
    odom_init(&m->odom, hal_encoder(HAL_LEFT), hal_encoder(HAL_RIGHT));
    profile_reset(&m->fwd);
    profile_reset(&m->rot);
    m->fwd_err_mm = m->rot_err_mm = 0;
    m->fwd_err_prev = m->rot_err_prev = 0;
    m->heading_rad = 0;
    m->lateral_mm = 0;
    m->lateral_valid = 0;
    m->stall_ms = 0;
    m->crashed = 0;
    m->enabled = 1;
    m->cmd[0] = m->cmd[1] = 0;
#if MOTION_FF_CAP
    m->ff_max_cmd = RC_CMD_FF_MAX;
#endif
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

void motion_turn_about(motion_t *m, float degrees, float offset_mm)
{
    motion_turn(m, degrees);
    /* the centre circles the pivot: the forward profile is the rotation's,
     * scaled by the radius, so both run in step */
    float k = offset_mm * DEG_TO_RAD; /* mm of travel per degree */
    float dist = degrees * k, ak = fabsf(k);
    if (dist != 0) profile_start(&m->fwd, dist, RC_TURN_DEG_S * ak, 0, RC_TURN_ACCEL_DEG_S2 * ak);
}

void motion_turn_smooth(motion_t *m, float degrees)
{
    profile_start(&m->rot, degrees, RC_SMOOTH_DEG_S, 0, RC_SMOOTH_ACCEL_DEG_S2);
    m->heading_rad += degrees * DEG_TO_RAD;
}

static float ff_spare(float ff_max_cmd, float v_mm_s, float w_deg_s);

/* A robot may turn only on the spot (RC_SMOOTH_TURNS 0): no smooth turn
 * then fits before any turn, however long the straight. */

/* Integrate a turn of `degrees` (> 0) at constant forward speed v_mm_s,
 * its rotation the profile the control tick runs (peak w_deg_s, accel
 * accel_deg_s2, speeding up within the outer wheel's spare command under
 * the cap ff_max_cmd):
 * where it ends (*x_mm to the turn's side, *y_mm along the entry heading)
 * and in how many ticks. */
static uint16_t turn_integrate(float v_mm_s, float degrees, float w_deg_s, float accel_deg_s2, float ff_max_cmd, float *x_mm,
                               float *y_mm)
{
    const float dt_s = 1.0f / HAL_TICK_HZ;
    profile_t p;
    float theta = 0, along = 0, side = 0;
    uint16_t ticks = 0;
    profile_reset(&p);
    profile_start(&p, degrees, w_deg_s, 0, accel_deg_s2);
    while (p.active && ticks < 5000u) { /* ~250 ticks; the bound is for bad constants */
        /* as motion_tick: the rotation speeds up within the outer wheel's spare command */
        profile_update_capped(&p, dt_s, ff_spare(FF_MAX_GIVEN(ff_max_cmd), v_mm_s, p.speed) * (1.0f / (RC_CMD_PER_ARC_MM_S2 * HALF_TRACK_MM * DEG_TO_RAD)));
        float w = p.speed * DEG_TO_RAD;
        along += v_mm_s * dt_s * cosf(theta + 0.5f * w * dt_s);
        side += v_mm_s * dt_s * sinf(theta + 0.5f * w * dt_s);
        theta += w * dt_s;
        ticks++;
    }
    *x_mm = side;
    *y_mm = along;
    return ticks;
}

void motion_smooth_geometry(float v_mm_s, float *offset_mm, float *length_mm)
{
    if (!RC_SMOOTH_TURNS) {
        *offset_mm = 1e9f; /* mm */
        *length_mm = 0;
        return;
    }
    float side;
    uint16_t ticks = turn_integrate(v_mm_s, 90.0f, RC_SMOOTH_DEG_S, RC_SMOOTH_ACCEL_DEG_S2, RC_CMD_FF_MAX, &side, offset_mm);
    /* the path is symmetric: the same along both lines */
    *length_mm = v_mm_s * (1.0f / HAL_TICK_HZ) * ticks;
}

void motion_slalom(motion_t *m, float degrees, float w_deg_s, float accel_deg_s2)
{
    profile_start(&m->rot, degrees, w_deg_s, 0, accel_deg_s2);
    m->heading_rad += degrees * DEG_TO_RAD;
}

void motion_slalom_geometry(float v_mm_s, float degrees, float w_deg_s, float accel_deg_s2, float ff_max_cmd, float *pre_mm,
                            float *post_mm, float *length_mm)
{
    float x, y;
    uint16_t ticks = turn_integrate(v_mm_s, degrees, w_deg_s, accel_deg_s2, ff_max_cmd, &x, &y);
    if (degrees > 179.0f) {
        *pre_mm = x; /* a U: how far to the side it ends, */
        *post_mm = y; /* and how far ahead of its start */
    } else {
        /* the exit line through (x, y) at `degrees` meets the entry line
         * (x = 0) at y - x / tan(degrees) */
        float a = degrees * DEG_TO_RAD;
        *pre_mm = y - x * cosf(a) / sinf(a);
        *post_mm = x / sinf(a);
    }
    *length_mm = v_mm_s * (1.0f / HAL_TICK_HZ) * ticks;
}

float motion_wall_angle(float left_mm, float right_mm)
{
    /* each sensor reads the wall along its cone's inner edge, 32.5 degrees
     * off the heading (RC_DIAG_EDGE_*): the nearest of its rays to the
     * wall's normal. The readings' end points on the wall, in the robot's
     * frame (x right, y ahead): (-X - l s, Y + l c) and (X + r s, Y + r c);
     * the wall runs through both, and the robot's turn from its normal is
     * the wall's slope */
    return atan2f((left_mm - right_mm) * RC_DIAG_EDGE_COS, 2.0f * RC_TOF_SIDE_X_MM + (left_mm + right_mm) * RC_DIAG_EDGE_SIN);
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

/* Command left within the cap ff_max_cmd for acceleration by the faster
 * wheel's feed-forward at forward speed v_mm_s while turning at w_deg_s. */
static float ff_spare(float ff_max_cmd, float v_mm_s, float w_deg_s)
{
    float v_wheel = fabsf(v_mm_s) + fabsf(w_deg_s) * (DEG_TO_RAD * HALF_TRACK_MM);
    return ff_max_cmd - RC_CMD_FRICTION - v_wheel / RC_MM_S_PER_CMD;
}

/* A wheel's command: back-EMF of its speed setpoint v_mm_s plus the
 * controller's correction pid (command), and the gearbox's friction, which
 * opposes the motion: in the direction the wheel is meant to turn, the
 * setpoint moved by the correction (as a speed), ramped in near rest. At
 * rest the correction alone decides: without it a position error under
 * 57 / RC_KP_FWD mm never moves a wheel held by the stiction (the AVR's
 * search stood 80 s in one cell of japan2019, busy settling). */
static float wheel_cmd(float v_mm_s, float pid)
{
    float f = (v_mm_s + pid * RC_MM_S_PER_CMD) * (1.0f / RC_FRICTION_RAMP_MM_S);
    if (f > 1.0f) f = 1.0f;
    if (f < -1.0f) f = -1.0f;
    return v_mm_s / RC_MM_S_PER_CMD + f * RC_CMD_FRICTION + pid;
}

void motion_tick(motion_t *m, float dt_s)
{
    odom_update(&m->odom, hal_encoder(HAL_LEFT), hal_encoder(HAL_RIGHT), dt_s);
    if (!m->enabled || m->crashed) return;
    /* speed up no faster than the faster wheel's feed-forward allows
     * within the cap: the motor's torque to spare falls with speed */
    float spare = ff_spare(FF_MAX_CMD(m), m->fwd.speed, m->rot.speed);
    profile_update_capped(&m->fwd, dt_s, spare * (1.0f / RC_CMD_PER_MM_S2));
    profile_update_capped(&m->rot, dt_s, spare * (1.0f / (RC_CMD_PER_ARC_MM_S2 * HALF_TRACK_MM * DEG_TO_RAD)));

    /* rotation setpoint: the turn profile, or hold the heading plus centring */
    float w_set = m->rot.speed * DEG_TO_RAD;
    if (m->rot.active) {
        /* a turn follows its profile from the held heading, not from
         * wherever centring had pointed the robot when it began: the
         * turn's geometry is then the one planned */
        float target = m->heading_rad - profile_remaining(&m->rot) * DEG_TO_RAD;
        w_set += RC_KP_HEADING * (target - m->odom.theta_rad);
    } else {
        float offset_rad = 0;
        if (m->lateral_valid) {
            m->heading_rad += RC_KI_LATERAL * m->lateral_mm * dt_s;
            offset_rad = RC_KP_LATERAL * m->lateral_mm;
            if (RC_LATERAL_REF_MM_S > 0 && m->fwd.speed > RC_LATERAL_REF_MM_S) offset_rad *= RC_LATERAL_REF_MM_S / m->fwd.speed;
            if (offset_rad > RC_LATERAL_MAX_RAD) offset_rad = RC_LATERAL_MAX_RAD;
            if (offset_rad < -RC_LATERAL_MAX_RAD) offset_rad = -RC_LATERAL_MAX_RAD;
        }
        float heading_err = m->heading_rad + offset_rad - m->odom.theta_rad;
        w_set += RC_KP_HEADING * heading_err;
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
    float a_fwd = m->fwd.accel_now * RC_CMD_PER_MM_S2, a_rot = a_arc * RC_CMD_PER_ARC_MM_S2;
    m->cmd[HAL_LEFT] = clamp_cmd(wheel_cmd(v_set - w_arc, fwd_out - rot_out) + a_fwd - a_rot);
    m->cmd[HAL_RIGHT] = clamp_cmd(wheel_cmd(v_set + w_arc, fwd_out + rot_out) + a_fwd + a_rot);

    /* stuck against something: stop rather than push forever */
    if (fabsf(m->fwd_err_mm) > RC_STALL_MM) {
        m->stall_ms = (uint16_t)(m->stall_ms + (uint16_t)(dt_s * 1000.0f + 0.5f));
        if (m->stall_ms > RC_STALL_MS) {
            m->crashed = 1;
            m->cmd[0] = m->cmd[1] = 0;
            HAL_LOG_STR("motion: stuck, motors off");
        }
    } else {
        m->stall_ms = 0;
    }
    hal_motor_set(m->cmd[HAL_LEFT], m->cmd[HAL_RIGHT]);
}

/* drive.c - the moves the search, the speed runs and command mode are
 * made of (drive.h): straights that read the walls of each cell ahead at
 * its sensing point, wall centring, front-wall alignment and the front fix,
 * turns on the spot (U-turns in two quarters) and smooth quarter turns. */
#include "drive.h"

#include <math.h>
#include <stdio.h>

#include "hal.h"
#include "robot_config.h"
#include "walls.h"

void drive_log(const char *fmt, unsigned a, unsigned b) /* fmt: HAL_STR("...") */
{
    char line[HAL_LOG_MAX + 1];
    hal_snprintf(line, sizeof line, fmt, a, b); /* fmt: a HAL_STR */
    hal_log(line);
}

/* Relative quarter turns from heading h to heading d: 0, 1 (right), 2, -1. */
int8_t drive_quarter(uint8_t h, uint8_t d)
{
    int8_t q = (int8_t)((d - h) & 3);
    return q == 3 ? -1 : q;
}

/* Walls of the cell ahead, read from the sensors (EXPLORE_WALL_* bits);
 * to_centre: mm from the robot to that cell's centre. */
uint8_t drive_read_walls(float to_centre)
{
    /* the far wall of the cell ahead is RC_FRONT_AT_CENTRE_MM beyond its centre */
    return walls_around(to_centre + RC_FRONT_AT_CENTRE_MM + RC_FRONT_WALL_MARGIN_MM);
}

/* Where the robot is along its heading relative to the nearest cell
 * centre, mm (negative before it), from the move under way: its end lies
 * move_shift_mm before a cell centre. */
static float along_cell(drive_t *dr)
{
    float y = -fmodf(profile_remaining(&dr->mo.fwd) + dr->move_shift_mm, RC_CELL_MM); /* (-180, 0] */
    return y < -RC_CELL_MM / 2 ? y + RC_CELL_MM : y;
}

/* The robot's offset right of the centre line, mm, from a diagonal
 * reading r_mm of the side wall on the right (right = 1) or left, the
 * robot turned psi_rad counter-clockwise from the corridor. The sensor
 * reads the wall along its cone's edge nearest the wall's normal, 32.5
 * degrees off it when the robot is square (1 mm sideways is 1 /
 * RC_DIAG_EDGE_COS = 1.19 mm of reading). Turned by s towards the wall,
 * the sensor (RC_TOF_SIDE_X_MM out, RC_TOF_SIDE_Y_MM ahead of the centre)
 * sits X cos s + Y sin s out from the centre and its edge is 32.5 deg - s
 * off the normal, so the wall is X cos s + Y sin s + r cos(32.5 deg - s)
 * from the centre. Square, that is 84 mm at the centre line. The turn
 * matters: 5.7 degrees towards the left wall read 42 and 65 mm on
 * us82's straight at (6,2), the robot 2 mm right of the centre line,
 * which is 8 mm left of it taken as square (seed 1); the centring then
 * steered on the robot's own weave (+-6 degrees, one cell a period) and
 * a U-turn's pivot went 4 mm the wrong way, a body corner into the wall. */
static float side_offset(float r_mm, float psi_rad, uint8_t right)
{
    float s = right ? -psi_rad : psi_rad, cs = cosf(s), sn = sinf(s);
    float out = RC_TOF_SIDE_X_MM * cs + RC_TOF_SIDE_Y_MM * sn + r_mm * (RC_DIAG_EDGE_COS * cs + RC_DIAG_EDGE_SIN * sn);
    float further = out - (RC_TOF_SIDE_X_MM + RC_DIAG_EDGE_COS * RC_SIDE_WALL_MM); /* than at the centre line */
    return right ? -further : further;
}

/* Whether a reading of the right (right = 1) or left diagonal sensor,
 * arriving now, can be of the post at the entry of the cell ahead (its
 * centre to_centre mm away) rather than of that cell's side wall: 0 if
 * it can. Turned s towards that side (odometry against the held heading),
 * the sensor sits Y cos s - X sin s ahead of the robot's centre and X cos
 * s + Y sin s out from it, and its cone's outer edge is 57.5 deg + s off
 * the heading; the edge meets the side wall's line gap * cot(57.5 deg + s)
 * ahead of the sensor. */
static int clear_of_entry_post(drive_t *dr, uint8_t right, float to_centre)
{
    float psi = dr->mo.odom.theta_rad - dr->mo.heading_rad, s = right ? -psi : psi, cs = cosf(s), sn = sinf(s);
    float short_mm = to_centre - RC_CELL_MM / 2 - (RC_TOF_SIDE_Y_MM * cs - RC_TOF_SIDE_X_MM * sn); /* of the boundary */
    float gap = RC_CELL_MM / 2 - RC_WALL_MM / 2 - (RC_TOF_SIDE_X_MM * cs + RC_TOF_SIDE_Y_MM * sn);
    /* cos and sin of 57.5 deg + s, from 57.5 = 90 - 32.5 */
    float reach = gap * (RC_DIAG_EDGE_SIN * cs - RC_DIAG_EDGE_COS * sn) / (RC_DIAG_EDGE_COS * cs + RC_DIAG_EDGE_SIN * sn);
    return reach - short_mm > RC_WALL_MM / 2 + RC_POST_MARGIN_MM;
}

/* Wall centring from the diagonal sensors: the robot's offset right of
 * the centre line, mm, when a side wall is seen (sets mo.lateral_*), each
 * reading taken with the robot's turn from the held heading when it
 * arrives (side_offset). A reading is judged where it arrived: between
 * RC_SIDE_BLIND_FROM_MM before a cell centre and RC_SIDE_BLIND_TO_MM past
 * it the rays can meet the wall across the end of the cell (or the next
 * one's, where the side wall is missing), which looks like a near side
 * wall; those readings are dropped. */
void drive_centring(drive_t *dr)
{
    float y = along_cell(dr);
    /* and not from a creep or a stop: the rays meet the wall ahead then */
    uint8_t usable = (y < -RC_SIDE_BLIND_FROM_MM || y > RC_SIDE_BLIND_TO_MM) && dr->mo.fwd.speed > RC_CENTRING_MIN_MM_S,
            news = 0;
    for (uint8_t i = 0; i < 2; i++) {
        uint8_t sensor = i ? HAL_TOF_RIGHT : HAL_TOF_LEFT;
        hal_distance_t d = walls_distance(sensor);
        if (d.seq == dr->side_seq[i]) continue;
        dr->side_seq[i] = d.seq;
        news = 1;
        dr->side_ok[i] = usable && !d.timeout && d.mm < RC_CENTRING_MAX_MM;
        dr->side_dmm[i] = (int16_t)(10.0f * side_offset((float)d.mm, dr->mo.odom.theta_rad - dr->mo.heading_rad, i));
        /* not fresh for the walls of the cell ahead if it may be its entry post */
        if (dr->sensed == SENSE_MARKED && !clear_of_entry_post(dr, i, profile_remaining(&dr->mo.fwd) + dr->move_shift_mm)) dr->tof_seq[sensor] = d.seq;
    }
    float el = 0.1f * (float)dr->side_dmm[0], er = 0.1f * (float)dr->side_dmm[1];
    dr->mo.lateral_mm = dr->side_ok[0] && dr->side_ok[1] ? 0.5f * (el + er) : dr->side_ok[0] ? el : dr->side_ok[1] ? er : 0.0f;
    dr->mo.lateral_valid = (uint8_t)(dr->side_ok[0] || dr->side_ok[1]);
    if (dr->mo.lateral_valid && news) { /* averaged over the last few readings for drive_turn */
        dr->last_lateral_mm = dr->last_lateral_ok ? dr->last_lateral_mm + RC_PIVOT_AVG * (dr->mo.lateral_mm - dr->last_lateral_mm) : dr->mo.lateral_mm;
        dr->last_lateral_ok = 1;
    }
}

void drive_no_centring(drive_t *dr) { dr->mo.lateral_valid = 0; }

/* With a wall ahead, move the end of the move towards what the front
 * sensor says (removes the odometry error of the straight). The move ends
 * `before_mm` short of the centre of the cell with that wall: 0 for a stop,
 * the smooth-turn offset for a turn. Each reading is used once, when it
 * arrives (it is exact then; 30 ms later the robot has moved up to 33 mm),
 * and only if taken during this straight (not while turning into it). The
 * sensor's noise is 5 % of the distance (6 mm at 120 mm), so each reading
 * moves the end by RC_ALIGN_GAIN of the difference. */
void drive_align_front(drive_t *dr, float before_mm)
{
    hal_distance_t f = walls_distance(HAL_TOF_FRONT);
    if (f.seq == dr->front_seq) return;
    dr->front_seq = f.seq;
    float left = profile_remaining(&dr->mo.fwd);
    if (f.timeout || left > RC_ALIGN_FROM_MM) return;
    float by_sensor = (float)f.mm - RC_FRONT_AT_CENTRE_MM - before_mm;
    if (by_sensor > left - 20.0f && by_sensor < left + 20.0f)
        profile_set_remaining(&dr->mo.fwd, left + RC_ALIGN_GAIN * (by_sensor - left));
}

/* Standing at a cell centre before a wall: the diagonal rays meet that
 * wall too, and their two readings give the robot's angle to it
 * (motion_wall_angle). The held heading moves towards the wall's normal by
 * 1 / (n + RC_WALL_HEADING_PRIOR) for the n-th reading of this stop, which
 * averages the readings (one has ~0.9 degrees of noise) with what the held
 * heading knew before. This is the only heading reference away from side
 * walls: odometry loses ~0.2 degrees per in-place quarter turn. */
static void wall_heading(drive_t *dr, uint8_t n)
{
    hal_distance_t l = walls_distance(HAL_TOF_LEFT), r = walls_distance(HAL_TOF_RIGHT), f = walls_distance(HAL_TOF_FRONT);
    if (l.timeout || r.timeout || f.timeout) return;
    float off = (float)f.mm - RC_FRONT_AT_CENTRE_MM;
    if (off > RC_WALL_HEADING_NEAR_MM || off < -RC_WALL_HEADING_NEAR_MM) return; /* rays may meet a side wall */
    float a = motion_wall_angle((float)l.mm, (float)r.mm);
    if (a > RC_WALL_HEADING_MAX_RAD || a < -RC_WALL_HEADING_MAX_RAD) return;
    dr->mo.heading_rad += (dr->mo.odom.theta_rad - a - dr->mo.heading_rad) / ((float)n + RC_WALL_HEADING_PRIOR);
}

/* Standing before a wall: wait for a fresh front reading (>= 35 ms: the
 * sensor updates every 30 ms), then creep to RC_FRONT_AT_CENTRE_MM from it.
 * Puts the robot on the cell's centre along its heading to +-2 mm before it
 * turns on the spot. Then RC_WALL_HEADING_READS fresh readings (the first
 * one's taken before any creep) square the heading to the wall
 * (wall_heading). Returns 1 when done. */
int drive_front_fix(drive_t *dr)
{
    if (motion_busy(&dr->mo)) return 0;
    if (dr->fix_stage == 0) {
        dr->stage_us = hal_micros();
        dr->fix_stage = 1;
        return 0;
    }
    if (dr->fix_stage == 1) {
        if (hal_micros() - dr->stage_us < 35000u) return 0;
        hal_distance_t f = walls_distance(HAL_TOF_FRONT);
        float adjust = (float)f.mm - RC_FRONT_AT_CENTRE_MM;
        wall_heading(dr, 1);
        dr->fix_stage = 2;
        if (!f.timeout && adjust > -30.0f && adjust < 30.0f && (adjust > 2.0f || adjust < -2.0f)) {
            motion_forward(&dr->mo, adjust, 200.0f, 0.0f);
            return 0;
        }
    }
    if (dr->fix_stage == 2 && RC_WALL_HEADING_READS > 1) {
        dr->stage_us = hal_micros();
        dr->fix_stage = 3;
        return 0;
    }
    if (dr->fix_stage >= 3) { /* reading fix_stage - 1 of RC_WALL_HEADING_READS */
        if (hal_micros() - dr->stage_us < 35000u) return 0;
        wall_heading(dr, (uint8_t)(dr->fix_stage - 1));
        if (dr->fix_stage <= RC_WALL_HEADING_READS) {
            dr->stage_us = hal_micros();
            dr->fix_stage++;
            return 0;
        }
    }
    dr->fix_stage = 0;
    return 1;
}

/* Remember the sensors' reading counts: fresh() is true once each has
 * delivered a reading taken after this moment. */
void drive_mark_readings(drive_t *dr)
{
    for (uint8_t i = 0; i < HAL_TOF_COUNT; i++) dr->tof_seq[i] = walls_distance(i).seq;
    dr->side_seq[0] = dr->tof_seq[HAL_TOF_LEFT];
    dr->side_seq[1] = dr->tof_seq[HAL_TOF_RIGHT];
    dr->side_ok[0] = dr->side_ok[1] = 0;
    dr->front_seq = dr->tof_seq[HAL_TOF_FRONT];
    dr->last_lateral_ok = 0;
}

int drive_fresh(drive_t *dr)
{
    for (uint8_t i = 0; i < HAL_TOF_COUNT; i++)
        if (walls_distance(i).seq == dr->tof_seq[i]) return 0;
    return 1;
}

/* A move reached the point where the walls of the cell ahead are read:
 * within RC_SENSE_BEFORE_MM of the move's end with readings taken within
 * RC_SENSE_FROM_MM of it (the side ones clear of the cell's entry post:
 * centring), or RC_SENSE_LATEST_MM at the latest; once per cell. */
int drive_sense_point(drive_t *dr, float left_mm)
{
    if (dr->sensed == SENSE_DONE) return 0;
    if (dr->sensed == SENSE_NONE && left_mm <= RC_SENSE_FROM_MM) {
        for (uint8_t i = 0; i < HAL_TOF_COUNT; i++) dr->tof_seq[i] = walls_distance(i).seq;
        dr->sensed = SENSE_MARKED;
    }
    return left_mm <= RC_SENSE_BEFORE_MM && (drive_fresh(dr) || left_mm <= RC_SENSE_LATEST_MM);
}

/* Read the walls of the cell ahead (its centre to_centre mm away) into the
 * map, committed to entering it (search and command mode). Returns the
 * walls (EXPLORE_WALL_*). */
uint8_t drive_sense_cell_ahead(drive_t *dr, float to_centre)
{
    dr->sensed = SENSE_DONE;
    uint8_t walls = drive_read_walls(to_centre);
    explore_moved(&dr->ex, dr->st.heading); /* committed to the cell ahead */
    explore_sense(&dr->ex, walls);
    return walls;
}

void drive_forward(drive_t *dr, float mm, float speed, float v_end, float accel)
{
    motion_forward_accel(&dr->mo, mm, speed, v_end, accel);
    dr->waiting = WAIT_MOVE;
    dr->sensed = SENSE_NONE;
    dr->wall_ahead = 0;
    dr->turn_pending = 0;
    dr->move_shift_mm = 0;
    drive_mark_readings(dr);
}

/* The straight before a smooth turn is over: turn, keeping the speed. */
static void start_smooth(drive_t *dr)
{
    motion_forward_accel(&dr->mo, dr->smooth_length_mm, RC_SMOOTH_MM_S, RC_SMOOTH_MM_S, RC_ACCEL_MM_S2);
    motion_turn_smooth(&dr->mo, -90.0f * dr->turn_pending); /* a right turn (+1) is clockwise */
    drive_no_centring(dr);
    dr->turn_pending = 0;
    dr->waiting = WAIT_SMOOTH;
}

/* On the straight before a smooth turn: align on the wall ahead (the turn
 * starts the smooth-turn offset before that cell's centre), turn at its end. */
void drive_approach_turn(drive_t *dr)
{
    if (dr->wall_ahead) drive_align_front(dr, dr->smooth_offset_mm);
    if (!dr->mo.fwd.active) start_smooth(dr);
}

/* A turn on the spot; a U-turn is two quarter turns with a stop between,
 * facing a side wall of the cell, where the front sensor puts the robot
 * back on the cell's centre line and the diagonal ones square it up (7 mm
 * of clearance for the body's corners sweeping round: the offset from the
 * straight must go first). The U-turn turns left first, unless only the
 * right wall is known to be there. st.heading is already the heading the
 * turn ends on. */
#define UTURN_CW 0x80u /* uturn_stage flag: a clockwise U-turn */
void drive_turn(drive_t *dr, int8_t q)
{
    /* off the centre line by more than the noise: turn about the centre */
    float pivot = 0;
    if (dr->last_lateral_ok && (dr->last_lateral_mm > 1.5f || dr->last_lateral_mm < -1.5f))
        pivot = dr->last_lateral_mm > RC_PIVOT_MAX_MM ? RC_PIVOT_MAX_MM
              : dr->last_lateral_mm < -RC_PIVOT_MAX_MM ? -RC_PIVOT_MAX_MM : dr->last_lateral_mm;
    dr->last_lateral_ok = 0;
    dr->last_lateral_mm = pivot; /* kept for a U-turn's second quarter */
    if (q == 2 || q == -2) {
        maze_cell_t here = dr->st.mode == MOUSE_SEARCH ? dr->ex.cell : dr->st.cell;
        /* st.heading is the old one's opposite: its left is the old right */
        uint8_t cw = maze_passable(&dr->ex.map, here, (uint8_t)((dr->st.heading + 1) & 3), 1) &&
                     !maze_passable(&dr->ex.map, here, (uint8_t)((dr->st.heading + 3) & 3), 1);
        motion_turn_about(&dr->mo, cw ? -90.0f : 90.0f, pivot);
        dr->uturn_stage = (uint8_t)(cw ? 1u | UTURN_CW : 1u);
    } else {
        motion_turn_about(&dr->mo, -90.0f * q, pivot); /* a right turn (q = 1) is clockwise */
        dr->uturn_stage = 0;
    }
    dr->waiting = WAIT_TURN;
}

/* 1 when the turn started by drive_turn (all its stages) is over. */
int drive_turn_done(drive_t *dr)
{
    if (motion_busy(&dr->mo)) return 0;
    uint8_t cw = dr->uturn_stage & UTURN_CW;
    if ((dr->uturn_stage & ~UTURN_CW) == 1) {
        if (!drive_front_fix(dr)) return 0;
        dr->uturn_stage = (uint8_t)(3u | cw);
    }
    if ((dr->uturn_stage & ~UTURN_CW) == 3) {
        /* the first quarter about the centre left the robot the pivot's
         * offset right of this heading's centre line: about it again */
        motion_turn_about(&dr->mo, cw ? -90.0f : 90.0f, dr->last_lateral_mm);
        dr->uturn_stage = 4;
        return 0;
    }
    dr->uturn_stage = 0;
    return 1;
}

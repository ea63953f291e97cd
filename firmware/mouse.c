/* mouse.c - the contest: search until the run path is proven, back to the
 * start, then speed runs on the proven path until the time is up.
 *
 * Search moves cell by cell without stopping on straights: RC_SENSE_BEFORE_MM
 * before the centre of the cell ahead, the walls of that cell are read
 * (diagonal sensors for its sides, the front sensor for its far wall), the
 * map and the plan are updated, and the move is either extended by a cell
 * or ends at that cell's centre for an in-place turn. A wall ahead also
 * resets the distance to go (front-wall alignment). Speed runs drive each
 * straight of the proven path in one move at RC_RUN_MM_S.
 *
 * Hardware seam: everything here goes through hal.h; fw_tick runs from the
 * control interrupt, fw_loop from the main loop. */
#include "mouse.h"

#include <math.h>
#include <stdio.h>

#include "diagref.h"
#include "explore.h"
#include "hal.h"
#include "motion.h"
#include "plan.h"
#include "robot_config.h"
#include "slalom.h"
#include "walls.h"

/* the wall sensors, ToF or IR, as distances (walls.h) */
#define hal_distance walls_distance

static explore_t ex;
static motion_t mo;
static uint8_t configured;    /* fw_set_maze was called */
static uint8_t speed_runs = MOUSE_SPEED_RUNS; /* fw_set_speed_runs */
static mouse_status_t st;

/* what the loop is waiting for */
enum { WAIT_NONE, WAIT_MOVE, WAIT_TURN, WAIT_SMOOTH };
static uint8_t waiting;
/* the walls of the cell ahead during this move: not read yet, readings
 * marked at RC_SENSE_FROM_MM (tof_seq), read */
enum { SENSE_NONE, SENSE_MARKED, SENSE_DONE };
static uint8_t sensed;
static int8_t next_dir;       /* heading to take at the end of the move, -1 none */
static uint8_t wall_ahead;    /* the move ends facing a wall */
static int8_t turn_pending;   /* +-1: a smooth turn starts when the straight ends */
static uint8_t uturn_stage;   /* 0, or the step of a U-turn under way */
static uint32_t stage_us;     /* when the current U-turn step began */
static uint8_t fix_stage;     /* 0, or the step of a front-wall fix under way */
/* readings' seq when the current move began, or (sense_point) when it
 * came within RC_SENSE_FROM_MM of the cell ahead */
static uint8_t tof_seq[HAL_TOF_COUNT];
static float smooth_offset_mm; /* a smooth turn starts this far before the turn cell's centre */
static float smooth_length_mm; /* and drives this far along its arc */
static float run_offset_mm;   /* speed runs: how far past st.cell's centre the robot is */
static float move_shift_mm;   /* the move under way ends this far before a cell centre */
static uint8_t side_seq[2];   /* centring: the side readings last looked at, */
static int16_t side_dmm[2];   /* the offsets right of the centre line they give, 0.1 mm */
static uint8_t side_ok[2];    /* and whether they show a wall where it can be trusted */
static uint8_t front_seq;     /* front-wall alignment: the reading last used */
static float last_lateral_mm; /* the last centring estimate of this straight, */
static uint8_t last_lateral_ok; /* if there was one */
static uint32_t start_us;
static uint8_t end_said; /* 1 once "contest done: ..." is logged for a search that ended early */

/* The map is set up here rather than copied: a second maze_t would cost
 * 292 of the ATmega328P's 2048 bytes of SRAM. */
void fw_set_maze(const struct maze_s *m)
{
    explore_init(&ex, m);
    configured = 1;
}

void fw_set_speed_runs(uint8_t runs) { speed_runs = runs ? runs : 1; }

const mouse_status_t *mouse_status(void) { return &st; }

static void log_line(const char *fmt, unsigned a, unsigned b) /* fmt: HAL_STR("...") */
{
    char line[HAL_LOG_MAX + 1];
    hal_snprintf(line, sizeof line, fmt, a, b); /* fmt: a HAL_STR */
    hal_log(line);
}

/* The contest's maze as the backend announces it (hal_maze), else a
 * classic contest: 16x16, the centre goal; built in place in ex.map (a
 * maze_t on the stack would cost 292 B of the AVR's 2 KB): explore_init
 * on its own map keeps only the size, so the goal and start follow it. */
static void contest_maze(void)
{
    hal_maze_t a;
    uint8_t ok = hal_maze(&a) && a.start_x < a.width && a.start_y < a.height && maze_init(&ex.map, a.width, a.height) == 0;
    if (!ok) maze_init(&ex.map, 16, 16);
    explore_init(&ex, &ex.map);
    if (!ok || maze_set_goal_rect(&ex.map, a.goal_x0, a.goal_y0, a.goal_x1, a.goal_y1) != 0) return;
    ex.cell = ex.map.start = maze_cell(&ex.map, a.start_x, a.start_y);
    ex.heading = ex.map.start_heading = a.start_heading & 3u;
}

void fw_setup(void)
{
    if (!configured) contest_maze();
    configured = 0; /* the next fw_setup without fw_set_maze is a classic contest */
    motion_init(&mo);
    walls_setup();
    st.mode = MOUSE_SEARCH;
    st.runs = 0;
    st.cell = ex.cell;
    st.heading = ex.heading;
    waiting = WAIT_NONE;
    sensed = SENSE_NONE;
    next_dir = -1;
    uturn_stage = 0;
    fix_stage = 0;
    turn_pending = 0;
    run_offset_mm = 0;
    motion_smooth_geometry(RC_SMOOTH_MM_S, &smooth_offset_mm, &smooth_length_mm);
    start_us = hal_micros();
    end_said = 0;
}

void fw_tick(void)
{
    motion_tick(&mo, 1.0f / HAL_TICK_HZ);
    if (mo.crashed && st.mode != MOUSE_CRASHED) st.mode = MOUSE_CRASHED;
}

/* Relative quarter turns from heading h to heading d: 0, 1 (right), 2, -1. */
static int8_t quarter(uint8_t h, uint8_t d)
{
    int8_t q = (int8_t)((d - h) & 3);
    return q == 3 ? -1 : q;
}

/* fw_loop runs with the control tick held off (hal_tick_hold): it reads
 * and changes the motion state fw_tick drives. A flood (explore_next:
 * 30-200 ms on a 16 MHz AVR) touches only the map, and the tick runs
 * meanwhile. */
static int explore_next_ticking(void)
{
    hal_tick_release();
    int d = explore_next(&ex);
    hal_tick_hold();
    return d;
}

/* Walls of the cell ahead, read from the sensors (EXPLORE_WALL_* bits);
 * to_centre: mm from the robot to that cell's centre. */
static uint8_t read_walls(float to_centre)
{
    uint8_t w = 0;
    hal_distance_t l = hal_distance(HAL_TOF_LEFT), f = hal_distance(HAL_TOF_FRONT), r = hal_distance(HAL_TOF_RIGHT);
    /* the far wall of the cell ahead is RC_FRONT_AT_CENTRE_MM beyond its centre */
    if (!f.timeout && f.mm < to_centre + RC_FRONT_AT_CENTRE_MM + RC_FRONT_WALL_MARGIN_MM) w |= EXPLORE_WALL_FRONT;
    if (!l.timeout && l.mm < RC_SIDE_THRESHOLD_MM) w |= EXPLORE_WALL_LEFT;
    if (!r.timeout && r.mm < RC_SIDE_THRESHOLD_MM) w |= EXPLORE_WALL_RIGHT;
    return w;
}

/* Where the robot is along its heading relative to the nearest cell
 * centre, mm (negative before it), from the move under way: its end lies
 * move_shift_mm before a cell centre. */
static float along_cell(void)
{
    float y = -fmodf(profile_remaining(&mo.fwd) + move_shift_mm, RC_CELL_MM); /* (-180, 0] */
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
static int clear_of_entry_post(uint8_t right, float to_centre)
{
    float psi = mo.odom.theta_rad - mo.heading_rad, s = right ? -psi : psi, cs = cosf(s), sn = sinf(s);
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
static void centring(void)
{
    float y = along_cell();
    /* and not from a creep or a stop: the rays meet the wall ahead then */
    uint8_t usable = (y < -RC_SIDE_BLIND_FROM_MM || y > RC_SIDE_BLIND_TO_MM) && mo.fwd.speed > RC_CENTRING_MIN_MM_S,
            news = 0;
    for (uint8_t i = 0; i < 2; i++) {
        uint8_t sensor = i ? HAL_TOF_RIGHT : HAL_TOF_LEFT;
        hal_distance_t d = hal_distance(sensor);
        if (d.seq == side_seq[i]) continue;
        side_seq[i] = d.seq;
        news = 1;
        side_ok[i] = usable && !d.timeout && d.mm < RC_CENTRING_MAX_MM;
        side_dmm[i] = (int16_t)(10.0f * side_offset((float)d.mm, mo.odom.theta_rad - mo.heading_rad, i));
        /* not fresh for the walls of the cell ahead if it may be its entry post */
        if (sensed == SENSE_MARKED && !clear_of_entry_post(i, profile_remaining(&mo.fwd) + move_shift_mm)) tof_seq[sensor] = d.seq;
    }
    float el = 0.1f * (float)side_dmm[0], er = 0.1f * (float)side_dmm[1];
    mo.lateral_mm = side_ok[0] && side_ok[1] ? 0.5f * (el + er) : side_ok[0] ? el : side_ok[1] ? er : 0.0f;
    mo.lateral_valid = (uint8_t)(side_ok[0] || side_ok[1]);
    if (mo.lateral_valid && news) { /* averaged over the last few readings for start_turn */
        last_lateral_mm = last_lateral_ok ? last_lateral_mm + RC_PIVOT_AVG * (mo.lateral_mm - last_lateral_mm) : mo.lateral_mm;
        last_lateral_ok = 1;
    }
}

static void no_centring(void) { mo.lateral_valid = 0; }

/* With a wall ahead, move the end of the move towards what the front
 * sensor says (removes the odometry error of the straight). The move ends
 * `before_mm` short of the centre of the cell with that wall: 0 for a stop,
 * the smooth-turn offset for a turn. Each reading is used once, when it
 * arrives (it is exact then; 30 ms later the robot has moved up to 33 mm),
 * and only if taken during this straight (not while turning into it). The
 * sensor's noise is 5 % of the distance (6 mm at 120 mm), so each reading
 * moves the end by RC_ALIGN_GAIN of the difference. */
static void align_to_front_wall(float before_mm)
{
    hal_distance_t f = hal_distance(HAL_TOF_FRONT);
    if (f.seq == front_seq) return;
    front_seq = f.seq;
    float left = profile_remaining(&mo.fwd);
    if (f.timeout || left > RC_ALIGN_FROM_MM) return;
    float by_sensor = (float)f.mm - RC_FRONT_AT_CENTRE_MM - before_mm;
    if (by_sensor > left - 20.0f && by_sensor < left + 20.0f)
        profile_set_remaining(&mo.fwd, left + RC_ALIGN_GAIN * (by_sensor - left));
}

/* Standing at a cell centre before a wall: the diagonal rays meet that
 * wall too, and their two readings give the robot's angle to it
 * (motion_wall_angle). The held heading moves towards the wall's normal by
 * 1 / (n + RC_WALL_HEADING_PRIOR) for the n-th reading of this stop, which
 * averages the readings (one has ~0.9 degrees of noise) with what the held
 * heading knew before. This is the only heading reference away from side
 * walls: odometry loses ~0.2 degrees per in-place quarter turn. */
static void wall_heading(uint8_t n)
{
    hal_distance_t l = hal_distance(HAL_TOF_LEFT), r = hal_distance(HAL_TOF_RIGHT), f = hal_distance(HAL_TOF_FRONT);
    if (l.timeout || r.timeout || f.timeout) return;
    float off = (float)f.mm - RC_FRONT_AT_CENTRE_MM;
    if (off > RC_WALL_HEADING_NEAR_MM || off < -RC_WALL_HEADING_NEAR_MM) return; /* rays may meet a side wall */
    float a = motion_wall_angle((float)l.mm, (float)r.mm);
    if (a > RC_WALL_HEADING_MAX_RAD || a < -RC_WALL_HEADING_MAX_RAD) return;
    mo.heading_rad += (mo.odom.theta_rad - a - mo.heading_rad) / ((float)n + RC_WALL_HEADING_PRIOR);
}

/* Standing before a wall: wait for a fresh front reading (>= 35 ms: the
 * sensor updates every 30 ms), then creep to RC_FRONT_AT_CENTRE_MM from it.
 * Puts the robot on the cell's centre along its heading to +-2 mm before it
 * turns on the spot. Then RC_WALL_HEADING_READS fresh readings (the first
 * one's taken before any creep) square the heading to the wall
 * (wall_heading). Returns 1 when done. */
static int front_fix(void)
{
    if (motion_busy(&mo)) return 0;
    if (fix_stage == 0) {
        stage_us = hal_micros();
        fix_stage = 1;
        return 0;
    }
    if (fix_stage == 1) {
        if (hal_micros() - stage_us < 35000u) return 0;
        hal_distance_t f = hal_distance(HAL_TOF_FRONT);
        float adjust = (float)f.mm - RC_FRONT_AT_CENTRE_MM;
        wall_heading(1);
        fix_stage = 2;
        if (!f.timeout && adjust > -30.0f && adjust < 30.0f && (adjust > 2.0f || adjust < -2.0f)) {
            motion_forward(&mo, adjust, 200.0f, 0.0f);
            return 0;
        }
    }
    if (fix_stage == 2 && RC_WALL_HEADING_READS > 1) {
        stage_us = hal_micros();
        fix_stage = 3;
        return 0;
    }
    if (fix_stage >= 3) { /* reading fix_stage - 1 of RC_WALL_HEADING_READS */
        if (hal_micros() - stage_us < 35000u) return 0;
        wall_heading((uint8_t)(fix_stage - 1));
        if (fix_stage <= RC_WALL_HEADING_READS) {
            stage_us = hal_micros();
            fix_stage++;
            return 0;
        }
    }
    fix_stage = 0;
    return 1;
}

/* Remember the sensors' reading counts: fresh() is true once each has
 * delivered a reading taken after this moment. */
static void mark_readings(void)
{
    for (uint8_t i = 0; i < HAL_TOF_COUNT; i++) tof_seq[i] = hal_distance(i).seq;
    side_seq[0] = tof_seq[HAL_TOF_LEFT];
    side_seq[1] = tof_seq[HAL_TOF_RIGHT];
    side_ok[0] = side_ok[1] = 0;
    front_seq = tof_seq[HAL_TOF_FRONT];
    last_lateral_ok = 0;
}

static int fresh(void)
{
    for (uint8_t i = 0; i < HAL_TOF_COUNT; i++)
        if (hal_distance(i).seq == tof_seq[i]) return 0;
    return 1;
}

/* A move reached the point where the walls of the cell ahead are read:
 * within RC_SENSE_BEFORE_MM of the move's end with readings taken within
 * RC_SENSE_FROM_MM of it (the side ones clear of the cell's entry post:
 * centring), or RC_SENSE_LATEST_MM at the latest; once per cell. */
static int sense_point(float left_mm)
{
    if (sensed == SENSE_DONE) return 0;
    if (sensed == SENSE_NONE && left_mm <= RC_SENSE_FROM_MM) {
        for (uint8_t i = 0; i < HAL_TOF_COUNT; i++) tof_seq[i] = hal_distance(i).seq;
        sensed = SENSE_MARKED;
    }
    return left_mm <= RC_SENSE_BEFORE_MM && (fresh() || left_mm <= RC_SENSE_LATEST_MM);
}

/* Read the walls of the cell ahead (its centre to_centre mm away) into the
 * map, committed to entering it (search and command mode). Returns the
 * walls (EXPLORE_WALL_*). */
static uint8_t sense_cell_ahead(float to_centre)
{
    sensed = SENSE_DONE;
    uint8_t walls = read_walls(to_centre);
    explore_moved(&ex, st.heading); /* committed to the cell ahead */
    explore_sense(&ex, walls);
    return walls;
}

static void start_forward(float mm, float speed, float v_end, float accel)
{
    motion_forward_accel(&mo, mm, speed, v_end, accel);
    waiting = WAIT_MOVE;
    sensed = SENSE_NONE;
    wall_ahead = 0;
    turn_pending = 0;
    move_shift_mm = 0;
    mark_readings();
}

/* The straight before a smooth turn is over: turn, keeping the speed. */
static void start_smooth(void)
{
    motion_forward_accel(&mo, smooth_length_mm, RC_SMOOTH_MM_S, RC_SMOOTH_MM_S, RC_ACCEL_MM_S2);
    motion_turn_smooth(&mo, -90.0f * turn_pending); /* a right turn (+1) is clockwise */
    no_centring();
    turn_pending = 0;
    waiting = WAIT_SMOOTH;
}

/* On the straight before a smooth turn: align on the wall ahead (the turn
 * starts the smooth-turn offset before that cell's centre), turn at its end. */
static void approach_turn(void)
{
    if (wall_ahead) align_to_front_wall(smooth_offset_mm);
    if (!mo.fwd.active) start_smooth();
}

/* A turn on the spot; a U-turn is two quarter turns with a stop between,
 * facing a side wall of the cell, where the front sensor puts the robot
 * back on the cell's centre line and the diagonal ones square it up (7 mm
 * of clearance for the body's corners sweeping round: the offset from the
 * straight must go first). The U-turn turns left first, unless only the
 * right wall is known to be there. st.heading is already the heading the
 * turn ends on. */
#define UTURN_CW 0x80u /* uturn_stage flag: a clockwise U-turn */
static void start_turn(int8_t q)
{
    /* off the centre line by more than the noise: turn about the centre */
    float pivot = 0;
    if (last_lateral_ok && (last_lateral_mm > 1.5f || last_lateral_mm < -1.5f))
        pivot = last_lateral_mm > RC_PIVOT_MAX_MM ? RC_PIVOT_MAX_MM
              : last_lateral_mm < -RC_PIVOT_MAX_MM ? -RC_PIVOT_MAX_MM : last_lateral_mm;
    last_lateral_ok = 0;
    last_lateral_mm = pivot; /* kept for a U-turn's second quarter */
    if (q == 2 || q == -2) {
        maze_cell_t here = st.mode == MOUSE_SEARCH ? ex.cell : st.cell;
        /* st.heading is the old one's opposite: its left is the old right */
        uint8_t cw = maze_passable(&ex.map, here, (uint8_t)((st.heading + 1) & 3), 1) &&
                     !maze_passable(&ex.map, here, (uint8_t)((st.heading + 3) & 3), 1);
        motion_turn_about(&mo, cw ? -90.0f : 90.0f, pivot);
        uturn_stage = (uint8_t)(cw ? 1u | UTURN_CW : 1u);
    } else {
        motion_turn_about(&mo, -90.0f * q, pivot); /* a right turn (q = 1) is clockwise */
        uturn_stage = 0;
    }
    waiting = WAIT_TURN;
}

/* 1 when the turn started by start_turn (all its stages) is over. */
static int turn_done(void)
{
    if (motion_busy(&mo)) return 0;
    uint8_t cw = uturn_stage & UTURN_CW;
    if ((uturn_stage & ~UTURN_CW) == 1) {
        if (!front_fix()) return 0;
        uturn_stage = (uint8_t)(3u | cw);
    }
    if ((uturn_stage & ~UTURN_CW) == 3) {
        /* the first quarter about the centre left the robot the pivot's
         * offset right of this heading's centre line: about it again */
        motion_turn_about(&mo, cw ? -90.0f : 90.0f, last_lateral_mm);
        uturn_stage = 4;
        return 0;
    }
    uturn_stage = 0;
    return 1;
}

/* Search, at the sensing point of the cell ahead (`left` mm of the move
 * to go): its walls sensed and the next direction decided: straight on
 * (the move extended by a cell), a smooth quarter turn at the turn's start,
 * or a stop in the cell ahead (next_dir; -1: explore has ended). */
static void search_decide(float left)
{
    uint8_t walls = sense_cell_ahead(left);
    log_line(HAL_STR("sensed cell %u walls %u"), ex.cell, walls);
    hal_belief(&ex.map, ex.cell, st.heading, st.mode);
    /* planning takes 30-200 ms on a 16 MHz AVR (no time in the
     * simulator): meanwhile the move brakes into the cell ahead (from
     * 60 mm before it at search speed) instead of running on */
    float v_end = mo.fwd.v_end;
    mo.fwd.v_end = 0;
    int d = explore_next_ticking();
    left = profile_remaining(&mo.fwd); /* where the robot is now */
    wall_ahead = (walls & EXPLORE_WALL_FRONT) != 0;
    if (d >= 0 && (uint8_t)d == st.heading && mo.fwd.active) {
        mo.fwd.v_end = v_end;
        profile_set_remaining(&mo.fwd, left + RC_CELL_MM);
        sensed = SENSE_NONE;
        return;
    }
    int8_t q = d >= 0 ? quarter(st.heading, (uint8_t)d) : 0;
    if ((q == 1 || q == -1) && left >= smooth_offset_mm + 1.0f) {
        /* go on to the turn's start, slowing to the turn's speed,
         * and turn there without stopping */
        mo.fwd.v_end = v_end < RC_SMOOTH_MM_S ? v_end : RC_SMOOTH_MM_S;
        profile_set_remaining(&mo.fwd, left - smooth_offset_mm);
        move_shift_mm = smooth_offset_mm;
        turn_pending = q;
        st.heading = (uint8_t)d;
        return;
    }
    next_dir = (int8_t)d; /* stop in the cell ahead */
}

/* Search: decide at the sensing point of each cell. st.heading is the way
 * the robot faces (or will face once a pending turn is made); ex.cell is
 * the cell it is in or committed to. */
static void search_step(void)
{
    if (waiting == WAIT_NONE) {
        /* standing at a cell centre: the start (or after the last stop) */
        if (ex.steps == 0 && ex.phase == EXPLORE_TO_GOAL) {
            hal_distance_t f = hal_distance(HAL_TOF_FRONT);
            /* the start cell: by the rules open only ahead */
            uint8_t w = EXPLORE_WALL_LEFT | EXPLORE_WALL_RIGHT;
            if (!f.timeout && f.mm < RC_FRONT_AT_CENTRE_MM + 60) w |= EXPLORE_WALL_FRONT;
            explore_sense(&ex, w);
        }
        int d = explore_next_ticking();
        if (d < 0) {
            st.mode = ex.phase == EXPLORE_DONE ? MOUSE_TO_RUN : MOUSE_NO_GOAL;
            return;
        }
        int8_t q = quarter(st.heading, (uint8_t)d);
        st.heading = (uint8_t)d;
        if (q) start_turn(q);
        else start_forward(RC_CELL_MM + (ex.steps ? 0.0f : RC_START_BEHIND_MM), RC_SEARCH_MM_S, RC_SEARCH_MM_S, RC_ACCEL_MM_S2);
        return;
    }
    if (waiting == WAIT_TURN) {
        if (!turn_done()) return;
        start_forward(RC_CELL_MM, RC_SEARCH_MM_S, RC_SEARCH_MM_S, RC_ACCEL_MM_S2);
        return;
    }
    if (waiting == WAIT_SMOOTH) {
        if (mo.rot.active) return;
        /* on the new heading, the offset past the turn cell's centre */
        start_forward(RC_CELL_MM - smooth_offset_mm, RC_SEARCH_MM_S, RC_SEARCH_MM_S, RC_ACCEL_MM_S2);
        return;
    }
    /* WAIT_MOVE */
    centring();
    if (turn_pending) {
        approach_turn();
        return;
    }
    float left = profile_remaining(&mo.fwd);
    if (sense_point(left)) {
        search_decide(left);
        return;
    }
    if (sensed == SENSE_DONE && wall_ahead && mo.fwd.active) align_to_front_wall(0);
    if (sensed == SENSE_DONE && !motion_busy(&mo)) {
        no_centring();
        if (wall_ahead && !front_fix()) return;
        if (next_dir < 0) {
            waiting = WAIT_NONE; /* explore has ended: the next call sees it */
            return;
        }
        int8_t q = quarter(st.heading, (uint8_t)next_dir);
        st.heading = (uint8_t)next_dir;
        start_turn(q);
    }
}

#if PLAN_ENABLED
/* ---- Speed runs on plan_run's moves: orthogonal straights (centred on
 * the side walls as above), diagonal straights (odometry's heading held:
 * no side walls there) and slaloms, each turn kind at its own speed
 * (slalom.h). Each turn's straight before it (slalom_drive_t before_mm) is
 * driven as part of the straight move ahead of it, its straight after as
 * part of the one behind it; between two turns those two alone make a
 * straight from one turn's speed to the next's (plan.h's cost). The run tracks the node each move ends on in half units
 * (slalom.h's grid) and its heading in eighths, to tell where the walls
 * ahead and the cell centres are. ---- */
static slalom_move_t run_moves[PLAN_MAX_MOVES];
static slalom_drive_t run_drive[SLALOM_KINDS];
static int16_t run_count;     /* moves of this run; 0: the orthogonal run (run_plan) */
static int16_t run_idx;       /* the next move to start */
static int16_t run_x2, run_y2; /* the node the moves so far end on, half units */
static uint8_t run_h8;        /* the heading there, eighths clockwise from north */
static float run_carry_mm;    /* the last turn's straight after it, not driven yet */
static uint8_t run_turn_next; /* the straight under way leads into the turn run_moves[run_idx] */
static uint8_t run_ortho;     /* the straight under way is orthogonal: centring */
static float run_v_turn[SLALOM_KINDS]; /* each turn kind's speed this run, mm/s */
static float run_v_diag;
static float run_v_max, run_accel; /* this run's cruise speed (mm/s) and acceleration (mm/s^2) */
static float run_err_mm;      /* the largest tracking error of this run */
static uint8_t run_dirty;     /* the last run's tracking error reached RC_RUN_CLEAN_MM */
static float run_align_mm;    /* a wall ahead: the straight ends this far before its cell's centre */

/* the cell whose centre is the node (x2, y2) */
static maze_cell_t run_cell(int16_t x2, int16_t y2)
{
    return maze_cell(&ex.map, (uint8_t)(x2 / 2), (uint8_t)(y2 / 2)); /* a cell centre: both even */
}

/* The node and heading after the move mv from the node (*x2, *y2)
 * heading *h8 (half units; eighths clockwise from north). */
static void move_pose(const slalom_move_t *mv, int16_t *x2, int16_t *y2, uint8_t *h8)
{
    if (mv->kind == SLALOM_ORTHO || mv->kind == SLALOM_DIAG) {
        *x2 = (int16_t)(*x2 + mv->n * slalom_step_x[*h8]);
        *y2 = (int16_t)(*y2 + mv->n * slalom_step_y[*h8]);
        return;
    }
    const slalom_geom_t *g = &slalom_geom[mv->kind];
    int dx, dy;
    slalom_place(g->exit_x, g->exit_y, g->from_diag, mv->dir, *h8, &dx, &dy);
    *x2 = (int16_t)(*x2 + dx);
    *y2 = (int16_t)(*y2 + dy);
    *h8 = (uint8_t)((*h8 + mv->dir * g->turn) & 7u);
}

#ifdef RC_DIAG_AFTER_TURN_HALVES
/* Whether the diagonals of a plan start where the robot knows where it
 * is, for a robot with room to spare on a diagonal (robot_ukmarsbot.h):
 * any turn may enter one, V90s join them; the half steps driven on
 * diagonals from an F45 or F135 to the turn back to an orthogonal heading
 * are at most RC_DIAG_MAX_HALVES where that entry follows an orthogonal
 * straight of at least RC_DIAG_ENTRY_HALVES (centred on its side walls),
 * else at most RC_DIAG_AFTER_TURN_HALVES (the heading the turns before it
 * left is held blind); that D45 or D135 leads into such a straight (the
 * robot centred again before its next turn or stop). */
static int prun_diag_ok(int n)
{
    int limit = 0, driven = 0;
    for (int i = 0; i < n; i++) {
        const slalom_move_t *mv = &run_moves[i];
        if (mv->kind == SLALOM_F45 || mv->kind == SLALOM_F135) {
            int centred = i > 0 && run_moves[i - 1].kind == SLALOM_ORTHO && run_moves[i - 1].n >= RC_DIAG_ENTRY_HALVES;
            limit = centred ? RC_DIAG_MAX_HALVES : RC_DIAG_AFTER_TURN_HALVES;
            driven = 0;
        } else if (mv->kind == SLALOM_DIAG) {
            driven += mv->n;
            if (driven > limit) return 0;
        } else if ((mv->kind == SLALOM_D45 || mv->kind == SLALOM_D135) &&
                   (i + 1 >= n || run_moves[i + 1].kind != SLALOM_ORTHO || run_moves[i + 1].n < RC_DIAG_ENTRY_HALVES)) {
            return 0;
        }
    }
    return 1;
}
#else
/* Whether the diagonals of a plan start where the robot knows where it
 * is: each entered by an F45 at the end of an orthogonal straight of at
 * least RC_DIAG_ENTRY_HALVES (centred on its side walls) and left by a D45
 * into one as long (centred again before the next turn), none longer than
 * RC_DIAG_MAX_HALVES, no lane change (an F45 straight into a D45: with
 * 3.2 mm to the posts it touched on alljapan-012-1991-exp-fin, seed 1),
 * and no V90, F135 or D135 (turns between diagonals, or into one from a
 * turn). */
static int prun_diag_ok(int n)
{
    for (int i = 0; i < n; i++) {
        const slalom_move_t *mv = &run_moves[i];
        if (mv->kind == SLALOM_V90 || mv->kind == SLALOM_F135 || mv->kind == SLALOM_D135) return 0;
        if (mv->kind == SLALOM_DIAG && mv->n > RC_DIAG_MAX_HALVES) return 0;
        if (mv->kind == SLALOM_F45 && (i == 0 || run_moves[i - 1].kind != SLALOM_ORTHO || run_moves[i - 1].n < RC_DIAG_ENTRY_HALVES))
            return 0;
        if (mv->kind == SLALOM_D45 && (i == 0 || run_moves[i - 1].kind != SLALOM_DIAG || i + 1 >= n ||
                                       run_moves[i + 1].kind != SLALOM_ORTHO || run_moves[i + 1].n < RC_DIAG_ENTRY_HALVES))
            return 0;
    }
    return 1;
}
#endif

#ifdef RC_BLIND_MAX_HALVES
/* The orthogonal straight of n half units from the node (x2, y2) heading
 * h8 (even): the half units at its end with no known wall on either side,
 * since the last one with a wall (centring holds nothing there: the robot
 * drives on the heading odometry kept from the turns before it), and in
 * *walled the half units with one. Each half unit lies in the cell of the
 * one of its two nodes that is a cell centre. */
static int prun_blind_halves(int16_t x2, int16_t y2, uint8_t h8, int n, int *walled)
{
    uint8_t d = (uint8_t)(h8 >> 1);
    int run = 0;
    *walled = 0;
    for (int k = 0; k < n; k++) {
        int16_t nx = (int16_t)(x2 + slalom_step_x[h8]), ny = (int16_t)(y2 + slalom_step_y[h8]);
        maze_cell_t c = ((x2 | y2) & 1) ? run_cell(nx, ny) : run_cell(x2, y2);
        int w = maze_wall(&ex.map, c, (uint8_t)((d + 1u) & 3u)) == MAZE_WALL_CLOSED ||
                maze_wall(&ex.map, c, (uint8_t)((d + 3u) & 3u)) == MAZE_WALL_CLOSED;
        *walled += w;
        run = w ? 0 : run + 1;
        x2 = nx;
        y2 = ny;
    }
    return run;
}

/* Whether the S90 entered at the node (x2, y2) heading h8 turns in a cell
 * with a wall ahead (prun_straight: the straight into it aligns on it). */
static int prun_s90_walled(int16_t x2, int16_t y2, uint8_t h8)
{
    if (!((x2 | y2) & 1)) return 0;
    maze_cell_t c = run_cell((int16_t)(x2 + slalom_step_x[h8]), (int16_t)(y2 + slalom_step_y[h8]));
    return !maze_passable(&ex.map, c, (uint8_t)(h8 >> 1), 0);
}

/* Whether a plan takes the robot out of each orthogonal straight that ends
 * with more than RC_BLIND_MAX_HALVES half units without side walls into at
 * most RC_BLIND_MAX_TURNS turns entered across that straight's line
 * before the offset it drifted across that line is measured again: by a
 * wall ahead of such a turn (an S90's straight aligns on it) or by
 * centring on a straight along that line (RC_DIAG_ENTRY_HALVES half units
 * with side walls). Off that straight's line the offset is an error along
 * the robot's way, which sets where each turn starts. */
static int prun_blind_ok(int n)
{
    int16_t x2 = (int16_t)(2 * maze_x(&ex.map, ex.map.start)), y2 = (int16_t)(2 * maze_y(&ex.map, ex.map.start));
    uint8_t h8 = (uint8_t)(2u * ex.map.start_heading);
    int axis = -1, turns = 0; /* the drifted straight's axis (h8 >> 1 & 1), -1: none */
    for (int i = 0; i < n; i++) {
        const slalom_move_t *mv = &run_moves[i];
        uint8_t ax = (uint8_t)((h8 >> 1) & 1u), ortho = !(h8 & 1u);
        if (mv->kind == SLALOM_ORTHO || mv->kind == SLALOM_DIAG) {
            int walled = 0, blind = mv->kind == SLALOM_ORTHO ? prun_blind_halves(x2, y2, h8, mv->n, &walled) : 0;
            if (axis == ax && ortho && walled >= RC_DIAG_ENTRY_HALVES) axis = -1;
            if (blind > RC_BLIND_MAX_HALVES && i + 1 < n) axis = ax, turns = 0;
        } else if (axis >= 0 && ortho && ax != axis) {
            if (mv->kind == SLALOM_S90 && prun_s90_walled(x2, y2, h8)) axis = -1;
            else if (++turns > RC_BLIND_MAX_TURNS) return 0;
        }
        move_pose(mv, &x2, &y2, &h8);
    }
    return 1;
}
#endif

/* This run's turns (each kind at its own speed, RC_SLALOM_*_MM_S) and the
 * planner's costs for them: each turn's legs are driven with the straights
 * beside it (prun_straight), its arc at its speed (prun_turn). */
static void prun_turns(uint8_t fast, float ff_max, plan_costs_t *c)
{
    float whole_s[SLALOM_KINDS];
    slalom_run_speeds(fast, run_v_turn);
    slalom_fit_kinds(run_v_turn, ff_max, run_drive, whole_s);
    for (uint8_t k = 0; k < SLALOM_KINDS; k++) {
        c->v_turn_mm_s[k] = run_v_turn[k];
        c->before_mm[k] = run_drive[k].before_mm;
        c->after_mm[k] = run_drive[k].after_mm;
        c->turn_s[k] = whole_s[k] > 0 ? run_drive[k].arc_mm / run_v_turn[k] : -1.0f;
    }
}

/* At the start of a speed run: the moves (run_count 0 if plan_run finds
 * none: the orthogonal run then), at the safe speeds (cruise, acceleration,
 * turns, diagonals) on the first run and after one whose tracking error
 * reached RC_RUN_CLEAN_MM, else the fast: the runs climb from the safe to
 * the fast figures and fall back after a run that was not clean. */
static void prun_begin(void)
{
    run_count = 0;
    if (!RC_DIAG_RUNS) return;
    uint8_t fast = st.runs > 0 && !run_dirty;
    plan_costs_t c;
    c.cell_mm = RC_CELL_MM;
    c.v_diag_mm_s = run_v_diag = fast ? RC_DIAG_FAST_MM_S : RC_DIAG_SAFE_MM_S;
    c.v_max_mm_s = run_v_max = fast ? RC_RUN_FAST_MM_S : RC_RUN_MM_S;
    c.accel_mm_s2 = run_accel = fast ? RC_RUN_FAST_ACCEL_MM_S2 : RC_RUN_ACCEL_MM_S2;
    float ff_max = fast ? RC_RUN_FAST_CMD_FF_MAX : RC_CMD_FF_MAX;
    prun_turns(fast, ff_max, &c);
    float t_s;
    int n = plan_run(&ex.map, &c, run_moves, PLAN_MAX_MOVES, &t_s);
    if (n > 0 && !prun_diag_ok(n)) { /* the same without diagonals */
        c.turn_s[SLALOM_F45] = c.turn_s[SLALOM_F135] = c.turn_s[SLALOM_D45] = c.turn_s[SLALOM_D135] = c.turn_s[SLALOM_V90] = -1;
        n = plan_run(&ex.map, &c, run_moves, PLAN_MAX_MOVES, &t_s);
    }
#ifdef RC_BLIND_MAX_HALVES
    if (n > 0 && !prun_blind_ok(n)) {
        log_line(HAL_STR("run %u: orthogonal (a blind straight, a turn)"), st.runs + 1u, 0);
        return;
    }
#endif
    if (n <= 0) return;
    mo.ff_max_cmd = ff_max; /* until prun_end */
    unsigned diag = 0;
    for (int i = 0; i < n; i++) diag += run_moves[i].kind == SLALOM_DIAG || run_moves[i].kind >= SLALOM_F45;
    char line[HAL_LOG_MAX + 1];
    hal_snprintf(line, sizeof line, HAL_STR("run %u: %u moves, %u diagonal, %u mm/s turns"), st.runs + 1u, (unsigned)n, diag, (unsigned)run_v_turn[SLALOM_S90]);
    hal_log(line);
    run_count = (int16_t)n;
    run_idx = 0;
    run_x2 = (int16_t)(2 * maze_x(&ex.map, ex.map.start));
    run_y2 = (int16_t)(2 * maze_y(&ex.map, ex.map.start));
    run_h8 = (uint8_t)(2u * ex.map.start_heading);
    run_carry_mm = 0;
    run_turn_next = 0;
    run_err_mm = 0;
}

/* The diagonal reference (RC_DIAG_TOF, diagref.h): the robot's position in
 * the maze (mm from the outer corner of cell (0, 0), x east, y north) is
 * dg_p plus odometry's travel since the diagonal began, turned into the
 * maze's frame by dg_psi; dg_p starts where the plan has the robot then and
 * each trusted side reading moves it. On a diagonal the left sensor looks
 * along one maze axis and the right one along the other, so the estimate's
 * x and y are two independent one-dimensional Kalman filters (variance
 * dg_var: RC_DIAG_TOF_START_MM at the start, growing by
 * RC_DIAG_TOF_DRIFT_MM2 per mm driven; a reading's variance (RC_TOF_CV x
 * its distance)^2). */
static float dg_px, dg_py;    /* the estimate at the diagonal's start, mm */
static float dg_ox, dg_oy;    /* odometry's position then, mm */
static float dg_psi;          /* the maze's frame turned from odometry's, rad */
static float dg_lx, dg_ly;    /* a point of the diagonal's line, mm */
static float dg_a;            /* its heading, rad counter-clockwise from east */
static uint8_t dg_seq[2];     /* the side readings last looked at */
static float dg_var[2];       /* the variance of dg_px and dg_py, mm^2 */
static float dg_dist_mm;      /* odometry's distance when they last grew */

/* A diagonal straight starts from the node (x2, y2) (half units: cell
 * (x, y)'s centre at (2x, 2y)) heading h8 (eighths clockwise from north),
 * the robot carry_mm short of it (a speed run: a turn's straight after
 * it): the reference's starting point. Speed runs and command mode's
 * diagonals (cmd_diagonal). */
static void diag_anchor(int16_t x2, int16_t y2, uint8_t h8, float carry_mm)
{
    float a = 1.5707963f - 0.7853982f * (float)h8; /* the heading, counter-clockwise from east */
    dg_lx = (float)(x2 + 1) * (RC_CELL_MM / 2);
    dg_ly = (float)(y2 + 1) * (RC_CELL_MM / 2);
    dg_px = dg_lx - carry_mm * cosf(a);
    dg_py = dg_ly - carry_mm * sinf(a);
    dg_ox = mo.odom.x_mm;
    dg_oy = mo.odom.y_mm;
    dg_psi = a - 1.5707963f - mo.heading_rad;
    dg_a = a;
    dg_var[0] = dg_var[1] = RC_DIAG_TOF_START_MM * RC_DIAG_TOF_START_MM;
    dg_dist_mm = mo.odom.dist_mm;
    dg_seq[0] = hal_distance(HAL_TOF_LEFT).seq;
    dg_seq[1] = hal_distance(HAL_TOF_RIGHT).seq;
}

/* On a diagonal straight: each new side reading that diagref_expect
 * trusts (and within RC_DIAG_TOF_GATE_MM of it) moves the position
 * estimate along the sensor's axis by the filter's gain times the
 * difference; the estimate's offset right of the diagonal's line steers
 * (mo.lateral_mm) as wall centring does. */
static void diag_centring(void)
{
    float cp = cosf(dg_psi), sp = sinf(dg_psi), dx = mo.odom.x_mm - dg_ox, dy = mo.odom.y_mm - dg_oy;
    float px = dg_px + cp * dx - sp * dy, py = dg_py + sp * dx + cp * dy;
    float b = 1.5707963f + mo.odom.theta_rad + dg_psi, cb = cosf(b), sb = sinf(b);
    float grow = RC_DIAG_TOF_DRIFT_MM2 * (mo.odom.dist_mm - dg_dist_mm);
    dg_var[0] += grow;
    dg_var[1] += grow;
    dg_dist_mm = mo.odom.dist_mm;
    for (uint8_t i = 0; i < 2; i++) {
        hal_distance_t d = hal_distance(i ? HAL_TOF_RIGHT : HAL_TOF_LEFT);
        if (d.seq == dg_seq[i]) continue;
        dg_seq[i] = d.seq;
        if (d.timeout || fabsf(mo.odom.theta_rad - mo.heading_rad) > 0.035f) continue; /* 2 degrees: turning */
        float side = i ? -RC_TOF_SIDE_X_MM : RC_TOF_SIDE_X_MM; /* to the left */
        float sx = px + RC_TOF_SIDE_Y_MM * cb - side * sb, sy = py + RC_TOF_SIDE_Y_MM * sb + side * cb;
        float ax = b + (i ? -0.7853982f : 0.7853982f);
        float e = diagref_expect(&ex.map, sx, sy, ax, RC_DIAG_TOF_MAX_MM, RC_DIAG_TOF_MARGIN_MM);
        if (e < 0 || fabsf((float)d.mm - e) > RC_DIAG_TOF_GATE_MM) continue;
        uint8_t ay = fabsf(cosf(ax)) < fabsf(sinf(ax)); /* the axis is the maze's y */
        float r = RC_TOF_CV * e, gain = dg_var[ay] / (dg_var[ay] + r * r), k = gain * (e - (float)d.mm);
        dg_var[ay] *= 1.0f - gain;
        dg_px += k * cosf(ax);
        dg_py += k * sinf(ax);
        px += k * cosf(ax);
        py += k * sinf(ax);
    }
    mo.lateral_mm = (px - dg_lx) * sinf(dg_a) - (py - dg_ly) * cosf(dg_a);
    mo.lateral_valid = 1;
}

/* A straight of n half units or half steps plus run_carry_mm, leading
 * into the turn `next` (NULL: the run's end, at rest) at that turn's
 * speed. Its top speed is the straights' (plan.h), or the speed it starts
 * or ends with where that is higher. */
static void prun_straight(uint8_t n, const slalom_move_t *next)
{
    uint8_t ortho = !(run_h8 & 1u);
    float unit = (run_h8 & 1u) ? RC_CELL_MM * 0.70710678f : RC_CELL_MM / 2;
    float before = next ? run_drive[next->kind].before_mm : 0;
    float mm = n * unit + run_carry_mm + before;
    float v = !ortho ? run_v_diag : run_v_max, v_end = next ? run_v_turn[next->kind] : 0;
    if (!ortho && RC_DIAG_TOF) diag_anchor(run_x2, run_y2, run_h8, run_carry_mm);
    move_pose(&(slalom_move_t){.kind = ortho ? SLALOM_ORTHO : SLALOM_DIAG, .n = n}, &run_x2, &run_y2, &run_h8);
    start_forward(mm, fmaxf(fmaxf(v, v_end), fabsf(mo.fwd.speed)), v_end, run_accel);
    run_carry_mm = 0;
    run_ortho = ortho;
    run_turn_next = next != NULL;
    /* the centre of the next cell ahead (centring's blind band) */
    uint8_t centre = !(run_x2 & 1) && !(run_y2 & 1);
    float shift = (centre ? RC_CELL_MM : RC_CELL_MM / 2) - before;
    move_shift_mm = shift < 0 ? shift + RC_CELL_MM : shift;
    /* a wall ahead to align on: at the goal's centre, or at the centre an S90 turns in */
    run_align_mm = next ? RC_CELL_MM / 2 - before : 0;
    if (ortho && !next && centre) wall_ahead = !maze_passable(&ex.map, run_cell(run_x2, run_y2), (uint8_t)(run_h8 >> 1), 0);
    if (ortho && next && next->kind == SLALOM_S90 && !centre)
        wall_ahead = !maze_passable(&ex.map, run_cell(run_x2 + slalom_step_x[run_h8], run_y2 + slalom_step_y[run_h8]), (uint8_t)(run_h8 >> 1), 0);
}

/* The turn run_moves[run_idx]: its slalom, at the turn speed throughout. */
static void prun_turn(void)
{
    const slalom_move_t *mv = &run_moves[run_idx++];
    const slalom_geom_t *g = &slalom_geom[mv->kind];
    const slalom_drive_t *d = &run_drive[mv->kind];
    move_pose(mv, &run_x2, &run_y2, &run_h8);
    motion_forward_accel(&mo, d->arc_mm, run_v_turn[mv->kind], run_v_turn[mv->kind], run_accel);
    motion_slalom(&mo, -45.0f * g->turn * mv->dir, d->w_deg_s, RC_SLALOM_ACCEL_DEG_S2); /* right (+1) is clockwise */
    no_centring();
    run_carry_mm = d->after_mm;
    run_turn_next = 0;
    waiting = WAIT_SMOOTH;
}
#endif

static int path_dir(int to_goal, maze_cell_t c, uint8_t h)
{
    hal_tick_release(); /* a flood: the tick runs meanwhile (explore_next_ticking) */
    int d = to_goal ? explore_run_dir(&ex, c, h) : explore_home_dir(&ex, c, h);
    hal_tick_hold();
    return d;
}

/* Speed runs and the way back: one move per straight of the known path,
 * joined by smooth turns; stops only at the end (or for a U-turn). The
 * robot is run_offset_mm past the centre of st.cell, facing st.heading. */
static void run_plan(int to_goal)
{
    float dist0 = mo.odom.dist_mm; /* the flood below takes up to ~11 ms on an AVR: the robot rolls on */
    /* one flood per run, at its start: the map no longer changes, so the
     * field stays valid along the path and ex.path_cost follows the robot
     * (cells + quarter turns made). On the AVR a flood after every smooth
     * turn let the robot roll past the next turn's start (japan2019's
     * staircases became stops and turns on the spot, into the walls). */
    int d = waiting == WAIT_NONE ? path_dir(to_goal, st.cell, st.heading) : explore_dir_ahead(&ex, st.cell, st.heading, 0);
    if (d < 0) {
        waiting = WAIT_NONE;
        if (to_goal) {
            st.runs++;
            /* whole seconds since the start: an AVR's 16-bit unsigned holds 18 hours of them (65.5 s of ms);
             * the exact times are the race's (the JSON's laps) */
            log_line(HAL_STR("run %u reached the goal at %u s"), st.runs, (unsigned)((hal_micros() - start_us) / 1000000u));
            st.mode = MOUSE_RETURN;
        } else {
            st.mode = MOUSE_TO_RUN;
        }
        return;
    }
    int8_t q = quarter(st.heading, (uint8_t)d);
    if (q) { /* standing at a centre: turn on the spot */
        ex.path_cost = (uint16_t)(ex.path_cost - (q == 2 ? 2u : 1u));
        st.heading = (uint8_t)d;
        start_turn(q);
        return;
    }
    /* the straight cells ahead, and what happens at the last one */
    maze_cell_t c = st.cell;
    uint8_t n = 0;
    int dd;
    for (;;) {
        maze_cell_t nx;
        if (!maze_neighbour(&ex.map, c, st.heading, &nx)) return; /* cannot happen on a known path */
        c = nx;
        n++;
        dd = explore_dir_ahead(&ex, c, st.heading, n); /* on path_dir's flood */
        if (dd != st.heading) break;
    }
    float v_max = to_goal ? RC_RUN_MM_S : RC_SEARCH_MM_S;
    float accel = to_goal ? RC_RUN_ACCEL_MM_S2 : RC_ACCEL_MM_S2;
    float mm = n * RC_CELL_MM - run_offset_mm - (mo.odom.dist_mm - dist0);
    int8_t qq = dd >= 0 ? quarter(st.heading, (uint8_t)dd) : 0;
    st.cell = c;
    ex.path_cost = (uint16_t)(ex.path_cost - n);
    if ((qq == 1 || qq == -1) && mm >= smooth_offset_mm) {
        ex.path_cost--; /* the smooth turn's quarter */
        start_forward(mm - smooth_offset_mm, v_max, RC_SMOOTH_MM_S, accel);
        move_shift_mm = smooth_offset_mm;
        turn_pending = qq;
        wall_ahead = !maze_passable(&ex.map, c, st.heading, 0);
        st.heading = (uint8_t)dd;
    } else {
        start_forward(mm, v_max, 0, accel);
        wall_ahead = !maze_passable(&ex.map, c, st.heading, 0);
    }
    run_offset_mm = 0;
}

#if PLAN_ENABLED
static void prun_step(void);
#endif

static void run_step(int to_goal)
{
#if PLAN_ENABLED
    if (to_goal && run_count > 0) {
        prun_step();
        return;
    }
#endif
    if (waiting == WAIT_TURN) {
        if (!turn_done()) return;
        run_offset_mm = 0;
        run_plan(to_goal);
        return;
    }
    if (waiting == WAIT_SMOOTH) {
        if (mo.rot.active) return;
        run_offset_mm = smooth_offset_mm;
        run_plan(to_goal);
        return;
    }
    if (waiting == WAIT_MOVE) {
        centring();
        if (turn_pending) {
            approach_turn();
            return;
        }
        if (wall_ahead) align_to_front_wall(0);
        if (motion_busy(&mo)) return;
        no_centring();
        if (wall_ahead && !front_fix()) return;
        run_offset_mm = 0;
    }
    run_plan(to_goal);
}


#if PLAN_ENABLED
/* The run reached the goal: as run_plan's end of a run. */
static void prun_end(void)
{
    waiting = WAIT_NONE;
    st.cell = run_cell(run_x2, run_y2);
    st.heading = (uint8_t)(run_h8 >> 1);
    st.runs++;
    run_dirty = run_err_mm >= RC_RUN_CLEAN_MM;
    mo.ff_max_cmd = RC_CMD_FF_MAX;
    log_line(HAL_STR("run %u reached the goal at %u s"), st.runs, (unsigned)((hal_micros() - start_us) / 1000000u));
    log_line(HAL_STR("run %u: largest tracking error %u mm"), st.runs, (unsigned)run_err_mm);
    run_count = 0;
    st.mode = MOUSE_RETURN;
}

/* Start the next move: a straight (with the turn after it, if any, in
 * view), the straight between two turns, or a turn. */
static void prun_next(void)
{
    if (run_idx >= run_count) {
        prun_end();
        return;
    }
    const slalom_move_t *mv = &run_moves[run_idx];
    if (mv->kind == SLALOM_ORTHO || mv->kind == SLALOM_DIAG) {
        run_idx++;
        prun_straight(mv->n, run_idx < run_count ? &run_moves[run_idx] : NULL);
        return;
    }
    if (!run_turn_next && run_carry_mm + run_drive[mv->kind].before_mm > 0.5f) {
        prun_straight(0, mv); /* the straights after the last turn and before this one */
        return;
    }
    prun_turn();
}

/* One loop of a planned speed run (run_step while run_count > 0). */
static void prun_step(void)
{
    float e = fmaxf(fabsf(mo.fwd_err_mm), fabsf(mo.rot_err_mm));
    if (e > run_err_mm) run_err_mm = e;
    if (waiting == WAIT_NONE) { /* at the start, facing the way the plan starts */
        int8_t q = quarter(st.heading, ex.map.start_heading);
        st.heading = ex.map.start_heading;
        if (q) start_turn(q);
        else prun_next();
        return;
    }
    if (waiting == WAIT_TURN) {
        if (turn_done()) prun_next();
        return;
    }
    if (waiting == WAIT_SMOOTH) {
        if (!mo.rot.active) prun_next();
        return;
    }
    if (run_ortho) centring();
    else if (RC_DIAG_TOF) diag_centring();
    else no_centring();
    if (wall_ahead && run_ortho) align_to_front_wall(run_align_mm);
    if (run_turn_next) {
        if (!mo.fwd.active) prun_turn();
        return;
    }
    if (motion_busy(&mo)) return;
    no_centring();
    if (wall_ahead && !front_fix()) return;
    prun_next();
}
#endif

static void cmd_step(void);

void fw_loop(void)
{
    hal_tick_hold();
    switch (st.mode) {
    case MOUSE_SEARCH:
        search_step();
        st.cell = ex.cell;
        if (st.mode == MOUSE_TO_RUN) {
            log_line(HAL_STR("search done in %u steps, path proven at step %u"), ex.steps, ex.proven_at_step);
            waiting = WAIT_NONE;
        }
        break;
    case MOUSE_TO_RUN:
        if (motion_busy(&mo)) break;
        if ((hal_micros() - start_us) / 1000000u >= MOUSE_RUN_DEADLINE_S || st.runs >= speed_runs) {
            st.mode = MOUSE_DONE;
            motion_stop(&mo);
            HAL_LOG_STR("contest done");
            break;
        }
        st.mode = MOUSE_RUN;
        waiting = WAIT_NONE;
#if PLAN_ENABLED
        prun_begin();
#endif
        break;
    case MOUSE_RUN:
        run_step(1);
        break;
    case MOUSE_RETURN:
        run_step(0);
        break;
    case MOUSE_NO_GOAL:
    case MOUSE_CRASHED:
        motion_stop(&mo);
        if (!end_said) { /* the contest's last word, whatever ended it (a console's reader waits for it) */
            end_said = 1;
            if (st.mode == MOUSE_NO_GOAL) HAL_LOG_STR("contest done: no path to the goal");
            else HAL_LOG_STR("contest done: crashed");
        }
        break;
    case MOUSE_COMMAND:
        cmd_step();
        break;
    default:
        break;
    }
    hal_tick_release();
}

const maze_t *mouse_map(void) { return &ex.map; }
uint16_t mouse_proven_at_step(void) { return ex.proven_at_step; }

/* ---- External command mode (mmsim --mms): the caller orders each move ----
 * The moves reuse the search's primitives: a straight senses the walls of
 * every cell it enters at RC_SENSE_BEFORE_MM before that cell's centre
 * (read_walls, into the map), centres on the side walls, aligns on a wall
 * ahead and ends with a front fix; turns are start_turn's in-place turns.
 * Between commands the mouse stands at a cell centre or, after an odd
 * number of half steps, on the boundary between two cells (RC_CELL_MM / 2
 * before the centre of ex.cell, the cell it was entering: sensed on the
 * way in, as in a full step). It may turn there (the body sweeps the same
 * circle as at a centre: the boundary's posts are as far as the walls);
 * facing along the boundary it faces a post and cannot move. It may also
 * turn by 45 degrees (CF_DIAG): facing a diagonal on a boundary, forward
 * moves go from boundary middle to boundary middle (cmd_diagonal; ex.cell
 * and the edge bits then name the boundary reached as above, the cell
 * being the one the diagonal heads into). */
enum { CMD_NONE = 0, CMD_SENSE, CMD_FORWARD, CMD_TURN };
static uint8_t cmd_kind;      /* CMD_*: the command under way */
static uint8_t cmd_result;    /* MOUSE_CMD_* of the last command */
static uint8_t cmd_left;      /* cells of the forward move still to enter */
static uint8_t cmd_entered;   /* cells entered by the last forward move */
/* cmd_flags: one byte (the Uno has 2 bytes of its 1,536 B budget left) */
#define CF_BLOCKED 0x01u      /* a wall sensed ahead ended the forward move early */
#define CF_HALF 0x02u         /* standing on a boundary (see above), not at a centre */
#define CF_START_HALF 0x04u   /* the last forward move began on a boundary */
#define CF_END_HALF 0x08u     /* and was to end on one */
#define CF_EDGE_SHIFT 4       /* bits 4-5: the heading from that boundary into ex.cell */
#define CF_DIAG 0x40u         /* the robot faces st.heading turned 45 degrees clockwise */
#define CF_UNSENSED 0x80u     /* on a boundary a diagonal reached: its cells were not sensed */
static uint8_t cmd_flags;
/* A diagonal half step (mms 1.2): from the middle of one cell boundary to
 * the middle of the next, across a quarter of a cell: half a cell's
 * diagonal, RC_CELL_MM * sqrt(2) / 2 (127 mm in a classic maze). */
#define HALF_DIAG_MM (RC_CELL_MM * 0.70710678f)

static uint8_t edge_dir(void) { return (uint8_t)((cmd_flags >> CF_EDGE_SHIFT) & 3u); }

uint8_t mouse_cmd_heading8(void) { return (uint8_t)(2u * st.heading + ((cmd_flags & CF_DIAG) ? 1u : 0u)); }

/* One diagonal half step from the boundary on side e + 2 of *c (the robot
 * standing there facing st.heading turned 45 degrees clockwise): the
 * diagonal's part across that boundary says which cell's quarter it
 * crosses (*c, or the cell behind the boundary), its part along the
 * boundary which side of that cell it leaves by, through the middle of
 * that side. 0 if the map shows a wall there (unknown counts as open, as
 * for the straights); else *c and *e become the cell beyond that side and
 * the heading into it. */
static int diag_step(maze_cell_t *c, uint8_t *e)
{
    uint8_t h = st.heading, h2 = (uint8_t)((h + 1u) & 3u);
    uint8_t across = ((h ^ *e) & 1u) ? h2 : h, along = across == h ? h2 : h;
    maze_cell_t base = *c;
    if (across != *e && !maze_neighbour(&ex.map, *c, across, &base)) return 0;
    if (!maze_passable(&ex.map, base, along, 1)) return 0;
    *c = maze_step(&ex.map, base, along);
    *e = along;
    return 1;
}

/* 1: diagonals steer on the speed runs' diagonal reference (host builds) */
#define CMD_DIAG_REF (PLAN_ENABLED && RC_CMD_DIAG_TOF)
#if CMD_DIAG_REF
/* The reference (diag_anchor, diag_centring) from the middle of the
 * boundary the robot stands on: ex.cell's centre half a cell back along
 * edge_dir(), in the half-unit grid. */
static void cmd_diag_anchor(void)
{
    uint8_t e2 = (uint8_t)(2u * edge_dir());
    diag_anchor((int16_t)(2 * maze_x(&ex.map, ex.cell) - slalom_step_x[e2]),
                (int16_t)(2 * maze_y(&ex.map, ex.cell) - slalom_step_y[e2]), mouse_cmd_heading8(), 0);
}
#endif

/* A diagonal move of `halves` half steps from a boundary: refused (-1) if
 * the map shows a wall at the middle of a boundary it would cross. The
 * cells crossed are not sensed. Held on odometry's heading, steered by the
 * side sensors' position reference where the map predicts their readings
 * (RC_CMD_DIAG_TOF: the held heading carries a few tenths of a degree out
 * of the move before, a few mm over a diagonal, and the wheels clear the
 * posts by 3 mm); blind without it. */
static int cmd_diagonal(uint16_t halves)
{
    maze_cell_t c = ex.cell;
    uint8_t e = edge_dir();
    if (!(cmd_flags & CF_HALF)) return -1; /* from a centre a diagonal aims at a post */
    for (uint16_t k = 0; k < halves; k++)
        if (!diag_step(&c, &e)) return -1;
#if CMD_DIAG_REF
    cmd_diag_anchor();
#endif
    ex.cell = c;
    cmd_flags = (uint8_t)(CF_DIAG | CF_HALF | CF_UNSENSED | (e << CF_EDGE_SHIFT) | ((halves & 1u) ? CF_START_HALF : 0u));
    cmd_entered = (uint8_t)(halves >> 1); /* mouse_cmd_moved: 2 x cmd_entered + the odd half */
    cmd_kind = CMD_FORWARD;
    /* at the smooth turns' speed: at the search's, the robot touched a
     * post on gen-8x8-s1's first diagonals (seed 1) */
    start_forward(halves * HALF_DIAG_MM, RC_SMOOTH_MM_S, 0, RC_ACCEL_MM_S2);
    return 0;
}

void mouse_cmd_mode(void)
{
    st.mode = MOUSE_COMMAND;
    waiting = WAIT_NONE;
    cmd_kind = CMD_SENSE; /* the start cell's walls first */
    cmd_result = MOUSE_CMD_BUSY;
    cmd_flags = 0;
    mark_readings();
}

uint8_t mouse_cmd_status(void)
{
    if (st.mode == MOUSE_CRASHED) return MOUSE_CMD_CRASHED;
    return cmd_kind != CMD_NONE ? MOUSE_CMD_BUSY : cmd_result;
}

/* blocked: stopped at the centre of the last cell entered; else as asked */
uint16_t mouse_cmd_moved(void)
{
    uint16_t moved = (uint16_t)(2u * cmd_entered + ((cmd_flags & CF_START_HALF) ? 1u : 0u));
    return (cmd_flags & (CF_END_HALF | CF_BLOCKED)) == CF_END_HALF ? (uint16_t)(moved - 1u) : moved;
}

uint8_t mouse_cmd_edge(void) { return (cmd_flags & CF_HALF) ? (uint8_t)(1u + ((edge_dir() + 2u) & 3u)) : 0u; }

int mouse_cmd_forward(uint16_t halves)
{
    if (st.mode != MOUSE_COMMAND || cmd_kind != CMD_NONE || halves == 0 || halves > 2u * 255u) return -1;
    if (cmd_flags & CF_DIAG) return cmd_diagonal(halves);
    uint8_t half = (cmd_flags & CF_HALF) ? 1u : 0u;
    maze_cell_t here = ex.cell;
    if (half && st.heading != edge_dir()) {
        /* along the boundary: a post ahead */
        if (st.heading != (uint8_t)((edge_dir() + 2u) & 3u) || !maze_neighbour(&ex.map, ex.cell, st.heading, &here))
            return -1;
        /* turned round on the boundary: entering the cell it came from */
    }
    /* the map shows a wall at a cell centre passed before the end: refuse,
     * nothing moves (from a boundary the first centre is one half step on) */
    maze_cell_t c = here;
    for (uint16_t k = 0; k < (halves + 1u - half) / 2u; k++) {
        if (!maze_passable(&ex.map, c, st.heading, 1)) return -1;
        c = maze_step(&ex.map, c, st.heading);
    }
    /* after a diagonal, `here` is sensed as the move starts (cmd_forward_step):
     * until then the robot counts as in the cell behind the boundary */
    uint8_t unsensed = half ? (uint8_t)(cmd_flags & CF_UNSENSED) : 0u;
    ex.cell = unsensed ? maze_step(&ex.map, here, (uint8_t)(st.heading + 2u)) : here;
    uint16_t end = halves - half; /* half steps past here's centre */
    cmd_left = (uint8_t)((end + 1u) / 2u);
    cmd_flags = (uint8_t)(unsensed | (half ? CF_START_HALF : 0u) | ((end & 1u) ? CF_END_HALF : 0u));
    cmd_entered = 0;
    cmd_kind = CMD_FORWARD;
    if (cmd_left == 0) { /* from the boundary to here's centre: nothing new to sense */
        start_forward(RC_CELL_MM / 2, RC_SEARCH_MM_S, 0, RC_ACCEL_MM_S2);
        sensed = SENSE_DONE;
        wall_ahead = maze_wall(&ex.map, here, st.heading) == MAZE_WALL_CLOSED;
    } else if (cmd_left == 1 && (end & 1u)) { /* to the next boundary */
        start_forward(half ? RC_CELL_MM : RC_CELL_MM / 2, RC_SEARCH_MM_S, 0, RC_ACCEL_MM_S2);
        move_shift_mm = RC_CELL_MM / 2;
    } else { /* to the next centre, extended at each sensing point */
        start_forward(half ? RC_CELL_MM * 1.5f : RC_CELL_MM, RC_SEARCH_MM_S, RC_SEARCH_MM_S, RC_ACCEL_MM_S2);
    }
    return 0;
}

int mouse_cmd_turn(int8_t q)
{
    if (st.mode != MOUSE_COMMAND || cmd_kind != CMD_NONE || (q != 1 && q != -1)) return -1;
    cmd_kind = CMD_TURN;
    st.heading = maze_turn(st.heading, q);
    ex.heading = st.heading;
    start_turn(q);
    return 0;
}

int mouse_cmd_turn45(int8_t e)
{
    if (st.mode != MOUSE_COMMAND || cmd_kind != CMD_NONE || (e != 1 && e != -1)) return -1;
    uint8_t h8 = (uint8_t)((mouse_cmd_heading8() + e) & 7u);
    st.heading = ex.heading = (uint8_t)(h8 >> 1);
    cmd_flags = (uint8_t)((cmd_flags & ~CF_DIAG) | ((h8 & 1u) ? CF_DIAG : 0u));
    cmd_kind = CMD_TURN;
    /* on the spot: a pivot off the centre line would keep the whole
     * offset across the diagonal, the spot keeps cos 45 of it */
    last_lateral_ok = 0;
    uturn_stage = 0;
    motion_turn(&mo, -45.0f * e); /* a right turn (+1) is clockwise */
    waiting = WAIT_TURN;
    return 0;
}

void mouse_cmd_reset(void)
{
    motion_init(&mo);
    ex.cell = ex.map.start;
    ex.heading = ex.map.start_heading;
    st.cell = ex.cell;
    st.heading = ex.heading;
    st.mode = MOUSE_COMMAND;
    waiting = WAIT_NONE;
    uturn_stage = 0;
    fix_stage = 0;
    turn_pending = 0;
    last_lateral_ok = 0;
    move_shift_mm = 0;
    cmd_flags = 0;
    cmd_kind = CMD_SENSE;
    cmd_result = MOUSE_CMD_BUSY;
    mark_readings();
}

static void cmd_finish(uint8_t result)
{
    cmd_kind = CMD_NONE;
    cmd_result = result;
    waiting = WAIT_NONE;
    st.cell = ex.cell;
    hal_belief(&ex.map, ex.cell, st.heading, st.mode);
}

static void cmd_forward_step(void)
{
    if (cmd_flags & CF_DIAG) { /* a diagonal (cmd_diagonal): unsensed to its end */
#if CMD_DIAG_REF
        if (motion_busy(&mo)) {
            diag_centring();
            return;
        }
#endif
        no_centring();
        if (!motion_busy(&mo)) cmd_finish(MOUSE_CMD_DONE);
        return;
    }
    if (cmd_flags & CF_UNSENSED) {
        /* from a boundary a diagonal reached: the cell ahead of it, with
         * the first fresh readings (under 90 mm from its centre the side
         * rays still meet its side walls, past its entry posts) */
        if (!fresh()) return;
        uint8_t walls = read_walls(RC_CELL_MM / 2 - mo.fwd.pos);
        explore_moved(&ex, st.heading);
        explore_sense(&ex, walls);
        if (cmd_left == 0) wall_ahead = (walls & EXPLORE_WALL_FRONT) != 0;
        cmd_flags &= (uint8_t)~CF_UNSENSED;
    }
    centring();
    float left = profile_remaining(&mo.fwd);
    float to_centre = left + move_shift_mm; /* the centre of the cell ahead */
    /* a move ending on a boundary may stop before a fresh reading: sense
     * with the last one then */
    if (cmd_left > 0 && (sense_point(to_centre) || (sensed != SENSE_DONE && !mo.fwd.active))) {
        uint8_t walls = sense_cell_ahead(to_centre);
        st.cell = ex.cell;
        hal_belief(&ex.map, ex.cell, st.heading, st.mode);
        cmd_entered++;
        cmd_left--;
        wall_ahead = (walls & EXPLORE_WALL_FRONT) != 0;
        if (cmd_left > 0 && maze_passable(&ex.map, ex.cell, st.heading, 1)) {
            if (cmd_left == 1 && (cmd_flags & CF_END_HALF)) { /* the last half step: stop on the boundary */
                profile_set_remaining(&mo.fwd, left + RC_CELL_MM / 2);
                mo.fwd.v_end = 0;
                move_shift_mm = RC_CELL_MM / 2;
            } else {
                profile_set_remaining(&mo.fwd, left + RC_CELL_MM);
            }
            sensed = SENSE_NONE;
            return;
        }
        if (cmd_left > 0) cmd_flags |= CF_BLOCKED;
        mo.fwd.v_end = 0; /* stop in the cell ahead (or on its boundary) */
        return;
    }
    uint8_t on_edge = (cmd_flags & (CF_END_HALF | CF_BLOCKED)) == CF_END_HALF;
    /* a wall ahead sets the end, except for a stop on a boundary: that
     * wall is 119 mm away there, and a reading's noise (5 % of the
     * distance) is more than odometry's error over a few cells. 45-degree
     * turns and diagonals start from those stops: with the wall they
     * ended 4-7 mm off on alljapan-006-1985-fin (seed 1), within 1.5 mm
     * without, and a diagonal clears the posts by 3 mm (paper robot) */
    if (sensed == SENSE_DONE && wall_ahead && mo.fwd.active && !on_edge) align_to_front_wall(move_shift_mm);
    if (sensed == SENSE_DONE && !motion_busy(&mo)) {
        no_centring();
        if (!on_edge && wall_ahead && !front_fix()) return;
        if (on_edge) cmd_flags |= (uint8_t)(CF_HALF | (st.heading << CF_EDGE_SHIFT));
        cmd_finish((cmd_flags & CF_BLOCKED) ? MOUSE_CMD_BLOCKED : MOUSE_CMD_DONE);
    }
}

static void cmd_step(void)
{
    switch (cmd_kind) {
    case CMD_SENSE: /* standing still: wait for a reading taken now */
        if (motion_busy(&mo) || !fresh()) return;
        {
            hal_distance_t f = hal_distance(HAL_TOF_FRONT);
            uint8_t w = 0;
            if (!f.timeout && f.mm < RC_FRONT_AT_CENTRE_MM + 60) w |= EXPLORE_WALL_FRONT;
            /* the diagonal sensors look past a cell's end when standing at
             * its centre: the sides come from the rules (start cell) or
             * from when the cell was entered */
            if (ex.cell == ex.map.start && ex.heading == ex.map.start_heading)
                w |= EXPLORE_WALL_LEFT | EXPLORE_WALL_RIGHT;
            else {
                if (!maze_passable(&ex.map, ex.cell, maze_turn(ex.heading, -1), 0)) w |= EXPLORE_WALL_LEFT;
                if (!maze_passable(&ex.map, ex.cell, maze_turn(ex.heading, 1), 0)) w |= EXPLORE_WALL_RIGHT;
            }
            explore_sense(&ex, w);
        }
        cmd_finish(MOUSE_CMD_DONE);
        break;
    case CMD_FORWARD:
        cmd_forward_step();
        break;
    case CMD_TURN:
        if (!turn_done()) return;
        /* facing a wall: put the robot back on the cell's centre (as the
         * U-turn's middle step), so that the next turn sweeps clear; not on
         * a boundary (a post or a far wall ahead) */
        if (!(cmd_flags & (CF_HALF | CF_DIAG)) && maze_wall(&ex.map, ex.cell, st.heading) == MAZE_WALL_CLOSED &&
            !front_fix())
            return;
        cmd_finish(MOUSE_CMD_DONE);
        break;
    default:
        break;
    }
}

/* search.c - the search (search.h): cell by cell without stopping on
 * straights. RC_SENSE_BEFORE_MM before the centre of the cell ahead, the
 * walls of that cell are read (diagonal sensors for its sides, the front
 * sensor for its far wall), the map and the plan are updated, and the move
 * is either extended by a cell, ends in a smooth turn, or ends at that
 * cell's centre for an in-place turn. A wall ahead also resets the
 * distance to go (front-wall alignment). */
#include "search.h"

#include <stdio.h>

#include "explore.h"
#include "hal.h"
#include "robot_config.h"
#include "walls.h"

/* fw_loop runs with the control tick held off (hal_tick_hold): it reads
 * and changes the motion state fw_tick drives. A flood (explore_next:
 * 30-200 ms on a 16 MHz AVR) touches only the map, and the tick runs
 * meanwhile. */
static int explore_next_ticking(drive_t *dr)
{
    hal_tick_release();
    int d = explore_next(&dr->ex);
    hal_tick_hold();
    return d;
}

/* Search, at the sensing point of the cell ahead (`left` mm of the move
 * to go): its walls sensed and the next direction decided: straight on
 * (the move extended by a cell), a smooth quarter turn at the turn's start,
 * or a stop in the cell ahead (next_dir; -1: explore has ended). */
static void search_decide(drive_t *dr, float left)
{
    uint8_t walls = drive_sense_cell_ahead(dr, left);
    drive_log(HAL_STR("sensed cell %u walls %u"), dr->ex.cell, walls);
    hal_belief(&dr->ex.map, dr->ex.cell, dr->st.heading, dr->st.mode);
    /* planning takes 30-200 ms on a 16 MHz AVR (no time in the
     * simulator): meanwhile the move brakes into the cell ahead (from
     * 60 mm before it at search speed) instead of running on */
    float v_end = dr->mo.fwd.v_end;
    dr->mo.fwd.v_end = 0;
    int d = explore_next_ticking(dr);
    left = profile_remaining(&dr->mo.fwd); /* where the robot is now */
    dr->wall_ahead = (walls & EXPLORE_WALL_FRONT) != 0;
    if (d >= 0 && (uint8_t)d == dr->st.heading && dr->mo.fwd.active) {
        dr->mo.fwd.v_end = v_end;
        profile_set_remaining(&dr->mo.fwd, left + RC_CELL_MM);
        dr->sensed = SENSE_NONE;
        return;
    }
    int8_t q = d >= 0 ? drive_quarter(dr->st.heading, (uint8_t)d) : 0;
    if ((q == 1 || q == -1) && left >= dr->smooth_offset_mm + 1.0f) {
        /* go on to the turn's start, slowing to the turn's speed,
         * and turn there without stopping */
        dr->mo.fwd.v_end = v_end < RC_SMOOTH_MM_S ? v_end : RC_SMOOTH_MM_S;
        profile_set_remaining(&dr->mo.fwd, left - dr->smooth_offset_mm);
        dr->move_shift_mm = dr->smooth_offset_mm;
        dr->turn_pending = q;
        dr->st.heading = (uint8_t)d;
        return;
    }
    dr->next_dir = (int8_t)d; /* stop in the cell ahead */
}

/* a straight of mm at the search's speed, on into the next cell */
static void search_forward(drive_t *dr, float mm) { drive_forward(dr, mm, RC_SEARCH_MM_S, RC_SEARCH_MM_S, RC_ACCEL_MM_S2); }

/* Search: decide at the sensing point of each cell. st.heading is the way
 * the robot faces (or will face once a pending turn is made); ex.cell is
 * the cell it is in or committed to. */
void search_step(drive_t *dr)
{
    if (dr->waiting == WAIT_NONE) {
        /* standing at a cell centre: the start (or after the last stop) */
        if (dr->ex.steps == 0 && dr->ex.phase == EXPLORE_TO_GOAL) {
            /* the start cell: by the rules open only ahead */
            explore_sense(&dr->ex, (uint8_t)(EXPLORE_WALL_LEFT | EXPLORE_WALL_RIGHT | walls_ahead(WALLS_HERE_FRONT_MM)));
        }
        int d = explore_next_ticking(dr);
        if (d < 0) {
            dr->st.mode = dr->ex.phase == EXPLORE_DONE ? MOUSE_TO_RUN : MOUSE_NO_GOAL;
            return;
        }
        int8_t q = drive_quarter(dr->st.heading, (uint8_t)d);
        dr->st.heading = (uint8_t)d;
        if (q) drive_turn(dr, q);
        else search_forward(dr, RC_CELL_MM + (dr->ex.steps ? 0.0f : RC_START_BEHIND_MM));
        return;
    }
    if (dr->waiting == WAIT_TURN) {
        if (!drive_turn_done(dr)) return;
        search_forward(dr, RC_CELL_MM);
        return;
    }
    if (dr->waiting == WAIT_SMOOTH) {
        if (dr->mo.rot.active) return;
        /* on the new heading, the offset past the turn cell's centre */
        search_forward(dr, RC_CELL_MM - dr->smooth_offset_mm);
        return;
    }
    /* WAIT_MOVE */
    drive_centring(dr);
    if (dr->turn_pending) {
        drive_approach_turn(dr);
        return;
    }
    float left = profile_remaining(&dr->mo.fwd);
    if (drive_sense_point(dr, left)) {
        search_decide(dr, left);
        return;
    }
    if (dr->sensed == SENSE_DONE && dr->wall_ahead && dr->mo.fwd.active) drive_align_front(dr, 0);
    if (dr->sensed == SENSE_DONE && !motion_busy(&dr->mo)) {
        drive_no_centring(dr);
        if (dr->wall_ahead && !drive_front_fix(dr)) return;
        if (dr->next_dir < 0) {
            dr->waiting = WAIT_NONE; /* explore has ended: the next call sees it */
            return;
        }
        int8_t q = drive_quarter(dr->st.heading, (uint8_t)dr->next_dir);
        dr->st.heading = (uint8_t)dr->next_dir;
        drive_turn(dr, q);
    }
}
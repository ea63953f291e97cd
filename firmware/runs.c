/* runs.c - speed runs on the proven path and the way back to the start
 * (runs.h): one move per straight of the known path, joined by smooth
 * turns, each straight driven at RC_RUN_MM_S (runs) or RC_SEARCH_MM_S (the
 * way back). A planned run (slalomrun.h) takes over a speed run when the
 * planner found one. */
#include "runs.h"

#include <stdio.h>

#include "explore.h"
#include "hal.h"
#include "plan.h"
#include "robot_config.h"
#include "slalomrun.h"

static int path_dir(drive_t *dr, int to_goal, maze_cell_t c, uint8_t h)
{
    hal_tick_release(); /* a flood: the tick runs meanwhile (explore_next_ticking) */
    int d = to_goal ? explore_run_dir(&dr->ex, c, h) : explore_home_dir(&dr->ex, c, h);
    hal_tick_hold();
    return d;
}

/* Speed runs and the way back: one move per straight of the known path,
 * joined by smooth turns; stops only at the end (or for a U-turn). The
 * robot is run_offset_mm past the centre of st.cell, facing st.heading. */
static void run_plan(drive_t *dr, int to_goal)
{
    float dist0 = dr->mo.odom.dist_mm; /* the flood below takes up to ~11 ms on an AVR: the robot rolls on */
    /* one flood per run, at its start: the map no longer changes, so the
     * field stays valid along the path and ex.path_cost follows the robot
     * (cells + quarter turns made). On the AVR a flood after every smooth
     * turn let the robot roll past the next turn's start (japan2019's
     * staircases became stops and turns on the spot, into the walls). */
    int d = dr->waiting == WAIT_NONE ? path_dir(dr, to_goal, dr->st.cell, dr->st.heading) : explore_dir_ahead(&dr->ex, dr->st.cell, dr->st.heading, 0);
    if (d < 0) {
        dr->waiting = WAIT_NONE;
        if (to_goal) {
            dr->st.runs++;
            /* whole seconds since the start: an AVR's 16-bit unsigned holds 18 hours of them (65.5 s of ms);
             * the exact times are the race's (the JSON's laps) */
            drive_log(HAL_STR("run %u reached the goal at %u s"), dr->st.runs, (unsigned)((hal_micros() - dr->start_us) / 1000000u));
            dr->st.mode = MOUSE_RETURN;
        } else {
            dr->st.mode = MOUSE_TO_RUN;
        }
        return;
    }
    int8_t q = drive_quarter(dr->st.heading, (uint8_t)d);
    if (q) { /* standing at a centre: turn on the spot */
        dr->ex.path_cost = (uint16_t)(dr->ex.path_cost - (q == 2 ? 2u : 1u));
        dr->st.heading = (uint8_t)d;
        drive_turn(dr, q);
        return;
    }
    /* the straight cells ahead, and what happens at the last one */
    maze_cell_t c = dr->st.cell;
    uint8_t n = 0;
    int dd;
    for (;;) {
        maze_cell_t nx;
        if (!maze_neighbour(&dr->ex.map, c, dr->st.heading, &nx)) return; /* cannot happen on a known path */
        c = nx;
        n++;
        dd = explore_dir_ahead(&dr->ex, c, dr->st.heading, n); /* on path_dir's flood */
        if (dd != dr->st.heading) break;
    }
    float v_max = to_goal ? RC_RUN_MM_S : RC_SEARCH_MM_S;
    float accel = to_goal ? RC_RUN_ACCEL_MM_S2 : RC_ACCEL_MM_S2;
    float mm = n * RC_CELL_MM - dr->run_offset_mm - (dr->mo.odom.dist_mm - dist0);
    int8_t qq = dd >= 0 ? drive_quarter(dr->st.heading, (uint8_t)dd) : 0;
    dr->st.cell = c;
    dr->ex.path_cost = (uint16_t)(dr->ex.path_cost - n);
    uint8_t wall = !maze_passable(&dr->ex.map, c, dr->st.heading, 0);
    if ((qq == 1 || qq == -1) && mm >= dr->smooth_offset_mm) {
        dr->ex.path_cost--; /* the smooth turn's quarter */
        drive_forward(dr, mm - dr->smooth_offset_mm, v_max, RC_SMOOTH_MM_S, accel);
        dr->move_shift_mm = dr->smooth_offset_mm;
        dr->turn_pending = qq;
        dr->st.heading = (uint8_t)dd;
    } else {
        drive_forward(dr, mm, v_max, 0, accel);
    }
    dr->wall_ahead = wall;
    dr->run_offset_mm = 0;
}

void runs_step(drive_t *dr, int to_goal)
{
    if (PLAN_ENABLED && to_goal && slalomrun_active()) {
        slalomrun_step(dr);
        return;
    }
    if (dr->waiting == WAIT_TURN) {
        if (!drive_turn_done(dr)) return;
        dr->run_offset_mm = 0;
        run_plan(dr, to_goal);
        return;
    }
    if (dr->waiting == WAIT_SMOOTH) {
        if (dr->mo.rot.active) return;
        dr->run_offset_mm = dr->smooth_offset_mm;
        run_plan(dr, to_goal);
        return;
    }
    if (dr->waiting == WAIT_MOVE) {
        drive_centring(dr);
        if (dr->turn_pending) {
            drive_approach_turn(dr);
            return;
        }
        if (dr->wall_ahead) drive_align_front(dr, 0);
        if (motion_busy(&dr->mo)) return;
        drive_no_centring(dr);
        if (dr->wall_ahead && !drive_front_fix(dr)) return;
        dr->run_offset_mm = 0;
    }
    run_plan(dr, to_goal);
}

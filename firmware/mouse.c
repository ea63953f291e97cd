/* mouse.c - the contest: search until the run path is proven, back to the
 * start, then speed runs on the proven path until the time is up; or, on
 * the caller's orders, command mode. The subsystems, each a step of
 * fw_loop on the mouse's one drive_t (drive.h):
 *   search.h     the search and the way home after it
 *   runs.h       speed runs on the proven path, the way back to the start
 *   slalomrun.h  speed runs on the planner's diagonals and slaloms (host)
 *   cmd.h        command mode (mmsim --mms)
 *
 * Hardware seam: everything here goes through hal.h; fw_tick runs from the
 * control interrupt, fw_loop from the main loop. */
#include "mouse.h"

#include <stdio.h>

#include "cmd.h"
#include "drive.h"
#include "explore.h"
#include "hal.h"
#include "motion.h"
#include "plan.h"
#include "robot_config.h"
#include "runs.h"
#include "search.h"
#include "slalomrun.h"
#include "walls.h"

static drive_t dr;
static uint8_t configured;    /* fw_set_maze was called */
static uint8_t speed_runs = MOUSE_SPEED_RUNS; /* fw_set_speed_runs */
static uint8_t end_said; /* 1 once "contest done: ..." is logged for a search that ended early */

/* The map is set up here rather than copied: a second maze_t would cost
 * 292 of the ATmega328P's 2048 bytes of SRAM. */
void fw_set_maze(const struct maze_s *m)
{
    explore_init(&dr.ex, m);
    configured = 1;
}

void fw_set_speed_runs(uint8_t runs) { speed_runs = runs ? runs : 1; }

const mouse_status_t *mouse_status(void) { return &dr.st; }

/* The contest's maze as the backend announces it (hal_maze), else a
 * classic contest: 16x16, the centre goal; built in place in ex.map (a
 * maze_t on the stack would cost 292 B of the AVR's 2 KB): explore_init
 * on its own map keeps only the size, so the goal and start follow it. */
static void contest_maze(void)
{
    explore_t *ex = &dr.ex;
    hal_maze_t a;
    uint8_t ok = hal_maze(&a) && a.start_x < a.width && a.start_y < a.height && maze_init(&ex->map, a.width, a.height) == 0;
    if (!ok) maze_init(&ex->map, 16, 16);
    explore_init(ex, &ex->map);
    if (!ok || maze_set_goal_rect(&ex->map, a.goal_x0, a.goal_y0, a.goal_x1, a.goal_y1) != 0) return;
    ex->cell = ex->map.start = maze_cell(&ex->map, a.start_x, a.start_y);
    ex->heading = ex->map.start_heading = a.start_heading & 3u;
}

void fw_setup(void)
{
    if (!configured) contest_maze();
    configured = 0; /* the next fw_setup without fw_set_maze is a classic contest */
    motion_init(&dr.mo);
    walls_setup();
    dr.st.mode = MOUSE_SEARCH;
    dr.st.runs = 0;
    dr.st.cell = dr.ex.cell;
    dr.st.heading = dr.ex.heading;
    dr.waiting = WAIT_NONE;
    dr.sensed = SENSE_NONE;
    dr.next_dir = -1;
    dr.uturn_stage = 0;
    dr.fix_stage = 0;
    dr.turn_pending = 0;
    dr.run_offset_mm = 0;
    motion_smooth_geometry(RC_SMOOTH_MM_S, &dr.smooth_offset_mm, &dr.smooth_length_mm);
    dr.start_us = hal_micros();
    end_said = 0;
}

void fw_tick(void)
{
    motion_tick(&dr.mo, 1.0f / HAL_TICK_HZ);
    if (dr.mo.crashed && dr.st.mode != MOUSE_CRASHED) dr.st.mode = MOUSE_CRASHED;
}

void fw_loop(void)
{
    hal_tick_hold();
    switch (dr.st.mode) {
    case MOUSE_SEARCH:
        search_step(&dr);
        dr.st.cell = dr.ex.cell;
        if (dr.st.mode == MOUSE_TO_RUN) {
            drive_log(HAL_STR("search done in %u steps, path proven at step %u"), dr.ex.steps, dr.ex.proven_at_step);
            dr.waiting = WAIT_NONE;
        }
        break;
    case MOUSE_TO_RUN: /* at the start: another speed run, or the contest is over */
        if (motion_busy(&dr.mo)) break;
        if ((hal_micros() - dr.start_us) / 1000000u >= MOUSE_RUN_DEADLINE_S || dr.st.runs >= speed_runs) {
            dr.st.mode = MOUSE_DONE;
            motion_stop(&dr.mo);
            HAL_LOG_STR("contest done");
            break;
        }
        dr.st.mode = MOUSE_RUN;
        dr.waiting = WAIT_NONE;
        if (PLAN_ENABLED) slalomrun_begin(&dr);
        break;
    case MOUSE_RUN:
        runs_step(&dr, 1);
        break;
    case MOUSE_RETURN:
        runs_step(&dr, 0);
        break;
    case MOUSE_NO_GOAL:
    case MOUSE_CRASHED:
        motion_stop(&dr.mo);
        if (!end_said) { /* the contest's last word, whatever ended it (a console's reader waits for it) */
            end_said = 1;
            if (dr.st.mode == MOUSE_NO_GOAL) HAL_LOG_STR("contest done: no path to the goal");
            else HAL_LOG_STR("contest done: crashed");
        }
        break;
    case MOUSE_COMMAND:
        cmd_step(&dr);
        break;
    default:
        break;
    }
    hal_tick_release();
}

const maze_t *mouse_map(void) { return &dr.ex.map; }
uint16_t mouse_proven_at_step(void) { return dr.ex.proven_at_step; }

/* ---- External command mode (cmd.h) ---- */
void mouse_cmd_mode(void) { cmd_mode(&dr); }
uint8_t mouse_cmd_status(void) { return cmd_status(&dr); }
uint16_t mouse_cmd_moved(void) { return cmd_moved(); }
uint8_t mouse_cmd_edge(void) { return cmd_edge(); }
int mouse_cmd_forward(uint16_t halves) { return cmd_forward(&dr, halves); }
int mouse_cmd_turn(int8_t q) { return cmd_turn(&dr, q); }
int mouse_cmd_turn45(int8_t e) { return cmd_turn45(&dr, e); }
uint8_t mouse_cmd_heading8(void) { return cmd_heading8(&dr); }
void mouse_cmd_reset(void) { cmd_reset(&dr); }

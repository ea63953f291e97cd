/* cmd.c - external command mode (cmd.h, mmsim --mms): the caller orders
 * each move; the moves are drive.h's. */
#include "cmd.h"

#include "diagref.h"
#include <stdio.h>

#include "explore.h"
#include "hal.h"
#include "plan.h"
#include "robot_config.h"
#include "slalom.h"
#include "walls.h"

/* ---- External command mode (mmsim --mms): the caller orders each move ----
 * The moves reuse the search's primitives: a straight senses the walls of
 * every cell it enters at RC_SENSE_BEFORE_MM before that cell's centre
 * (drive_read_walls, into the map), centres on the side walls, aligns on a wall
 * ahead and ends with a front fix; turns are drive_turn's in-place turns.
 * Between commands the mouse stands at a cell centre or, after an odd
 * number of half steps, on the boundary between two cells (RC_CELL_MM / 2
 * before the centre of ex.cell, the cell it was entering: sensed on the
 * way in, as in a full step). It may turn there (the body sweeps the same
 * circle as at a centre: the boundary's posts are as far as the walls);
 * facing along the boundary it faces a post and cannot move. It may also
 * turn by 45 degrees (CF_DIAG): facing a diagonal on a boundary, forward
 * moves go from boundary middle to boundary middle (diagonal(); ex.cell
 * and the edge bits then name the boundary reached as above, the cell
 * being the one the diagonal heads into). */
enum { CMD_NONE = 0, CMD_SENSE, CMD_FORWARD, CMD_TURN };
typedef struct {
    uint8_t kind;    /* CMD_*: the command under way */
    uint8_t result;  /* MOUSE_CMD_* of the last command */
    uint8_t left;    /* cells of the forward move still to enter */
    uint8_t entered; /* cells entered by the last forward move */
    uint8_t flags;   /* CF_*, below: one byte (the Uno has 2 bytes of its 1,536 B budget left) */
} cmd_t;

static cmd_t cm;
/* the diagonal reference (CMD_DIAG_REF, below): host builds only */
static diagref_t cm_ref;

#define CF_BLOCKED 0x01u      /* a wall sensed ahead ended the forward move early */
#define CF_HALF 0x02u         /* standing on a boundary (see above), not at a centre */
#define CF_START_HALF 0x04u   /* the last forward move began on a boundary */
#define CF_END_HALF 0x08u     /* and was to end on one */
#define CF_EDGE_SHIFT 4       /* bits 4-5: the heading from that boundary into ex.cell */
#define CF_DIAG 0x40u         /* the robot faces st.heading turned 45 degrees clockwise */
#define CF_UNSENSED 0x80u     /* on a boundary a diagonal reached: its cells were not sensed */
/* A diagonal half step (mms 1.2): from the middle of one cell boundary to
 * the middle of the next, across a quarter of a cell: half a cell's
 * diagonal, RC_CELL_MM * sqrt(2) / 2 (127 mm in a classic maze). */
#define HALF_DIAG_MM (RC_CELL_MM * 0.70710678f)

static uint8_t edge_dir(void) { return (uint8_t)((cm.flags >> CF_EDGE_SHIFT) & 3u); }

uint8_t cmd_heading8(drive_t *dr) { return (uint8_t)(2u * dr->st.heading + ((cm.flags & CF_DIAG) ? 1u : 0u)); }

/* One diagonal half step from the boundary on side e + 2 of *c (the robot
 * standing there facing st.heading turned 45 degrees clockwise): the
 * diagonal's part across that boundary says which cell's quarter it
 * crosses (*c, or the cell behind the boundary), its part along the
 * boundary which side of that cell it leaves by, through the middle of
 * that side. 0 if the map shows a wall there (unknown counts as open, as
 * for the straights); else *c and *e become the cell beyond that side and
 * the heading into it. */
static int diag_step(drive_t *dr, maze_cell_t *c, uint8_t *e)
{
    uint8_t h = dr->st.heading, h2 = (uint8_t)((h + 1u) & 3u);
    uint8_t across = ((h ^ *e) & 1u) ? h2 : h, along = across == h ? h2 : h;
    maze_cell_t base = *c;
    if (across != *e && !maze_neighbour(&dr->ex.map, *c, across, &base)) return 0;
    if (!maze_passable(&dr->ex.map, base, along, 1)) return 0;
    *c = maze_step(&dr->ex.map, base, along);
    *e = along;
    return 1;
}

/* 1: diagonals steer on the speed runs' diagonal reference (host builds) */
#define CMD_DIAG_REF (PLAN_ENABLED && RC_CMD_DIAG_TOF)
/* The reference (diagref_anchor, diagref_centring) from the middle of the
 * boundary the robot stands on: ex.cell's centre half a cell back along
 * edge_dir(), in the half-unit grid. */
static void diag_anchor(drive_t *dr)
{
    uint8_t e2 = (uint8_t)(2u * edge_dir());
    diagref_anchor(&cm_ref, &dr->mo, (int16_t)(2 * maze_x(&dr->ex.map, dr->ex.cell) - slalom_step_x[e2]),
                   (int16_t)(2 * maze_y(&dr->ex.map, dr->ex.cell) - slalom_step_y[e2]), cmd_heading8(dr), 0);
}

/* A diagonal move of `halves` half steps from a boundary: refused (-1) if
 * the map shows a wall at the middle of a boundary it would cross. The
 * cells crossed are not sensed. Held on odometry's heading, steered by the
 * side sensors' position reference where the map predicts their readings
 * (RC_CMD_DIAG_TOF: the held heading carries a few tenths of a degree out
 * of the move before, a few mm over a diagonal, and the wheels clear the
 * posts by 3 mm); blind without it. */
static int diagonal(drive_t *dr, uint16_t halves)
{
    maze_cell_t c = dr->ex.cell;
    uint8_t e = edge_dir();
    if (!(cm.flags & CF_HALF)) return -1; /* from a centre a diagonal aims at a post */
    for (uint16_t k = 0; k < halves; k++)
        if (!diag_step(dr, &c, &e)) return -1;
    if (CMD_DIAG_REF) diag_anchor(dr);
    dr->ex.cell = c;
    cm.flags = (uint8_t)(CF_DIAG | CF_HALF | CF_UNSENSED | (e << CF_EDGE_SHIFT) | ((halves & 1u) ? CF_START_HALF : 0u));
    cm.entered = (uint8_t)(halves >> 1); /* cmd_moved: 2 x entered + the odd half */
    cm.kind = CMD_FORWARD;
    /* at the smooth turns' speed: at the search's, the robot touched a
     * post on gen-8x8-s1's first diagonals (seed 1) */
    drive_forward(dr, halves * HALF_DIAG_MM, RC_SMOOTH_MM_S, 0, RC_ACCEL_MM_S2);
    return 0;
}

void cmd_mode(drive_t *dr)
{
    dr->st.mode = MOUSE_COMMAND;
    dr->waiting = WAIT_NONE;
    cm.kind = CMD_SENSE; /* the start cell's walls first */
    cm.result = MOUSE_CMD_BUSY;
    cm.flags = 0;
    drive_mark_readings(dr);
}

uint8_t cmd_status(drive_t *dr)
{
    if (dr->st.mode == MOUSE_CRASHED) return MOUSE_CMD_CRASHED;
    return cm.kind != CMD_NONE ? MOUSE_CMD_BUSY : cm.result;
}

/* blocked: stopped at the centre of the last cell entered; else as asked */
uint16_t cmd_moved(void)
{
    uint16_t moved = (uint16_t)(2u * cm.entered + ((cm.flags & CF_START_HALF) ? 1u : 0u));
    return (cm.flags & (CF_END_HALF | CF_BLOCKED)) == CF_END_HALF ? (uint16_t)(moved - 1u) : moved;
}

uint8_t cmd_edge(void) { return (cm.flags & CF_HALF) ? (uint8_t)(1u + ((edge_dir() + 2u) & 3u)) : 0u; }

int cmd_forward(drive_t *dr, uint16_t halves)
{
    if (dr->st.mode != MOUSE_COMMAND || cm.kind != CMD_NONE || halves == 0 || halves > 2u * 255u) return -1;
    if (cm.flags & CF_DIAG) return diagonal(dr, halves);
    uint8_t half = (cm.flags & CF_HALF) ? 1u : 0u;
    maze_cell_t here = dr->ex.cell;
    if (half && dr->st.heading != edge_dir()) {
        /* along the boundary: a post ahead */
        if (dr->st.heading != (uint8_t)((edge_dir() + 2u) & 3u) || !maze_neighbour(&dr->ex.map, dr->ex.cell, dr->st.heading, &here))
            return -1;
        /* turned round on the boundary: entering the cell it came from */
    }
    /* the map shows a wall at a cell centre passed before the end: refuse,
     * nothing moves (from a boundary the first centre is one half step on) */
    maze_cell_t c = here;
    for (uint16_t k = 0; k < (halves + 1u - half) / 2u; k++) {
        if (!maze_passable(&dr->ex.map, c, dr->st.heading, 1)) return -1;
        c = maze_step(&dr->ex.map, c, dr->st.heading);
    }
    /* after a diagonal, `here` is sensed as the move starts (cmd_forward_step):
     * until then the robot counts as in the cell behind the boundary */
    uint8_t unsensed = half ? (uint8_t)(cm.flags & CF_UNSENSED) : 0u;
    dr->ex.cell = unsensed ? maze_step(&dr->ex.map, here, (uint8_t)(dr->st.heading + 2u)) : here;
    uint16_t end = halves - half; /* half steps past here's centre */
    cm.left = (uint8_t)((end + 1u) / 2u);
    cm.flags = (uint8_t)(unsensed | (half ? CF_START_HALF : 0u) | ((end & 1u) ? CF_END_HALF : 0u));
    cm.entered = 0;
    cm.kind = CMD_FORWARD;
    if (cm.left == 0) { /* from the boundary to here's centre: nothing new to sense */
        drive_forward(dr, RC_CELL_MM / 2, RC_SEARCH_MM_S, 0, RC_ACCEL_MM_S2);
        dr->sensed = SENSE_DONE;
        dr->wall_ahead = maze_wall(&dr->ex.map, here, dr->st.heading) == MAZE_WALL_CLOSED;
    } else if (cm.left == 1 && (end & 1u)) { /* to the next boundary */
        drive_forward(dr, half ? RC_CELL_MM : RC_CELL_MM / 2, RC_SEARCH_MM_S, 0, RC_ACCEL_MM_S2);
        dr->move_shift_mm = RC_CELL_MM / 2;
    } else { /* to the next centre, extended at each sensing point */
        drive_forward(dr, half ? RC_CELL_MM * 1.5f : RC_CELL_MM, RC_SEARCH_MM_S, RC_SEARCH_MM_S, RC_ACCEL_MM_S2);
    }
    return 0;
}

int cmd_turn(drive_t *dr, int8_t q)
{
    if (dr->st.mode != MOUSE_COMMAND || cm.kind != CMD_NONE || (q != 1 && q != -1)) return -1;
    cm.kind = CMD_TURN;
    dr->st.heading = maze_turn(dr->st.heading, q);
    dr->ex.heading = dr->st.heading;
    drive_turn(dr, q);
    return 0;
}

int cmd_turn45(drive_t *dr, int8_t e)
{
    if (dr->st.mode != MOUSE_COMMAND || cm.kind != CMD_NONE || (e != 1 && e != -1)) return -1;
    uint8_t h8 = (uint8_t)((cmd_heading8(dr) + e) & 7u);
    dr->st.heading = dr->ex.heading = (uint8_t)(h8 >> 1);
    cm.flags = (uint8_t)((cm.flags & ~CF_DIAG) | ((h8 & 1u) ? CF_DIAG : 0u));
    cm.kind = CMD_TURN;
    /* on the spot: a pivot off the centre line would keep the whole
     * offset across the diagonal, the spot keeps cos 45 of it */
    dr->last_lateral_ok = 0;
    dr->uturn_stage = 0;
    motion_turn(&dr->mo, -45.0f * e); /* a right turn (+1) is clockwise */
    dr->waiting = WAIT_TURN;
    return 0;
}

void cmd_reset(drive_t *dr)
{
    motion_init(&dr->mo);
    dr->ex.cell = dr->ex.map.start;
    dr->ex.heading = dr->ex.map.start_heading;
    dr->st.cell = dr->ex.cell;
    dr->st.heading = dr->ex.heading;
    dr->st.mode = MOUSE_COMMAND;
    dr->waiting = WAIT_NONE;
    dr->uturn_stage = 0;
    dr->fix_stage = 0;
    dr->turn_pending = 0;
    dr->last_lateral_ok = 0;
    dr->move_shift_mm = 0;
    cm.flags = 0;
    cm.kind = CMD_SENSE;
    cm.result = MOUSE_CMD_BUSY;
    drive_mark_readings(dr);
}

static void finish(drive_t *dr, uint8_t result)
{
    cm.kind = CMD_NONE;
    cm.result = result;
    dr->waiting = WAIT_NONE;
    dr->st.cell = dr->ex.cell;
    hal_belief(&dr->ex.map, dr->ex.cell, dr->st.heading, dr->st.mode);
}

static void forward_step(drive_t *dr)
{
    if (cm.flags & CF_DIAG) { /* a diagonal (diagonal()): unsensed to its end */
        if (CMD_DIAG_REF && motion_busy(&dr->mo)) {
            diagref_centring(&cm_ref, &dr->mo, &dr->ex.map);
            return;
        }
        drive_no_centring(dr);
        if (!motion_busy(&dr->mo)) finish(dr, MOUSE_CMD_DONE);
        return;
    }
    if (cm.flags & CF_UNSENSED) {
        /* from a boundary a diagonal reached: the cell ahead of it, with
         * the first fresh readings (under 90 mm from its centre the side
         * rays still meet its side walls, past its entry posts) */
        if (!drive_fresh(dr)) return;
        uint8_t walls = drive_read_walls(RC_CELL_MM / 2 - dr->mo.fwd.pos);
        explore_moved(&dr->ex, dr->st.heading);
        explore_sense(&dr->ex, walls);
        if (cm.left == 0) dr->wall_ahead = (walls & EXPLORE_WALL_FRONT) != 0;
        cm.flags &= (uint8_t)~CF_UNSENSED;
    }
    drive_centring(dr);
    float left = profile_remaining(&dr->mo.fwd);
    float to_centre = left + dr->move_shift_mm; /* the centre of the cell ahead */
    /* a move ending on a boundary may stop before a fresh reading: sense
     * with the last one then */
    if (cm.left > 0 && (drive_sense_point(dr, to_centre) || (dr->sensed != SENSE_DONE && !dr->mo.fwd.active))) {
        uint8_t walls = drive_sense_cell_ahead(dr, to_centre);
        dr->st.cell = dr->ex.cell;
        hal_belief(&dr->ex.map, dr->ex.cell, dr->st.heading, dr->st.mode);
        cm.entered++;
        cm.left--;
        dr->wall_ahead = (walls & EXPLORE_WALL_FRONT) != 0;
        if (cm.left > 0 && maze_passable(&dr->ex.map, dr->ex.cell, dr->st.heading, 1)) {
            if (cm.left == 1 && (cm.flags & CF_END_HALF)) { /* the last half step: stop on the boundary */
                profile_set_remaining(&dr->mo.fwd, left + RC_CELL_MM / 2);
                dr->mo.fwd.v_end = 0;
                dr->move_shift_mm = RC_CELL_MM / 2;
            } else {
                profile_set_remaining(&dr->mo.fwd, left + RC_CELL_MM);
            }
            dr->sensed = SENSE_NONE;
            return;
        }
        if (cm.left > 0) cm.flags |= CF_BLOCKED;
        dr->mo.fwd.v_end = 0; /* stop in the cell ahead (or on its boundary) */
        return;
    }
    uint8_t on_edge = (cm.flags & (CF_END_HALF | CF_BLOCKED)) == CF_END_HALF;
    /* a wall ahead sets the end, except for a stop on a boundary: that
     * wall is 119 mm away there, and a reading's noise (5 % of the
     * distance) is more than odometry's error over a few cells. 45-degree
     * turns and diagonals start from those stops: with the wall they
     * ended 4-7 mm off on alljapan-006-1985-fin (seed 1), within 1.5 mm
     * without, and a diagonal clears the posts by 3 mm (paper robot) */
    if (dr->sensed == SENSE_DONE && dr->wall_ahead && dr->mo.fwd.active && !on_edge) drive_align_front(dr, dr->move_shift_mm);
    if (dr->sensed == SENSE_DONE && !motion_busy(&dr->mo)) {
        drive_no_centring(dr);
        if (!on_edge && dr->wall_ahead && !drive_front_fix(dr)) return;
        if (on_edge) cm.flags |= (uint8_t)(CF_HALF | (dr->st.heading << CF_EDGE_SHIFT));
        finish(dr, (cm.flags & CF_BLOCKED) ? MOUSE_CMD_BLOCKED : MOUSE_CMD_DONE);
    }
}

void cmd_step(drive_t *dr)
{
    switch (cm.kind) {
    case CMD_SENSE: /* standing still: wait for a reading taken now */
        if (motion_busy(&dr->mo) || !drive_fresh(dr)) return;
        {
            uint8_t w = walls_ahead(WALLS_HERE_FRONT_MM);
            /* the diagonal sensors look past a cell's end when standing at
             * its centre: the sides come from the rules (start cell) or
             * from when the cell was entered */
            if (dr->ex.cell == dr->ex.map.start && dr->ex.heading == dr->ex.map.start_heading)
                w |= EXPLORE_WALL_LEFT | EXPLORE_WALL_RIGHT;
            else {
                if (!maze_passable(&dr->ex.map, dr->ex.cell, maze_turn(dr->ex.heading, -1), 0)) w |= EXPLORE_WALL_LEFT;
                if (!maze_passable(&dr->ex.map, dr->ex.cell, maze_turn(dr->ex.heading, 1), 0)) w |= EXPLORE_WALL_RIGHT;
            }
            explore_sense(&dr->ex, w);
        }
        finish(dr, MOUSE_CMD_DONE);
        break;
    case CMD_FORWARD:
        forward_step(dr);
        break;
    case CMD_TURN:
        if (!drive_turn_done(dr)) return;
        /* facing a wall: put the robot back on the cell's centre (as the
         * U-turn's middle step), so that the next turn sweeps clear; not on
         * a boundary (a post or a far wall ahead) */
        if (!(cm.flags & (CF_HALF | CF_DIAG)) && maze_wall(&dr->ex.map, dr->ex.cell, dr->st.heading) == MAZE_WALL_CLOSED &&
            !drive_front_fix(dr))
            return;
        finish(dr, MOUSE_CMD_DONE);
        break;
    default:
        break;
    }
}
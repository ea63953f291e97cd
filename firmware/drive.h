/* drive.h - the moves the search (search.h), the speed runs (runs.h,
 * slalomrun.h) and command mode (cmd.h) are made of, and the state they
 * share: the explorer with the mouse's map, the motion layer, the status,
 * and the move under way (drive_t). mouse.c owns the one drive_t and hands
 * it to each subsystem's step; nothing here keeps state of its own.
 *
 * A straight (drive_forward) reads the walls of the cell ahead once per
 * cell at its sensing point (drive_sense_point, drive_sense_cell_ahead),
 * centres on the side walls (drive_centring) and aligns its end on a wall
 * ahead (drive_align_front); standing before a wall, drive_front_fix puts
 * the robot on the cell's centre and squares its heading; drive_turn turns
 * on the spot (a U-turn in two quarters), drive_approach_turn runs a
 * straight into a smooth quarter turn. */
#ifndef DRIVE_H
#define DRIVE_H

#include <stdint.h>

#include "explore.h"
#include "hal.h"
#include "motion.h"
#include "mouse.h"

/* what the loop is waiting for */
enum { WAIT_NONE, WAIT_MOVE, WAIT_TURN, WAIT_SMOOTH };
/* the walls of the cell ahead during this move: not read yet, readings
 * marked at RC_SENSE_FROM_MM (tof_seq), read */
enum { SENSE_NONE, SENSE_MARKED, SENSE_DONE };

typedef struct {
    mouse_status_t st;
    uint8_t waiting;         /* WAIT_* */
    uint8_t sensed;          /* SENSE_* */
    int8_t next_dir;         /* heading to take at the end of the move, -1 none */
    uint8_t wall_ahead;      /* the move ends facing a wall */
    int8_t turn_pending;     /* +-1: a smooth turn starts when the straight ends */
    uint8_t uturn_stage;     /* 0, or the step of a U-turn under way */
    uint8_t fix_stage;       /* 0, or the step of a front-wall fix under way */
    /* readings' seq when the current move began, or (drive_sense_point)
     * when it came within RC_SENSE_FROM_MM of the cell ahead */
    uint8_t tof_seq[HAL_TOF_COUNT];
    uint8_t side_seq[2];     /* centring: the side readings last looked at, */
    int16_t side_dmm[2];     /* the offsets right of the centre line they give, 0.1 mm */
    uint8_t side_ok[2];      /* and whether they show a wall where it can be trusted */
    uint8_t front_seq;       /* front-wall alignment: the reading last used */
    uint8_t last_lateral_ok; /* last_lateral_mm holds an estimate of this straight */
    uint32_t stage_us;       /* when the current U-turn or front-fix step began */
    float smooth_offset_mm;  /* a smooth turn starts this far before the turn cell's centre */
    float smooth_length_mm;  /* and drives this far along its arc */
    float run_offset_mm;     /* speed runs: how far past st.cell's centre the robot is */
    float move_shift_mm;     /* the move under way ends this far before a cell centre */
    float last_lateral_mm;   /* the last centring estimate of this straight */
    explore_t ex;
    uint32_t start_us;       /* when the contest began (fw_setup) */
    motion_t mo;
} drive_t;

/* a console line: fmt a HAL_STR with up to two %u */
void drive_log(const char *fmt, unsigned a, unsigned b);
/* Relative quarter turns from heading h to heading d: 0, 1 (right), 2, -1. */
int8_t drive_quarter(uint8_t h, uint8_t d);
/* The walls of the cell ahead (EXPLORE_WALL_* bits), its centre to_centre mm away. */
uint8_t drive_read_walls(float to_centre);
void drive_centring(drive_t *dr);
void drive_no_centring(drive_t *dr);
void drive_align_front(drive_t *dr, float before_mm);
int drive_front_fix(drive_t *dr);
void drive_mark_readings(drive_t *dr);
int drive_fresh(drive_t *dr);
int drive_sense_point(drive_t *dr, float left_mm);
uint8_t drive_sense_cell_ahead(drive_t *dr, float to_centre);
void drive_forward(drive_t *dr, float mm, float speed, float v_end, float accel);
void drive_approach_turn(drive_t *dr);
void drive_turn(drive_t *dr, int8_t q);
int drive_turn_done(drive_t *dr);

#endif

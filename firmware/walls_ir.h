/* walls_ir.h - wall detection from IR reflectance sensors (hal_ir_raw),
 * with a calibration the backend may keep in non-volatile memory.
 *
 * The sensors' roles follow the robot's sensor set, told by hal_ir_count()
 * (the robot file's [ir.*] order, docs/ROBOTS.md):
 *   4: UKMARSBOT's advanced board: left front, left diagonal, right
 *      diagonal, right front (robots/ukmarsbot.ini);
 *   3: the basic board: front, right, left (robots/ukmarsbot-basic-12.ini).
 * A reading is lit minus dark; each sensor is judged against its own
 * reference, taken in a known pose:
 *   sides: backed against the start cell's rear wall, where the classic
 *          rules put a wall on both sides (walls_ir_calibrate_sides);
 *   front: backed against a rear wall with a wall at the far end of the
 *          same cell (walls_ir_calibrate_front).
 * A wall is there when the reading reaches WALLS_IR_*_PCT of its
 * reference. */
#ifndef WALLS_IR_H
#define WALLS_IR_H

#include <stdint.h>

#define WALLS_IR_MAGIC 0x4952u /* "IR": a calibration was stored */
/* mazerunner-core's thresholds as shares of its calibrated readings:
 * LEFT_THRESHOLD = RIGHT_THRESHOLD = 40 and FRONT_THRESHOLD = 45 of
 * SIDE_NOMINAL = FRONT_NOMINAL = 100 (config-robot-orion.h l.334-352) */
#define WALLS_IR_SIDE_PCT 40u
#define WALLS_IR_FRONT_PCT 45u
#define WALLS_IR_PASSES 16u /* schedule passes averaged by a calibration */

/* the sensors' roles */
enum { WALLS_IR_FRONT_L, WALLS_IR_FRONT_R, WALLS_IR_LEFT, WALLS_IR_RIGHT, WALLS_IR_ROLES };
/* The hal_ir index of role (WALLS_IR_*) for the robot's sensor set, 255:
 * none (no IR sensors, or a set of another size). */
uint8_t walls_ir_sensor(uint8_t role);

typedef struct {
    uint16_t magic;        /* WALLS_IR_MAGIC */
    uint16_t side_ref[2];  /* left, right side sensor's reading in the side pose */
    uint16_t front_ref[2]; /* the forward sensors' (left, right; basic: one, twice) in the front pose */
    uint8_t side_pct;      /* wall threshold, % of side_ref */
    uint8_t front_pct;     /* wall threshold, % of the front pair's sum of front_ref */
    uint8_t check;         /* 0x5a minus the sum of the bytes before it */
} walls_ir_cal_t;

/* The calibration in use (ORION's published one until another is set or
 * loaded); a backend may store and reload its bytes. */
walls_ir_cal_t *walls_ir_cal(void);
/* 1 if c is a sealed calibration (magic and check right) */
uint8_t walls_ir_cal_ok(const walls_ir_cal_t *c);
/* makes c's check match its bytes */
void walls_ir_cal_seal(walls_ir_cal_t *c);
/* Take the side (front) references from the sensors now, averaged over
 * WALLS_IR_PASSES passes of the backend's schedule (blocking: the main
 * loop only). 0 (nothing changed) if the robot has no IR sensors or a
 * reading is too small to be a wall. */
uint8_t walls_ir_calibrate_sides(void);
uint8_t walls_ir_calibrate_front(void);
/* Each role's reading in % of its reference (left, front, right). */
void walls_ir_levels(uint16_t pct[3]);

#endif

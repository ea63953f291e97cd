/* robot.h - the robot file: a robot as components (docs/ROBOTS.md).
 *
 * INI, one section per component, [KIND.NAME]:
 *   [chassis.NAME]          one: body, wheels, tyres, caster
 *   [motor.left], [motor.right]     the drives' motors, gearboxes, H-bridge
 *   [encoder.left], [encoder.right] counts per motor turn, channels
 *   [battery.NAME]          one: open-circuit voltage by charge, resistance
 *   [tof.NAME] [ir.NAME] [gyro.NAME] ...  sensors: any kind in
 *                           sensors/sensor.c's list, each with its pose on
 *                           the chassis (x_mm y_mm z_mm yaw_deg pitch_deg)
 * Lengths in mm, masses in g, angles in deg; the chassis frame has its
 * origin at the body's centre on the floor, x right, y forward, z up.
 * At most WORLD_TOF_COUNT (world.h) ToF sensors: left, front, right, in the
 * file's order. Bad files: "FILE:LINE: KIND.NAME.key: reason" (unknown
 * kind, missing key, pose outside the chassis, two components with one
 * name, a key given twice, an indented continuation line: inifile.h, ...).
 *
 * The paper's robot (robots/paper.ini) is built in: config_defaults loads
 * it, so a run without --robot is the paper's. */
#ifndef ROBOT_H
#define ROBOT_H

#include <stdio.h>

#include "config.h"

#define ROBOT_MAX_BYTES (1u << 20) /* bytes of a robot file */
#define ROBOT_MAX_IR 8             /* hal.h HAL_IR_MAX */

/* 0 if the robot fits the world's corridors, else -1 with "world.cell_m:
 * the robot is wider than a corridor (...)" in reason: checked once both
 * the config and the robot are known (run_load_config). */
int robot_fits(const simcfg_t *c, char *reason, size_t len);
/* The built-in paper robot into c->robot (aborts if the built-in
 * text does not load: a build error, caught by test_robot). */
void robot_defaults(simcfg_t *c);
/* Replace c's robot by the one in the file (its world numbers are
 * checked against c's: a robot wider than a corridor is an error).
 * 0, or -1 with one line in err; c is unchanged then. */
int robot_load(simcfg_t *c, const char *path, char *err, size_t errlen);
int robot_load_string(simcfg_t *c, const char *text, const char *name, char *err, size_t errlen);
/* The robot as a robot file (every key with its unit and source). */
void robot_print(const simcfg_t *c, FILE *out);
/* 1 if a config file's section is a robot's (a component kind, or the
 * sections that held the robot before robot files). */
int robot_section(const char *section);
/* The i-th part of kind `kind` (in the file's order), its index in
 * c->robot.part, or -1. */
int robot_part_of_kind(const simcfg_t *c, const char *kind, unsigned i);
/* The first ToF sensor's range, m (1.2 if the robot has none: the link's
 * distance scale). */
double robot_tof_range_m(const simcfg_t *c);
/* How many parts of kind `kind`. */
unsigned robot_count(const simcfg_t *c, const char *kind);

/* Every key a robot file's sections take, for tests: the fixed parts'
 * (kinds chassis, motor, encoder, battery), then for each sensor kind (in
 * sensors/sensor.c's order) the pose keys and the kind's own. How many,
 * and the i-th key's kind, name and range in the file's unit: 0, or -1
 * past the end. */
size_t robot_key_count(void);
int robot_key_info(size_t i, const char **kind, const char **key, double *min, double *max);
/* A word key's word for value v (robot_key_info's min..max are its
 * indexes); NULL for a number key or past the end. */
const char *robot_key_word(size_t i, double v);

#endif

/* validate.h - `mmsim --validate`: every model figure of the simulator checked
 * against an analytic value, a datasheet or a measurement, each scenario run
 * in the real simulator (sim/world: ODE, motors, encoders, sensors) on a
 * bench it builds (the robot lifted, its wheels locked, a corridor, an open
 * field), with the configured robot.
 *
 * A check passes when the measured value is within tolerance_pct of the
 * expected one (bound VALIDATE_NEAR), at most the expected one
 * (VALIDATE_MAX: a limit such as creep), or always (VALIDATE_REPORT: a
 * residual that is reported, with no bar). */
#ifndef VALIDATE_H
#define VALIDATE_H

#include <jansson.h>
#include <stdio.h>

#include "world/config.h"

enum { VALIDATE_NEAR, VALIDATE_MAX, VALIDATE_REPORT };

typedef struct {
    const char *name, *unit, *source;
    double expected, measured, tolerance_pct;
    int bound; /* VALIDATE_* */
    int pass;
} validate_check_t;

#define VALIDATE_MAX_CHECKS 64

/* Runs every scenario with config c; fills checks, returns their number. */
int validate_run(const simcfg_t *c, validate_check_t *checks);
/* The table (name, expected, measured, unit, tolerance, pass, source). */
void validate_print(const validate_check_t *checks, int n, FILE *out);
/* {"checks":[{"name","expected","measured","unit","tolerance_pct","source","pass","bound"}...]} */
json_t *validate_json(const validate_check_t *checks, int n);

#endif

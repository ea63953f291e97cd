/* validate.h - `mmsim --validate`: every model figure of the simulator checked
 * against an analytic value, a datasheet or a measurement, each scenario run
 * in the real simulator (sim/world: ODE, motors, encoders, sensors) on a
 * bench it builds (the robot lifted, its wheels locked, a corridor, an open
 * field), with the configured robot.
 *
 * Every check is of one kind and names its data in `source`:
 * - VALIDATE_FITTED: the model was built from this figure (a datasheet
 *   point it was fitted to, a robot-file measurement, the model's own
 *   input reproduced). Printed with its residual, never graded: it cannot
 *   tell a good model from a bad one.
 * - VALIDATE_PREDICTED: data the model was not built from (a datasheet
 *   point the fit left out, a measurement of the real robot the fit did
 *   not use, an independent solution of the same equations, a physical
 *   requirement). Graded at the config's step_s, the step a contest runs.
 * A predicted check passes when the measured value is within tolerance_pct
 * of the expected one (bound VALIDATE_NEAR) or at most the expected one
 * (VALIDATE_MAX: a limit such as creep); with VALIDATE_REPORT it is a
 * residual reported with no bar, like a fitted figure. */
#ifndef VALIDATE_H
#define VALIDATE_H

#include <jansson.h>
#include <stdio.h>

#include "world/config.h"

enum { VALIDATE_NEAR, VALIDATE_MAX, VALIDATE_REPORT };
enum { VALIDATE_PREDICTED, VALIDATE_FITTED };

typedef struct {
    const char *name, *unit, *source;
    double expected, measured, tolerance_pct;
    int bound; /* VALIDATE_NEAR, _MAX, _REPORT */
    int kind;  /* VALIDATE_PREDICTED, _FITTED */
    int pass;  /* graded checks: within the bar; others always 1 */
} validate_check_t;

/* The counts of the summary line: graded predictions and how many pass,
 * fitted figures, and predictions reported with no bar. */
typedef struct {
    int graded, passed, fitted, reported;
} validate_summary_t;

#define VALIDATE_MAX_CHECKS 64

/* Runs every scenario with config c; fills checks, returns their number. */
int validate_run(const simcfg_t *c, validate_check_t *checks);
/* 1 if check k is graded (a prediction with a bar): only these decide
 * whether validation passes. */
int validate_graded(const validate_check_t *k);
validate_summary_t validate_summary(const validate_check_t *checks, int n);
/* The table (name, kind, expected, measured, unit, tolerance, pass, source)
 * and its summary line "N of M predicted checks pass; K fitted figures
 * reported" (and "; R predictions reported with no bar" when there are). */
void validate_print(const validate_check_t *checks, int n, FILE *out);
/* {"checks":[{"name","kind","expected","measured","unit","tolerance_pct","source","pass","bound"}...],
 *  "predicted":M,"passed":N,"fitted":K,"reported":R}; "kind" is "fitted" or "predicted", "pass" null
 * for a check that is not graded. */
json_t *validate_json(const validate_check_t *checks, int n);

#endif

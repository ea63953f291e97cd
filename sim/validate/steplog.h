/* steplog.h - `mmsim --bench-log SPEC`: one bench run of the configured
 * robot printed as a CSV log in the form a builder records on the real
 * robot, for tools/mmfit (docs/ROBOTS.md, "Your own robot"):
 *   fwd:VOLTS  both motors stepped to +VOLTS from rest in an open field,
 *   rot:VOLTS  left -VOLTS, right +VOLTS (a spin in place, counter-clockwise):
 *     1.2 s, one row a millisecond: t_s,volts,left_counts,right_counts;
 *   ir:NAME:D_MM:ANGLE_DEG  sensor NAME facing a flat wall D_MM away along its
 *     axis, the wall turned ANGLE_DEG off square: one row,
 *     sensor,distance_mm,angle_deg,counts (mean lit minus dark of 64 samples). */
#ifndef VALIDATE_STEPLOG_H
#define VALIDATE_STEPLOG_H

#include <stdio.h>

#include "world/config.h"

/* Runs SPEC with config c and prints its log to out: 0, or -1 after one
 * line on stderr (a bad SPEC or an unknown sensor). */
int steplog_run(const simcfg_t *c, const char *spec, FILE *out);

#endif

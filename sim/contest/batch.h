/* batch.h - `mmsim --batch DIR`: every maze of a folder, one child process
 * per maze (run_one), `jobs` at a time; one JSON line per maze on stdout in
 * input order (a maze whose child printed none: exit_reason "no_result"). */
#ifndef BATCH_H
#define BATCH_H

#include "contest/run.h"

/* Returns the worst exit code of the runs (RUN_BAD_INPUT: no such folder;
 * RUN_EXTERNAL: pipe, fork or wait failed). */
int batch_run(const run_opts_t *o, const char *dir);

#endif

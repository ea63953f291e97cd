/* outfile.h - atomic output files: write to a temporary file in the same
 * folder, then rename over the target, so a reader never sees a file
 * half written and a failed write leaves nothing behind. */
#ifndef OUTFILE_H
#define OUTFILE_H

#include <stddef.h>
#include <stdio.h>

typedef struct {
    FILE *f;
    char tmp[4096];  /* the temporary file's path */
    char path[4096]; /* the target */
} outfile_t;

/* Open a temporary beside path. Returns 0, or -1 with one line in err. */
int outfile_open(outfile_t *o, const char *path, char *err, size_t errlen);
/* Flush, close and rename over the target. Returns 0, or -1 with one line
 * in err (the temporary is removed). */
int outfile_commit(outfile_t *o, char *err, size_t errlen);
/* Close and remove the temporary. */
void outfile_abort(outfile_t *o);

#endif

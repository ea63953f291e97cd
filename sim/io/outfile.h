/* outfile.h - atomic output files: write to a temporary file in the same
 * folder, then rename over the target, so a reader never sees a file
 * half written and a failed write leaves nothing behind (an existing file
 * at the target stays as it was). Several files that belong together are
 * all written (outfile_finish) before any is renamed (outfile_rename).
 * A SIGINT, SIGTERM or SIGHUP removes every temporary still open (the
 * first outfile_open installs the handler where the signal's action is
 * the default); SIGKILL cannot be caught: its temporaries stay. */
#ifndef OUTFILE_H
#define OUTFILE_H

#include <stddef.h>
#include <stdio.h>

typedef struct {
    FILE *f;
    char tmp[4096];  /* the temporary file's path */
    char path[4096]; /* the target */
} outfile_t;

/* Could path be written? An empty name or a folder is refused, then a
 * temporary is created beside it and removed. 0, or -1 with one line in
 * err ("PATH: is a directory", "PATH: cannot write: REASON"). For the
 * checks before a long run. */
int outfile_probe(const char *path, char *err, size_t errlen);
/* Open a temporary beside path. Returns 0, or -1 with one line in err. */
int outfile_open(outfile_t *o, const char *path, char *err, size_t errlen);
/* outfile_finish, then outfile_rename. Returns 0, or -1 with one line in
 * err (the temporary is removed). */
int outfile_commit(outfile_t *o, char *err, size_t errlen);
/* Flush, sync and close the temporary, which stays for outfile_rename.
 * Returns 0, or -1 with one line in err (the temporary is removed). */
int outfile_finish(outfile_t *o, char *err, size_t errlen);
/* Rename the finished temporary over the target. Returns 0, or -1 with
 * one line in err (the temporary is removed). */
int outfile_rename(outfile_t *o, char *err, size_t errlen);
/* Close (if open) and remove the temporary. */
void outfile_abort(outfile_t *o);
/* Remove every temporary still open; async-signal-safe, for a program's
 * own handler of a fatal signal and for an exit on a broken pipe. */
void outfile_unlink_live(void);

#endif

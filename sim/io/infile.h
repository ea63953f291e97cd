/* infile.h - input files (mazes, configs, LCM logs): regular files only,
 * opened without blocking and read with a size bound, so a FIFO, a device
 * such as /dev/zero or a directory is one error line instead of a hang or
 * a silent empty read. */
#ifndef INFILE_H
#define INFILE_H

#include <stddef.h>
#include <stdint.h>
#include <stdio.h>

#define INFILE_NO_LIMIT UINT64_MAX /* bytes: no limit here, the caller bounds its reads itself */

/* What infile_open checks before it opens path: 0, or -1 with its line. */
int infile_check(const char *path, uint64_t max_bytes, char *err, size_t errlen);

/* Open path for reading. It must be a regular file (checked before it is
 * opened: opening a FIFO would wait for a writer, a serial device would
 * reset its board) of at most max_bytes bytes. Returns the stream, its
 * size in *size_bytes (may be NULL), or NULL with one line in err:
 * "PATH: cannot open: REASON", "PATH: not a regular file (a directory)",
 * "PATH: too large (N bytes; at most M)". */
FILE *infile_open(const char *path, uint64_t max_bytes, uint64_t *size_bytes, char *err, size_t errlen);

/* The whole file in a malloc'd buffer with a NUL after its *len bytes
 * (free it), read through infile_open: at most the size it had when
 * opened (a file that grew meanwhile is an error). NULL with one line in
 * err. */
char *infile_read(const char *path, size_t max_bytes, size_t *len, char *err, size_t errlen);

#endif

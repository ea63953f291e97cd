/* stdstream.h - a tool's standard output, checked: a write that failed on
 * the way (a full disk, /dev/full, a closed pipe or descriptor) or a failed
 * flush or close is one error line with its reason and the external-failure
 * exit code, never a silent exit 0 after a half-written output. */
#ifndef STDSTREAM_H
#define STDSTREAM_H

/* First thing in main: stdout becomes a stream on descriptor 1 that keeps
 * the reason of the first write that failed (glibc's own stdout forgets
 * it); same buffering as before (by line on a terminal). If that cannot be
 * set up, stdout stays as it was and the reason may be unknown.
 * SIGPIPE and SIGXFSZ are ignored from now on: a write to a closed pipe
 * ends the tool at once with "PROG: stdout: Broken pipe" and exit 3 (its
 * temporary output files removed); a file over `ulimit -f` is a write
 * that fails with EFBIG, reported where it happens. */
void io_stdout_open(const char *prog);
/* Last thing in main: flush and close stdout. 0 if every write reached it;
 * else -1 after one line "PROG: stdout: REASON" on stderr (e.g. "No space
 * left on device"; "write error" when the reason is not known). */
int io_stdout_close(const char *prog);

#endif

/* stdstream.c - a tool's standard output, checked (see stdstream.h).
 * stdout is replaced by a glibc cookie stream (fopencookie; the GNU C
 * Library lets a program assign stdout) whose write loops over write(2)
 * on descriptor 1 and keeps the errno of the first failure. SIGPIPE and
 * SIGXFSZ are ignored: a closed pipe or a file over its size limit is a
 * write that fails (EPIPE, EFBIG), reported as every other. */
#define _GNU_SOURCE
#include "stdstream.h"

#include "outfile.h"

#include <errno.h>
#include <signal.h>
#include <stdio.h>
#include <string.h>
#include <unistd.h>

static int first_errno; /* of the first write or close that failed; 0 none */
static int installed;
static const char *prog_name = "mmsim";

/* The reader of a pipe has gone (`| head`): nothing more can reach it, so
 * the tool stops now, one line and the external-failure exit code, its
 * temporaries removed (exit() would flush this stream again). */
static void on_broken_pipe(void)
{
    char line[128];
    int n = snprintf(line, sizeof line, "%s: stdout: %s\n", prog_name, strerror(EPIPE));
    if (n > 0 && write(STDERR_FILENO, line, (size_t)n) < 0) { /* nothing left to tell it to */ }
    outfile_unlink_live();
    _exit(3);
}

static ssize_t fd1_write(void *cookie, const char *buf, size_t size)
{
    size_t done = 0;
    while (done < size) {
        ssize_t k = write(STDOUT_FILENO, buf + done, size - done);
        if (k < 0 && errno == EINTR) continue;
        if (k < 0 && errno == EPIPE) on_broken_pipe();
        if (k <= 0) {
            if (!first_errno) first_errno = k < 0 ? errno : EIO;
            return -1;
        }
        done += (size_t)k;
    }
    return (ssize_t)done;
}

static int fd1_close(void *cookie)
{
    if (close(STDOUT_FILENO) != 0 && errno != EINTR) {
        if (!first_errno) first_errno = errno;
        return -1;
    }
    return 0;
}

void io_stdout_open(const char *prog)
{
    prog_name = prog;
    signal(SIGPIPE, SIG_IGN);
    signal(SIGXFSZ, SIG_IGN);
    static const cookie_io_functions_t fns = { .read = NULL, .write = fd1_write, .seek = NULL, .close = fd1_close };
    fflush(stdout);
    FILE *f = fopencookie(NULL, "w", fns);
    if (!f) return;
    if (isatty(STDOUT_FILENO)) setvbuf(f, NULL, _IOLBF, BUFSIZ);
    stdout = f;
    installed = 1;
}

int io_stdout_close(const char *prog)
{
    /* an earlier write that failed left the error flag: its reason is in
     * first_errno (installed), else in what the data still waiting says */
    int bad = ferror(stdout) != 0, e = 0;
    errno = 0;
    if (fflush(stdout) != 0) {
        bad = 1;
        e = errno;
    }
    errno = 0;
    if (fclose(stdout) != 0) {
        bad = 1;
        if (!e) e = errno;
    }
    if (installed && first_errno) e = first_errno;
    if (!bad) return 0;
    fprintf(stderr, "%s: stdout: %s\n", prog, e ? strerror(e) : "write error");
    return -1;
}

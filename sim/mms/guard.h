/* guard.h - the process tree of an mms algorithm, held so that nothing it
 * starts outlives the run (Linux).
 *
 *   mmsim ── guardian ─┬─ holder   (keeps the algorithm's process group id)
 *   (subreaper)        └─ /bin/sh -c COMMAND ... (in the holder's group)
 *
 * The guardian is a child of mmsim and a child subreaper
 * (PR_SET_CHILD_SUBREAPER): whatever the algorithm starts and leaves
 * behind (also in a new session: `setsid cmd &`) becomes the guardian's
 * child when its parent ends. The guardian reaps them all and reports the
 * shell's exit status on a pipe. It ends the tree, SIGKILL to the group and
 * then to each child until it has none left, when mmsim closes the "life"
 * pipe: on mms_stop, and when mmsim dies in any way, SIGKILL included (the
 * pipe's write end closes with it). The holder and the shell get SIGKILL
 * if the guardian itself dies (PR_SET_PDEATHSIG); mmsim is a subreaper
 * too, so orphans then come to mmsim, which ends them in guard_stop.
 * What cannot be prevented: docs/MMS.md. */
#ifndef GUARD_H
#define GUARD_H

#include <stddef.h>
#include <sys/types.h>

typedef struct {
    pid_t guardian;  /* our child; 0 when reaped */
    pid_t shell;     /* the shell's pid (the guardian's child) */
    int life_fd;     /* write end: closed = end the tree; -1 once closed */
    int status_fd;   /* read end of the guardian's reports; -1 once at its end */
    int exited;      /* the shell has ended: */
    int exit_code;   /* its status (-1 if killed) */
    int exit_signal; /* the signal that ended it, 0 if none */
    int started;     /* guard_start forked the guardian; guard_stop not done yet */
} guard_t;

/* A guard_t with nothing started (guard_stop on it does nothing). */
void guard_init(guard_t *g);

/* Start /bin/sh -c command under a guardian, with stdin, stdout and stderr
 * on these descriptors (which stay open here: the caller closes its
 * copies). 0, or -1 with one line in err. */
int guard_start(guard_t *g, const char *command, int in_fd, int out_fd, int err_fd, char *err, size_t len);
/* Has the shell ended? Waits up to wait_s for the guardian's report; its
 * status goes into exit_code / exit_signal. */
int guard_shell_ended(guard_t *g, double wait_s);
/* End everything the algorithm started, SIGKILL, and reap the guardian
 * (SIGKILL to it if it has not finished in 10 s; then mmsim ends the
 * orphans itself). The shell's status is kept if it had ended before. */
void guard_stop(guard_t *g);
/* For a signal handler of mmsim (async-signal-safe): end the tree now and
 * wait for the guardian. */
void guard_stop_from_signal(void);

#endif

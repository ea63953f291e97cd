/* guard.c - the process tree of an mms algorithm under a guardian (see
 * guard.h). The guardian is a fork of mmsim that never returns to mmsim's
 * code: it only moves descriptors, forks, waits and kills. */
#define _GNU_SOURCE /* ppoll */
#include "guard.h"

#include "io/outfile.h"

#include <dirent.h>
#include <errno.h>
#include <fcntl.h>
#include <math.h>
#include <poll.h>
#include <signal.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/prctl.h>
#include <sys/syscall.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

enum { MSG_SHELL = 1, MSG_ENDED = 2 }; /* the guardian's reports on the status pipe */
typedef struct {
    int32_t kind;
    int32_t a, b; /* MSG_SHELL: the shell's pid (<= 0: it could not be started), errno; MSG_ENDED: signalled, code */
} msg_t;

enum { FD_IN, FD_OUT, FD_ERR, FD_LIFE, FD_STATUS, FD_COUNT }; /* the guardian's descriptors 0..4 */
#define SWEEP_MAX_S 5.0   /* the longest the guardian keeps killing */
#define GUARD_WAIT_S 10.0 /* mmsim's wait for the guardian's end */

static double now_s(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + ts.tv_nsec * 1e-9;
}

static void sleep_ms(long ms)
{
    struct timespec ts = { ms / 1000, (ms % 1000) * 1000000L };
    nanosleep(&ts, NULL);
}

/* The pids of this process's children (at most max), from /proc (the
 * parent field of each process's stat; covers every thread's children). */
static int list_children(pid_t *out, int max)
{
    DIR *d = opendir("/proc");
    if (!d) return 0;
    int n = 0, me = (int)getpid();
    struct dirent *e;
    while (n < max && (e = readdir(d))) {
        char path[300], buf[512];
        if (e->d_name[0] < '1' || e->d_name[0] > '9') continue;
        snprintf(path, sizeof path, "/proc/%s/stat", e->d_name);
        int fd = open(path, O_RDONLY | O_CLOEXEC);
        if (fd < 0) continue;
        ssize_t k = read(fd, buf, sizeof buf - 1);
        close(fd);
        if (k <= 0) continue;
        buf[k] = '\0';
        char *rp = strrchr(buf, ')'); /* after "pid (comm)": " state ppid ..." */
        int ppid;
        char state;
        if (rp && sscanf(rp + 1, " %c %d", &state, &ppid) == 2 && ppid == me) out[n++] = (pid_t)atoi(e->d_name);
    }
    closedir(d);
    return n;
}

typedef void (*reaped_fn)(pid_t pid, int status, void *ctx);

/* SIGKILL to the process group (if group > 0), then to every child, again
 * and again as orphans come, until there is no child left (0) or max_s
 * has passed (-1). Each child reaped is passed to note (if not NULL).
 * Killing an unreaped child by its pid is safe: its pid cannot be reused. */
static int sweep(pid_t group, double max_s, reaped_fn note, void *ctx)
{
    double t0 = now_s();
    if (group > 0) kill(-group, SIGKILL);
    for (;;) {
        pid_t kids[256];
        int n = list_children(kids, 256), reaped = 0, status;
        for (int i = 0; i < n; i++) kill(kids[i], SIGKILL);
        pid_t p;
        while ((p = waitpid(-1, &status, WNOHANG)) > 0) {
            if (note) note(p, status, ctx);
            reaped++;
        }
        if (p < 0 && errno == ECHILD) return 0;
        if (now_s() - t0 > max_s) return -1;
        if (!reaped) sleep_ms(1);
    }
}

/* ---- the guardian (a forked process, never returns) ---- */

typedef struct {
    pid_t shell, holder;
    int holder_reaped;
} tree_t;

static volatile sig_atomic_t guardian_stop;
static void on_guardian_term(int sig) { guardian_stop = 1; (void)sig; }
static void on_guardian_chld(int sig) { (void)sig; } /* wakes ppoll */

static void report(int32_t kind, int32_t a, int32_t b)
{
    msg_t m = { kind, a, b };
    ssize_t k = write(FD_STATUS, &m, sizeof m); /* one atomic write (< PIPE_BUF); mmsim may be gone */
    (void)k;
}

static void note_reaped(pid_t pid, int status, void *ctx)
{
    tree_t *t = ctx;
    if (pid == t->shell)
        report(MSG_ENDED, WIFSIGNALED(status), WIFSIGNALED(status) ? WTERMSIG(status) : WEXITSTATUS(status));
    if (pid == t->holder) t->holder_reaped = 1;
}

/* fds (in, out, err, life, status) as 0..4, everything else closed. */
static void own_descriptors(const int *fds)
{
    int hi[FD_COUNT];
    for (int i = 0; i < FD_COUNT; i++)
        if ((hi[i] = fcntl(fds[i], F_DUPFD, 10)) < 0) _exit(127);
    for (int i = 0; i < FD_COUNT; i++)
        if (dup2(hi[i], i) < 0) _exit(127);
#ifdef SYS_close_range
    if (syscall(SYS_close_range, FD_COUNT, ~0U, 0) == 0) goto closed;
#endif
    for (int fd = FD_COUNT; fd < 65536; fd++) close(fd); /* older kernels */
#ifdef SYS_close_range
closed:
#endif
    fcntl(FD_LIFE, F_SETFD, FD_CLOEXEC); /* not the shell's */
    fcntl(FD_STATUS, F_SETFD, FD_CLOEXEC);
}

/* The holder: a member of the algorithm's process group that does nothing,
 * so the group's id stays ours until the guardian reaps it. */
static void holder_main(pid_t guardian)
{
    setpgid(0, 0);
    prctl(PR_SET_PDEATHSIG, SIGKILL);
    if (getppid() != guardian) _exit(0);
    for (int fd = 0; fd < FD_COUNT; fd++) close(fd);
    for (;;) pause();
}

static void shell_main(pid_t guardian, pid_t group, const char *command, const sigset_t *mask)
{
    setpgid(0, group);
    prctl(PR_SET_PDEATHSIG, SIGKILL);
    if (getppid() != guardian) _exit(127);
    static const int sigs[] = { SIGINT, SIGQUIT, SIGHUP, SIGTERM, SIGPIPE, SIGCHLD };
    for (size_t i = 0; i < sizeof sigs / sizeof sigs[0]; i++) signal(sigs[i], SIG_DFL);
    sigprocmask(SIG_SETMASK, mask, NULL);
    execl("/bin/sh", "sh", "-c", command, (char *)NULL);
    _exit(127);
}

static void guardian_main(const char *command, const int *fds, const sigset_t *mask) __attribute__((noreturn));
static void guardian_main(const char *command, const int *fds, const sigset_t *mask)
{
    tree_t t = { 0, 0, 0 };
    pid_t me = getpid();
    setpgid(0, 0); /* not in mmsim's job: a signal to that group reaches mmsim, which ends us in order */
    prctl(PR_SET_CHILD_SUBREAPER, 1);
    signal(SIGINT, SIG_IGN);
    signal(SIGQUIT, SIG_IGN);
    signal(SIGHUP, SIG_IGN);
    signal(SIGPIPE, SIG_IGN);
    struct sigaction sa;
    memset(&sa, 0, sizeof sa);
    sa.sa_handler = on_guardian_term;
    sigaction(SIGTERM, &sa, NULL);
    sa.sa_handler = on_guardian_chld;
    sa.sa_flags = SA_NOCLDSTOP;
    sigaction(SIGCHLD, &sa, NULL);
    own_descriptors(fds);
    sigset_t chld, waiting = *mask;
    sigemptyset(&chld);
    sigaddset(&chld, SIGCHLD);
    sigaddset(&chld, SIGTERM);
    sigprocmask(SIG_BLOCK, &chld, NULL);
    sigdelset(&waiting, SIGCHLD);
    sigdelset(&waiting, SIGTERM);
    if ((t.holder = fork()) == 0) holder_main(me);
    if (t.holder > 0) {
        setpgid(t.holder, t.holder);
        if ((t.shell = fork()) == 0) shell_main(me, t.holder, command, mask);
        if (t.shell > 0) setpgid(t.shell, t.holder); /* also here: no race with a kill of the group */
    }
    report(MSG_SHELL, t.holder > 0 && t.shell > 0 ? (int32_t)t.shell : -1, errno);
    int null_fd = open("/dev/null", O_RDWR); /* the algorithm's pipes are not ours to hold */
    for (int fd = 0; fd < 3 && null_fd >= 0; fd++) dup2(null_fd, fd);
    while (t.shell > 0 && !guardian_stop) {
        struct pollfd p = { FD_LIFE, POLLIN, 0 };
        int r = ppoll(&p, 1, NULL, &waiting); /* until mmsim ends us, or a child ends */
        int status;
        pid_t c;
        while ((c = waitpid(-1, &status, WNOHANG)) > 0) note_reaped(c, status, &t);
        if (r > 0 || (r < 0 && errno != EINTR)) break; /* the life pipe: closed (or a byte) */
    }
    sweep(t.holder_reaped ? 0 : t.holder, SWEEP_MAX_S, note_reaped, &t);
    _exit(0);
}

/* ---- mmsim's side ---- */

static volatile pid_t live_guardian; /* for the signal handler */
static volatile int live_life_fd = -1;

void guard_stop_from_signal(void)
{
    int fd = live_life_fd;
    live_life_fd = -1;
    if (fd >= 0) close(fd);
    if (live_guardian > 0) waitpid(live_guardian, NULL, 0);
}

/* mmsim interrupted (Ctrl-C, kill): the guardian ends the algorithm's tree
 * (it sees the life pipe close), we wait for it, then die of the signal. */
static void on_fatal_signal(int sig)
{
    guard_stop_from_signal();
    outfile_unlink_live(); /* the run's temporary outputs (--lcm-log, --report) */
    signal(sig, SIG_DFL);
    raise(sig);
}

static void guard_signals(int on)
{
    static const int sigs[3] = { SIGINT, SIGTERM, SIGHUP };
    static void (*old[3])(int);
    for (int i = 0; i < 3; i++) {
        if (on) {
            old[i] = signal(sigs[i], on_fatal_signal);
            if (old[i] == SIG_IGN) signal(sigs[i], SIG_IGN); /* ignored stays ignored (nohup) */
        } else {
            signal(sigs[i], old[i] == SIG_ERR ? SIG_DFL : old[i]);
        }
    }
}

static int pipe_cloexec(int fd[2])
{
    if (pipe(fd) != 0) return -1;
    fcntl(fd[0], F_SETFD, FD_CLOEXEC);
    fcntl(fd[1], F_SETFD, FD_CLOEXEC);
    return 0;
}

/* The guardian's first report: the shell's pid. 0, or -1 with err. */
static int await_shell(guard_t *g, char *err, size_t len)
{
    msg_t m;
    struct pollfd p = { g->status_fd, POLLIN, 0 };
    ssize_t k = -1;
    if (poll(&p, 1, (int)(GUARD_WAIT_S * 1000)) > 0) k = read(g->status_fd, &m, sizeof m);
    if (k == (ssize_t)sizeof m && m.kind == MSG_SHELL && m.a > 0) {
        g->shell = (pid_t)m.a;
        return 0;
    }
    snprintf(err, len, "mms: cannot start the algorithm: %s", k == (ssize_t)sizeof m ? strerror(m.b) : "no answer");
    return -1;
}

void guard_init(guard_t *g)
{
    memset(g, 0, sizeof *g);
    g->life_fd = g->status_fd = -1;
    g->exit_code = -1;
}

int guard_start(guard_t *g, const char *command, int in_fd, int out_fd, int err_fd, char *err, size_t len)
{
    int life[2], st[2];
    guard_init(g);
    if (pipe_cloexec(life) != 0) {
        snprintf(err, len, "mms: pipe: %s", strerror(errno));
        return -1;
    }
    if (pipe_cloexec(st) != 0) {
        snprintf(err, len, "mms: pipe: %s", strerror(errno));
        close(life[0]);
        close(life[1]);
        return -1;
    }
    prctl(PR_SET_CHILD_SUBREAPER, 1); /* orphans come to us if the guardian dies */
    fflush(stdout);
    fflush(stderr);
    /* a SIGINT/SIGTERM/SIGHUP around the fork waits (blocked) until the
     * handler knows the guardian */
    sigset_t block, prev;
    sigemptyset(&block);
    sigaddset(&block, SIGINT);
    sigaddset(&block, SIGTERM);
    sigaddset(&block, SIGHUP);
    sigprocmask(SIG_BLOCK, &block, &prev);
    pid_t pid = fork();
    if (pid == 0) {
        int fds[FD_COUNT] = { in_fd, out_fd, err_fd, life[0], st[1] };
        guardian_main(command, fds, &prev);
    }
    close(life[0]);
    close(st[1]);
    if (pid < 0) {
        snprintf(err, len, "mms: fork: %s", strerror(errno));
        close(life[1]);
        close(st[0]);
        sigprocmask(SIG_SETMASK, &prev, NULL);
        prctl(PR_SET_CHILD_SUBREAPER, 0);
        return -1;
    }
    g->guardian = pid;
    g->life_fd = life[1];
    g->status_fd = st[0];
    g->started = 1;
    live_guardian = pid;
    live_life_fd = life[1];
    guard_signals(1);
    sigprocmask(SIG_SETMASK, &prev, NULL);
    int started = await_shell(g, err, len);
    fcntl(g->status_fd, F_SETFL, fcntl(g->status_fd, F_GETFL) | O_NONBLOCK);
    if (started != 0) {
        guard_stop(g);
        return -1;
    }
    return 0;
}

int guard_shell_ended(guard_t *g, double wait_s)
{
    double t0 = now_s();
    while (!g->exited && g->status_fd >= 0) {
        msg_t m;
        ssize_t k = read(g->status_fd, &m, sizeof m);
        if (k == (ssize_t)sizeof m) {
            if (m.kind == MSG_ENDED) {
                g->exited = 1;
                if (m.a) g->exit_signal = m.b;
                else g->exit_code = m.b;
            }
            continue;
        }
        if (k == 0 || (k < 0 && errno != EAGAIN && errno != EINTR)) { /* the guardian is gone */
            close(g->status_fd);
            g->status_fd = -1;
            break;
        }
        double left_ms = (wait_s - (now_s() - t0)) * 1000.0;
        if (left_ms <= 0) return 0;
        struct pollfd p = { g->status_fd, POLLIN, 0 };
        poll(&p, 1, (int)ceil(left_ms));
    }
    if (!g->exited && g->status_fd < 0 && g->shell) { /* no report: it died with its guardian (PR_SET_PDEATHSIG) */
        g->exited = 1;
        g->exit_signal = SIGKILL;
    }
    return g->exited;
}

void guard_stop(guard_t *g)
{
    guard_shell_ended(g, 0); /* its own status if it has ended, before the kill */
    live_life_fd = -1;
    if (g->life_fd >= 0) close(g->life_fd); /* the guardian ends the tree */
    g->life_fd = -1;
    if (g->guardian > 0) {
        double t0 = now_s();
        while (waitpid(g->guardian, NULL, WNOHANG) == 0) {
            if (now_s() - t0 > GUARD_WAIT_S) { /* stuck: it goes, its orphans come to us */
                kill(g->guardian, SIGKILL);
                waitpid(g->guardian, NULL, 0);
                break;
            }
            sleep_ms(1);
        }
    }
    g->guardian = 0;
    live_guardian = 0;
    if (g->status_fd >= 0) guard_shell_ended(g, GUARD_WAIT_S); /* the reports up to the guardian's end */
    if (g->status_fd >= 0) close(g->status_fd);
    g->status_fd = -1;
    if (!g->started) return;
    g->started = 0;
    sweep(0, SWEEP_MAX_S, NULL, NULL); /* orphans of a guardian that died early (mmsim has no other child here) */
    prctl(PR_SET_CHILD_SUBREAPER, 0);
    guard_signals(0);
}

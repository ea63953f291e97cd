/* batch.c - many contests as child processes (see batch.h).
 * A reaped child is matched among the running jobs only: process ids are
 * reused (pid_max 32768 here; a 481-maze batch beside a busy machine wraps
 * it, and matching an earlier, finished job lost two lines). */
#include "batch.h"

#include <errno.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <sys/wait.h>
#include <unistd.h>

#include "maze/mazedir.h"

typedef struct {
    const run_opts_t *o;
    char **names;
    size_t n, next, done, printed;
    pid_t *pid; /* 0: not started, or reaped */
    int *fd;    /* the read end of each started job's pipe */
    char **text; /* each finished job's output */
    int running, worst;
    size_t by_code[4]; /* finished jobs by exit code: ok, goal not reached, bad input, failed */
    int tty;           /* stderr is a terminal: a progress line */
} batch_t;

/* All a child wrote to its pipe, until end of file (NUL-terminated). */
static char *read_all(int fd)
{
    size_t len = 0, cap = 4096;
    char *buf = malloc(cap);
    for (;;) {
        if (!buf) return NULL;
        if (len + 1 >= cap) {
            char *b = realloc(buf, cap *= 2);
            if (!b) { free(buf); return NULL; }
            buf = b;
        }
        ssize_t k = read(fd, buf + len, cap - 1 - len);
        if (k < 0 && errno == EINTR) continue;
        if (k <= 0) break;
        len += (size_t)k;
    }
    buf[len] = '\0';
    return buf;
}

/* The line of a maze whose child printed no JSON (it died, or the maze
 * file was bad: its error line is on stderr): one line per maze all the same. */
static char *failed_line(const char *maze, int status)
{
    json_t *j = json_object();
    json_object_set_new(j, "maze", json_string(maze));
    json_object_set_new(j, "exit_reason", json_string("no_result"));
    if (WIFSIGNALED(status)) json_object_set_new(j, "signal", json_integer(WTERMSIG(status)));
    else json_object_set_new(j, "exit_code", json_integer(WIFEXITED(status) ? WEXITSTATUS(status) : -1));
    char *s = json_dumps(j, JSON_COMPACT | JSON_ENSURE_ASCII);
    json_decref(j);
    if (!s) return NULL;
    char *line = malloc(strlen(s) + 2);
    if (line) sprintf(line, "%s\n", s);
    free(s);
    return line;
}

/* SIGINT, SIGTERM or SIGHUP to the batch: the handler passes it on to
 * every running job at once; the loop then waits for them and the batch
 * dies of the signal. The signals are blocked except while waiting, so the
 * handler never sees the job table half updated. */
static const int stop_sigs[3] = { SIGINT, SIGTERM, SIGHUP };
static volatile sig_atomic_t stop_sig;
static batch_t *live;

static void on_stop(int sig)
{
    stop_sig = sig;
    for (size_t i = 0; live && i < live->next; i++)
        if (live->pid[i] > 0) kill(live->pid[i], sig);
}

/* Install (on) or restore the handlers; *blocked gets the three signals. */
static void batch_signals(int on, sigset_t *blocked)
{
    static struct sigaction old[3];
    sigemptyset(blocked);
    for (int i = 0; i < 3; i++) {
        sigaddset(blocked, stop_sigs[i]);
        if (!on) {
            sigaction(stop_sigs[i], &old[i], NULL);
            continue;
        }
        struct sigaction sa;
        memset(&sa, 0, sizeof sa);
        sa.sa_handler = on_stop; /* no SA_RESTART: the wait returns */
        sigfillset(&sa.sa_mask);
        sigaction(stop_sigs[i], &sa, &old[i]);
        if (old[i].sa_handler == SIG_IGN) sigaction(stop_sigs[i], &old[i], NULL); /* ignored stays ignored (nohup) */
    }
}

static int fail(batch_t *b, const char *what)
{
    fprintf(stderr, "mmsim: %s: %s\n", what, strerror(errno));
    b->worst = RUN_EXTERNAL;
    return -1;
}

/* The next maze in a child whose stdout is a pipe: 0, or -1 after an error line. */
static int start_job(batch_t *b)
{
    int p[2];
    if (pipe(p) != 0) return fail(b, "pipe");
    fflush(stdout);
    pid_t c = fork();
    if (c < 0) {
        close(p[0]);
        close(p[1]);
        return fail(b, "fork");
    }
    if (c == 0) {
        for (int i = 0; i < 3; i++) signal(stop_sigs[i], SIG_DFL); /* a job dies of them */
        sigset_t none;
        sigemptyset(&none);
        sigprocmask(SIG_SETMASK, &none, NULL);
        close(p[0]);
        for (size_t i = 0; i < b->next; i++) /* the other jobs' pipes are not this child's */
            if (b->pid[i]) close(b->fd[i]);
        if (dup2(p[1], STDOUT_FILENO) < 0) _exit(RUN_EXTERNAL);
        json_t *j;
        int rc = run_one(b->o, b->names[b->next], &j, 0);
        if (j) run_json_line(j);
        fflush(stdout);
        _exit(rc);
    }
    close(p[1]);
    b->pid[b->next] = c;
    b->fd[b->next] = p[0];
    b->next++;
    b->running++;
    return 0;
}

/* Any job that ended, its output kept, and what is complete in input order
 * printed. Its output (one JSON line, far below the pipe's 64 KB, so a child
 * never blocks on it) is read to the end after it is reaped. 0, or -1. */
static int reap_job(batch_t *b, const sigset_t *blocked)
{
    int status = 0;
    sigprocmask(SIG_UNBLOCK, blocked, NULL); /* a stop signal may come now */
    pid_t c = wait(&status);
    sigprocmask(SIG_BLOCK, blocked, NULL);
    if (c < 0) return errno == EINTR ? 0 : fail(b, "wait");
    size_t i = 0;
    while (i < b->next && b->pid[i] != c) i++;
    if (i == b->next) return 0; /* not one of the running jobs */
    char *out = read_all(b->fd[i]);
    close(b->fd[i]);
    b->pid[i] = 0;
    b->running--;
    b->done++;
    int code = WIFEXITED(status) ? WEXITSTATUS(status) : RUN_EXTERNAL;
    if (code > b->worst) b->worst = code;
    b->by_code[code >= 0 && code <= 3 ? code : 3]++;
    if (!out || !strchr(out, '{')) { /* no JSON from the child */
        free(out);
        out = failed_line(b->names[i], status);
    }
    b->text[i] = out ? out : strdup("");
    if (b->tty) fprintf(stderr, "\r[%zu/%zu] %-60.60s", b->done, b->n, b->names[i]);
    while (b->printed < b->n && b->text[b->printed]) { /* results in input order */
        fputs(b->text[b->printed], stdout);
        b->printed++;
    }
    return 0;
}

/* Has job c ended (it got the stop signal) within wait_s? Reaps it if so. */
static int reaped_within(pid_t c, double wait_s)
{
    for (int k = 0; k < (int)(wait_s * 100); k++) {
        if (waitpid(c, NULL, WNOHANG) == c) return 1;
        struct timespec ts = { 0, 10000000 };
        nanosleep(&ts, NULL);
    }
    return 0;
}

int batch_run(const run_opts_t *o, const char *dir)
{
    batch_t b = { .o = o, .tty = isatty(STDERR_FILENO) };
    long nn = mazedir_list_or_report(dir, &b.names);
    if (nn < 0) return RUN_BAD_INPUT;
    b.n = (size_t)nn;
    b.pid = calloc(b.n, sizeof *b.pid);
    b.fd = calloc(b.n, sizeof *b.fd);
    b.text = calloc(b.n, sizeof *b.text);
    int failed = !b.pid || !b.fd || !b.text;
    if (failed) {
        fprintf(stderr, "mmsim: out of memory\n");
        b.worst = RUN_EXTERNAL;
    }
    sigset_t blocked, prev;
    batch_signals(1, &blocked);
    sigprocmask(SIG_BLOCK, &blocked, &prev);
    live = &b;
    while (!failed && !stop_sig && b.done < b.n) {
        while (!failed && !stop_sig && b.running < o->jobs && b.next < b.n) failed = start_job(&b) != 0;
        if (!failed && !stop_sig) failed = reap_job(&b, &blocked) != 0;
        if (!failed && ferror(stdout)) { /* the results cannot be written: stop (mmsim's end says why) */
            failed = 1;
            b.worst = RUN_EXTERNAL;
        }
    }
    if (b.done && b.tty) fputc('\n', stderr); /* the end of the progress line */
    fflush(stdout);
    if (!failed && !stop_sig && !ferror(stdout)) /* a batch that ran to its end (a failure has its own line) */
        fprintf(stderr, "mmsim: --batch %s: %zu of %zu mazes run: %zu reached the goal, %zu did not, %zu bad input, %zu failed\n",
            dir, b.done, b.n, b.by_code[0], b.by_code[1], b.by_code[2], b.by_code[3]);
    for (size_t i = 0; b.pid && b.fd && i < b.next; i++)
        if (b.pid[i]) { /* after a failure or a stop signal: end the jobs still running */
            if (!stop_sig || !reaped_within(b.pid[i], 5.0)) kill(b.pid[i], SIGKILL);
            close(b.fd[i]);
            waitpid(b.pid[i], NULL, 0);
            b.pid[i] = 0;
        }
    live = NULL;
    batch_signals(0, &blocked);
    sigprocmask(SIG_SETMASK, &prev, NULL);
    if (stop_sig) { /* the jobs are gone: die of the signal, as without a batch */
        sigset_t one;
        sigemptyset(&one);
        sigaddset(&one, stop_sig);
        signal(stop_sig, SIG_DFL);
        sigprocmask(SIG_UNBLOCK, &one, NULL);
        raise(stop_sig);
    }
    for (size_t i = 0; b.text && i < b.n; i++) free(b.text[i]);
    mazedir_free(b.names, nn);
    free(b.text);
    free(b.pid);
    free(b.fd);
    return b.worst;
}

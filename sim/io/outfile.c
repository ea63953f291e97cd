/* outfile.c - atomic output files (see outfile.h). */
#include "outfile.h"

#include <errno.h>
#include <signal.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

/* The temporaries alive now, for outfile_unlink_live from a signal handler:
 * pointers to their outfile_t's tmp[] (an empty string once gone). */
#define LIVE_MAX 64
static char *volatile live[LIVE_MAX];

static void live_add(char *tmp)
{
    for (int i = 0; i < LIVE_MAX; i++)
        if (!live[i]) {
            live[i] = tmp;
            return;
        }
}

static void live_del(char *tmp)
{
    tmp[0] = '\0';
    for (int i = 0; i < LIVE_MAX; i++)
        if (live[i] == tmp) live[i] = NULL;
}

void outfile_unlink_live(void)
{
    for (int i = 0; i < LIVE_MAX; i++) {
        char *t = live[i];
        if (t && t[0]) unlink(t); /* unlink(2) is async-signal-safe */
    }
}

/* SIGINT, SIGTERM, SIGHUP: the temporaries removed, then the process dies of
 * the signal as it would have (the shell sees 128 + N). */
static void on_stop_signal(int sig)
{
    outfile_unlink_live();
    signal(sig, SIG_DFL);
    raise(sig);
}

/* Our handler where the signal still has its default action; a handler of
 * the program's own (sim/mms/guard.c, sim/contest/batch.c) calls
 * outfile_unlink_live itself, an ignored signal stays ignored (nohup). */
static void install_stop_handlers(void)
{
    static const int sigs[3] = { SIGINT, SIGTERM, SIGHUP };
    for (int i = 0; i < 3; i++) {
        struct sigaction old, sa;
        if (sigaction(sigs[i], NULL, &old) != 0 || old.sa_handler != SIG_DFL) continue;
        memset(&sa, 0, sizeof sa);
        sa.sa_handler = on_stop_signal;
        sigaction(sigs[i], &sa, NULL);
    }
}

int outfile_probe(const char *path, char *err, size_t errlen)
{
    struct stat st;
    size_t n = strlen(path);
    if (n == 0) {
        snprintf(err, errlen, "an empty file name");
        return -1;
    }
    if (path[n - 1] == '/' || (stat(path, &st) == 0 && S_ISDIR(st.st_mode))) {
        snprintf(err, errlen, "%s: is a directory", path);
        return -1;
    }
    outfile_t o;
    if (outfile_open(&o, path, err, errlen) != 0) return -1;
    outfile_abort(&o);
    return 0;
}

int outfile_open(outfile_t *o, const char *path, char *err, size_t errlen)
{
    o->f = NULL;
    o->tmp[0] = '\0';
    if (strlen(path) + 16 > sizeof o->tmp) {
        snprintf(err, errlen, "%.200s...: path too long", path);
        return -1;
    }
    snprintf(o->path, sizeof o->path, "%s", path);
    snprintf(o->tmp, sizeof o->tmp, "%s.tmp.XXXXXX", path);
    install_stop_handlers();
    /* a signal between mkstemp and live_add would leave the file: blocked */
    sigset_t stop, was;
    sigemptyset(&stop);
    sigaddset(&stop, SIGINT);
    sigaddset(&stop, SIGTERM);
    sigaddset(&stop, SIGHUP);
    sigprocmask(SIG_BLOCK, &stop, &was);
    int fd = mkstemp(o->tmp);
    if (fd >= 0) live_add(o->tmp);
    sigprocmask(SIG_SETMASK, &was, NULL);
    if (fd < 0) {
        snprintf(err, errlen, "%s: cannot write: %s", path, strerror(errno));
        o->tmp[0] = '\0';
        return -1;
    }
    mode_t um = umask(0); /* mkstemp makes 0600: give the usual 0666 & ~umask */
    umask(um);
    fchmod(fd, 0666 & ~um);
    o->f = fdopen(fd, "wb");
    if (!o->f) {
        snprintf(err, errlen, "%s: cannot write: %s", path, strerror(errno));
        close(fd);
        unlink(o->tmp);
        live_del(o->tmp);
        return -1;
    }
    return 0;
}

int outfile_finish(outfile_t *o, char *err, size_t errlen)
{
    int bad = ferror(o->f) != 0, e = 0; /* an earlier failure's reason is gone */
    if (fflush(o->f) != 0 || fsync(fileno(o->f)) != 0) bad = 1, e = errno;
    if (fclose(o->f) != 0 && !e) bad = 1, e = errno;
    o->f = NULL;
    if (bad) {
        unlink(o->tmp);
        live_del(o->tmp);
        snprintf(err, errlen, "%s: cannot write: %s", o->path, e ? strerror(e) : "write error");
        return -1;
    }
    return 0;
}

int outfile_rename(outfile_t *o, char *err, size_t errlen)
{
    if (rename(o->tmp, o->path) != 0) {
        int e = errno;
        unlink(o->tmp);
        live_del(o->tmp);
        snprintf(err, errlen, "%s: cannot write: %s", o->path, strerror(e));
        return -1;
    }
    live_del(o->tmp);
    return 0;
}

int outfile_commit(outfile_t *o, char *err, size_t errlen)
{
    if (outfile_finish(o, err, errlen) != 0) return -1;
    return outfile_rename(o, err, errlen);
}

void outfile_abort(outfile_t *o)
{
    if (o->f) fclose(o->f);
    o->f = NULL;
    if (o->tmp[0]) unlink(o->tmp);
    live_del(o->tmp);
}

/* outfile.c - atomic output files (see outfile.h). */
#include "outfile.h"

#include <errno.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

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
    int fd = mkstemp(o->tmp);
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
        o->tmp[0] = '\0';
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
        o->tmp[0] = '\0';
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
        o->tmp[0] = '\0';
        snprintf(err, errlen, "%s: cannot write: %s", o->path, strerror(e));
        return -1;
    }
    o->tmp[0] = '\0';
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
    o->tmp[0] = '\0';
}

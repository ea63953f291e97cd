/* infile.c - regular input files of a bounded size (see infile.h). */
#include "infile.h"

#include <errno.h>
#include <fcntl.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

static const char *kind(mode_t m)
{
    if (S_ISDIR(m)) return "a directory";
    if (S_ISFIFO(m)) return "a FIFO";
    if (S_ISCHR(m)) return "a character device";
    if (S_ISBLK(m)) return "a block device";
    if (S_ISSOCK(m)) return "a socket";
    return "not a file";
}

/* 0 if st is a regular file within max_bytes, else -1 with err. */
static int check(const char *path, const struct stat *st, uint64_t max_bytes, char *err, size_t errlen)
{
    if (!S_ISREG(st->st_mode)) {
        snprintf(err, errlen, "%s: not a regular file (%s)", path, kind(st->st_mode));
        return -1;
    }
    if ((uint64_t)st->st_size > max_bytes) {
        snprintf(err, errlen, "%s: too large (%llu bytes; at most %llu)", path, (unsigned long long)st->st_size,
                 (unsigned long long)max_bytes);
        return -1;
    }
    return 0;
}

int infile_check(const char *path, uint64_t max_bytes, char *err, size_t errlen)
{
    struct stat st;
    if (stat(path, &st) != 0) {
        snprintf(err, errlen, "%s: cannot open: %s", path, strerror(errno));
        return -1;
    }
    return check(path, &st, max_bytes, err, errlen);
}

FILE *infile_open(const char *path, uint64_t max_bytes, uint64_t *size_bytes, char *err, size_t errlen)
{
    struct stat st;
    if (infile_check(path, max_bytes, err, errlen) != 0) return NULL;
    /* O_NONBLOCK: if path was swapped for a FIFO since stat, open still
     * returns at once, and fstat below says what it is */
    int fd = open(path, O_RDONLY | O_NONBLOCK | O_NOCTTY | O_CLOEXEC);
    if (fd < 0) {
        snprintf(err, errlen, "%s: cannot open: %s", path, strerror(errno));
        return NULL;
    }
    if (fstat(fd, &st) != 0) {
        snprintf(err, errlen, "%s: cannot open: %s", path, strerror(errno));
        close(fd);
        return NULL;
    }
    if (check(path, &st, max_bytes, err, errlen) != 0) {
        close(fd);
        return NULL;
    }
    int flags = fcntl(fd, F_GETFL);
    if (flags >= 0) fcntl(fd, F_SETFL, flags & ~O_NONBLOCK);
    FILE *f = fdopen(fd, "rb");
    if (!f) {
        snprintf(err, errlen, "%s: cannot open: %s", path, strerror(errno));
        close(fd);
        return NULL;
    }
    if (size_bytes) *size_bytes = (uint64_t)st.st_size;
    return f;
}

char *infile_read(const char *path, size_t max_bytes, size_t *len, char *err, size_t errlen)
{
    uint64_t size;
    FILE *f = infile_open(path, max_bytes, &size, err, errlen);
    if (!f) return NULL;
    /* the size at open, one byte more to tell a file that grew, the NUL */
    char *buf = malloc((size_t)size + 2);
    if (!buf) {
        fclose(f);
        snprintf(err, errlen, "%s: out of memory", path);
        return NULL;
    }
    errno = 0;
    size_t n = fread(buf, 1, (size_t)size + 1, f);
    int read_errno = ferror(f) ? (errno ? errno : EIO) : 0;
    fclose(f);
    if (read_errno || n > size) {
        if (read_errno) snprintf(err, errlen, "%s: cannot read: %s", path, strerror(read_errno));
        else snprintf(err, errlen, "%s: cannot read: it grew while read", path);
        free(buf);
        return NULL;
    }
    buf[n] = '\0';
    *len = n;
    return buf;
}

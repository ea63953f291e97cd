/* lcmlog.c - reading LCM event logs with their checks (see lcmlog.h). */
#include "lcmlog.h"

#include <errno.h>
#include <stdio.h>
#include <string.h>
#include <sys/stat.h>

int lcmlog_each(const char *path, lcmlog_fn fn, void *ctx, long *events, char *err, size_t errlen)
{
    long n = 0, good_end = 0; /* byte after the last whole event */
    struct stat st;
    if (events) *events = 0;
    if (stat(path, &st) != 0 || !S_ISREG(st.st_mode)) {
        snprintf(err, errlen, "%s: cannot read: %s", path, errno == ENOENT ? strerror(errno) : "not a regular file");
        return -1;
    }
    errno = 0;
    lcm_eventlog_t *log = lcm_eventlog_create(path, "r");
    if (!log) {
        snprintf(err, errlen, "%s: cannot read: %s", path, errno ? strerror(errno) : "unknown error");
        return -1;
    }
    int rc = 0;
    lcm_eventlog_event_t *ev;
    while ((ev = lcm_eventlog_read_next_event(log)) != NULL) {
        n++;
        good_end = ftell(log->f);
        rc = fn(ctx, ev);
        lcm_eventlog_free_event(ev);
        if (rc) break;
    }
    lcm_eventlog_destroy(log);
    if (events) *events = n;
    if (rc) return rc;
    if (n == 0 && st.st_size > 0) {
        snprintf(err, errlen, "%s: not an LCM log (no event found)", path);
        return -1;
    }
    if (good_end < (long)st.st_size) {
        snprintf(err, errlen, "%s: truncated or corrupt event at byte %ld of %lld", path, good_end,
                 (long long)st.st_size);
        return -1;
    }
    return 0;
}

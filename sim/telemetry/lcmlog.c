/* lcmlog.c - reading LCM event logs with their checks (see lcmlog.h).
 *
 * The events are read here, not by liblcm's lcm_eventlog_read_next_event:
 * that one callocs whatever data length an event declares (a crafted 2 GB
 * length crashed mmlog and mmview) and skips garbage between events in
 * silence. A record is, big-endian: u32 sync 0xEDA1DA01, u64 event
 * number, u64 timestamp (us), u32 channel length, u32 data length, the
 * channel's bytes, the data's bytes. */
#include "lcmlog.h"

#include <lcm/lcm.h>
#include <stdarg.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "io/infile.h"

#define LCMLOG_SYNC 0xEDA1DA01u
#define LCMLOG_HEADER_BYTES 28

typedef struct {
    FILE *f;
    const char *path;
    uint64_t size, at; /* file size at open; offset of the next event, bytes */
    long n;            /* events read */
    char *err;
    size_t errlen;
    lcm_eventlog_event_t ev;
    size_t cap; /* bytes allocated at ev.data */
    char channel[LCM_MAX_CHANNEL_NAME_LENGTH + 1];
} reader_t;

static uint64_t be(const unsigned char *p, int bytes)
{
    uint64_t v = 0;
    for (int i = 0; i < bytes; i++) v = v << 8 | p[i];
    return v;
}

/* "PATH: event N at byte B: " and the reason. Returns -1. */
static int bad(reader_t *r, const char *fmt, ...)
{
    char text[200];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(text, sizeof text, fmt, ap);
    va_end(ap);
    snprintf(r->err, r->errlen, "%s: event %ld at byte %llu: %s", r->path, r->n + 1, (unsigned long long)r->at, text);
    return -1;
}

typedef unsigned long long ull;

/* The header's checks: the sync word, LCM's limits, the bytes left. */
static int check_header(reader_t *r, const unsigned char *h, uint64_t got)
{
    if (got < 4 || be(h, 4) != LCMLOG_SYNC) {
        if (r->n == 0) {
            snprintf(r->err, r->errlen, "%s: not an LCM log (no sync word 0x%08X at byte 0)", r->path, LCMLOG_SYNC);
            return -1;
        }
        return got < 4 ? bad(r, "truncated: %llu bytes", (ull)got) : bad(r, "corrupt: no sync word (0x%08llX)", (ull)be(h, 4));
    }
    if (got < LCMLOG_HEADER_BYTES) return bad(r, "truncated: %llu of the header's %d bytes", (ull)got, LCMLOG_HEADER_BYTES);
    uint64_t chan = be(h + 20, 4), data = be(h + 24, 4), left = r->size - r->at - LCMLOG_HEADER_BYTES;
    if (chan < 1 || chan > LCM_MAX_CHANNEL_NAME_LENGTH)
        return bad(r, "corrupt: channel length %llu bytes (LCM's are 1..%d)", (ull)chan, LCM_MAX_CHANNEL_NAME_LENGTH);
    if (data > LCM_MAX_MESSAGE_SIZE)
        return bad(r, "corrupt: data length %llu bytes (LCM's maximum is %d)", (ull)data, LCM_MAX_MESSAGE_SIZE);
    if (chan + data > left)
        return bad(r, "truncated: %llu bytes of channel and data declared, %llu left in the file", (ull)(chan + data),
                   (ull)left);
    return 0;
}

/* The next event into r->ev: 1, 0 at the end of the file, -1 on an error. */
static int next(reader_t *r)
{
    unsigned char h[LCMLOG_HEADER_BYTES];
    if (r->at == r->size) return 0;
    uint64_t want = r->size - r->at < sizeof h ? r->size - r->at : sizeof h;
    if (fread(h, 1, (size_t)want, r->f) != want) return bad(r, "cannot read: the file shrank");
    if (check_header(r, h, want) != 0) return -1;
    uint64_t chan = be(h + 20, 4), data = be(h + 24, 4);
    if (data + 1 > r->cap) { /* + 1: never a 0-byte block */
        void *grown = realloc(r->ev.data, (size_t)data + 1);
        if (!grown) return bad(r, "out of memory for %llu bytes of data", (ull)data);
        r->ev.data = grown;
        r->cap = (size_t)data + 1;
    }
    if (fread(r->channel, 1, (size_t)chan, r->f) != chan || fread(r->ev.data, 1, (size_t)data, r->f) != data)
        return bad(r, "cannot read: the file shrank");
    r->channel[chan] = '\0';
    r->ev.channel = r->channel;
    r->ev.eventnum = (int64_t)be(h + 4, 8);
    r->ev.timestamp = (int64_t)be(h + 12, 8);
    r->ev.channellen = (int32_t)chan;
    r->ev.datalen = (int32_t)data;
    r->at += LCMLOG_HEADER_BYTES + chan + data;
    return 1;
}

int lcmlog_each(const char *path, lcmlog_fn fn, void *ctx, long *events, char *err, size_t errlen)
{
    reader_t r;
    memset(&r, 0, sizeof r);
    r.path = path;
    r.err = err;
    r.errlen = errlen;
    if (events) *events = 0;
    r.f = infile_open(path, LCMLOG_MAX_BYTES, &r.size, err, errlen);
    if (!r.f) return -1;
    int rc;
    while ((rc = next(&r)) == 1) {
        r.n++;
        if ((rc = fn(ctx, &r.ev)) != 0) break;
    }
    fclose(r.f);
    free(r.ev.data);
    if (events) *events = r.n;
    return rc;
}

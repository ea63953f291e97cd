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

/* ---- messages with arrays or strings ----
 * lcm-gen's decoders malloc what a message's count or string length says
 * before checking it against the data (a negative count asks for ~2^64
 * bytes), leave what they allocated when they fail half way, and do not
 * check that a string ends in its NUL. So the layout of these types is
 * checked here first, field by field as lcm/belief_t.lcm, lcm/maze_t.lcm,
 * lcm/parts_t.lcm (with lcm/part_t.lcm) and lcm/watch_t.lcm declare them
 * (keep in step). */
typedef struct {
    const unsigned char *d;
    int64_t len, at;
    int ok;
} cursor_t;

static void skip(cursor_t *c, int64_t n)
{
    if (n < 0 || n > c->len - c->at) c->ok = 0;
    else c->at += n;
}

static int64_t count16(cursor_t *c) /* an int16_t array length, >= 0 */
{
    if (c->len - c->at < 2) return c->ok = 0;
    int16_t v = (int16_t)be(c->d + c->at, 2);
    c->at += 2;
    if (v < 0) c->ok = 0;
    return v < 0 ? 0 : v;
}

static int64_t count8(cursor_t *c) /* an int8_t array length, >= 0 */
{
    if (c->len - c->at < 1) return c->ok = 0;
    int8_t v = (int8_t)c->d[c->at];
    c->at += 1;
    if (v < 0) c->ok = 0;
    return v < 0 ? 0 : v;
}

static void string(cursor_t *c) /* int32_t length with its NUL, the bytes */
{
    if (c->len - c->at < 4) {
        c->ok = 0;
        return;
    }
    int32_t n = (int32_t)be(c->d + c->at, 4);
    c->at += 4;
    if (n < 1 || n > c->len - c->at || c->d[c->at + n - 1] != 0) c->ok = 0;
    else c->at += n;
}

static int belief_layout_ok(const void *data, int len)
{
    cursor_t c = { data, len, 0, 1 };
    skip(&c, 8 + 8 + 1 + 1); /* hash, utime, width, height */
    int64_t cells = count16(&c);
    skip(&c, cells * 1 + cells * 2 + 2 + 1 + 1); /* walls, cost, cell, heading, state */
    skip(&c, count16(&c) * 2);                   /* path */
    return c.ok && c.at == len;
}

static int maze_layout_ok(const void *data, int len)
{
    cursor_t c = { data, len, 0, 1 };
    skip(&c, 8 + 8); /* hash, utime */
    string(&c);      /* path */
    skip(&c, 1 + 1); /* width, height */
    skip(&c, count16(&c) + 2 + 1); /* walls, start, start_heading */
    skip(&c, count16(&c) * 2 + 1 + 8); /* goals, centre_post, seed */
    string(&c);                        /* config */
    string(&c);                        /* robot */
    return c.ok && c.at == len;
}

static int parts_layout_ok(const void *data, int len)
{
    cursor_t c = { data, len, 0, 1 };
    skip(&c, 8 + 8); /* hash, utime */
    int64_t n = count16(&c);
    for (int64_t i = 0; i < n && c.ok; i++) { /* part_t, nested: no hash of its own */
        string(&c);                /* kind */
        string(&c);                /* name */
        skip(&c, count8(&c) * 8);  /* values */
        string(&c);                /* units */
    }
    skip(&c, 8 + 8);           /* battery_v, battery_soc */
    skip(&c, count8(&c) * 1);  /* emitter */
    return c.ok && c.at == len;
}

static int watch_layout_ok(const void *data, int len)
{
    cursor_t c = { data, len, 0, 1 };
    skip(&c, 8 + 8); /* hash, utime */
    int64_t n = count16(&c);
    for (int64_t i = 0; i < 2 * n && c.ok; i++) string(&c); /* name[], then type[] */
    skip(&c, n * 8);                                        /* value */
    return c.ok && c.at == len;
}

int lcmlog_decode_belief(const void *data, int len, mmlcm_belief_t *m)
{
    memset(m, 0, sizeof *m);
    if (!belief_layout_ok(data, len)) return -1;
    if (mmlcm_belief_t_decode(data, 0, len, m) == len) return 0;
    mmlcm_belief_t_decode_cleanup(m); /* the fields are zero where it stopped */
    memset(m, 0, sizeof *m);
    return -1;
}

int lcmlog_decode_maze(const void *data, int len, mmlcm_maze_t *m)
{
    memset(m, 0, sizeof *m);
    if (!maze_layout_ok(data, len)) return -1;
    if (mmlcm_maze_t_decode(data, 0, len, m) == len) return 0;
    mmlcm_maze_t_decode_cleanup(m);
    memset(m, 0, sizeof *m);
    return -1;
}

int lcmlog_decode_parts(const void *data, int len, mmlcm_parts_t *m)
{
    memset(m, 0, sizeof *m);
    if (!parts_layout_ok(data, len)) return -1;
    if (mmlcm_parts_t_decode(data, 0, len, m) == len) return 0;
    mmlcm_parts_t_decode_cleanup(m);
    memset(m, 0, sizeof *m);
    return -1;
}

int lcmlog_decode_watch(const void *data, int len, mmlcm_watch_t *m)
{
    memset(m, 0, sizeof *m);
    if (!watch_layout_ok(data, len)) return -1;
    if (mmlcm_watch_t_decode(data, 0, len, m) == len) return 0;
    mmlcm_watch_t_decode_cleanup(m);
    memset(m, 0, sizeof *m);
    return -1;
}

/* fuzz_lcmlog.c - libFuzzer target for the LCM log reader (make fuzz).
 *
 * The input is written to a file and read with lcmlog_each (what mmlog and
 * mmview do with a log): never a crash, an overread or a large allocation
 * (ASan's allocation limit is on), and either every byte of the file is
 * in the events passed on, or one error line "PATH: ..." with the events
 * before it counted. Each event's data also goes through every generated
 * mmlcm decoder, as mmlog's and the replay's decoding of untrusted logs. */
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "mmlcm_belief_t.h"
#include "mmlcm_link_t.h"
#include "mmlcm_maze_t.h"
#include "mmlcm_motors_t.h"
#include "mmlcm_parts_t.h"
#include "mmlcm_pose_t.h"
#include "mmlcm_race_event_t.h"
#include "mmlcm_race_t.h"
#include "mmlcm_sensors_t.h"
#include "telemetry/lcmlog.h"

static char path[64];

typedef struct {
    long events;
    uint64_t bytes;
} count_t;

static void check(int ok, const char *what)
{
    if (!ok) {
        fprintf(stderr, "fuzz_lcmlog: %s\n", what);
        abort();
    }
}

/* Every decoder on the data, as mmlog and the replay decode it: the
 * fixed-size types directly (they allocate nothing), the three with arrays
 * and strings through lcmlog_decode_*. */
#define DECODE(type)                                                        \
    do {                                                                    \
        type m;                                                             \
        int used = type##_decode(ev->data, 0, ev->datalen, &m);             \
        check(used <= ev->datalen, #type " read past the data");          \
    } while (0)

static void decode_all(const lcm_eventlog_event_t *ev)
{
    DECODE(mmlcm_pose_t);
    DECODE(mmlcm_motors_t);
    DECODE(mmlcm_sensors_t);
    DECODE(mmlcm_race_t);
    DECODE(mmlcm_race_event_t);
    DECODE(mmlcm_link_t);
    mmlcm_belief_t b;
    if (lcmlog_decode_belief(ev->data, ev->datalen, &b) == 0) {
        check(b.ncells >= 0 && b.path_len >= 0, "belief counts");
        mmlcm_belief_t_decode_cleanup(&b);
    }
    mmlcm_maze_t mz;
    if (lcmlog_decode_maze(ev->data, ev->datalen, &mz) == 0) {
        check(strlen(mz.path) < (size_t)ev->datalen && strlen(mz.config) < (size_t)ev->datalen, "maze strings");
        mmlcm_maze_t_decode_cleanup(&mz);
    }
    mmlcm_parts_t pt;
    if (lcmlog_decode_parts(ev->data, ev->datalen, &pt) == 0) {
        check(pt.nparts >= 0 && pt.nemitters >= 0, "parts counts");
        for (int i = 0; i < pt.nparts; i++)
            check(pt.parts[i].nvalues >= 0 && strlen(pt.parts[i].units) < (size_t)ev->datalen, "part values and units");
        mmlcm_parts_t_decode_cleanup(&pt);
    }
    mmlcm_watch_t wt;
    if (lcmlog_decode_watch(ev->data, ev->datalen, &wt) == 0) {
        check(wt.nvars >= 0, "watch count");
        for (int i = 0; i < wt.nvars; i++)
            check(strlen(wt.name[i]) < (size_t)ev->datalen && strlen(wt.type[i]) < (size_t)ev->datalen, "watch strings");
        mmlcm_watch_t_decode_cleanup(&wt);
    }
}

static int on_event(void *ctx, const lcm_eventlog_event_t *ev)
{
    count_t *c = ctx;
    check(ev->channellen >= 1 && ev->channellen <= 63 && (int)strlen(ev->channel) <= ev->channellen, "channel");
    check(ev->datalen >= 0, "data length");
    c->events++;
    c->bytes += 28 + (uint64_t)ev->channellen + (uint64_t)ev->datalen;
    decode_all(ev);
    return 0;
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    if (!path[0]) /* in memory if there is a tmpfs (the disk's writes: 300 runs/s); removed after each run */
        snprintf(path, sizeof path, "%s/fuzz_lcmlog_%d.lcmlog", access("/dev/shm", W_OK) ? "/tmp" : "/dev/shm", (int)getpid());
    FILE *f = fopen(path, "wb");
    check(f && fwrite(data, 1, size, f) == size && fclose(f) == 0, "cannot write the input file");
    count_t c = { 0, 0 };
    long events = -1;
    char err[600] = "";
    int rc = lcmlog_each(path, on_event, &c, &events, err, sizeof err);
    check(events == c.events, "event count");
    if (rc == 0) {
        check(c.bytes == size, "a log read whole but not every byte in its events");
    } else {
        check(rc == -1, "return value");
        check(!strncmp(err, path, strlen(path)) && err[strlen(path)] == ':' && !strchr(err, '\n'), err);
        check(c.bytes < size, "an error although every byte was read");
    }
    unlink(path);
    return 0;
}

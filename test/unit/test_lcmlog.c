/* test_lcmlog.c - the LCM log reader on crafted logs: every event's
 * lengths are checked against LCM's limits and the file before anything is
 * read or allocated (a declared 2 GB data length crashed liblcm's reader),
 * one line "PATH: event N at byte B: ..." for the first bad event, the
 * events before it passed on, good logs read as liblcm wrote them. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <cmocka.h>

#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "telemetry/lcmlog.h"

static char path[64], err[600];

typedef struct {
    int n, stop_at;
    char last_channel[80];
    int64_t last_num, last_time;
    int32_t last_len;
    unsigned char last_byte;
} seen_t;

static int on_event(void *ctx, const lcm_eventlog_event_t *ev)
{
    seen_t *s = ctx;
    s->n++;
    snprintf(s->last_channel, sizeof s->last_channel, "%s", ev->channel);
    s->last_num = ev->eventnum;
    s->last_time = ev->timestamp;
    s->last_len = ev->datalen;
    s->last_byte = ev->datalen ? ((const unsigned char *)ev->data)[ev->datalen - 1] : 0;
    return s->n == s->stop_at ? 7 : 0;
}

static void put_be(FILE *f, uint64_t v, int bytes)
{
    for (int i = bytes - 1; i >= 0; i--) fputc((int)(v >> (8 * i)) & 0xff, f);
}

/* One record with the header's fields as given and `have` bytes after it. */
static void record(FILE *f, uint32_t sync, uint64_t num, uint32_t chan_len, uint32_t data_len, const char *chan,
                   size_t have)
{
    put_be(f, sync, 4);
    put_be(f, num, 8);
    put_be(f, 1000 * num, 8);
    put_be(f, chan_len, 4);
    put_be(f, data_len, 4);
    size_t c = strlen(chan);
    fwrite(chan, 1, c < have ? c : have, f);
    for (size_t i = c; i < have; i++) fputc((int)(i & 0xff), f);
}

static FILE *fresh(void)
{
    FILE *f = fopen(path, "wb");
    assert_non_null(f);
    return f;
}

/* lcmlog_each on path: its return value; err and the events seen. */
static int run(seen_t *s, long *events)
{
    memset(s, 0, sizeof *s);
    err[0] = '\0';
    return lcmlog_each(path, on_event, s, events, err, sizeof err);
}

static void want(const char *what, int events_before)
{
    seen_t s;
    long n = -1;
    assert_int_equal(run(&s, &n), -1);
    assert_int_equal(n, events_before);
    assert_int_equal(s.n, events_before);
    if (strncmp(err, path, strlen(path)) != 0 || !strstr(err, what)) fail_msg("'%s' does not say '%s'", err, what);
    assert_null(strchr(err, '\n'));
}

static void test_crafted_lengths(void **state)
{
    (void)state;
    FILE *f = fresh(); /* the reproduction: 0x7FFFFFFF bytes declared, 100 there */
    record(f, 0xEDA1DA01u, 0, 7, 0x7FFFFFFF, "MM_MAZE", 107);
    fclose(f);
    want(": event 1 at byte 0: corrupt: data length 2147483647 bytes (LCM's maximum is 268435456)", 0);
    f = fresh();
    record(f, 0xEDA1DA01u, 0, 7, 0xFFFFFFFFu, "MM_MAZE", 107);
    fclose(f);
    want(": event 1 at byte 0: corrupt: data length 4294967295 bytes", 0);
    f = fresh();
    record(f, 0xEDA1DA01u, 0, 7, 1000, "MM_MAZE", 107);
    fclose(f);
    want(": event 1 at byte 0: truncated: 1007 bytes of channel and data declared, 107 left in the file", 0);
    const uint32_t chans[] = { 0, 64, 0xFFFFFFFFu };
    for (int i = 0; i < 3; i++) {
        f = fresh();
        record(f, 0xEDA1DA01u, 0, chans[i], 4, "MM_MAZE", 200);
        fclose(f);
        want(": event 1 at byte 0: corrupt: channel length", 0);
    }
}

static void test_good_then_bad(void **state)
{
    (void)state;
    FILE *f = fresh();
    record(f, 0xEDA1DA01u, 1, 7, 3, "MM_POSE", 10);
    record(f, 0xEDA1DA01u, 2, 8, 0, "MM_EMPTY", 8); /* no data: fine */
    record(f, 0xEDA1DA01u, 3, 7, 5, "MM_RACE", 12);
    fclose(f);
    seen_t s;
    long n;
    assert_int_equal(run(&s, &n), 0);
    assert_int_equal(n, 3);
    assert_string_equal(s.last_channel, "MM_RACE");
    assert_true(s.last_num == 3 && s.last_time == 3000 && s.last_len == 5 && s.last_byte == 11);
    /* fn stops the reading with its own value */
    memset(&s, 0, sizeof s);
    s.stop_at = 2;
    assert_int_equal(lcmlog_each(path, on_event, &s, &n, err, sizeof err), 7);
    assert_int_equal(n, 2);
    /* garbage after two events: the third (at 74 = 28 + 10 + 28 + 8) has no sync word */
    f = fopen(path, "r+b");
    fseek(f, 0, SEEK_END);
    long end2 = ftell(f) - (28 + 12);
    fseek(f, end2, SEEK_SET);
    fputs("garbage!", f);
    fclose(f);
    want(": event 3 at byte 74: corrupt: no sync word (0x67617262)", 2);
    assert_int_equal(end2, 74);
    /* a header cut short after an event */
    assert_int_equal(truncate(path, end2 + 10), 0);
    f = fopen(path, "r+b");
    fseek(f, end2, SEEK_SET);
    put_be(f, 0xEDA1DA01u, 4);
    fclose(f);
    want(": event 3 at byte 74: truncated: 10 of the header's 28 bytes", 2);
}

static void test_not_a_log(void **state)
{
    (void)state;
    FILE *f = fresh();
    fputs("not a log at all\n", f);
    fclose(f);
    want(": not an LCM log (no sync word 0xEDA1DA01 at byte 0)", 0);
    f = fresh();
    fclose(f);
    seen_t s;
    long n = -1;
    assert_int_equal(run(&s, &n), 0); /* empty: no events, no error */
    assert_int_equal(n, 0);
    assert_int_equal(lcmlog_each("/tmp", on_event, &s, &n, err, sizeof err), -1);
    assert_string_equal(err, "/tmp: not a regular file (a directory)");
    assert_int_equal(lcmlog_each("/nonexistent/x.lcmlog", on_event, &s, &n, err, sizeof err), -1);
    assert_string_equal(err, "/nonexistent/x.lcmlog: cannot open: No such file or directory");
}

/* What liblcm writes is read back the same. */
static void test_liblcm_round_trip(void **state)
{
    (void)state;
    lcm_eventlog_t *lg = lcm_eventlog_create(path, "w");
    assert_non_null(lg);
    static uint8_t data[70000];
    for (size_t i = 0; i < sizeof data; i++) data[i] = (uint8_t)(i * 7);
    for (int i = 0; i < 5; i++) {
        lcm_eventlog_event_t ev = { 0, 123456789 + i, 11, (int32_t)(i * 17000), (char *)"MM_BELIEF_X", data };
        assert_int_equal(lcm_eventlog_write_event(lg, &ev), 0);
    }
    lcm_eventlog_destroy(lg);
    seen_t s;
    long n;
    assert_int_equal(run(&s, &n), 0);
    assert_int_equal(n, 5);
    assert_string_equal(s.last_channel, "MM_BELIEF_X");
    assert_true(s.last_num == 4 && s.last_time == 123456793 && s.last_len == 68000 && s.last_byte == (uint8_t)(67999 * 7));
}

/* MM_MAZE and MM_BELIEF from a log: lcm-gen's decoders would malloc what
 * a negative count or a huge string length says, leak when they fail half
 * way and accept a string without its NUL (then read past it). */
static void test_messages_with_arrays(void **state)
{
    (void)state;
    int8_t walls[4] = { 1, 2, 3, 4 };
    int16_t goals[1] = { 3 }, cost[4] = { 0, 1, 2, 3 }, path_cells[2] = { 0, 1 };
    mmlcm_maze_t mz = { 0, (char *)"m.txt", 2, 2, 4, walls, 0, 0, 1, goals, 1, 9, (char *)"[sim]\nstep_s = 0.001\n",
                        (char *)"[battery.main]\nocv_v = 7\n" };
    static uint8_t buf[512];
    int n = mmlcm_maze_t_encode(buf, 0, sizeof buf, &mz);
    assert_true(n > 0);
    mmlcm_maze_t out;
    assert_int_equal(lcmlog_decode_maze(buf, n, &out), 0);
    assert_string_equal(out.path, "m.txt");
    assert_string_equal(out.config, "[sim]\nstep_s = 0.001\n");
    assert_string_equal(out.robot, "[battery.main]\nocv_v = 7\n");
    assert_true(out.ncells == 4 && out.walls[3] == 4 && out.ngoals == 1 && out.goals[0] == 3 && out.seed == 9);
    mmlcm_maze_t_decode_cleanup(&out);
    /* the path's length (bytes 16..19) made huge, negative, 0; its NUL gone;
     * the robot's NUL gone (the last byte); a byte short; a byte more */
    const uint32_t lens[] = { 0x7FFFFFFF, 0xFFFFFFF0u, 0 };
    for (int i = 0; i < 3; i++) {
        uint8_t bad[512];
        memcpy(bad, buf, (size_t)n);
        for (int k = 0; k < 4; k++) bad[16 + k] = (uint8_t)(lens[i] >> (24 - 8 * k));
        assert_int_equal(lcmlog_decode_maze(bad, n, &out), -1);
        assert_null(out.path);
    }
    buf[20 + 5] = 'x'; /* "m.txt" then its NUL at 25 */
    assert_int_equal(lcmlog_decode_maze(buf, n, &out), -1);
    buf[25] = 0;
    buf[n - 1] = 'x';
    assert_int_equal(lcmlog_decode_maze(buf, n, &out), -1);
    buf[n - 1] = 0;
    assert_int_equal(lcmlog_decode_maze(buf, n - 1, &out), -1);
    assert_int_equal(lcmlog_decode_maze(buf, n + 1, &out), -1);
    assert_int_equal(lcmlog_decode_maze(buf, n, &out), 0);
    mmlcm_maze_t_decode_cleanup(&out);

    mmlcm_belief_t b = { 5, 2, 2, 4, walls, cost, 1, 2, 0, 2, path_cells };
    n = mmlcm_belief_t_encode(buf, 0, sizeof buf, &b);
    assert_true(n > 0);
    mmlcm_belief_t bo;
    assert_int_equal(lcmlog_decode_belief(buf, n, &bo), 0);
    assert_true(bo.ncells == 4 && bo.cost[3] == 3 && bo.path_len == 2 && bo.path[1] == 1);
    mmlcm_belief_t_decode_cleanup(&bo);
    buf[18] = 0xFF; /* ncells (bytes 18, 19) = -1 */
    buf[19] = 0xFF;
    assert_int_equal(lcmlog_decode_belief(buf, n, &bo), -1);
    assert_null(bo.walls);
    buf[18] = 0;
    buf[19] = 4;
    assert_int_equal(lcmlog_decode_belief(buf, n + 2, &bo), -1); /* trailing bytes: it decoded, then was cleaned up */
    assert_null(bo.walls);
}

/* MM_PARTS (nested part_t with strings and arrays): decoded whole or not
 * at all; a negative or huge count, a string without its NUL, bytes
 * missing or left over are refused before lcm-gen's decoder mallocs. */
static void test_parts(void **state)
{
    (void)state;
    double v0[3] = { 66.5, 0, 62.25 }, v1[2] = { 1.5, 2.5 };
    mmlcm_part_t parts[2] = { { (char *)"tof", (char *)"left", 3, v0, (char *)"mm timeout true_mm" },
                              { (char *)"gyro", (char *)"z", 2, v1, (char *)"dps true_dps" } };
    int8_t em[4] = { 0, 1, 0, 0 };
    mmlcm_parts_t m = { 7, 2, parts, 7.9, 0.5, 4, em };
    static uint8_t buf[512];
    int n = mmlcm_parts_t_encode(buf, 0, sizeof buf, &m);
    assert_true(n > 0);
    mmlcm_parts_t out;
    assert_int_equal(lcmlog_decode_parts(buf, n, &out), 0);
    assert_true(out.utime == 7 && out.nparts == 2 && out.nemitters == 4 && out.emitter[1] && out.battery_v == 7.9);
    assert_string_equal(out.parts[0].kind, "tof");
    assert_string_equal(out.parts[1].name, "z");
    assert_string_equal(out.parts[1].units, "dps true_dps");
    assert_true(out.parts[0].nvalues == 3 && out.parts[0].values[2] == 62.25 && out.parts[1].values[1] == 2.5);
    mmlcm_parts_t_decode_cleanup(&out);
    /* bytes: hash 0..7, utime 8..15, nparts 16..17, kind's length 18..21 and
     * "tof" 22..25, name's length 26..29 and "left" 30..34, nvalues 35 */
    static const struct { int at; uint8_t byte; } bad[] = {
        { 16, 0xFF }, { 17, 0x40 },              /* nparts -1 (with byte 17), then 0x4002 */
        { 18, 0x7F }, { 21, 0xF0 }, { 25, 'x' }, /* kind's length huge, 240; its NUL gone */
        { 35, 0xFF }, { 35, 0x7F },              /* nvalues -1, 127 */
    };
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
        uint8_t b[512];
        memcpy(b, buf, (size_t)n);
        b[bad[i].at] = bad[i].byte;
        if (i == 0) b[17] = 0xFF;
        assert_int_equal(lcmlog_decode_parts(b, n, &out), -1);
        assert_null(out.parts);
    }
    buf[n - 5] = 0xFF; /* nemitters -1 (the last 5 bytes: nemitters and 4 emitters) */
    assert_int_equal(lcmlog_decode_parts(buf, n, &out), -1);
    buf[n - 5] = 4;
    assert_int_equal(lcmlog_decode_parts(buf, n - 1, &out), -1);
    assert_int_equal(lcmlog_decode_parts(buf, n + 1, &out), -1);
    buf[0] ^= 1; /* another type's fingerprint: the layout fits, the decoder refuses */
    assert_int_equal(lcmlog_decode_parts(buf, n, &out), -1);
    assert_null(out.parts);
    buf[0] ^= 1;
    assert_int_equal(lcmlog_decode_parts(buf, n, &out), 0);
    mmlcm_parts_t_decode_cleanup(&out);
}

/* MM_WATCH (lcm/watch_t.lcm): decoded whole; a bad count, a string
 * without its NUL, bytes missing or left over refused before lcm-gen's
 * decoder mallocs. */
static void test_watch(void **state)
{
    (void)state;
    char *names[2] = { (char *)"ticks", (char *)"ratio" }, *types[2] = { (char *)"u16", (char *)"f32" };
    double v[2] = { 199, 24.875 };
    mmlcm_watch_t m = { 5000, 2, names, types, v };
    static uint8_t buf[256];
    int n = mmlcm_watch_t_encode(buf, 0, sizeof buf, &m);
    assert_true(n > 0);
    mmlcm_watch_t out;
    assert_int_equal(lcmlog_decode_watch(buf, n, &out), 0);
    assert_true(out.utime == 5000 && out.nvars == 2 && out.value[0] == 199 && out.value[1] == 24.875);
    assert_string_equal(out.name[1], "ratio");
    assert_string_equal(out.type[0], "u16");
    mmlcm_watch_t_decode_cleanup(&out);
    /* bytes: hash 0..7, utime 8..15, nvars 16..17, name[0]'s length 18..21 and "ticks" 22..27 */
    static const struct { int at; uint8_t byte; } bad[] = {
        { 16, 0xFF }, { 16, 0x40 }, /* nvars -1 (with byte 17), 0x4002 */
        { 18, 0x7F }, { 21, 0xF0 }, { 27, 'x' }, /* name's length huge, 240; its NUL gone */
    };
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
        uint8_t b[256];
        memcpy(b, buf, (size_t)n);
        b[bad[i].at] = bad[i].byte;
        if (i == 0) b[17] = 0xFF;
        assert_int_equal(lcmlog_decode_watch(b, n, &out), -1);
        assert_null(out.name);
    }
    assert_int_equal(lcmlog_decode_watch(buf, n - 1, &out), -1);
    assert_int_equal(lcmlog_decode_watch(buf, n + 1, &out), -1);
    buf[0] ^= 1; /* another type's fingerprint */
    assert_int_equal(lcmlog_decode_watch(buf, n, &out), -1);
    assert_null(out.name);
}

static int setup(void **state)
{
    (void)state;
    snprintf(path, sizeof path, "/tmp/test_lcmlog_%d.lcmlog", (int)getpid());
    return 0;
}

static int teardown(void **state)
{
    (void)state;
    unlink(path);
    return 0;
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_crafted_lengths),
        cmocka_unit_test(test_good_then_bad),
        cmocka_unit_test(test_not_a_log),
        cmocka_unit_test(test_liblcm_round_trip),
        cmocka_unit_test(test_messages_with_arrays),
        cmocka_unit_test(test_parts),
        cmocka_unit_test(test_watch),
    };
    return cmocka_run_group_tests_name("lcmlog", tests, setup, teardown);
}

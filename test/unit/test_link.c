/* test_link.c - the simulator's link end over a socketpair (the other end
 * plays the MCU): byte budget per step at the baud, queue drops, handshake,
 * silence timeout, compat manager messages (stop stops the robot, not the
 * run), receive pacing, garbage, disconnect; over a pty: compat's sensor
 * request kept over a reconnect; version 2 (ROBOT, GYRO, BATTERY, EMITTER
 * answered by IR) to a version-2 MCU only. No physics: link_step_io with
 * made-up readings. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <string.h>
#include <signal.h>
#include <sys/socket.h>
#include <fcntl.h>
#include <poll.h>
#include <math.h>
#include <termios.h>
#include <unistd.h>
#include <cmocka.h>

#include "link/link.h"
#include "wire.h"

static link_t lk;
static int peer;
static double pair_compat_range_m; /* open_pair's compat scale, m (0 = the default) */

static void open_pair(int protocol, uint32_t baud, double silence_s)
{
    int sv[2];
    assert_int_equal(socketpair(AF_UNIX, SOCK_STREAM, 0, sv), 0);
    fcntl(sv[0], F_SETFL, O_NONBLOCK);
    fcntl(sv[1], F_SETFL, O_NONBLOCK);
    link_opts_t o = { NULL, 0, baud, protocol, silence_s, pair_compat_range_m };
    link_open_fd(&lk, sv[0], "socketpair", &o, 0.001, 1200, 35832, NULL);
    peer = sv[1];
}

static void close_pair(void)
{
    link_close(&lk);
    if (peer >= 0) close(peer);
    peer = -1;
}

/* one step with encoder counts e and a ToF reading every 30 steps */
static int step(int32_t e, int16_t mo[2])
{
    link_io_t io;
    memset(&io, 0, sizeof io);
    io.t_us = (uint32_t)(lk.step + 1) * 1000u;
    io.encoder[0] = e;
    io.encoder[1] = -e;
    for (int i = 0; i < 3; i++)
        if ((lk.step + 1 + 10 * (uint64_t)i) % 30 == 0) {
            io.tof_new[i] = 1;
            io.tof_mm[i] = (uint16_t)(100 + i);
        }
    return link_step_io(&lk, &io, mo);
}

static size_t drain(uint8_t *buf, size_t cap)
{
    ssize_t k = read(peer, buf, cap);
    return k > 0 ? (size_t)k : 0;
}

static void send_msg(const wire_msg_t *m)
{
    uint8_t b[WIRE_FRAME_MAX];
    size_t n = wire_encode(m, b, sizeof b);
    assert_true(n > 0);
    assert_int_equal(write(peer, b, n), (ssize_t)n);
}

static void send_hello(void)
{
    wire_msg_t m = { .type = WIRE_HELLO, .u.hello = { WIRE_VERSION, WIRE_ROLE_MCU, 1200, 35832, 500 } };
    send_msg(&m);
}

static void test_compat_budget(void **state)
{
    static uint8_t all[20000];
    uint8_t buf[4096];
    size_t total = 0, most = 0;
    int16_t mo[2];
    open_pair(LINK_COMPAT, 115200, 10.0);
    step(0, mo);
    assert_int_equal(drain(buf, sizeof buf), 0); /* compat: nothing before requestEnableSensors */
    static const uint8_t enable[] = { 7, 2 };
    assert_int_equal(write(peer, enable, 2), 2);
    for (int s = 0; s < 1000; s++) {
        step(s * 3, mo);
        size_t n = drain(buf, sizeof buf);
        if (n > most) most = n;
        memcpy(all + total, buf, n);
        total += n;
    }
    assert_true(most <= 12); /* 11.52 bytes per 1 ms step at 115200 */
    assert_int_equal(lk.st.tx_dropped, 0);
    assert_int_equal(lk.st.tx_bytes, total);
    assert_true(total <= 11520 + 12);
    /* 6 B encoders each step + 3 B per ToF reading: 6,300 B/s of 11,520 */
    double u = link_util_tx(&lk);
    assert_true(u > 0.5 && u < 0.6);
    /* decode what the MCU got: counts sum up to what was sent, no error */
    wire_compat_rx_t rx;
    wire_msg_t m;
    wire_compat_rx_init(&rx, 1200);
    int32_t last = 0;
    int dist = 0;
    for (size_t i = 0; i < total; i++)
        if (wire_compat_decode_byte(&rx, all[i], &m)) {
            if (m.type == WIRE_ENCODER) last = m.u.encoder.left;
            if (m.type == WIRE_DISTANCE) dist++;
        }
    assert_int_equal(wire_stats_errors(&rx.stats), 0);
    assert_true(last > 2800 && last <= 999 * 3); /* the queue lags by at most a few steps */
    /* disabled: no sensor bytes at all */
    static const uint8_t disable[] = { 7, 3 };
    assert_int_equal(write(peer, disable, 2), 2);
    step(0, mo);
    step(0, mo);
    drain(buf, sizeof buf);
    for (int s = 0; s < 50; s++) step(0, mo);
    assert_int_equal(drain(buf, sizeof buf), 0);
    assert_true(dist >= 95);
    close_pair();
}

static void test_framed_overload_drops_whole(void **state)
{
    static uint8_t all[20000];
    int16_t mo[2];
    size_t total = 0;
    open_pair(LINK_FRAMED, 115200, 10.0);
    for (int s = 0; s < 1000; s++) {
        step(s, mo);
        total += drain(all + total, sizeof all - total);
    }
    assert_true(total <= 11521);
    assert_true(lk.st.tx_dropped > 300); /* 18,300 B/s offered, 11,520 allowed */
    wire_decoder_t d;
    wire_msg_t m;
    wire_decoder_init(&d);
    int32_t prev = -1;
    for (size_t i = 0; i < total; i++)
        if (wire_decode_byte(&d, all[i], &m) && m.type == WIRE_ENCODER) {
            assert_true(m.u.encoder.left > prev); /* fresh, never a torn frame */
            prev = m.u.encoder.left;
        }
    assert_int_equal(wire_stats_errors(&d.stats), 0);
    assert_true(d.stats.frames_ok > 500);
    close_pair();
}

/* version 2: made-up IR sensors; an EMITTER lights groups, each sensor reads
 * 100 x (its index + 1) + the lit groups */
static uint8_t lit;
static int samples;
static void fake_ir(void *ctx, uint8_t groups, uint16_t raw[WIRE_IR_MAX])
{
    lit = groups;
    samples++;
    for (int i = 0; i < 3; i++) raw[i] = (uint16_t)(100 * (i + 1) + groups);
    raw[3] = 5000; /* past the count: not sent */
}
static void step_v2(int16_t mo[2])
{
    link_io_t io;
    memset(&io, 0, sizeof io);
    io.t_us = (uint32_t)(lk.step + 1) * 1000u;
    io.ir_count = 3;
    io.has_gyro = 1;
    io.gyro_mdps = -123456;
    io.battery_mv = 8012;
    io.ir_sample = fake_ir;
    link_step_io(&lk, &io, mo);
}
/* the messages the MCU end received, counted per type; the last IR kept */
static void count_msgs(wire_decoder_t *d, unsigned counts[16], wire_msg_t *ir)
{
    uint8_t buf[4096];
    wire_msg_t m;
    size_t n = drain(buf, sizeof buf);
    for (size_t i = 0; i < n; i++)
        if (wire_decode_byte(d, buf[i], &m)) {
            counts[m.type & 15]++;
            if (m.type == WIRE_IR) *ir = m;
            if (m.type == WIRE_ROBOT) {
                assert_int_equal(m.u.robot.ir_count, 3);
                assert_int_equal(m.u.robot.flags, WIRE_ROBOT_GYRO | WIRE_ROBOT_BATTERY);
            }
            if (m.type == WIRE_GYRO) assert_int_equal(m.u.gyro.mdps, -123456);
            if (m.type == WIRE_BATTERY) assert_int_equal(m.u.battery.mv, 8012);
        }
}

static void test_v2_messages(void **state)
{
    for (uint8_t version = 1; version <= WIRE_VERSION; version++) {
        int16_t mo[2];
        wire_decoder_t d;
        wire_msg_t ir;
        unsigned c[16] = { 0 };
        open_pair(LINK_FRAMED, 1000000, 0.1);
        wire_decoder_init(&d);
        wire_msg_t h = { .type = WIRE_HELLO, .u.hello = { version, WIRE_ROLE_MCU, 1200, 35832, 250 } };
        send_msg(&h);
        for (int s = 0; s < 200; s++) step_v2(mo);
        count_msgs(&d, c, &ir);
        assert_int_equal(lk.mcu_version, version);
        assert_int_equal(c[WIRE_ENCODER], 51); /* step 1 (before the HELLO is read), then every 4th step */
        if (version < 2) { /* an old MCU: nothing it cannot decode */
            assert_int_equal(c[WIRE_ROBOT] + c[WIRE_GYRO] + c[WIRE_BATTERY] + c[WIRE_IR], 0);
            close_pair();
            continue;
        }
        assert_int_equal(c[WIRE_ROBOT], 1);
        assert_int_equal(c[WIRE_GYRO], 50);    /* with each ENCODER */
        assert_int_equal(c[WIRE_BATTERY], 2);  /* every 100 ms */
        assert_int_equal(c[WIRE_IR], 0);       /* only when asked */
        /* two EMITTERs in one step: two samples, two IR frames, out in that step */
        wire_msg_t e = { .type = WIRE_EMITTER, .u.emitter = { 0x5 } };
        send_msg(&e);
        e.u.emitter.groups = 0x2;
        send_msg(&e);
        samples = 0;
        step_v2(mo);
        count_msgs(&d, c, &ir);
        assert_int_equal(samples, 2);
        assert_int_equal(c[WIRE_IR], 2);
        assert_int_equal(ir.u.ir.seq, 2);
        assert_int_equal(ir.u.ir.emitters, 0x2);
        assert_int_equal(ir.u.ir.count, 3);
        for (uint8_t i = 0; i < 3; i++) assert_int_equal(wire_ir_get(&ir, i), 100 * (i + 1) + 2);
        assert_int_equal(lk.st.emitters, 2);
        assert_int_equal(lk.st.ir_frames, 2);
        /* a reset MCU says HELLO again: ROBOT again */
        send_msg(&h);
        step_v2(mo);
        step_v2(mo); /* read in the first step, sent in the next */
        count_msgs(&d, c, &ir);
        assert_int_equal(c[WIRE_ROBOT], 2);
        assert_int_equal(wire_stats_errors(&d.stats), 0);
        assert_int_equal(wire_stats_errors(&lk.dec.stats), 0);
        close_pair();
    }
}

static void test_handshake_and_motor(void **state)
{
    uint8_t buf[4096];
    int16_t mo[2];
    open_pair(LINK_FRAMED, 1000000, 0.1);
    wire_msg_t cmd = { .type = WIRE_MOTOR, .u.motor = { 0, 300, -200 } };
    send_msg(&cmd);
    for (int s = 0; s < 5; s++) step(0, mo);
    assert_int_equal(mo[0], 0); /* no HELLO yet: motors stay off */
    /* the sim's HELLO went out first */
    wire_decoder_t d;
    wire_msg_t m;
    wire_decoder_init(&d);
    size_t n = drain(buf, sizeof buf);
    int hello = 0;
    for (size_t i = 0; i < n; i++)
        if (wire_decode_byte(&d, buf[i], &m) && m.type == WIRE_HELLO) {
            hello++;
            assert_int_equal(m.u.hello.tof_range_mm, 1200);
            assert_int_equal(m.u.hello.role, WIRE_ROLE_SIM);
        }
    assert_int_equal(hello, 1);
    send_hello();
    send_msg(&cmd);
    step(0, mo);
    assert_int_equal(mo[0], 300);
    assert_int_equal(mo[1], -200);
    /* silence: 100 ms without a message -> 0 */
    for (int s = 0; s < 100; s++) {
        step(0, mo);
        drain(buf, sizeof buf);
    }
    assert_int_equal(mo[0], 300);
    step(0, mo);
    step(0, mo);
    assert_int_equal(mo[0], 0);
    assert_int_equal(lk.st.silences, 1);
    send_msg(&cmd);
    step(0, mo);
    assert_int_equal(mo[0], 300);
    /* garbage between frames: counted, the next command still lands */
    static const uint8_t junk[] = { 0x13, 0x37, 0xFF, 0x00, 0x05, 0x00, 0x42, 0x00 }; /* three bad chunks */
    assert_int_equal(write(peer, junk, sizeof junk), (ssize_t)sizeof junk);
    cmd.u.motor.left = 77;
    send_msg(&cmd);
    step(0, mo);
    assert_int_equal(mo[0], 77);
    assert_int_equal(wire_stats_errors(&lk.dec.stats), 3);
    /* run stop / start (framed stop: mmsim ends the run) */
    wire_msg_t run = { .type = WIRE_RUN, .u.flag = { 0 } };
    send_msg(&run);
    step(0, mo);
    assert_int_equal(mo[0], 0);
    assert_int_equal(lk.st.stops, 1);
    run.u.flag.on = 1;
    send_msg(&run);
    step(0, mo);
    assert_int_equal(mo[0], 77);
    /* a newer protocol version: motors off */
    wire_msg_t h = { .type = WIRE_HELLO, .u.hello = { WIRE_VERSION + 1, WIRE_ROLE_MCU, 1200, 35832, 500 } };
    send_msg(&h);
    step(0, mo);
    assert_int_equal(mo[0], 0);
    close_pair();
}

static void test_compat_manager_and_pacing(void **state)
{
    uint8_t b[1200];
    int16_t mo[2];
    open_pair(LINK_COMPAT, 115200, 10.0);
    static const uint8_t disable[] = { 7, 3 }, enable[] = { 7, 2 }, motor[] = { 5, 0x64, 0x00, 6, 0x9C, 0xFF };
    assert_int_equal(write(peer, disable, 2), 2);
    assert_int_equal(step(0, mo), 0);
    assert_int_equal(write(peer, enable, 2), 2);
    assert_int_equal(step(0, mo), 1);
    assert_int_equal(write(peer, motor, 6), 6);
    step(0, mo);
    assert_int_equal(mo[0], 100);
    assert_int_equal(mo[1], -100);
    /* ID 7 value 0 (stop) stops the robot, not the run: motors 0 while
     * commands arrive, until start; then a side drives from its next command */
    static const uint8_t stop[] = { 7, 0 }, start[] = { 7, 1 }, left[] = { 5, 0x32, 0x00 };
    assert_int_equal(write(peer, stop, 2), 2);
    step(0, mo);
    assert_int_equal(mo[0], 0);
    assert_int_equal(write(peer, motor, 6), 6);
    step(0, mo);
    assert_int_equal(mo[0], 0);
    assert_int_equal(mo[1], 0);
    assert_int_equal(lk.st.halts, 1);
    assert_int_equal(lk.st.stops, 0); /* mmsim ends the run on stops only */
    assert_int_equal(write(peer, start, 2), 2);
    assert_int_equal(write(peer, left, 3), 3);
    step(0, mo);
    assert_int_equal(mo[0], 50);
    assert_int_equal(mo[1], 0); /* the right side's 100 before the stop is forgotten */
    assert_int_equal(write(peer, motor, 6), 6);
    step(0, mo);
    assert_int_equal(mo[1], -100);
    /* 1,200 bytes at once: read at the baud, not faster */
    for (size_t i = 0; i < sizeof b; i += 2) { b[i] = 7; b[i + 1] = 2; }
    assert_int_equal(write(peer, b, sizeof b), (ssize_t)sizeof b);
    uint64_t before = lk.st.rx_bytes;
    step(0, mo);
    assert_true(lk.st.rx_bytes - before <= 12);
    for (int s = 0; s < 200; s++) step(0, mo);
    assert_int_equal(lk.st.rx_bytes, 29 + sizeof b);
    /* the MCU unplugged: motors off, reported */
    close(peer);
    peer = -1;
    step(0, mo);
    step(0, mo);
    assert_int_equal(lk.connected, 0);
    assert_int_equal(lk.st.disconnects, 1);
    assert_int_equal(mo[0], 0);
    close_pair();
}

/* Silence: compat holds the last motor command for ever by
 * default (the paper's sketches send a command only when it changes; its
 * Unity simulator has no watchdog); framed's default is 100 ms; 0 turns the
 * watchdog off in either protocol; a positive value turns it on in compat. */
static void test_silence_defaults_and_off(void **state)
{
    static const uint8_t enable[] = { 7, 2 }, motor[] = { 5, 0x2C, 0x01, 6, 0x2C, 0x01 }; /* 300, 300 */
    uint8_t sink[4096];
    int16_t mo[2];
    open_pair(LINK_COMPAT, 115200, -1); /* the default */
    assert_true(lk.o.silence_s == 0.0);
    assert_int_equal(write(peer, enable, 2), 2);
    assert_int_equal(write(peer, motor, 6), 6);
    for (int s = 0; s < 60000; s++) { /* a minute of nothing but sensor readings */
        step(s, mo);
        drain(sink, sizeof sink);
        if (s > 0 && (mo[0] != 300 || mo[1] != 300)) fail_msg("compat dropped the held command at step %d", s);
    }
    assert_int_equal(lk.st.silences, 0);
    close_pair();
    open_pair(LINK_COMPAT, 115200, 0.1); /* asked for: compat has a watchdog too */
    assert_int_equal(write(peer, motor, 6), 6);
    for (int s = 0; s < 200; s++) step(0, mo);
    assert_int_equal(mo[0], 0);
    assert_int_equal(lk.st.silences, 1);
    close_pair();
    for (int off = 0; off < 2; off++) { /* framed: default 100 ms; 0 = never */
        wire_msg_t cmd = { .type = WIRE_MOTOR, .u.motor = { 0, 300, 300 } };
        open_pair(LINK_FRAMED, 1000000, off ? 0.0 : -1);
        assert_true(lk.o.silence_s == (off ? 0.0 : LINK_SILENCE_S));
        send_hello();
        send_msg(&cmd);
        for (int s = 0; s < 5000; s++) {
            step(0, mo);
            drain(sink, sizeof sink);
        }
        assert_int_equal(mo[0], off ? 300 : 0);
        assert_int_equal(lk.st.silences, off ? 0 : 1);
        close_pair();
    }
}

/* Faults on the wire MCU -> sim: motor frames hit by drops, bit flips and
 * garbage bursts; the link reads them at the baud and its decoder must count
 * exactly one error per corrupted chunk between delimiters, and apply every
 * intact command. */
static void test_faults_through_link(void **state)
{
    enum { N = 400 };
    static uint8_t clean[N * 16], bad[N * 16 * 4];
    static size_t start[N + 1];
    size_t len = 0, blen = 0;
    uint64_t r = 5;
    int16_t mo[2];
    for (int i = 0; i < N; i++) {
        wire_msg_t m = { .type = WIRE_MOTOR, .u.motor = { (uint32_t)i * 4000u, (int16_t)(i % 1000), (int16_t)-(i % 777) } };
        start[i] = len;
        len += wire_encode(&m, clean + len, 16);
    }
    start[N] = len;
    for (size_t i = 0; i < len; i++) {
        r = r * 6364136223846793005ull + 1442695040888963407ull;
        unsigned x = (unsigned)(r >> 33) % 1000;
        if (x < 4) continue;                                          /* drop */
        uint8_t b = clean[i];
        if (x < 8) b ^= (uint8_t)(1u << ((r >> 20) & 7));             /* flip */
        bad[blen++] = b;
        if (x < 11) for (unsigned k = (unsigned)(r >> 40) % 9; k; k--) bad[blen++] = (uint8_t)(r >> (k * 3)); /* garbage */
    }
    unsigned exp_ok = 0, exp_err = 0;
    size_t cs = 0;
    for (size_t i = 0; i < blen; i++) {
        if (bad[i] != 0) continue;
        size_t clen = i - cs + 1;
        if (clen > 1) {
            int found = 0;
            for (int f = 0; f < N && !found; f++)
                found = start[f + 1] - start[f] == clen && !memcmp(clean + start[f], bad + cs, clen);
            if (found) exp_ok++;
            else exp_err++;
        }
        cs = i + 1;
    }
    open_pair(LINK_FRAMED, 115200, 10.0);
    send_hello();
    step(0, mo);
    assert_int_equal(write(peer, bad, blen), (ssize_t)blen);
    uint8_t sink[4096];
    for (int s = 0; s < 2000 && lk.st.rx_bytes < blen + 15; s++) {
        step(0, mo);
        drain(sink, sizeof sink);
    }
    assert_int_equal(lk.st.rx_bytes, blen + 15); /* every byte, at the baud */
    assert_int_equal(lk.dec.stats.frames_ok, exp_ok + 1);  /* + the HELLO */
    assert_int_equal(wire_stats_errors(&lk.dec.stats), exp_err);
    assert_true(exp_err > 5 && exp_ok > N / 2);
    close_pair();
}

/* Compat distances are scaled from the true metres, not from whole mm:
 * round(d / range * 65535) exactly (one count = 15 um at 1.0 m), with the
 * range the paper's 1.0 m by default (its library converts with 1.0 m;
 * another scale, e.g. our ToF's 1.2 m, would read 1/1.2 of the truth) or the
 * configured [link] compat_range_m; a reading at or beyond the range and a
 * timeout go as 65535; the MCU's decoder gives both the u16 and mm. */
static void test_compat_distance_from_metres(void **state)
{
    static const double d_m[] = { 0.123456, 0.0004, 0.05, 0.0907, 0.18, 0.6, 0.99999, 1.0, 1.1, 1.19999, 1.2, 1.5,
                                  -1 /* timeout */ };
    static const double ranges[] = { 0 /* default: 1.0 m */, 1.2 };
    uint8_t buf[256];
    int16_t mo[2];
    wire_compat_rx_t rx;
    wire_msg_t m;
    for (size_t r = 0; r < 2; r++) {
        double range = ranges[r] > 0 ? ranges[r] : 1.0;
        long range_mm = lround(range * 1000.0);
        pair_compat_range_m = ranges[r];
        open_pair(LINK_COMPAT, 115200, 10.0);
        pair_compat_range_m = 0;
        static const uint8_t enable[] = { 7, 2 };
        assert_int_equal(write(peer, enable, 2), 2);
        step(0, mo);
        drain(buf, sizeof buf);
        wire_compat_rx_init(&rx, (uint16_t)range_mm);
        for (size_t k = 0; k < sizeof d_m / sizeof d_m[0]; k++) {
            link_io_t io;
            memset(&io, 0, sizeof io);
            io.tof_new[WIRE_SENSOR_FRONT] = 1;
            io.tof_timeout[WIRE_SENSOR_FRONT] = d_m[k] < 0;
            io.tof_m[WIRE_SENSOR_FRONT] = d_m[k] < 0 ? 1.2 : d_m[k];
            io.tof_mm[WIRE_SENSOR_FRONT] = (uint16_t)lround(io.tof_m[WIRE_SENSOR_FRONT] * 1000.0);
            link_step_io(&lk, &io, mo);
            size_t n = drain(buf, sizeof buf);
            int timeout = d_m[k] < 0 || d_m[k] >= range;
            long want = timeout ? 65535 : lround(d_m[k] / range * 65535.0);
            if (want > 65534 && !timeout) want = 65534;
            int seen = 0;
            for (size_t i = 0; i < n; i++)
                if (wire_compat_decode_byte(&rx, buf[i], &m) && m.type == WIRE_DISTANCE) {
                    seen++;
                    assert_int_equal(m.u.distance.compat, want);
                    assert_int_equal(m.u.distance.timeout, timeout);
                    assert_int_equal(m.u.distance.mm, timeout ? range_mm : lround(want * range * 1000.0 / 65535.0));
                }
            assert_int_equal(seen, 1);
        }
        assert_int_equal(wire_stats_errors(&rx.stats), 0);
        close_pair();
    }
}

/* the MCU's end of a --pty link: opens the slave, raw */
static int open_slave(void)
{
    int fd = open(lk.path, O_RDWR | O_NOCTTY | O_NONBLOCK);
    assert_true(fd >= 0);
    struct termios t;
    assert_int_equal(tcgetattr(fd, &t), 0);
    cfmakeraw(&t);
    assert_int_equal(tcsetattr(fd, TCSANOW, &t), 0);
    return fd;
}

/* A pty moves bytes through the kernel's tty buffers asynchronously: the
 * helpers below step the link until a condition holds, 1 ms apart, giving up
 * after PTY_TRIES (a bound for a loaded machine, not a timing check). */
enum { PTY_TRIES = 5000 };
static int16_t pty_mo[2];

/* step until lk's sensor request is on (1) / off (0); whether it got there */
static int step_until_sensors(int on)
{
    for (int i = 0; i < PTY_TRIES && lk.sensors_on != on; i++) {
        step(0, pty_mo);
        usleep(1000);
    }
    return lk.sensors_on == on;
}

/* step until the link is connected (1) / not (0) */
static int step_until_connected(int on)
{
    for (int i = 0; i < PTY_TRIES && lk.connected != on; i++) {
        step(0, pty_mo);
        usleep(1000);
    }
    return lk.connected == on;
}

/* step and read fd until want bytes arrived; the bytes read */
static size_t step_read(int fd, size_t want)
{
    uint8_t buf[4096];
    size_t got = 0;
    for (int i = 0; i < PTY_TRIES && got < want; i++) {
        step(0, pty_mo);
        ssize_t k = read(fd, buf, sizeof buf);
        if (k > 0) got += (size_t)k;
        else usleep(1000);
    }
    return got;
}

/* read fd until nothing arrives for 50 ms; the bytes read */
static size_t drain_quiet(int fd)
{
    uint8_t buf[4096];
    size_t got = 0;
    struct pollfd p = { fd, POLLIN, 0 };
    while (poll(&p, 1, 50) > 0) {
        ssize_t k = read(fd, buf, sizeof buf);
        if (k <= 0) break;
        got += (size_t)k;
    }
    return got;
}

/* Compat over a pty, the MCU unplugs and plugs back without asking for the
 * sensors again (a board not reset when the port opens): the link keeps its
 * last request, so readings flow again; a disable is kept as well. */
static void test_compat_reconnect_keeps_sensors(void **state)
{
    char err[300];
    link_opts_t o = { NULL, 1, 115200, LINK_COMPAT, 10.0, 0 };
    if (link_open(&lk, &o, 0.001, 1200, 35832, NULL, err, sizeof err) != 0) skip(); /* no pseudo-terminals here */
    step(0, pty_mo);
    assert_int_equal(lk.connected, 0); /* nobody has the terminal open */
    int fd = open_slave();
    static const uint8_t enable[] = { 7, 2 }, disable[] = { 7, 3 };
    assert_int_equal(write(fd, enable, 2), 2);
    assert_true(step_until_sensors(1));
    assert_true(step_read(fd, 100) >= 100);
    close(fd); /* unplug */
    assert_true(step_until_connected(0));
    assert_int_equal(lk.sensors_on, 1);
    fd = open_slave(); /* plug back, no enable */
    assert_true(step_until_connected(1));
    assert_int_equal(lk.st.connects, 2);
    assert_true(step_read(fd, 100) >= 100); /* readings without a new request */
    assert_int_equal(write(fd, disable, 2), 2);
    assert_true(step_until_sensors(0));
    drain_quiet(fd); /* what was sent before the disable arrived (a pty keeps it over a reopen) */
    close(fd);
    assert_true(step_until_connected(0));
    fd = open_slave();
    assert_true(step_until_connected(1));
    assert_int_equal(lk.st.connects, 3);
    for (int s = 0; s < 50; s++) assert_int_equal(step(0, pty_mo), 0);
    assert_int_equal(drain_quiet(fd), 0); /* still disabled: nothing sent */
    close(fd);
    link_close(&lk);
}

int main(void)
{
    signal(SIGPIPE, SIG_IGN); /* a socket peer gone: EPIPE, as a tty gives EIO */
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_compat_budget),
        cmocka_unit_test(test_framed_overload_drops_whole),
        cmocka_unit_test(test_handshake_and_motor),
        cmocka_unit_test(test_compat_manager_and_pacing),
        cmocka_unit_test(test_faults_through_link),
        cmocka_unit_test(test_compat_reconnect_keeps_sensors),
        cmocka_unit_test(test_compat_distance_from_metres),
        cmocka_unit_test(test_silence_defaults_and_off),
        cmocka_unit_test(test_v2_messages),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}

/* test_wire.c - the wire codec: shared vectors, round trips, malformed
 * frames, and fault injection (drops, bit flips, garbage) with the error
 * counters checked against what the injected faults must produce. Built
 * twice: with the host's decoder buffers (test_wire) and with an MCU's
 * (test_wire_rx14: -DWIRE_RX_LOG_MAX=14, as make arduino builds the library). */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include <cmocka.h>

#include "wire.h"
#include "wire_vectors.h"

static uint64_t rng = 1;
static uint32_t rnd(void) /* splitmix64, deterministic */
{
    uint64_t z = (rng += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return (uint32_t)((z ^ (z >> 31)) >> 16);
}

static char texts[3000][WIRE_LOG_MAX + 1]; /* log text behind random messages */
static unsigned text_next;

static void random_msg(wire_msg_t *m)
{
    memset(m, 0, sizeof *m);
    switch (rnd() % 12) {
    case 0:
        m->type = WIRE_HELLO;
        m->u.hello.version = (uint8_t)rnd();
        m->u.hello.role = (uint8_t)(rnd() & 1);
        m->u.hello.tof_range_mm = (uint16_t)rnd();
        m->u.hello.counts_per_rev_x100 = rnd();
        m->u.hello.tick_hz = (uint16_t)rnd();
        break;
    case 1:
        m->type = WIRE_MOTOR;
        m->u.motor.t_us = rnd();
        m->u.motor.left = (int16_t)((int)(rnd() % 2047) - 1023);
        m->u.motor.right = (int16_t)((int)(rnd() % 2047) - 1023);
        break;
    case 2:
        m->type = WIRE_ENCODER;
        m->u.encoder.t_us = rnd();
        m->u.encoder.left = (int32_t)(rnd() * 3u);
        m->u.encoder.right = (int32_t)rnd() - 1000;
        break;
    case 3:
        m->type = WIRE_DISTANCE;
        m->u.distance.t_us = rnd();
        m->u.distance.sensor = (uint8_t)(rnd() % 3);
        m->u.distance.timeout = (uint8_t)(rnd() & 1);
        m->u.distance.mm = (uint16_t)rnd();
        break;
    case 4: m->type = WIRE_SENSORS; m->u.flag.on = (uint8_t)(rnd() & 1); break;
    case 5: m->type = WIRE_RUN; m->u.flag.on = (uint8_t)(rnd() & 1); break;
    case 6: m->type = WIRE_EMITTER; m->u.emitter.groups = (uint8_t)(rnd() % 16); break;
    case 7:
        m->type = WIRE_IR;
        m->u.ir.seq = (uint8_t)rnd();
        m->u.ir.emitters = (uint8_t)(rnd() % 16);
        m->u.ir.count = (uint8_t)(rnd() % (WIRE_IR_MAX + 1));
        for (uint8_t i = 0; i < m->u.ir.count; i++) wire_ir_set(m, i, (uint16_t)(rnd() % 1024));
        break;
    case 8: m->type = WIRE_GYRO; m->u.gyro.t_us = rnd(); m->u.gyro.mdps = (int32_t)(rnd() * 5u); break;
    case 9: m->type = WIRE_BATTERY; m->u.battery.t_us = rnd(); m->u.battery.mv = (uint16_t)rnd(); break;
    case 10:
        m->type = WIRE_ROBOT;
        m->u.robot.ir_count = (uint8_t)(rnd() % (WIRE_IR_MAX + 1));
        m->u.robot.flags = (uint8_t)(rnd() % 4);
        break;
    default:
        m->type = WIRE_LOG;
        m->u.log.len = (uint8_t)(rnd() % (WIRE_LOG_MAX + 1));
        char *t = texts[text_next++ % 3000];
        for (uint8_t i = 0; i < m->u.log.len; i++) t[i] = (char)(1 + rnd() % 255);
        m->u.log.text = t;
        break;
    }
}

static void assert_same(const wire_msg_t *a, const wire_msg_t *b)
{
    wire_msg_t x = *a, y = *b; /* compare the used bytes only */
    if (x.type == WIRE_LOG) {
        assert_int_equal(x.u.log.len, y.u.log.len);
        if (x.u.log.len) assert_memory_equal(x.u.log.text, y.u.log.text, x.u.log.len);
        return;
    }
    assert_int_equal(x.type, y.type);
    uint8_t ex[WIRE_FRAME_MAX], ey[WIRE_FRAME_MAX];
    size_t nx = wire_encode(&x, ex, sizeof ex), ny = wire_encode(&y, ey, sizeof ey);
    assert_true(nx > 0);
    assert_int_equal(nx, ny);
    assert_memory_equal(ex, ey, nx);
}

/* whether the framed decoder takes m's frame whole: all of it before the
 * delimiter fits its buffer (WIRE_RX_MAX; less than the longest frame when
 * built for an MCU with -DWIRE_RX_LOG_MAX=14), else it counts an overflow */
static int fits(const wire_msg_t *m)
{
    uint8_t f[WIRE_FRAME_MAX];
    size_t n = wire_encode(m, f, sizeof f);
    return n > 0 && n - 1 <= WIRE_RX_MAX;
}

static void test_vectors(void **state)
{
    const char *first;
    unsigned bad = wire_vectors_check(&first);
    if (bad) fail_msg("%u vector checks failed, first: %s", bad, first);
}

static void test_round_trip_stream(void **state)
{
    enum { N = 2000 };
    static wire_msg_t sent[N];
    static uint8_t stream[N * WIRE_FRAME_MAX];
    size_t len = 0;
    rng = 7;
    for (int i = 0; i < N; i++) {
        random_msg(&sent[i]);
        size_t n = wire_encode(&sent[i], stream + len, WIRE_FRAME_MAX);
        assert_true(n > 0 && n <= WIRE_FRAME_MAX);
        for (size_t k = 0; k < n - 1; k++) assert_int_not_equal(stream[len + k], 0);
        assert_int_equal(stream[len + n - 1], 0);
        len += n;
    }
    wire_decoder_t d;
    wire_decoder_init(&d);
    wire_msg_t m;
    int got = 0, too_long = 0;
    for (size_t i = 0; i < len; i++)
        if (wire_decode_byte(&d, stream[i], &m)) {
            for (; !fits(&sent[got]); got++) too_long++; /* an MCU's decoder drops long LOG frames, counted */
            assert_same(&m, &sent[got++]);
        }
    for (; got < N && !fits(&sent[got]); got++) too_long++;
    assert_int_equal(got, N);
    assert_int_equal(wire_stats_errors(&d.stats), too_long);
    assert_int_equal(d.stats.overflow, too_long);
    assert_int_equal(too_long > 0, WIRE_RX_LOG_MAX < WIRE_LOG_MAX);
    assert_int_equal(d.stats.bytes, len);
}

static void test_encode_rejects(void **state)
{
    uint8_t buf[WIRE_FRAME_MAX];
    wire_msg_t m = { .type = WIRE_MOTOR, .u.motor = { 0, 1024, 0 } };
    assert_int_equal(wire_encode(&m, buf, sizeof buf), 0);
    m.u.motor.left = -1024;
    assert_int_equal(wire_encode(&m, buf, sizeof buf), 0);
    m = (wire_msg_t){ .type = WIRE_DISTANCE, .u.distance = { 0, 3, 0, 5 } };
    assert_int_equal(wire_encode(&m, buf, sizeof buf), 0);
    m = (wire_msg_t){ .type = WIRE_LOG, .u.log = { WIRE_LOG_MAX + 1, "x" } };
    assert_int_equal(wire_encode(&m, buf, sizeof buf), 0);
    m = (wire_msg_t){ .type = WIRE_HELLO, .u.hello = { WIRE_VERSION, 2, 1200, 35832, 1000 } }; /* found by fuzz_wire */
    assert_int_equal(wire_encode(&m, buf, sizeof buf), 0);
    m = (wire_msg_t){ .type = 0x7F };
    assert_int_equal(wire_encode(&m, buf, sizeof buf), 0);
    m = (wire_msg_t){ .type = WIRE_RUN, .u.flag = { 1 } };
    assert_int_equal(wire_encode(&m, buf, 5), 0); /* needs 6 */
    assert_int_equal(wire_encode(&m, buf, 6), 6);
    char longest[WIRE_LOG_MAX];
    memset(longest, 'x', sizeof longest);
    m = (wire_msg_t){ .type = WIRE_LOG, .u.log = { WIRE_LOG_MAX, longest } };
    assert_int_equal(wire_encode(&m, buf, sizeof buf), WIRE_FRAME_MAX - 1); /* longest frame */
    assert_int_equal(wire_encode(&m, buf, WIRE_FRAME_MAX - 2), 0);
    m = (wire_msg_t){ .type = WIRE_LOG, .u.log = { 0, NULL } };
    assert_int_equal(wire_encode(&m, buf, sizeof buf), 5); /* an empty line */
}

/* a frame with a valid CRC around arbitrary raw bytes (type + payload) */
static size_t frame_raw(const uint8_t *raw, size_t n, uint8_t *out)
{
    uint8_t r[256];
    memcpy(r, raw, n);
    uint16_t c = wire_crc16(r, n);
    r[n] = (uint8_t)c;
    r[n + 1] = (uint8_t)(c >> 8);
    n += 2;
    size_t code_at = 0, o = 1;
    uint8_t code = 1;
    for (size_t i = 0; i < n; i++) {
        if (r[i] == 0) { out[code_at] = code; code_at = o++; code = 1; }
        else { out[o++] = r[i]; code++; }
    }
    out[code_at] = code;
    out[o++] = 0;
    return o;
}

static wire_stats_t feed(const uint8_t *b, size_t n, int *ok)
{
    wire_decoder_t d;
    wire_msg_t m;
    wire_decoder_init(&d);
    *ok = 0;
    for (size_t i = 0; i < n; i++) *ok += wire_decode_byte(&d, b[i], &m);
    return d.stats;
}

static void test_malformed_frames(void **state)
{
    uint8_t f[300];
    int ok;
    wire_stats_t s;
    static const uint8_t unknown[] = { 0x42, 1, 2 }, short_motor[] = { WIRE_MOTOR, 1, 2, 3 },
                         big_motor[] = { WIRE_MOTOR, 0, 0, 0, 0, 0x00, 0x04, 0, 0 }, /* left 1024 */
                         bad_sensor[] = { WIRE_DISTANCE, 0, 0, 0, 0, 3, 0, 1, 0 },
                         bad_flag[] = { WIRE_RUN, 2 }, bad_role[] = { WIRE_HELLO, 1, 2, 0, 0, 0, 0, 0, 0, 0, 0 };
    s = feed(f, frame_raw(unknown, sizeof unknown, f), &ok);
    assert_int_equal(s.unknown, 1);
    assert_int_equal(ok, 0);
    s = feed(f, frame_raw(short_motor, sizeof short_motor, f), &ok);
    assert_int_equal(s.length, 1);
    s = feed(f, frame_raw(big_motor, sizeof big_motor, f), &ok);
    assert_int_equal(s.value, 1);
    s = feed(f, frame_raw(bad_sensor, sizeof bad_sensor, f), &ok);
    assert_int_equal(s.value, 1);
    s = feed(f, frame_raw(bad_flag, sizeof bad_flag, f), &ok);
    assert_int_equal(s.value, 1);
    s = feed(f, frame_raw(bad_role, sizeof bad_role, f), &ok);
    assert_int_equal(s.value, 1);
    /* too short to hold a type and a CRC */
    static const uint8_t tiny[] = { 0x02, 0x07, 0x00 };
    s = feed(tiny, sizeof tiny, &ok);
    assert_int_equal(s.length, 1);
    /* a COBS code pointing past the end */
    static const uint8_t past[] = { 0x09, 0x01, 0x02, 0x00 };
    s = feed(past, sizeof past, &ok);
    assert_int_equal(s.cobs, 1);
    /* idle delimiters are not errors */
    static const uint8_t idle[] = { 0, 0, 0 };
    s = feed(idle, sizeof idle, &ok);
    assert_int_equal(wire_stats_errors(&s), 0);
    /* 200 non-zero bytes: one overflow, then the next frame decodes */
    memset(f, 0x55, 200);
    f[200] = 0;
    wire_msg_t m = { .type = WIRE_SENSORS, .u.flag = { 1 } };
    size_t n = wire_encode(&m, f + 201, 99);
    s = feed(f, 201 + n, &ok);
    assert_int_equal(s.overflow, 1);
    assert_int_equal(wire_stats_errors(&s), 1);
    assert_int_equal(ok, 1);
}

/* Fault injection: a stream of random frames hit by drops, bit flips and
 * garbage bursts. Whatever happens, decoding must see exactly the chunks
 * between delimiters: an untouched frame decodes (if it fits the decoder's
 * buffer), every other non-empty chunk is one counted error. */
static void fault_run(uint64_t seed, int n_frames, int per_mille)
{
    enum { MAXN = 3000 };
    static uint8_t clean[MAXN * WIRE_FRAME_MAX], bad[MAXN * WIRE_FRAME_MAX * 2];
    static size_t start[MAXN + 1];
    static wire_msg_t sent[MAXN];
    size_t len = 0, blen = 0;
    rng = seed;
    for (int i = 0; i < n_frames; i++) {
        random_msg(&sent[i]);
        start[i] = len;
        len += wire_encode(&sent[i], clean + len, WIRE_FRAME_MAX);
    }
    start[n_frames] = len;
    unsigned drops = 0, flips = 0, bursts = 0;
    for (size_t i = 0; i < len; i++) {
        uint32_t r = rnd() % 1000;
        if ((int)r < per_mille / 3) { drops++; continue; }
        uint8_t b = clean[i];
        if ((int)r < 2 * per_mille / 3) { b ^= (uint8_t)(1u << (rnd() % 8)); flips++; }
        bad[blen++] = b;
        if ((int)r >= 2 * per_mille / 3 && (int)r < per_mille) {
            bursts++;
            for (uint32_t k = rnd() % 40; k > 0; k--) bad[blen++] = (uint8_t)rnd();
        }
    }
    assert_true(drops > 0 && flips > 0 && bursts > 0);
    /* expected: split at delimiters; a chunk equal to a whole clean frame decodes */
    unsigned exp_ok = 0, exp_err = 0;
    size_t cs = 0;
    static wire_msg_t expect[MAXN];
    for (size_t i = 0; i < blen; i++) {
        if (bad[i] != 0) continue;
        size_t clen = i - cs + 1;
        if (clen > 1) {
            int found = -1;
            for (int f = 0; f < n_frames && found < 0; f++) /* a clean frame is unique: it carries random data */
                if (start[f + 1] - start[f] == clen && !memcmp(clean + start[f], bad + cs, clen)) found = f;
            if (found >= 0 && clen - 1 <= WIRE_RX_MAX) expect[exp_ok++] = sent[found];
            else exp_err++; /* corrupt, or a whole frame too long for the decoder (overflow) */
        }
        cs = i + 1;
    }
    wire_decoder_t d;
    wire_decoder_init(&d);
    wire_msg_t m;
    unsigned got = 0;
    for (size_t i = 0; i < blen; i++)
        if (wire_decode_byte(&d, bad[i], &m)) {
            assert_true(got < exp_ok);
            assert_same(&m, &expect[got]);
            got++;
        }
    assert_int_equal(got, exp_ok);
    assert_int_equal(d.stats.frames_ok, exp_ok);
    assert_int_equal(wire_stats_errors(&d.stats), exp_err);
    assert_true(exp_ok > (unsigned)n_frames / 4); /* the stream recovered again and again */
}

static void test_faults_light(void **state) { fault_run(11, 3000, 3); }
static void test_faults_heavy(void **state) { fault_run(12, 3000, 30); }

static void test_pure_garbage(void **state)
{
    wire_decoder_t d;
    wire_compat_rx_t c;
    wire_msg_t m;
    wire_decoder_init(&d);
    wire_compat_rx_init(&c, 1200);
    rng = 99;
    for (int i = 0; i < 200000; i++) {
        uint8_t b = (uint8_t)rnd();
        wire_decode_byte(&d, b, &m);
        wire_compat_decode_byte(&c, b, &m);
    }
    assert_int_equal(d.stats.bytes, 200000);
    assert_int_equal(d.stats.frames_ok, 0); /* CRC-16 lets through ~1 in 65536 chunks; none with this seed */
    assert_true(wire_stats_errors(&d.stats) > 0);
    /* compat has no checksum: garbage decodes; it must only not crash or run out of bounds */
    assert_int_equal(c.stats.bytes, 200000);
    assert_true(c.stats.unknown > 0);
}

static void test_compat_details(void **state)
{
    wire_compat_tx_t tx;
    wire_compat_rx_t rx;
    uint8_t b[128];
    wire_msg_t m = { .type = WIRE_ENCODER, .u.encoder = { 0, 40000, -40000 } }, out;
    wire_compat_tx_init(&tx, 1200);
    wire_compat_rx_init(&rx, 1200);
    /* a delta beyond int16 goes in two sends, nothing lost */
    size_t n = wire_compat_encode(&tx, &m, b, sizeof b);
    n += wire_compat_encode(&tx, &m, b + n, sizeof b - n);
    assert_int_equal(n, 12);
    int k = 0;
    for (size_t i = 0; i < n; i++) k += wire_compat_decode_byte(&rx, b[i], &out);
    assert_int_equal(k, 4);
    assert_int_equal(out.u.encoder.left, 40000);
    assert_int_equal(out.u.encoder.right, -40000);
    /* no room: state unchanged */
    m.u.encoder.left = 40010;
    assert_int_equal(wire_compat_encode(&tx, &m, b, 5), 0);
    assert_int_equal(tx.enc_sent[0], 40000);
    /* distance scaling: at or beyond the range -> the timeout code (the
     * paper's Unity simulator sends such a reading as a timeout); just below
     * it the largest reading */
    m = (wire_msg_t){ .type = WIRE_DISTANCE, .u.distance = { 0, WIRE_SENSOR_LEFT, 0, 5000 } };
    assert_int_equal(wire_compat_encode(&tx, &m, b, sizeof b), 3);
    assert_int_equal(b[1] | b[2] << 8, 65535);
    m.u.distance.mm = 1200;
    wire_compat_encode(&tx, &m, b, sizeof b);
    assert_int_equal(b[1] | b[2] << 8, 65535);
    m.u.distance.mm = 1199;
    wire_compat_encode(&tx, &m, b, sizeof b);
    assert_int_equal(b[1] | b[2] << 8, 65480); /* round(1199 / 1200 * 65535) */
    /* the sender's own scaling (finer than mm) goes as is, never as 65535 */
    m.u.distance.mm = 123;
    m.u.distance.compat = 6742; /* 0.123456 m of 1.2 */
    wire_compat_encode(&tx, &m, b, sizeof b);
    assert_int_equal(b[1] | b[2] << 8, 6742);
    m.u.distance.compat = 65535;
    wire_compat_encode(&tx, &m, b, sizeof b);
    assert_int_equal(b[1] | b[2] << 8, 65534);
    /* motor clamping on receive (the paper clamps to +-1023) */
    static const uint8_t big[] = { 5, 0x10, 0x27, 6, 0xF0, 0xD8 }; /* +10000, -10000 */
    k = 0;
    for (size_t i = 0; i < sizeof big; i++) k += wire_compat_decode_byte(&rx, big[i], &out);
    assert_int_equal(k, 2);
    assert_int_equal(out.u.motor.left, 1023);
    assert_int_equal(out.u.motor.right, -1023);
    /* unknown IDs and manager values are counted and skipped */
    static const uint8_t junk[] = { 9, 200, 7, 9, 7, 1 };
    k = 0;
    for (size_t i = 0; i < sizeof junk; i++) k += wire_compat_decode_byte(&rx, junk[i], &out);
    assert_int_equal(k, 1);
    assert_int_equal(out.type, WIRE_RUN);
    assert_int_equal(rx.stats.unknown, 2);
    assert_int_equal(rx.stats.value, 1);
    /* the longest log line the encoder sends: whole with the decoder's
     * default buffer, cut and counted with an MCU's (-DWIRE_RX_LOG_MAX=14) */
    char zs[WIRE_LOG_MAX];
    memset(zs, 'z', sizeof zs);
    m = (wire_msg_t){ .type = WIRE_LOG, .u.log = { WIRE_LOG_MAX, zs } };
    n = wire_compat_encode(&tx, &m, b, sizeof b);
    assert_int_equal(n, WIRE_LOG_MAX + 2);
    wire_compat_rx_init(&rx, 1200);
    k = 0;
    for (size_t i = 0; i < n; i++) k += wire_compat_decode_byte(&rx, b[i], &out);
    assert_int_equal(k, 1);
    assert_int_equal(out.u.log.len, WIRE_LOG_MAX < WIRE_RX_LOG_MAX ? WIRE_LOG_MAX : WIRE_RX_LOG_MAX);
    assert_int_equal(strlen(out.u.log.text), out.u.log.len);
    assert_int_equal(rx.stats.overflow, WIRE_LOG_MAX > WIRE_RX_LOG_MAX);
    /* hello has no compat form */
    m = (wire_msg_t){ .type = WIRE_HELLO };
    assert_int_equal(wire_compat_encode(&tx, &m, b, sizeof b), 0);
}

/* A compat log line longer than the decoder's buffer, then a motor command:
 * the rest of the line up to its NUL is skipped (counted once, the line
 * delivered cut), and the motor command after it decodes intact. Lengths
 * around the buffer (WIRE_RX_LOG_MAX: 80, or 14 in the MCU's build) and far
 * past it; the line holds bytes that are valid IDs (5, 7, 8) and a motor
 * ID + payload, which a decoder that lost its place would take for messages. */
static void test_compat_log_overflow(void **state)
{
    static const size_t lens[] = { WIRE_RX_LOG_MAX - 1, WIRE_RX_LOG_MAX, WIRE_RX_LOG_MAX + 1, 30, 100, 255, 1000 };
    for (size_t li = 0; li < sizeof lens / sizeof lens[0]; li++) {
        static uint8_t b[1100];
        size_t len = lens[li], n = 0;
        b[n++] = WIRE_C_LOGGER;
        for (size_t i = 0; i < len; i++) {
            static const uint8_t pattern[] = { 'a', 5, 0x10, 0x27, 7, 2, 8, 'b' };
            b[n++] = pattern[i % sizeof pattern];
        }
        b[n++] = 0;
        static const uint8_t motor[] = { 5, 0x2C, 0x01, 6, 0x9C, 0xFE }; /* +300, -356 */
        memcpy(b + n, motor, sizeof motor);
        n += sizeof motor;
        wire_compat_rx_t rx;
        wire_msg_t out;
        wire_compat_rx_init(&rx, 1200);
        int logs = 0, motors = 0;
        for (size_t i = 0; i < n; i++) {
            if (!wire_compat_decode_byte(&rx, b[i], &out)) continue;
            if (out.type == WIRE_LOG) {
                logs++;
                size_t want = len < WIRE_RX_LOG_MAX ? len : WIRE_RX_LOG_MAX;
                assert_int_equal(out.u.log.len, want);
                assert_int_equal(strlen(out.u.log.text), want);
                assert_memory_equal(out.u.log.text, b + 1, want);
            } else {
                assert_int_equal(out.type, WIRE_MOTOR);
                motors++;
            }
        }
        assert_int_equal(logs, 1);
        assert_int_equal(motors, 2);
        assert_int_equal(out.u.motor.left, 300);
        assert_int_equal(out.u.motor.right, -356);
        assert_int_equal(rx.stats.overflow, len > WIRE_RX_LOG_MAX);
        assert_int_equal(wire_stats_errors(&rx.stats), len > WIRE_RX_LOG_MAX);
        assert_int_equal(rx.stats.frames_ok, 3);
    }
}

/* Version 2 (EMITTER, IR, GYRO, BATTERY, ROBOT): the 10-bit packing, what
 * the encoder refuses, and malformed frames: each costs exactly one counted
 * error, never a message, and the decoder goes on with the next frame. */
static void test_v2_packing_and_rejects(void **state)
{
    wire_msg_t m = { .type = WIRE_IR };
    for (uint16_t v = 0; v < 1024; v += 73) /* every position, neighbours untouched */
        for (uint8_t i = 0; i < WIRE_IR_MAX; i++) {
            for (uint8_t k = 0; k < WIRE_IR_MAX; k++) wire_ir_set(&m, k, (uint16_t)(1023 - k));
            wire_ir_set(&m, i, v);
            for (uint8_t k = 0; k < WIRE_IR_MAX; k++) assert_int_equal(wire_ir_get(&m, k), k == i ? v : 1023 - k);
        }
    wire_ir_set(&m, 0, 5000);
    assert_int_equal(wire_ir_get(&m, 0), 1023); /* clamped */
    wire_ir_set(&m, WIRE_IR_MAX, 7);           /* out of range: ignored */
    assert_int_equal(wire_ir_get(&m, WIRE_IR_MAX), 0);
    /* the longest sim -> MCU frame (IR, 8 sensors) fits an MCU's decoder */
    m.u.ir.count = WIRE_IR_MAX;
    uint8_t buf[WIRE_FRAME_MAX];
    size_t n = wire_encode(&m, buf, sizeof buf);
    assert_int_equal(n, 18);
    assert_true(n - 1 <= WIRE_RX_MAX);
    static const wire_msg_t bad[] = {
        { .type = WIRE_EMITTER, .u.emitter = { 16 } },
        { .type = WIRE_IR, .u.ir = { 0, 0, WIRE_IR_MAX + 1, { 0 } } },
        { .type = WIRE_IR, .u.ir = { 0, 16, 1, { 0 } } },
        { .type = WIRE_ROBOT, .u.robot = { WIRE_IR_MAX + 1, 0 } },
        { .type = WIRE_ROBOT, .u.robot = { 1, 4 } },
    };
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) assert_int_equal(wire_encode(&bad[i], buf, sizeof buf), 0);
    /* the encoder sends the padding bits after the last sample as 0 */
    m = (wire_msg_t){ .type = WIRE_IR, .u.ir = { 1, 0, 1, { 0xFF, 0xFF } } };
    wire_decoder_t d;
    wire_decoder_init(&d);
    wire_msg_t out;
    n = wire_encode(&m, buf, sizeof buf);
    int ok = 0;
    for (size_t i = 0; i < n; i++) ok += wire_decode_byte(&d, buf[i], &out);
    assert_int_equal(ok, 1);
    assert_int_equal(wire_ir_get(&out, 0), 1023);
    assert_int_equal(out.u.ir.packed[1], 0x03);
    /* no compat form */
    wire_compat_tx_t tx;
    wire_compat_tx_init(&tx, 1200);
    static const uint8_t v2[] = { WIRE_EMITTER, WIRE_IR, WIRE_GYRO, WIRE_BATTERY, WIRE_ROBOT };
    for (size_t i = 0; i < sizeof v2; i++) {
        m = (wire_msg_t){ .type = v2[i] };
        assert_int_equal(wire_compat_encode(&tx, &m, buf, sizeof buf), 0);
    }
}

static void test_v2_malformed(void **state)
{
    static const struct {
        uint8_t raw[16], n;
        int err; /* 0 length, 1 value */
    } cases[] = {
        { { WIRE_IR, 1, 0, 8, 1, 2, 3, 4, 5, 6, 7, 8, 9 }, 13, 0 },  /* 8 samples, 9 of 10 bytes: truncated */
        { { WIRE_IR, 1, 0, 2, 1, 2, 3, 4 }, 8, 0 },                 /* 2 samples, a byte too many */
        { { WIRE_IR, 1, 0 }, 3, 0 },                                /* no count */
        { { WIRE_IR }, 1, 0 },                                      /* empty */
        { { WIRE_IR, 1, 0, 9, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12 }, 16, 1 }, /* 9 sensors */
        { { WIRE_IR, 1, 0x10, 1, 1, 0 }, 6, 1 },                    /* emitter group 4 */
        { { WIRE_IR, 1, 0, 1, 1, 0x04 }, 6, 1 },                    /* a padding bit set */
        { { WIRE_EMITTER, 0x10 }, 2, 1 },
        { { WIRE_EMITTER }, 1, 0 },
        { { WIRE_GYRO, 1, 2, 3, 4, 5, 6, 7 }, 8, 0 },
        { { WIRE_BATTERY, 1, 2, 3, 4, 5, 6, 7 }, 8, 0 },
        { { WIRE_ROBOT, 9, 0 }, 3, 1 },
        { { WIRE_ROBOT, 1, 4 }, 3, 1 },
        { { WIRE_ROBOT, 1 }, 2, 0 },
    };
    for (size_t c = 0; c < sizeof cases / sizeof cases[0]; c++) {
        uint8_t f[64];
        size_t n = frame_raw(cases[c].raw, cases[c].n, f);
        wire_msg_t m = { .type = WIRE_ROBOT, .u.robot = { 2, 1 } }; /* then a good frame */
        n += wire_encode(&m, f + n, sizeof f - n);
        int ok;
        wire_stats_t s = feed(f, n, &ok);
        assert_int_equal(wire_stats_errors(&s), 1);
        assert_int_equal(cases[c].err ? s.value : s.length, 1);
        assert_int_equal(ok, 1);
    }
    /* a frame cut off on the wire (the delimiter and its tail lost) runs into the next: one error */
    uint8_t f[64];
    wire_msg_t ir = { .type = WIRE_IR, .u.ir = { 3, 1, 4, { 1, 2, 3, 4, 5 } } };
    size_t n = wire_encode(&ir, f, sizeof f);
    size_t cut = n - 6;
    n = cut + wire_encode(&ir, f + cut, sizeof f - cut);
    n += wire_encode(&ir, f + n, sizeof f - n);
    int ok;
    wire_stats_t s = feed(f, n, &ok);
    assert_int_equal(wire_stats_errors(&s), 1);
    assert_int_equal(ok, 1);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_vectors),
        cmocka_unit_test(test_round_trip_stream),
        cmocka_unit_test(test_encode_rejects),
        cmocka_unit_test(test_malformed_frames),
        cmocka_unit_test(test_faults_light),
        cmocka_unit_test(test_faults_heavy),
        cmocka_unit_test(test_pure_garbage),
        cmocka_unit_test(test_compat_details),
        cmocka_unit_test(test_compat_log_overflow),
        cmocka_unit_test(test_v2_packing_and_rejects),
        cmocka_unit_test(test_v2_malformed),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}

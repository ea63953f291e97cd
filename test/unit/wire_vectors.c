/* wire_vectors.c - the shared vectors (see wire_vectors.h). */
#include "wire_vectors.h"

#include <string.h>

static const uint8_t f_hello[] = { 0x03, 0x01, 0x01, 0x05, 0xB0, 0x04, 0xF8, 0x8B, 0x01, 0x05, 0xE8, 0x03, 0x31, 0xE2, 0x00 };
static const uint8_t f_motor[] = { 0x04, 0x02, 0xE8, 0x03, 0x01, 0x01, 0x06, 0x02, 0x01, 0xFC, 0xB6, 0x1B, 0x00 };
static const uint8_t f_encoder[] = { 0x05, 0x03, 0x40, 0xE2, 0x01, 0x03, 0xE8, 0x03, 0x01, 0x07, 0xFB, 0xFF, 0xFF, 0xFF, 0x45, 0x77, 0x00 };
static const uint8_t f_dist[] = { 0x04, 0x04, 0x30, 0x75, 0x01, 0x02, 0x01, 0x02, 0x5A, 0x03, 0x47, 0xA8, 0x00 };
static const uint8_t f_dist_to[] = { 0x04, 0x04, 0x60, 0xEA, 0x01, 0x07, 0x02, 0x01, 0xB0, 0x04, 0x59, 0x66, 0x00 };
static const uint8_t f_sens[] = { 0x05, 0x05, 0x01, 0xDB, 0xF2, 0x00 };
static const uint8_t f_run[] = { 0x02, 0x06, 0x03, 0xA9, 0xB7, 0x00 };
static const uint8_t f_log[] = { 0x09, 0x07, 0x68, 0x65, 0x6C, 0x6C, 0x6F, 0x33, 0x05, 0x00 };
/* version 2 */
static const uint8_t f_hello2[] = { 0x03, 0x01, 0x02, 0x05, 0xB0, 0x04, 0xF8, 0x8B, 0x01, 0x05, 0xE8, 0x03, 0xFE, 0x53, 0x00 };
static const uint8_t f_emitter[] = { 0x05, 0x08, 0x05, 0x03, 0xC4, 0x00 };
static const uint8_t f_ir3[] = { 0x05, 0x09, 0x07, 0x01, 0x03, 0x06, 0xFC, 0x0F, 0x20, 0x6E, 0x78, 0x00 };
static const uint8_t f_ir8[] = { 0x11, 0x09, 0xFF, 0x0F, 0x08, 0x64, 0x20, 0xC3, 0x12, 0x64, 0xF4, 0x61, 0xC9, 0xEB, 0xFF, 0xC0, 0xE2, 0x00 };
static const uint8_t f_ir0[] = { 0x03, 0x09, 0x01, 0x01, 0x03, 0x87, 0x40, 0x00 };
static const uint8_t f_gyro[] = { 0x05, 0x0A, 0x40, 0xE2, 0x01, 0x07, 0x80, 0x03, 0xF5, 0xFF, 0x36, 0x4A, 0x00 };
static const uint8_t f_battery[] = { 0x04, 0x0B, 0xA0, 0x0F, 0x01, 0x05, 0xBB, 0x1F, 0x19, 0x1F, 0x00 };
static const uint8_t f_robot[] = { 0x06, 0x0C, 0x06, 0x03, 0x38, 0x23, 0x00 };
static const uint8_t f_motor0[] = { 0x02, 0x02, 0x01, 0x01, 0x01, 0x01, 0x01, 0x01, 0x01, 0x03, 0x15, 0xDE, 0x00 };

#define V(n, b, ...) { n, __VA_ARGS__, b, (uint8_t)sizeof b }
const wire_vector_t wire_vectors_framed[] = {
    V("hello v1", f_hello, { .type = WIRE_HELLO, .u.hello = { 1, WIRE_ROLE_SIM, 1200, 35832, 1000 } }),
    V("hello v2", f_hello2, { .type = WIRE_HELLO, .u.hello = { 2, WIRE_ROLE_SIM, 1200, 35832, 1000 } }),
    V("emitter", f_emitter, { .type = WIRE_EMITTER, .u.emitter = { 5 } }),
    /* samples 0, 1023, 512: 10 bits each, LSB first */
    V("ir 3", f_ir3, { .type = WIRE_IR, .u.ir = { 7, 1, 3, { 0x00, 0xFC, 0x0F, 0x20 } } }),
    /* 100, 200, ..., 700, 1023 */
    V("ir 8", f_ir8, { .type = WIRE_IR, .u.ir = { 255, 15, 8, { 0x64, 0x20, 0xC3, 0x12, 0x64, 0xF4, 0x61, 0xC9, 0xEB, 0xFF } } }),
    V("ir none", f_ir0, { .type = WIRE_IR, .u.ir = { 1, 0, 0, { 0 } } }),
    V("gyro", f_gyro, { .type = WIRE_GYRO, .u.gyro = { 123456, -720000 } }),
    V("battery", f_battery, { .type = WIRE_BATTERY, .u.battery = { 4000, 8123 } }),
    V("robot", f_robot, { .type = WIRE_ROBOT, .u.robot = { 6, WIRE_ROBOT_GYRO | WIRE_ROBOT_BATTERY } }),
    V("motor", f_motor, { .type = WIRE_MOTOR, .u.motor = { 1000, 512, -1023 } }),
    V("encoder", f_encoder, { .type = WIRE_ENCODER, .u.encoder = { 123456, 1000, -5 } }),
    V("distance", f_dist, { .type = WIRE_DISTANCE, .u.distance = { 30000, WIRE_SENSOR_FRONT, 0, 90 } }),
    V("distance timeout", f_dist_to, { .type = WIRE_DISTANCE, .u.distance = { 60000, WIRE_SENSOR_RIGHT, 1, 1200 } }),
    V("sensors on", f_sens, { .type = WIRE_SENSORS, .u.flag = { 1 } }),
    V("run stop", f_run, { .type = WIRE_RUN, .u.flag = { 0 } }),
    V("log", f_log, { .type = WIRE_LOG, .u.log = { 5, "hello" } }),
    V("motor zero", f_motor0, { .type = WIRE_MOTOR, .u.motor = { 0, 0, 0 } }),
};
const uint8_t wire_vectors_framed_count = sizeof wire_vectors_framed / sizeof wire_vectors_framed[0];

/* the paper's layout: ID + little-endian payload */
static const uint8_t c_enc[] = { 3, 0x05, 0x00, 4, 0xFD, 0xFF };   /* deltas +5, -3 */
static const uint8_t c_front[] = { 2, 0x00, 0x80 };               /* 600 of 1200 mm -> 32768 */
static const uint8_t c_left_to[] = { 0, 0xFF, 0xFF };             /* timeout */
static const uint8_t c_right[] = { 1, 0x00, 0x00 };               /* 0 mm */
static const uint8_t c_motor[] = { 5, 0xFF, 0x03, 6, 0x01, 0xFC }; /* +1023, -1023 */
static const uint8_t c_start[] = { 7, 1 };
static const uint8_t c_stop[] = { 7, 0 };
static const uint8_t c_enable[] = { 7, 2 };
static const uint8_t c_disable[] = { 7, 3 };
static const uint8_t c_log[] = { 8, 'h', 'i', 0 };
const wire_vector_t wire_vectors_compat[] = {
    V("c encoder", c_enc, { .type = WIRE_ENCODER, .u.encoder = { 0, 5, -3 } }),
    V("c front", c_front, { .type = WIRE_DISTANCE, .u.distance = { 0, WIRE_SENSOR_FRONT, 0, 600 } }),
    V("c left timeout", c_left_to, { .type = WIRE_DISTANCE, .u.distance = { 0, WIRE_SENSOR_LEFT, 1, 1200 } }),
    V("c right", c_right, { .type = WIRE_DISTANCE, .u.distance = { 0, WIRE_SENSOR_RIGHT, 0, 0 } }),
    V("c motor", c_motor, { .type = WIRE_MOTOR, .u.motor = { 0, 1023, -1023 } }),
    V("c start", c_start, { .type = WIRE_RUN, .u.flag = { 1 } }),
    V("c stop", c_stop, { .type = WIRE_RUN, .u.flag = { 0 } }),
    V("c enable", c_enable, { .type = WIRE_SENSORS, .u.flag = { 1 } }),
    V("c disable", c_disable, { .type = WIRE_SENSORS, .u.flag = { 0 } }),
    V("c log", c_log, { .type = WIRE_LOG, .u.log = { 2, "hi" } }),
};
const uint8_t wire_vectors_compat_count = sizeof wire_vectors_compat / sizeof wire_vectors_compat[0];

static int same_msg(const wire_msg_t *a, const wire_msg_t *b)
{
    if (a->type != b->type) return 0;
    switch (a->type) {
    case WIRE_HELLO: return !memcmp(&a->u.hello, &b->u.hello, sizeof a->u.hello);
    case WIRE_MOTOR: return a->u.motor.t_us == b->u.motor.t_us && a->u.motor.left == b->u.motor.left &&
                            a->u.motor.right == b->u.motor.right;
    case WIRE_ENCODER: return a->u.encoder.t_us == b->u.encoder.t_us && a->u.encoder.left == b->u.encoder.left &&
                              a->u.encoder.right == b->u.encoder.right;
    case WIRE_DISTANCE: return a->u.distance.t_us == b->u.distance.t_us && a->u.distance.sensor == b->u.distance.sensor &&
                               a->u.distance.timeout == b->u.distance.timeout && a->u.distance.mm == b->u.distance.mm;
    case WIRE_SENSORS:
    case WIRE_RUN: return a->u.flag.on == b->u.flag.on;
    case WIRE_LOG: return a->u.log.len == b->u.log.len && (!a->u.log.len || !memcmp(a->u.log.text, b->u.log.text, a->u.log.len));
    case WIRE_EMITTER: return a->u.emitter.groups == b->u.emitter.groups;
    case WIRE_IR:
        if (a->u.ir.seq != b->u.ir.seq || a->u.ir.emitters != b->u.ir.emitters || a->u.ir.count != b->u.ir.count) return 0;
        for (uint8_t i = 0; i < a->u.ir.count; i++)
            if (wire_ir_get(a, i) != wire_ir_get(b, i)) return 0;
        return 1;
    case WIRE_GYRO: return a->u.gyro.t_us == b->u.gyro.t_us && a->u.gyro.mdps == b->u.gyro.mdps;
    case WIRE_BATTERY: return a->u.battery.t_us == b->u.battery.t_us && a->u.battery.mv == b->u.battery.mv;
    case WIRE_ROBOT: return a->u.robot.ir_count == b->u.robot.ir_count && a->u.robot.flags == b->u.robot.flags;
    default: return 0;
    }
}

static unsigned fail(const char **first, const char *name)
{
    if (first && !*first) *first = name;
    return 1;
}

unsigned wire_vectors_check(const char **first)
{
    unsigned bad = 0;
    uint8_t buf[WIRE_FRAME_MAX];
    wire_msg_t got;
    if (first) *first = 0;
    if (wire_crc16((const uint8_t *)"123456789", 9) != 0x29B1u) bad += fail(first, "crc16 check value");
    for (uint8_t i = 0; i < wire_vectors_framed_count; i++) {
        const wire_vector_t *v = &wire_vectors_framed[i];
        size_t n = wire_encode(&v->msg, buf, sizeof buf);
        if (n != v->len || memcmp(buf, v->bytes, n)) bad += fail(first, v->name);
        wire_decoder_t d;
        wire_decoder_init(&d);
        int got_n = 0;
        for (uint8_t k = 0; k < v->len; k++) got_n += wire_decode_byte(&d, v->bytes[k], &got);
        if (got_n != 1 || !same_msg(&got, &v->msg) || wire_stats_errors(&d.stats)) bad += fail(first, v->name);
    }
    for (uint8_t i = 0; i < wire_vectors_compat_count; i++) {
        const wire_vector_t *v = &wire_vectors_compat[i];
        wire_compat_tx_t tx;
        wire_compat_tx_init(&tx, 1200);
        size_t n = wire_compat_encode(&tx, &v->msg, buf, sizeof buf);
        if (n != v->len || memcmp(buf, v->bytes, n)) bad += fail(first, v->name);
        wire_compat_rx_t rx;
        wire_compat_rx_init(&rx, 1200);
        int got_n = 0;
        for (uint8_t k = 0; k < v->len; k++) got_n += wire_compat_decode_byte(&rx, v->bytes[k], &got);
        /* two-message encodings (encoder, motor) deliver twice; the last has both sides */
        int want_n = (v->msg.type == WIRE_ENCODER || v->msg.type == WIRE_MOTOR) ? 2 : 1;
        if (got_n != want_n || !same_msg(&got, &v->msg) || wire_stats_errors(&rx.stats)) bad += fail(first, v->name);
    }
    return bad;
}

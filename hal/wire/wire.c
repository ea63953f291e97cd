/* wire.c - framed (COBS + CRC-16) and compat codecs of the wire protocol.
 * All multi-byte fields little-endian; no float, no malloc; shifts are done
 * on 32-bit types so the code is right where int has 16 bits. */
#include "wire.h"

#include <string.h>

/* payload lengths per type, bytes (LOG is variable: 0..WIRE_LOG_MAX) */
#define LEN_HELLO 10u
#define LEN_MOTOR 8u
#define LEN_ENCODER 12u
#define LEN_DISTANCE 8u
#define LEN_FLAG 1u
#define LEN_IR_HEAD 3u /* seq, emitters, count; then the packed samples */
#define LEN_GYRO 8u
#define LEN_BATTERY 6u
#define LEN_ROBOT 2u

/* bytes of n packed 10-bit samples */
static uint8_t ir_bytes(uint8_t n) { return (uint8_t)((n * 10u + 7u) / 8u); }

uint32_t wire_stats_errors(const wire_stats_t *s)
{
    return s->crc + s->cobs + s->overflow + s->unknown + s->length + s->value;
}

uint16_t wire_crc16(const uint8_t *p, size_t n)
{
    /* byte-wise, no table (the classic shift form of poly 0x1021, MSB
     * first): ~25 AVR cycles a byte instead of ~100 for the bit loop */
    uint16_t crc = 0xFFFFu;
    while (n--) {
        crc = (uint16_t)((crc >> 8) | (crc << 8));
        crc ^= *p++;
        crc ^= (uint16_t)((crc & 0xFFu) >> 4);
        crc ^= (uint16_t)(crc << 12);
        crc ^= (uint16_t)((crc & 0xFFu) << 5);
    }
    return crc;
}

static void put16(uint8_t *p, uint16_t v)
{
    p[0] = (uint8_t)v;
    p[1] = (uint8_t)(v >> 8);
}
static void put32(uint8_t *p, uint32_t v)
{
    p[0] = (uint8_t)v;
    p[1] = (uint8_t)(v >> 8);
    p[2] = (uint8_t)(v >> 16);
    p[3] = (uint8_t)(v >> 24);
}
static uint16_t get16(const uint8_t *p) { return (uint16_t)(p[0] | ((uint16_t)p[1] << 8)); }
static uint32_t get32(const uint8_t *p)
{
    return (uint32_t)p[0] | ((uint32_t)p[1] << 8) | ((uint32_t)p[2] << 16) | ((uint32_t)p[3] << 24);
}

static int motor_ok(int16_t v) { return v >= -WIRE_MOTOR_MAX && v <= WIRE_MOTOR_MAX; }
static int groups_ok(uint8_t g) { return g < (1u << WIRE_EMITTER_GROUPS); }

uint16_t wire_ir_sample(const uint8_t packed[WIRE_IR_PACKED], uint8_t i)
{
    if (i >= WIRE_IR_MAX) return 0;
    uint8_t bit = (uint8_t)(i * 10u);
    return (uint16_t)((get16(packed + (bit >> 3)) >> (bit & 7u)) & 0x3FFu); /* bytes 0..9 */
}

uint16_t wire_ir_get(const wire_msg_t *m, uint8_t i) { return wire_ir_sample(m->u.ir.packed, i); }

void wire_ir_set(wire_msg_t *m, uint8_t i, uint16_t v)
{
    if (i >= WIRE_IR_MAX) return;
    uint8_t bit = (uint8_t)(i * 10u), sh = bit & 7u;
    uint8_t *p = m->u.ir.packed + (bit >> 3);
    uint16_t mask = (uint16_t)(0x3FFu << sh);
    put16(p, (uint16_t)((get16(p) & ~mask) | ((v > 1023u ? 1023u : v) << sh)));
}

/* whether the bits past sample count-1 in the last packed byte are 0 */
static int ir_padding_ok(const uint8_t *packed, uint8_t count)
{
    uint8_t used = (uint8_t)((count * 10u) & 7u);
    return !used || !(packed[ir_bytes(count) - 1] >> used);
}

/* bytes of type + payload for m, 0 if m is invalid */
static size_t raw_len(const wire_msg_t *m)
{
    switch (m->type) {
    case WIRE_HELLO: return m->u.hello.role <= WIRE_ROLE_MCU ? 1 + LEN_HELLO : 0;
    case WIRE_MOTOR: return motor_ok(m->u.motor.left) && motor_ok(m->u.motor.right) ? 1 + LEN_MOTOR : 0;
    case WIRE_ENCODER: return 1 + LEN_ENCODER;
    case WIRE_DISTANCE:
        return m->u.distance.sensor < WIRE_SENSOR_COUNT && m->u.distance.timeout <= 1 ? 1 + LEN_DISTANCE : 0;
    case WIRE_SENSORS:
    case WIRE_RUN: return m->u.flag.on <= 1 ? 1 + LEN_FLAG : 0;
    case WIRE_LOG: return m->u.log.len <= WIRE_LOG_MAX && (m->u.log.text || !m->u.log.len) ? 1u + m->u.log.len : 0;
    case WIRE_EMITTER: return groups_ok(m->u.emitter.groups) ? 1 + LEN_FLAG : 0;
    case WIRE_IR:
        return m->u.ir.count <= WIRE_IR_MAX && groups_ok(m->u.ir.emitters) ? 1u + LEN_IR_HEAD + ir_bytes(m->u.ir.count) : 0;
    case WIRE_GYRO: return 1 + LEN_GYRO;
    case WIRE_BATTERY: return 1 + LEN_BATTERY;
    case WIRE_ROBOT:
        return m->u.robot.ir_count <= WIRE_IR_MAX && m->u.robot.flags <= (WIRE_ROBOT_GYRO | WIRE_ROBOT_BATTERY)
                   ? 1 + LEN_ROBOT : 0;
    default: return 0;
    }
}

/* the payload of a version-2 message (m valid) */
static void pack2(const wire_msg_t *m, uint8_t *p)
{
    switch (m->type) {
    case WIRE_EMITTER: p[0] = m->u.emitter.groups; break;
    case WIRE_IR: {
        uint8_t n = ir_bytes(m->u.ir.count), used = (uint8_t)((m->u.ir.count * 10u) & 7u);
        p[0] = m->u.ir.seq;
        p[1] = m->u.ir.emitters;
        p[2] = m->u.ir.count;
        memcpy(p + 3, m->u.ir.packed, n);
        if (used) p[2 + n] &= (uint8_t)((1u << used) - 1u); /* the padding goes as 0 */
        break;
    }
    case WIRE_GYRO:
        put32(p, m->u.gyro.t_us);
        put32(p + 4, (uint32_t)m->u.gyro.mdps);
        break;
    case WIRE_BATTERY:
        put32(p, m->u.battery.t_us);
        put16(p + 4, m->u.battery.mv);
        break;
    case WIRE_ROBOT:
        p[0] = m->u.robot.ir_count;
        p[1] = m->u.robot.flags;
        break;
    }
}

/* type + payload into raw (raw_len(m) bytes, m valid) */
static void pack(const wire_msg_t *m, uint8_t *raw)
{
    raw[0] = m->type;
    uint8_t *p = raw + 1;
    switch (m->type) {
    case WIRE_HELLO:
        p[0] = m->u.hello.version;
        p[1] = m->u.hello.role;
        put16(p + 2, m->u.hello.tof_range_mm);
        put32(p + 4, m->u.hello.counts_per_rev_x100);
        put16(p + 8, m->u.hello.tick_hz);
        break;
    case WIRE_MOTOR:
        put32(p, m->u.motor.t_us);
        put16(p + 4, (uint16_t)m->u.motor.left);
        put16(p + 6, (uint16_t)m->u.motor.right);
        break;
    case WIRE_ENCODER:
        put32(p, m->u.encoder.t_us);
        put32(p + 4, (uint32_t)m->u.encoder.left);
        put32(p + 8, (uint32_t)m->u.encoder.right);
        break;
    case WIRE_DISTANCE:
        put32(p, m->u.distance.t_us);
        p[4] = m->u.distance.sensor;
        p[5] = m->u.distance.timeout;
        put16(p + 6, m->u.distance.mm);
        break;
    case WIRE_SENSORS:
    case WIRE_RUN: p[0] = m->u.flag.on; break;
    case WIRE_LOG:
        if (m->u.log.len) memcpy(p, m->u.log.text, m->u.log.len);
        break;
    default: pack2(m, p); break;
    }
}

size_t wire_encode(const wire_msg_t *m, uint8_t *out, size_t cap)
{
    size_t n = raw_len(m);
    if (n == 0 || cap < n + 4) return 0; /* + CRC + COBS code + delimiter (n < 254: one code per zero) */
    pack(m, out + 1);
    put16(out + 1 + n, wire_crc16(out + 1, n));
    n += 2;
    /* COBS in place: raw is at out[1..n]; each zero becomes the distance
     * to the next one, out[0] the distance to the first */
    size_t last = 0;
    for (size_t i = 1; i <= n; i++)
        if (out[i] == 0) {
            out[last] = (uint8_t)(i - last);
            last = i;
        }
    out[last] = (uint8_t)(n + 1 - last);
    out[n + 1] = 0;
    return n + 2;
}

void wire_decoder_init(wire_decoder_t *d) { memset(d, 0, sizeof *d); }

/* a version-2 payload of the right length -> m; 0 if a field is out of range */
static int unpack2(wire_msg_t *m, const uint8_t *p)
{
    switch (m->type) {
    case WIRE_EMITTER:
        m->u.emitter.groups = p[0];
        return groups_ok(p[0]);
    case WIRE_IR:
        m->u.ir.seq = p[0];
        m->u.ir.emitters = p[1];
        m->u.ir.count = p[2];
        memcpy(m->u.ir.packed, p + 3, ir_bytes(p[2]));
        return groups_ok(p[1]) && ir_padding_ok(p + 3, p[2]);
    case WIRE_GYRO:
        m->u.gyro.t_us = get32(p);
        m->u.gyro.mdps = (int32_t)get32(p + 4);
        return 1;
    case WIRE_BATTERY:
        m->u.battery.t_us = get32(p);
        m->u.battery.mv = get16(p + 4);
        return 1;
    default: /* WIRE_ROBOT */
        m->u.robot.ir_count = p[0];
        m->u.robot.flags = p[1];
        return p[0] <= WIRE_IR_MAX && p[1] <= (WIRE_ROBOT_GYRO | WIRE_ROBOT_BATTERY);
    }
}

/* raw (type + payload, CRC after it) -> message; 0 and counted if malformed */
static int unpack(wire_stats_t *st, uint8_t *raw, size_t n, wire_msg_t *m)
{
    uint8_t *p = raw + 1;
    size_t len = n - 1, want;
    memset(m, 0, sizeof *m);
    m->type = raw[0];
    switch (m->type) {
    case WIRE_HELLO: want = LEN_HELLO; break;
    case WIRE_MOTOR: want = LEN_MOTOR; break;
    case WIRE_ENCODER: want = LEN_ENCODER; break;
    case WIRE_DISTANCE: want = LEN_DISTANCE; break;
    case WIRE_SENSORS:
    case WIRE_RUN: want = LEN_FLAG; break;
    case WIRE_LOG: want = len <= WIRE_LOG_MAX ? len : WIRE_LOG_MAX + 1; break;
    case WIRE_EMITTER: want = LEN_FLAG; break;
    case WIRE_IR:
        if (len >= LEN_IR_HEAD && p[2] > WIRE_IR_MAX) goto bad_value; /* the count sizes the rest */
        want = LEN_IR_HEAD + ir_bytes(len >= LEN_IR_HEAD ? p[2] : 0);
        break;
    case WIRE_GYRO: want = LEN_GYRO; break;
    case WIRE_BATTERY: want = LEN_BATTERY; break;
    case WIRE_ROBOT: want = LEN_ROBOT; break;
    default: st->unknown++; return 0;
    }
    if (len != want) {
        st->length++;
        return 0;
    }
    switch (m->type) {
    case WIRE_HELLO:
        m->u.hello.version = p[0];
        m->u.hello.role = p[1];
        m->u.hello.tof_range_mm = get16(p + 2);
        m->u.hello.counts_per_rev_x100 = get32(p + 4);
        m->u.hello.tick_hz = get16(p + 8);
        if (m->u.hello.role > WIRE_ROLE_MCU) goto bad_value;
        break;
    case WIRE_MOTOR:
        m->u.motor.t_us = get32(p);
        m->u.motor.left = (int16_t)get16(p + 4);
        m->u.motor.right = (int16_t)get16(p + 6);
        if (!motor_ok(m->u.motor.left) || !motor_ok(m->u.motor.right)) goto bad_value;
        break;
    case WIRE_ENCODER:
        m->u.encoder.t_us = get32(p);
        m->u.encoder.left = (int32_t)get32(p + 4);
        m->u.encoder.right = (int32_t)get32(p + 8);
        break;
    case WIRE_DISTANCE:
        m->u.distance.t_us = get32(p);
        m->u.distance.sensor = p[4];
        m->u.distance.timeout = p[5];
        m->u.distance.mm = get16(p + 6);
        if (p[4] >= WIRE_SENSOR_COUNT || p[5] > 1) goto bad_value;
        break;
    case WIRE_SENSORS:
    case WIRE_RUN:
        m->u.flag.on = p[0];
        if (p[0] > 1) goto bad_value;
        break;
    case WIRE_LOG:
        m->u.log.len = (uint8_t)len;
        p[len] = 0; /* over the CRC, already checked */
        m->u.log.text = (const char *)p;
        break;
    default:
        if (!unpack2(m, p)) goto bad_value;
        break;
    }
    return 1;
bad_value:
    st->value++;
    return 0;
}

int wire_decode_byte(wire_decoder_t *d, uint8_t b, wire_msg_t *out)
{
    d->stats.bytes++;
    if (b != 0) {
        if (d->skipping) return 0;
        if (d->len >= sizeof d->buf) {
            d->stats.overflow++;
            d->skipping = 1;
            d->len = 0;
            return 0;
        }
        d->buf[d->len++] = b;
        return 0;
    }
    /* delimiter: decode what was gathered */
    size_t len = d->len;
    d->len = 0;
    if (d->skipping) {
        d->skipping = 0;
        return 0;
    }
    if (len == 0) return 0; /* back-to-back delimiters: idle, not an error */
    uint8_t *buf = d->buf;
    size_t i = 0, o = 0;
    while (i < len) { /* in place: the output never overtakes the input */
        uint8_t code = buf[i++];
        if (i + code - 1u > len) {
            d->stats.cobs++;
            return 0;
        }
        for (uint8_t k = 1; k < code; k++) buf[o++] = buf[i++];
        if (code != 0xFF && i < len) buf[o++] = 0;
    }
    if (o < 3) {
        d->stats.length++;
        return 0;
    }
    if (wire_crc16(buf, o - 2) != get16(buf + o - 2)) {
        d->stats.crc++;
        return 0;
    }
    if (!unpack(&d->stats, buf, o - 2, out)) return 0;
    d->stats.frames_ok++;
    return 1;
}

/* ---- compat ---- */

void wire_compat_tx_init(wire_compat_tx_t *t, uint16_t range_mm)
{
    memset(t, 0, sizeof *t);
    t->range_mm = range_mm ? range_mm : WIRE_COMPAT_RANGE_MM;
}

static int16_t clamp16(int32_t v, int32_t lim)
{
    return (int16_t)(v > lim ? lim : v < -lim ? -lim : v);
}

static size_t put_id16(uint8_t *out, uint8_t id, uint16_t v)
{
    out[0] = id;
    put16(out + 1, v);
    return 3;
}

size_t wire_compat_encode(wire_compat_tx_t *t, const wire_msg_t *m, uint8_t *out, size_t cap)
{
    switch (m->type) {
    case WIRE_ENCODER: {
        if (cap < 6) return 0;
        int32_t now[2] = { m->u.encoder.left, m->u.encoder.right };
        for (uint8_t s = 0; s < 2; s++) {
            int16_t d = clamp16(now[s] - t->enc_sent[s], 32767);
            put_id16(out + 3 * s, (uint8_t)(WIRE_C_ENC_LEFT + s), (uint16_t)d);
            t->enc_sent[s] += d;
        }
        return 6;
    }
    case WIRE_DISTANCE: {
        static const uint8_t id[WIRE_SENSOR_COUNT] = { WIRE_C_TOF_LEFT, WIRE_C_TOF_FRONT, WIRE_C_TOF_RIGHT };
        if (cap < 3 || m->u.distance.sensor >= WIRE_SENSOR_COUNT) return 0;
        uint16_t v = 65535u;
        if (!m->u.distance.timeout) {
            uint32_t s = m->u.distance.compat; /* scaled by the sender from the true distance */
            if (s == 0 && m->u.distance.mm >= t->range_mm) s = 65535u; /* at or beyond the range: a timeout */
            else if (s == 0) s = ((uint32_t)m->u.distance.mm * 65535u + t->range_mm / 2u) / t->range_mm;
            else if (s > 65534u) s = 65534u; /* a reading, never the timeout code */
            v = (uint16_t)s;
        }
        return put_id16(out, id[m->u.distance.sensor], v);
    }
    case WIRE_MOTOR:
        if (cap < 6) return 0;
        put_id16(out, WIRE_C_MOTOR_LEFT, (uint16_t)clamp16(m->u.motor.left, WIRE_MOTOR_MAX));
        put_id16(out + 3, WIRE_C_MOTOR_RIGHT, (uint16_t)clamp16(m->u.motor.right, WIRE_MOTOR_MAX));
        return 6;
    case WIRE_SENSORS:
    case WIRE_RUN:
        if (cap < 2) return 0;
        out[0] = WIRE_C_MANAGER;
        out[1] = m->type == WIRE_RUN ? (m->u.flag.on ? WIRE_C_START : WIRE_C_STOP)
                                     : (m->u.flag.on ? WIRE_C_ENABLE : WIRE_C_DISABLE);
        return 2;
    case WIRE_LOG: {
        size_t n = m->u.log.len <= WIRE_LOG_MAX ? m->u.log.len : WIRE_LOG_MAX;
        const char *nul = n ? memchr(m->u.log.text, 0, n) : NULL;
        if (nul) n = (size_t)(nul - m->u.log.text);
        if (cap < n + 2) return 0;
        out[0] = WIRE_C_LOGGER;
        if (n) memcpy(out + 1, m->u.log.text, n);
        out[n + 1] = 0;
        return n + 2;
    }
    default:
        return 0;
    }
}

void wire_compat_rx_init(wire_compat_rx_t *r, uint16_t range_mm)
{
    memset(r, 0, sizeof *r);
    r->id = 0xFF;
    r->range_mm = range_mm ? range_mm : WIRE_COMPAT_RANGE_MM;
}

static const uint8_t compat_len[9] = { 2, 2, 2, 2, 2, 2, 2, 1, 0 }; /* payload bytes per ID; 8 = to NUL */

int wire_compat_decode_byte(wire_compat_rx_t *r, uint8_t b, wire_msg_t *out)
{
    r->stats.bytes++;
    if (r->id == 0xFF) {
        if (b > WIRE_C_LOGGER) {
            r->stats.unknown++;
            return 0;
        }
        r->id = b;
        r->n = 0;
        r->need = compat_len[b];
        return 0;
    }
    if (r->id == WIRE_C_LOGGER) {
        if (b != 0) {
            if (r->n < WIRE_RX_LOG_MAX) r->buf[r->n++] = b;
            else if (!r->log_overflow) { /* overlong: counted once; the rest up to the NUL is skipped */
                r->log_overflow = 1;
                r->stats.overflow++;
            }
            return 0;
        }
        /* the NUL ends the line (cut to WIRE_RX_LOG_MAX bytes if it overflowed): the next byte is an ID */
        r->log_overflow = 0;
        memset(out, 0, sizeof *out);
        out->type = WIRE_LOG;
        out->u.log.len = r->n;
        r->buf[r->n] = 0;
        out->u.log.text = (const char *)r->buf;
        r->id = 0xFF;
        r->stats.frames_ok++;
        return 1;
    }
    r->buf[r->n++] = b;
    if (r->n < r->need) return 0;
    uint8_t id = r->id;
    r->id = 0xFF;
    memset(out, 0, sizeof *out);
    uint16_t v = get16(r->buf);
    switch (id) {
    case WIRE_C_TOF_LEFT:
    case WIRE_C_TOF_RIGHT:
    case WIRE_C_TOF_FRONT:
        out->type = WIRE_DISTANCE;
        out->u.distance.sensor = id == WIRE_C_TOF_LEFT ? WIRE_SENSOR_LEFT
                               : id == WIRE_C_TOF_RIGHT ? WIRE_SENSOR_RIGHT : WIRE_SENSOR_FRONT;
        out->u.distance.timeout = v == 65535u;
        out->u.distance.compat = v;
        out->u.distance.mm = v == 65535u ? r->range_mm
                                         : (uint16_t)(((uint32_t)v * r->range_mm + 32767u) / 65535u);
        break;
    case WIRE_C_ENC_LEFT:
    case WIRE_C_ENC_RIGHT:
        r->enc[id - WIRE_C_ENC_LEFT] += (int16_t)v;
        out->type = WIRE_ENCODER;
        out->u.encoder.left = r->enc[0];
        out->u.encoder.right = r->enc[1];
        break;
    case WIRE_C_MOTOR_LEFT:
    case WIRE_C_MOTOR_RIGHT:
        r->motor[id - WIRE_C_MOTOR_LEFT] = clamp16((int16_t)v, WIRE_MOTOR_MAX);
        out->type = WIRE_MOTOR;
        out->u.motor.left = r->motor[0];
        out->u.motor.right = r->motor[1];
        break;
    default: /* WIRE_C_MANAGER */
        if (r->buf[0] > WIRE_C_DISABLE) {
            r->stats.value++;
            return 0;
        }
        out->type = r->buf[0] <= WIRE_C_START ? WIRE_RUN : WIRE_SENSORS;
        out->u.flag.on = r->buf[0] == WIRE_C_START || r->buf[0] == WIRE_C_ENABLE;
        break;
    }
    r->stats.frames_ok++;
    return 1;
}

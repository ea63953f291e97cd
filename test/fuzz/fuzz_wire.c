/* fuzz_wire.c - libFuzzer target for the wire codec (make fuzz).
 * 1. The input as a byte stream into both decoders (framed and compat):
 *    no crash, no out-of-bounds; every delivered message re-encodes and
 *    decodes to itself.
 * 2. The input as message fields: encode, decode, compare (the CRC would
 *    otherwise keep the fuzzer out of the decoders' success paths). */
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "wire.h"

static void same_or_die(const wire_msg_t *a, const wire_msg_t *b)
{
    uint8_t x[WIRE_FRAME_MAX], y[WIRE_FRAME_MAX];
    size_t nx = wire_encode(a, x, sizeof x), ny = wire_encode(b, y, sizeof y);
    if (nx != ny || memcmp(x, y, nx)) abort();
}

static void round_trip(const wire_msg_t *m)
{
    uint8_t f[WIRE_FRAME_MAX];
    size_t n = wire_encode(m, f, sizeof f);
    if (n == 0) return; /* invalid fields are refused, fine */
    if (n > WIRE_FRAME_MAX || f[n - 1] != 0 || memchr(f, 0, n - 1)) abort();
    wire_decoder_t d;
    wire_msg_t out;
    wire_decoder_init(&d);
    int got = 0;
    for (size_t i = 0; i < n; i++) got += wire_decode_byte(&d, f[i], &out);
    if (got != 1 || wire_stats_errors(&d.stats)) abort();
    same_or_die(m, &out);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    wire_decoder_t d;
    wire_compat_rx_t c;
    wire_msg_t m;
    wire_decoder_init(&d);
    wire_compat_rx_init(&c, 1200);
    for (size_t i = 0; i < size; i++) {
        if (wire_decode_byte(&d, data[i], &m)) round_trip(&m);
        if (wire_compat_decode_byte(&c, data[i], &m) && m.type != WIRE_LOG) {
            uint8_t b[WIRE_FRAME_MAX];
            wire_compat_tx_t tx;
            wire_compat_tx_init(&tx, 1200);
            if (!wire_compat_encode(&tx, &m, b, sizeof b)) abort(); /* every compat message has a compat form */
        }
    }
    if (d.stats.bytes != size || c.stats.bytes != size) abort();

    if (size >= 14) { /* fields from the input */
        memset(&m, 0, sizeof m);
        m.type = (uint8_t)(data[0] % 9);
        uint32_t a, b2, t;
        memcpy(&t, data + 1, 4);
        memcpy(&a, data + 5, 4);
        memcpy(&b2, data + 9, 4);
        switch (m.type) {
        case WIRE_HELLO: m.u.hello.version = (uint8_t)a; m.u.hello.role = (uint8_t)(b2 & 3);
            m.u.hello.tof_range_mm = (uint16_t)t; m.u.hello.counts_per_rev_x100 = a ^ b2; m.u.hello.tick_hz = (uint16_t)(t >> 16); break;
        case WIRE_MOTOR: m.u.motor.t_us = t; m.u.motor.left = (int16_t)a; m.u.motor.right = (int16_t)b2; break;
        case WIRE_ENCODER: m.u.encoder.t_us = t; m.u.encoder.left = (int32_t)a; m.u.encoder.right = (int32_t)b2; break;
        case WIRE_DISTANCE: m.u.distance.t_us = t; m.u.distance.sensor = (uint8_t)a; m.u.distance.timeout = (uint8_t)(a >> 8);
            m.u.distance.mm = (uint16_t)b2; break;
        case WIRE_SENSORS: case WIRE_RUN: m.u.flag.on = (uint8_t)a; break;
        case WIRE_LOG: m.u.log.len = (uint8_t)(size - 13 > 90 ? 90 : size - 13); m.u.log.text = (const char *)data + 13; break;
        default: break;
        }
        round_trip(&m);
    }
    return 0;
}

/* MMLink.cpp - see MMLink.h. */
#include "MMLink.h"

#include <stdio.h>

MMLink mmLink;

void MMLink::begin(Stream &stream, uint8_t protocol, uint16_t tick, uint16_t range)
{
    s = &stream;
    proto = protocol == MM_COMPAT ? MM_COMPAT : MM_FRAMED;
    tick_hz = tick;
    range_mm = range ? range : proto == MM_COMPAT ? WIRE_COMPAT_RANGE_MM : WIRE_TOF_RANGE_MM;
    if (proto == MM_COMPAT) wire_compat_rx_init(&dec.compat, range_mm);
    else wire_decoder_init(&dec.framed);
    wire_compat_tx_init(&ctx, range_mm);
    for (uint8_t i = 0; i < 2; i++) enc[i] = 0;
    for (uint8_t i = 0; i < MM_TOF_COUNT; i++) {
        tof_mm[i] = range_mm;
        tof_timeout[i] = 1;
        tof_seq[i] = 0;
    }
    sim_us = 0;
    hello_seen = 0;
    if (proto == MM_FRAMED) sendHello();
}

const wire_stats_t &MMLink::stats() const { return proto == MM_COMPAT ? dec.compat.stats : dec.framed.stats; }

void MMLink::sendHello()
{
    wire_msg_t m;
    memset(&m, 0, sizeof m);
    m.type = WIRE_HELLO;
    m.u.hello.version = hello_seen == 1 ? 1 : WIRE_VERSION; /* a version-1 sim takes only 1 */
    m.u.hello.role = WIRE_ROLE_MCU;
    m.u.hello.tof_range_mm = range_mm;
    m.u.hello.counts_per_rev_x100 = 35832u; /* 12 PPR x 29.86 gear, the default robot */
    m.u.hello.tick_hz = tick_hz;
    send(m);
}

/* One log line for a sim whose HELLO differs from this build (the sim keeps
 * the motors off on a version mismatch; a ToF range mismatch scales every
 * distance wrong). Not inlined: its buffer is on the stack only then. */
void __attribute__((noinline)) MMLink::logMismatch(const wire_msg_t &hello)
{
    char line[64];
    wire_msg_t m;
    memset(&m, 0, sizeof m);
    m.type = WIRE_LOG;
    m.u.log.len = (uint8_t)snprintf_P(line, sizeof line, PSTR("sim hello differs: protocol %u, ToF %u mm (MCU: %u, %u mm)"),
                                      (unsigned)hello.u.hello.version, (unsigned)hello.u.hello.tof_range_mm,
                                      (unsigned)WIRE_VERSION, (unsigned)range_mm);
    if (m.u.log.len >= sizeof line) m.u.log.len = sizeof line - 1;
    m.u.log.text = line;
    send(m);
}

void MMLink::send(const wire_msg_t &m)
{
    if (!s) return;
    uint8_t b[WIRE_FRAME_MAX];
    size_t n = proto == MM_COMPAT ? wire_compat_encode(&ctx, &m, b, sizeof b) : wire_encode(&m, b, sizeof b);
    if (n) s->write(b, n);
}

void MMLink::sendMotorSide(uint8_t side, int16_t v)
{
    if (!s || side > MM_RIGHT) return;
    if (v > WIRE_MOTOR_MAX) v = WIRE_MOTOR_MAX;
    if (v < -WIRE_MOTOR_MAX) v = -WIRE_MOTOR_MAX;
    uint8_t b[3] = { (uint8_t)(WIRE_C_MOTOR_LEFT + side), (uint8_t)v, (uint8_t)((uint16_t)v >> 8) };
    s->write(b, 3);
}

void MMLink::poll()
{
    if (!s) return;
    wire_msg_t m;
    int c;
    while ((c = s->read()) >= 0) {
        int got = proto == MM_COMPAT ? wire_compat_decode_byte(&dec.compat, (uint8_t)c, &m)
                                     : wire_decode_byte(&dec.framed, (uint8_t)c, &m);
        if (!got) continue;
        switch (m.type) {
        case WIRE_ENCODER:
            enc[0] = m.u.encoder.left;
            enc[1] = m.u.encoder.right;
            sim_us = m.u.encoder.t_us;
            break;
        case WIRE_DISTANCE:
            tof_mm[m.u.distance.sensor] = m.u.distance.mm; /* sensor < 3: checked by the decoder */
            tof_timeout[m.u.distance.sensor] = m.u.distance.timeout;
            tof_seq[m.u.distance.sensor]++;
            break;
        case WIRE_HELLO:
            if (m.u.hello.role == WIRE_ROLE_SIM) {
                if (m.u.hello.version < WIRE_VERSION_MIN || m.u.hello.version > WIRE_VERSION ||
                    m.u.hello.tof_range_mm != range_mm)
                    logMismatch(m);
                hello_seen = m.u.hello.version ? m.u.hello.version : 0xFF;
                sendHello();
            }
            break;
        case WIRE_IR:
        case WIRE_GYRO:
        case WIRE_BATTERY:
        case WIRE_ROBOT:
            if (hal_wire_extra) hal_wire_extra(&m, NULL); /* linked in only if the firmware reads them */
            break;
        default: break; /* commands are for the sim */
        }
    }
}

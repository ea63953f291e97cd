/* hal_arduino_sensors.cpp - hal/hal.h's IR, emitter, gyro and battery
 * functions from the link's messages (protocol version 2, docs/PROTOCOL.md).
 *
 * A file of its own: MMLink.cpp and the runner call hal_wire_extra through
 * a weak reference (MMLink.h), which makes the linker pull nothing; it
 * takes the messages and hands the runner the EMITTER to send, so this
 * file never calls the link. It is linked in, with its storage, only
 * when the firmware calls one of
 * the functions below, so a firmware that does not (the example Mouse on
 * the Uno: 1,536 B) keeps every byte of SRAM.
 *
 * Interrupt discipline (MMMouse.h): the runner's tick is the only code on
 * the link. hal_emitter queues the groups; the tick sends one EMITTER after
 * fw_tick (the calls of one tick make one EMITTER); the simulator answers
 * it with an IR frame, taken with those groups lit, that arrives at a later
 * tick. An IR frame taken with other groups than the ones asked for last
 * (an answer to an earlier EMITTER) is ignored: hal_ir_raw only gives a
 * sample of the emitters as the firmware set them. */
#include "MMLink.h"

#include <util/atomic.h>

#include "hal.h"

static uint8_t ir_packed[WIRE_IR_PACKED]; /* the latest IR frame's samples, 10 bits each */
static volatile uint8_t ir_n;             /* IR sensors (ROBOT, or the latest IR frame) */
static volatile uint8_t ir_seq;           /* the latest IR frame's seq */
static volatile uint8_t flags;            /* WIRE_ROBOT_* */
static volatile uint8_t lit, pending;     /* the groups asked for; an EMITTER waits for the tick */
static volatile int32_t gyro_mdps;
static volatile uint16_t battery_mv;

static void take_ir(const wire_msg_t *m)
{
    if (m->u.ir.emitters != lit) return; /* sampled before the latest hal_emitter */
    for (uint8_t i = 0; i < WIRE_IR_PACKED; i++) ir_packed[i] = m->u.ir.packed[i];
    ir_n = m->u.ir.count;
    ir_seq = m->u.ir.seq;
}

uint8_t hal_wire_extra(const wire_msg_t *m, wire_msg_t *out)
{
    if (!m) {
        if (!pending) return 0;
        memset(out, 0, sizeof *out);
        out->type = WIRE_EMITTER;
        out->u.emitter.groups = lit;
        pending = 0;
        return 1; /* the runner sends it (compat has no EMITTER: nothing goes, no IR comes) */
    }
    switch (m->type) {
    case WIRE_IR: take_ir(m); break;
    case WIRE_GYRO:
        gyro_mdps = m->u.gyro.mdps;
        flags |= WIRE_ROBOT_GYRO;
        break;
    case WIRE_BATTERY:
        battery_mv = m->u.battery.mv;
        flags |= WIRE_ROBOT_BATTERY;
        break;
    case WIRE_ROBOT:
        ir_n = m->u.robot.ir_count;
        flags = m->u.robot.flags;
        break;
    default: break;
    }
    return 0;
}

uint8_t hal_ir_count(void) { return ir_n; }

void hal_emitter(uint8_t group, uint8_t on)
{
    if (group >= HAL_EMITTER_GROUPS || group >= WIRE_EMITTER_GROUPS) return;
    uint8_t bit = (uint8_t)(1u << group);
    ATOMIC_BLOCK(ATOMIC_RESTORESTATE)
    {
        lit = on ? (uint8_t)(lit | bit) : (uint8_t)(lit & ~bit);
        pending = 1;
    }
}

uint16_t hal_ir_raw(uint8_t sensor)
{
    uint16_t v = 0;
    ATOMIC_BLOCK(ATOMIC_RESTORESTATE)
    {
        if (sensor < ir_n) v = wire_ir_sample(ir_packed, sensor); /* the codec's, checked by the vectors on AVR */
    }
    return v;
}

uint8_t hal_ir_seq(void) { return ir_seq; }
uint8_t hal_gyro_present(void) { return (flags & WIRE_ROBOT_GYRO) ? 1 : 0; }

int32_t hal_gyro_mdps(void)
{
    int32_t v;
    ATOMIC_BLOCK(ATOMIC_RESTORESTATE) { v = gyro_mdps; }
    return v;
}

uint16_t hal_battery_mv(void)
{
    uint16_t v;
    ATOMIC_BLOCK(ATOMIC_RESTORESTATE) { v = battery_mv; }
    return v;
}

/* MMApi.cpp - see MMApi.h. */
#include "MMApi.h"

#include <util/atomic.h>

static int16_t motor_cmd[2]; /* framed MOTOR carries both sides */

void SensorManager::begin() { mmLink.begin(*stream, proto, 0); }

static void flag(uint8_t type, uint8_t on)
{
    wire_msg_t m;
    memset(&m, 0, sizeof m);
    m.type = type;
    m.u.flag.on = on;
    mmLink.send(m);
}

void SensorManager::requestEnableSensors() { flag(WIRE_SENSORS, 1); }
void SensorManager::requestDisableSensors() { flag(WIRE_SENSORS, 0); }
void SensorManager::update() { mmLink.poll(); }

void ActuatorManager::requestStart() { flag(WIRE_RUN, 1); }
void ActuatorManager::requestStop() { flag(WIRE_RUN, 0); }

void ActuatorManager::log(const char *text)
{
    wire_msg_t m;
    memset(&m, 0, sizeof m);
    m.type = WIRE_LOG;
    size_t n = text ? strnlen(text, WIRE_LOG_MAX) : 0;
    m.u.log.text = text;
    m.u.log.len = (uint8_t)n;
    mmLink.send(m);
}

bool Motor::setVoltage(int16_t value)
{
    if (side > MM_RIGHT) return false;
    bool ok = value >= -WIRE_MOTOR_MAX && value <= WIRE_MOTOR_MAX;
    if (value > WIRE_MOTOR_MAX) value = WIRE_MOTOR_MAX;
    if (value < -WIRE_MOTOR_MAX) value = -WIRE_MOTOR_MAX;
    motor_cmd[side] = value;
    if (mmLink.protocol() == MM_COMPAT) {
        mmLink.sendMotorSide(side, value);
    } else {
        wire_msg_t m;
        memset(&m, 0, sizeof m);
        m.type = WIRE_MOTOR;
        m.u.motor.t_us = micros();
        m.u.motor.left = motor_cmd[0];
        m.u.motor.right = motor_cmd[1];
        mmLink.send(m);
    }
    return ok;
}

static int32_t counts(uint8_t side)
{
    int32_t c;
    ATOMIC_BLOCK(ATOMIC_RESTORESTATE) { c = mmLink.enc[side]; }
    return c;
}

int32_t Encoder::getCounts() const { return side > MM_RIGHT ? 0 : counts(side) - zero; }
void Encoder::reset()
{
    if (side <= MM_RIGHT) zero = counts(side);
}

DistanceReading DistanceSensor::getReading() const
{
    DistanceReading r = { WIRE_COMPAT_RANGE_MM / 1000.0f, WIRE_COMPAT_RANGE_MM, true };
    if (which >= MM_TOF_COUNT) return r;
    ATOMIC_BLOCK(ATOMIC_RESTORESTATE)
    {
        r.distance_mm = mmLink.tof_mm[which];
        r.timeout = mmLink.tof_timeout[which] != 0;
    }
    r.distance = r.distance_mm / 1000.0f;
    return r;
}

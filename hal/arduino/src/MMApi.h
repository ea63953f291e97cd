/* MMApi.h - the user API of the Arduino library shipped with the paper's
 * Unity simulator, on top of mmLink: SensorManager (receives), ActuatorManager
 * (sends), Motor, Encoder, DistanceSensor. Works in compat mode (existing
 * sketches, the default) and framed mode. Every index is bounds-checked: a
 * bad side or sensor gives a harmless value, never a wild access. */
#ifndef MM_API_H
#define MM_API_H

#include "MMLink.h"

struct DistanceReading {
    float distance;       /* metres */
    uint16_t distance_mm; /* millimetres */
    bool timeout;         /* nothing within range (distance is then the range) */
};

class SensorManager {
public:
    explicit SensorManager(Stream &s = Serial, uint8_t protocol = MM_COMPAT) : stream(&s), proto(protocol) {}
    /* After Serial.begin(baud): attach the link. */
    void begin();
    /* Ask the simulator to send sensor readings (it sends none before). */
    void requestEnableSensors();
    void requestDisableSensors();
    /* Read what arrived; call it often (every loop). */
    void update();

private:
    Stream *stream;
    uint8_t proto;
};

class ActuatorManager {
public:
    /* Compat: stop holds the robot's motors at 0 until start (the
     * simulator runs on); framed: stop ends the simulator's run. */
    void requestStart();
    void requestStop();
    /* One line to the simulator's log (at most 80 bytes are sent). */
    void log(const char *text);
};

class Motor {
public:
    explicit Motor(uint8_t side) : side(side) {}
    /* 11-bit signed command: -1023..1023 = -100..100 % of the battery
     * voltage. Out of range is clamped and returns false; a bad side sends
     * nothing and returns false. */
    bool setVoltage(int16_t value);

private:
    uint8_t side;
};

class Encoder {
public:
    explicit Encoder(uint8_t side) : side(side) {}
    /* Counts since start or the last reset (0 for a bad side). */
    int32_t getCounts() const;
    void reset();

private:
    uint8_t side;
    int32_t zero = 0;
};

class DistanceSensor {
public:
    /* MM_TOF_LEFT, MM_TOF_FRONT or MM_TOF_RIGHT */
    explicit DistanceSensor(uint8_t which) : which(which) {}
    /* The latest reading; a bad index reads as a timeout. */
    DistanceReading getReading() const;

private:
    uint8_t which;
};

#endif

/* MMLink.h - the MCU's end of the wire protocol (docs/PROTOCOL.md) over an
 * Arduino Stream: decodes sensor messages into the latest encoder counts
 * and ToF readings, sends commands. One link per sketch: mmLink. */
#ifndef MM_LINK_H
#define MM_LINK_H

#include <Arduino.h>

#include "wire.h"

enum { MM_FRAMED = 0, MM_COMPAT = 1 };
enum { MM_LEFT = 0, MM_RIGHT = 1 };
enum { MM_TOF_LEFT = 0, MM_TOF_FRONT = 1, MM_TOF_RIGHT = 2, MM_TOF_COUNT = 3 };

class MMLink {
public:
    /* tick_hz goes in HELLO (framed). range_mm: framed, the ToF range sent in
     * HELLO; compat, the distance that 65535 stands for; 0 = the protocol's
     * default (framed WIRE_TOF_RANGE_MM, compat WIRE_COMPAT_RANGE_MM: the
     * paper's library's 1.0 m, which the simulator's compat mode follows) */
    void begin(Stream &s, uint8_t protocol, uint16_t tick_hz, uint16_t range_mm = 0);
    /* Decode every byte waiting in the Stream; answers the sim's HELLO (and
     * logs one line if its protocol version or ToF range differs). */
    void poll();
    /* Encode and write one message (blocks while the Stream's buffer is full). */
    void send(const wire_msg_t &m);
    /* Compat only: one motor's command as ID 5/6 (the paper's Motor::setVoltage). */
    void sendMotorSide(uint8_t side, int16_t value);
    void sendHello();
    uint8_t protocol() const { return proto; }
    /* The latest readings (copy with interrupts off if poll runs in an ISR). */
    volatile int32_t enc[2];           /* accumulated counts */
    volatile uint16_t tof_mm[MM_TOF_COUNT];
    volatile uint8_t tof_timeout[MM_TOF_COUNT];
    volatile uint8_t tof_seq[MM_TOF_COUNT];     /* +1 per reading received (hal_distance_t.seq) */
    volatile uint32_t sim_us;          /* sim time of the latest reading (framed), us */
    volatile uint8_t hello_seen;       /* framed: the protocol version of the sim's HELLO (0 = none yet);
                                          a version-1 sim is answered in version 1 */
    const wire_stats_t &stats() const;

private:
    void logMismatch(const wire_msg_t &hello);
    Stream *s = nullptr;
    uint8_t proto = MM_FRAMED;
    uint16_t tick_hz = 0, range_mm = WIRE_TOF_RANGE_MM;
    union { /* one decoder at a time: saves SRAM on the Uno */
        wire_decoder_t framed;
        wire_compat_rx_t compat;
    } dec;
    wire_compat_tx_t ctx;
};

extern MMLink mmLink;

/* The version-2 sensor messages (IR, GYRO, BATTERY, ROBOT) go here from
 * poll(); m == NULL: the runner's tick is done: a queued EMITTER goes into
 * *out and 1 is returned (the runner sends it), else 0. The sensors' file
 * never sends itself, so the link and it do not call each other.
 * Defined in hal_arduino_sensors.cpp, which the linker takes from the
 * library only when the firmware calls hal_emitter, hal_ir_*, hal_gyro_*
 * or hal_battery_mv. The callers hold a weak reference (the linker pulls
 * no archive member for one; it is NULL without that file) and call it
 * only if it is there: a firmware without those calls keeps every byte
 * of SRAM (the Uno Mouse: 1,536 B, test/cli/cli_pil.sh). */
uint8_t hal_wire_extra(const wire_msg_t *m, wire_msg_t *out) __attribute__((weak));

#endif

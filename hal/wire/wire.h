/* wire.h - the serial wire protocol between the simulator and a
 * microcontroller (hardware in the loop). One codec for both ends: portable
 * C99, no malloc, no floating point, correct with a 16-bit int (AVR).
 * Layouts, rates and byte budgets: docs/PROTOCOL.md.
 *
 * Two modes:
 * - framed (default): each message is type byte + payload + CRC-16
 *   (CCITT-FALSE, little-endian), COBS-encoded, ended by a 0x00 delimiter.
 *   A corrupt, unknown or malformed frame is counted and skipped; decoding
 *   resynchronises at the next 0x00.
 * - compat: byte-compatible with the Arduino library shipped with the
 *   paper's Unity simulator: ID byte + fixed-length little-endian payload,
 *   no framing, no checksum. The codec converts to and from the framed
 *   message structs so both ends' upper layers handle one message kind.
 */
#ifndef WIRE_H
#define WIRE_H

#include <stddef.h>
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

#define WIRE_VERSION 2          /* protocol version carried in HELLO (2: EMITTER, IR, GYRO, BATTERY, ROBOT) */
#define WIRE_VERSION_MIN 1      /* the oldest version a peer may speak: a version-1 peer gets no
                                   version-2 message (docs/PROTOCOL.md, "Versions") */
#define WIRE_LOG_MAX 80         /* bytes of text in a LOG message (= HAL_LOG_MAX) */
#define WIRE_RAW_MAX (1 + WIRE_LOG_MAX + 2)      /* type + longest payload + CRC, bytes */
#define WIRE_FRAME_MAX (WIRE_RAW_MAX + 2 + 1)    /* + COBS overhead + delimiter, bytes */
/* The longest LOG text a decoder takes, bytes: WIRE_LOG_MAX by default.
 * An MCU never receives LOG (the sim's longest message, IR with 8 sensors,
 * is 17 bytes before the delimiter, ENCODER 16) and may build ALL its files with
 * -DWIRE_RX_LOG_MAX=14 (it sizes both decoders' buffers: 66 B less SRAM);
 * a longer frame is then counted as overflow (and dropped), a longer compat
 * log line counted as overflow and delivered cut to WIRE_RX_LOG_MAX bytes. */
#ifndef WIRE_RX_LOG_MAX
#define WIRE_RX_LOG_MAX WIRE_LOG_MAX
#endif
#define WIRE_RX_MAX (WIRE_RX_LOG_MAX + 6) /* framed decoder's buffer: WIRE_FRAME_MAX by default */
#define WIRE_MOTOR_MAX 1023     /* motor command limit, +-1023 = +-100 % battery */
#define WIRE_TOF_RANGE_MM 1200u    /* our robot's ToF range, mm, sent in HELLO: the simulator's [tof]
                                      tof_range_m default (VL53L0X long range) */
#define WIRE_COMPAT_RANGE_MM 1000u /* compat's distance scale, mm: u16 65535 stands for this distance. The
                                      paper's Arduino library converts with 1.0 m and its Unity simulator's
                                      default ToF (TimeOfFlight asset) has range 1.0 m; the simulator's
                                      [link] compat_range_m */

enum wire_type {
    WIRE_HELLO = 0x01,    /* both ways: version, role, scaling */
    WIRE_MOTOR = 0x02,    /* MCU -> sim: motor commands */
    WIRE_ENCODER = 0x03,  /* sim -> MCU: accumulated encoder counts */
    WIRE_DISTANCE = 0x04, /* sim -> MCU: one ToF reading */
    WIRE_SENSORS = 0x05,  /* MCU -> sim: enable / disable the ToF sensors */
    WIRE_RUN = 0x06,      /* MCU -> sim: start / stop */
    WIRE_LOG = 0x07,      /* MCU -> sim: one text line */
    /* version 2: sensors of robots other than the paper's (hal/hal.h) */
    WIRE_EMITTER = 0x08,  /* MCU -> sim: which emitter groups are lit; the sim answers with IR */
    WIRE_IR = 0x09,       /* sim -> MCU: every IR sensor's 10-bit sample, taken after an EMITTER */
    WIRE_GYRO = 0x0A,     /* sim -> MCU: the gyro's z rate, mdps (robots with a gyro) */
    WIRE_BATTERY = 0x0B,  /* sim -> MCU: the battery's terminal voltage, mV (robots with one) */
    WIRE_ROBOT = 0x0C     /* sim -> MCU: IR sensor count, gyro and battery present (after HELLO) */
};

#define WIRE_IR_MAX 8            /* IR sensors in an IR frame (= HAL_IR_MAX) */
#define WIRE_IR_PACKED 10        /* bytes of WIRE_IR_MAX packed 10-bit samples */
#define WIRE_EMITTER_GROUPS 4    /* emitter groups, bits 0..3 of a mask (= HAL_EMITTER_GROUPS) */
enum { WIRE_ROBOT_GYRO = 1, WIRE_ROBOT_BATTERY = 2 }; /* ROBOT flags */

enum { WIRE_ROLE_SIM = 0, WIRE_ROLE_MCU = 1 };
enum { WIRE_SENSOR_LEFT = 0, WIRE_SENSOR_FRONT = 1, WIRE_SENSOR_RIGHT = 2, WIRE_SENSOR_COUNT = 3 };

typedef struct {
    uint8_t type; /* enum wire_type */
    union {
        struct {
            uint8_t version;        /* WIRE_VERSION */
            uint8_t role;           /* WIRE_ROLE_* of the sender */
            uint16_t tof_range_mm;  /* distance that means "nothing in range", mm */
            uint32_t counts_per_rev_x100; /* encoder counts per wheel turn x 100 */
            uint16_t tick_hz;       /* sender's control tick (MCU) or physics rate (sim), Hz */
        } hello;
        struct {
            uint32_t t_us;          /* sender's time, us (MCU hal_micros) */
            int16_t left, right;    /* -1023..1023 */
        } motor;
        struct {
            uint32_t t_us;          /* sim time of the reading, us */
            int32_t left, right;    /* counts accumulated since start */
        } encoder;
        struct {
            uint32_t t_us;          /* sim time of the reading, us */
            uint8_t sensor;         /* WIRE_SENSOR_* */
            uint8_t timeout;        /* 1 = nothing within range */
            uint16_t mm;            /* distance, mm */
            uint16_t compat;        /* compat's u16, round(d / range * 65535), 65535 = timeout:
                                       the decoder fills it; the encoder sends it for a
                                       reading when non-zero (finer than mm), else scales mm
                                       (mm at or beyond the range: sent as a timeout).
                                       Not in framed frames. */
        } distance;
        struct {
            uint8_t on;             /* 1 enable, 0 disable (SENSORS); 1 start, 0 stop (RUN) */
        } flag;
        struct {
            uint8_t groups;         /* bit g = emitter group g lit (g < WIRE_EMITTER_GROUPS) */
        } emitter;
        struct {
            uint8_t seq;            /* +1 (mod 256) with every IR frame the sim sends */
            uint8_t emitters;       /* the groups lit when it sampled (the EMITTER it answers) */
            uint8_t count;          /* sensors, 0..WIRE_IR_MAX */
            uint8_t packed[WIRE_IR_PACKED]; /* samples 0..1023, 10 bits each, LSB first:
                                       use wire_ir_get / wire_ir_set */
        } ir;
        struct {
            uint32_t t_us;          /* sim time of the reading, us */
            int32_t mdps;           /* z rate, millidegrees/s, counter-clockwise positive */
        } gyro;
        struct {
            uint32_t t_us;          /* sim time of the reading, us */
            uint16_t mv;            /* terminal voltage, mV */
        } battery;
        struct {
            uint8_t ir_count;       /* IR sensors, 0..WIRE_IR_MAX */
            uint8_t flags;          /* WIRE_ROBOT_GYRO | WIRE_ROBOT_BATTERY */
        } robot;
        struct {
            uint8_t len;            /* 0..WIRE_LOG_MAX */
            const char *text;       /* len bytes; decoded: NUL-terminated, inside the
                                       decoder, valid until the next byte is fed */
        } log;
    } u;
} wire_msg_t;

/* Decoder error counters (both modes use the relevant subset). */
typedef struct {
    uint32_t bytes;       /* bytes fed */
    uint32_t frames_ok;   /* messages delivered */
    uint32_t crc;         /* framed: CRC mismatch */
    uint32_t cobs;        /* framed: COBS code points past the end */
    uint32_t overflow;    /* framed: no delimiter within WIRE_FRAME_MAX bytes; compat: log too long */
    uint32_t unknown;     /* unknown message type / compat ID */
    uint32_t length;      /* framed: wrong payload length for the type (incl. too short) */
    uint32_t value;       /* a field out of range (motor > 1023, sensor index, flag) */
} wire_stats_t;

/* Sum of all error counters. */
uint32_t wire_stats_errors(const wire_stats_t *s);

/* CRC-16/CCITT-FALSE (poly 0x1021, init 0xFFFF); "123456789" -> 0x29B1. */
uint16_t wire_crc16(const uint8_t *p, size_t n);

/* IR sample i (0..WIRE_IR_MAX-1) of an IR message (0 past the end); set
 * clamps v to 1023. wire_ir_sample reads it from a copy of the packed bytes. */
uint16_t wire_ir_sample(const uint8_t packed[WIRE_IR_PACKED], uint8_t i);
uint16_t wire_ir_get(const wire_msg_t *m, uint8_t i);
void wire_ir_set(wire_msg_t *m, uint8_t i, uint16_t v);

/* ---- framed mode ---- */

/* Encode one message into out (a complete frame incl. the trailing 0x00),
 * in place (no second buffer: small stack on the MCU). Returns the bytes
 * written, or 0 if the message is invalid or does not fit cap. */
size_t wire_encode(const wire_msg_t *m, uint8_t *out, size_t cap);

typedef struct {
    uint8_t buf[WIRE_RX_MAX];
    uint8_t len;
    uint8_t skipping;   /* overflowed: ignore bytes until the next delimiter */
    wire_stats_t stats;
} wire_decoder_t;

void wire_decoder_init(wire_decoder_t *d);
/* Feed one byte. Returns 1 and fills *out when it completed a valid
 * message, else 0 (errors are counted in d->stats). */
int wire_decode_byte(wire_decoder_t *d, uint8_t b, wire_msg_t *out);

/* ---- compat mode (the paper's byte layout) ---- */

enum {
    WIRE_C_TOF_LEFT = 0, WIRE_C_TOF_RIGHT = 1, WIRE_C_TOF_FRONT = 2,
    WIRE_C_ENC_LEFT = 3, WIRE_C_ENC_RIGHT = 4,
    WIRE_C_MOTOR_LEFT = 5, WIRE_C_MOTOR_RIGHT = 6,
    WIRE_C_MANAGER = 7, WIRE_C_LOGGER = 8
};
enum { WIRE_C_STOP = 0, WIRE_C_START = 1, WIRE_C_ENABLE = 2, WIRE_C_DISABLE = 3 };

/* Sender state: encoders go as int16 deltas since the last *sent* count. */
typedef struct {
    int32_t enc_sent[2];
    uint16_t range_mm;     /* ToF range for the distance scaling */
} wire_compat_tx_t;

void wire_compat_tx_init(wire_compat_tx_t *t, uint16_t range_mm);
/* Encode m as compat message(s): ENCODER -> IDs 3 and 4 (a delta beyond
 * int16 is sent in part, the rest follows next time), DISTANCE -> ID 0/1/2,
 * MOTOR -> IDs 5 and 6 (clamped to +-1023), SENSORS/RUN -> ID 7, LOG -> ID 8
 * + text + NUL. HELLO and the version-2 messages have no compat form
 * (return 0). Returns the bytes
 * written, 0 if it does not fit cap (t is then unchanged). */
size_t wire_compat_encode(wire_compat_tx_t *t, const wire_msg_t *m, uint8_t *out, size_t cap);

typedef struct {
    uint8_t id;            /* message being received, 0xFF = waiting for an ID */
    uint8_t need;          /* payload bytes still expected */
    uint8_t n;
    uint8_t buf[WIRE_RX_LOG_MAX + 1];
    uint8_t log_overflow;  /* skipping the rest of an overlong log line */
    int32_t enc[2];        /* receiver: counts accumulated from deltas */
    int16_t motor[2];      /* receiver: last command per side */
    uint16_t range_mm;
    wire_stats_t stats;
} wire_compat_rx_t;

void wire_compat_rx_init(wire_compat_rx_t *r, uint16_t range_mm);
/* Feed one byte; returns 1 and fills *out on a complete message: ENCODER
 * (both sides' accumulated counts), DISTANCE (mm from the scaled value,
 * 65535 = timeout), MOTOR (both sides' latest commands), SENSORS, RUN, LOG.
 * An unknown ID is counted and skipped (one byte). A log line longer than
 * WIRE_RX_LOG_MAX is counted (overflow) once, skipped up to its NUL and
 * delivered cut, so the byte after the NUL is read as an ID again. */
int wire_compat_decode_byte(wire_compat_rx_t *r, uint8_t b, wire_msg_t *out);

#ifdef __cplusplus
}
#endif

#endif

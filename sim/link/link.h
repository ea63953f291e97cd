/* link.h - the simulator's end of the hardware-in-the-loop serial link.
 *
 * After each physics step link_step_io (the contest calls it through
 * sim/contest/run_link.c) sends the robot's sensor readings to
 * the microcontroller (ENCODER every step, DISTANCE when a ToF sensor took a
 * new reading; to a version-2 MCU also ROBOT after the handshake, GYRO with
 * ENCODER, BATTERY every 100 ms, and an IR frame in answer to each EMITTER)
 * and applies the motor commands it received. Bytes cross at
 * the baud rate, 8N1 = 10 bits per byte, never faster; queue, drop,
 * silence and reconnect policy: docs/PROTOCOL.md, "Link timing". */
#ifndef LINK_H
#define LINK_H

#include <stddef.h>
#include <stdint.h>
#include <stdio.h>

#include <jansson.h>

#include "wire.h"

enum { LINK_FRAMED = 0, LINK_COMPAT = 1 };

#define LINK_Q_MAX 4096u          /* sim -> MCU queue limit, bytes */
#define LINK_RETRY_S 0.5          /* reopen / HELLO interval, s of sim time */
#define LINK_BATTERY_S 0.1        /* BATTERY interval, s of sim time */
#define LINK_IR_REPORT 32         /* IR frames reported one line each (then only counted) */
#define LINK_SILENCE_S 0.1        /* framed's default silence timeout, s (our library sends MOTOR every tick);
                                     compat has none by default: the paper's Unity simulator applies a motor
                                     command until the next one and has no watchdog */

/* The protocol's baud when none is given, bits/s: framed 1,000,000 (our
 * Arduino library's Serial.begin, hal/arduino/src/MMMouse.h), compat
 * 115200 (the paper's Arduino side). */
uint32_t link_default_baud(int protocol);

typedef struct {
    const char *device;   /* serial device path, or NULL with pty */
    int pty;              /* create a pseudo-terminal instead */
    uint32_t baud;        /* bits/s; 0 = the protocol's default */
    int protocol;         /* LINK_FRAMED / LINK_COMPAT */
    double silence_s;     /* no valid message this long -> motors 0; 0 = never (no watchdog);
                             < 0 = the protocol's default (framed LINK_SILENCE_S, compat never) */
    double compat_range_m; /* compat: the distance u16 65535 stands for, m (config [link] compat_range_m);
                              0 = WIRE_COMPAT_RANGE_MM. A reading at or beyond it goes as a timeout */
} link_opts_t;

typedef struct {
    uint64_t tx_bytes, rx_bytes;         /* moved over the wire */
    uint64_t tx_msgs, rx_msgs;           /* messages queued / decoded */
    uint64_t tx_dropped;                 /* messages dropped: queue full */
    uint64_t tx_blocked_bytes;           /* bytes the budget allowed but the OS did not take */
    uint64_t steps;                      /* physics steps seen */
    uint32_t silences, disconnects, connects, logs;
    uint32_t stops;                      /* framed RUN stop received (mmsim ends the run) */
    uint32_t halts;                      /* compat ID 7 value 0 (stop): motors held at 0 until start */
    uint32_t emitters, ir_frames;        /* EMITTER received, IR sent (one per EMITTER) */
    uint32_t gyro_frames, battery_frames, robot_frames; /* queued (a full queue drops them: tx_dropped) */
} link_stats_t;

/* What the link reads from and writes to each step (sim-independent, so the
 * link can be tested without the physics). */
typedef struct {
    uint32_t t_us;              /* sim time after the step, us */
    int32_t encoder[2];         /* accumulated counts */
    uint8_t tof_new[3];         /* 1 = this sensor took a reading this step (HAL order) */
    uint16_t tof_mm[3];
    double tof_m[3];            /* the same reading unrounded, m (compat scales it: 18 um a count
                                   at 1.2 m); 0 = use tof_mm */
    uint8_t tof_timeout[3];
    /* version 2: sent only to an MCU whose HELLO says 2 or more */
    uint8_t ir_count;           /* IR sensors, 0..WIRE_IR_MAX (ROBOT, IR) */
    uint8_t has_gyro;           /* 1: GYRO with every ENCODER */
    int32_t gyro_mdps;          /* z rate, mdps, CCW positive */
    uint16_t battery_mv;        /* terminal voltage; 0 = no battery monitor (no BATTERY) */
    /* Called during link_step_io for each EMITTER the MCU sent: light the
     * groups (bit g = group g), then sample IR sensors 0..ir_count-1 into
     * raw (0..1023). NULL: the IR frame carries zeros. */
    void (*ir_sample)(void *ctx, uint8_t groups, uint16_t raw[WIRE_IR_MAX]);
    void *ctx;
} link_io_t;

typedef struct link_s {
    link_opts_t o;
    double step_s;
    uint16_t tof_range_mm;    /* framed: sent in HELLO */
    double compat_range_m;    /* compat: distance scale, m (65535 = this) */
    uint32_t counts_per_rev_x100;
    int fd;
    int connected;
    char path[256];
    uint64_t credit_tx, credit_rx; /* bit-microseconds: a byte costs 10e6 */
    uint64_t credit_step, credit_cap;
    uint8_t q[LINK_Q_MAX];
    size_t q_head, q_len, q_cap;
    wire_decoder_t dec;
    wire_compat_rx_t crx;
    wire_compat_tx_t ctx;
    int16_t motor[2];         /* latest command received */
    int running;              /* RUN start (default, and at each connection) / stop */
    int sensors_on;           /* SENSORS enable / disable: the MCU's last request, kept over
                                 reconnects; at open on in framed, off in compat */
    int hello_ok;             /* framed: MCU HELLO with our version seen */
    int hello_reply;          /* framed: send our HELLO once more (the MCU's first arrived) */
    uint8_t mcu_version;      /* framed: the version in the MCU's latest HELLO (0 = none yet) */
    int robot_due;            /* send ROBOT (a version-2 MCU's HELLO arrived) */
    int robot_reported;       /* ROBOT described in the report (once per connection) */
    uint8_t ir_seq;           /* IR frames sent on this connection, mod 256 */
    int flush;                /* an IR frame was queued while reading: send it this step */
    int silent;
    uint32_t enc_every;       /* framed: ENCODER every this many steps (the MCU's tick, from its HELLO) */
    uint64_t step, last_rx_step, next_hello_step, next_retry_step;
    uint64_t tof_seen[3];
    link_stats_t st;
    FILE *report;             /* state changes and MCU log lines; NULL = quiet */
} link_t;

/* -1 unless s is "framed" or "compat". */
int link_parse_protocol(const char *s);
/* Open the link (device or pty). tof_range_mm and counts_per_rev_x100 go in
 * HELLO. Returns 0, or -1 with a one-line message in err. */
int link_open(link_t *l, const link_opts_t *o, double step_s, uint16_t tof_range_mm, uint32_t counts_per_rev_x100,
              FILE *report, char *err, size_t errn);
/* Same on an already open fd (simavr's UART, tests: a socketpair), named
 * name in reports; the link owns fd. */
void link_open_fd(link_t *l, int fd, const char *name, const link_opts_t *o, double step_s, uint16_t tof_range_mm,
                  uint32_t counts_per_rev_x100, FILE *report);
/* One physics step: queue this step's sensor messages, move at most the
 * baud's bytes each way, decode; motor_out gets the commands to apply: the
 * last command received, held until the next one (0 when silent, stopped,
 * disconnected or before the handshake). Returns whether
 * the MCU asked for the ToF sensors on (1) or off (0). */
int link_step_io(link_t *l, const link_io_t *in, int16_t motor_out[2]);
/* Utilisation of each direction so far: bytes moved / bytes the baud allowed. */
double link_util_tx(const link_t *l);
double link_util_rx(const link_t *l);
/* Share of the line's capacity that bytes used over steps physics steps. */
double link_util_over(const link_t *l, uint64_t bytes, uint64_t steps);
/* The decoder's counters of the link's protocol (framed or compat). */
const wire_stats_t *link_decoder_stats(const link_t *l);
void link_close(link_t *l);
/* The link's settings, traffic, utilisation and decoder error counters. */
json_t *link_json(const link_t *l);

#endif

/* link.c - the simulator's end of the HIL serial link (see link.h and
 * docs/PROTOCOL.md). Time is sim time: everything is counted in physics
 * steps; bytes move by a credit of bit-microseconds. */
#include "link.h"

#include <errno.h>
#include <math.h>
#include <string.h>
#include <unistd.h>

#include "io/escape.h"
#include "serial.h"

#define BYTE_COST 10000000ull /* one 8N1 byte = 10 bits = 10e6 bit-us */

int link_parse_protocol(const char *s)
{
    if (!strcmp(s, "framed")) return LINK_FRAMED;
    if (!strcmp(s, "compat")) return LINK_COMPAT;
    return -1;
}

static void say(link_t *l, const char *what)
{
    if (l->report) fprintf(l->report, "mmsim: link %s: %s at %.3f s\n", l->path, what, (double)l->step * l->step_s);
}

static uint64_t steps_of(const link_t *l, double s) { return (uint64_t)llround(s / l->step_s); }

/* a new connection: fresh queue, decoders, handshake */
static void on_connect(link_t *l)
{
    l->connected = 1;
    l->st.connects++;
    l->q_head = l->q_len = 0;
    l->credit_tx = l->credit_rx = 0;
    wire_stats_t keep_d = l->dec.stats, keep_c = l->crx.stats; /* error counts add up over connections */
    wire_decoder_init(&l->dec);
    uint16_t compat_mm = (uint16_t)lround(l->compat_range_m * 1000.0);
    wire_compat_rx_init(&l->crx, compat_mm);
    l->dec.stats = keep_d;
    l->crx.stats = keep_c;
    wire_compat_tx_init(&l->ctx, compat_mm);
    l->ctx.enc_sent[0] = l->ctx.enc_sent[1] = INT32_MIN; /* set from the first reading sent */
    l->motor[0] = l->motor[1] = 0;
    l->running = 1; /* motors stay 0 until the MCU's first command on this connection */
    /* sensors_on is kept: a board that is not reset when the port opens
     * does not ask again (init_common sets the state at open) */
    l->hello_ok = l->o.protocol == LINK_COMPAT; /* compat has no handshake */
    l->hello_reply = 0;
    l->mcu_version = 0;
    l->robot_due = l->robot_reported = 0;
    l->ir_seq = 0;
    l->silent = 0;
    l->enc_every = 1;
    l->last_rx_step = l->step;
    l->next_hello_step = l->step;
    say(l, "connected");
}

static void on_disconnect(link_t *l)
{
    l->connected = 0;
    l->st.disconnects++;
    if (!l->o.pty && l->fd >= 0) {
        close(l->fd);
        l->fd = -1;
    }
    l->next_retry_step = l->step + steps_of(l, LINK_RETRY_S);
    say(l, "disconnected, motors off");
}

static void init_common(link_t *l, const link_opts_t *o, double step_s, uint16_t range_mm, uint32_t cpr_x100,
                        FILE *report)
{
    int fd = l->fd;
    char path[sizeof l->path];
    memcpy(path, l->path, sizeof path);
    memset(l, 0, sizeof *l);
    l->fd = fd;
    memcpy(l->path, path, sizeof path);
    l->o = *o;
    if (l->o.baud == 0) l->o.baud = link_default_baud(o->protocol);
    if (l->o.silence_s < 0) l->o.silence_s = o->protocol == LINK_COMPAT ? 0.0 : LINK_SILENCE_S;
    l->step_s = step_s;
    l->tof_range_mm = range_mm;
    l->compat_range_m = o->compat_range_m > 0 ? o->compat_range_m : WIRE_COMPAT_RANGE_MM / 1000.0;
    l->counts_per_rev_x100 = cpr_x100;
    l->report = report;
    l->sensors_on = o->protocol != LINK_COMPAT; /* compat: nothing until requestEnableSensors, as in the paper */
    l->credit_step = (uint64_t)l->o.baud * (uint64_t)llround(step_s * 1e6);
    l->credit_cap = l->credit_step + BYTE_COST;
    uint64_t cap = 4 * l->credit_step / BYTE_COST;
    l->q_cap = cap < 64 ? 64 : cap > LINK_Q_MAX ? LINK_Q_MAX : (size_t)cap;
    for (int i = 0; i < 3; i++) l->tof_seen[i] = UINT64_MAX; /* not yet synced to the sim */
}

void link_open_fd(link_t *l, int fd, const char *name, const link_opts_t *o, double step_s, uint16_t tof_range_mm,
                  uint32_t counts_per_rev_x100, FILE *report)
{
    l->fd = fd;
    snprintf(l->path, sizeof l->path, "%s", name);
    init_common(l, o, step_s, tof_range_mm, counts_per_rev_x100, report);
    l->o.pty = 0;
    l->o.device = NULL;
    on_connect(l);
}

uint32_t link_default_baud(int protocol) { return protocol == LINK_COMPAT ? 115200u : 1000000u; }

int link_open(link_t *l, const link_opts_t *o, double step_s, uint16_t tof_range_mm, uint32_t counts_per_rev_x100,
              FILE *report, char *err, size_t errn)
{
    uint32_t baud = o->baud ? o->baud : link_default_baud(o->protocol);
    if (baud > SERIAL_BAUD_MAX) {
        snprintf(err, errn, "baud %u above %u", (unsigned)baud, SERIAL_BAUD_MAX);
        return -1;
    }
    if (o->pty) {
        l->fd = serial_open_pty(l->path, sizeof l->path, err, errn);
    } else {
        l->fd = serial_open(o->device, baud, err, errn);
        snprintf(l->path, sizeof l->path, "%s", o->device);
    }
    if (l->fd < 0) return -1;
    init_common(l, o, step_s, tof_range_mm, counts_per_rev_x100, report);
    if (o->pty && report) {
        fprintf(report, "mmsim: pty %s\n", l->path);
        fflush(report);
    }
    if (!o->pty || serial_pty_peer(l->fd)) on_connect(l);
    else say(l, "waiting for a program to open it");
    return 0;
}

void link_close(link_t *l)
{
    if (l->fd >= 0) close(l->fd);
    l->fd = -1;
    l->connected = 0;
}

static void enqueue(link_t *l, const wire_msg_t *m)
{
    uint8_t b[WIRE_FRAME_MAX];
    wire_compat_tx_t keep = l->ctx;
    size_t n = l->o.protocol == LINK_COMPAT ? wire_compat_encode(&l->ctx, m, b, sizeof b)
                                              : wire_encode(m, b, sizeof b);
    if (n == 0) return; /* no form in this mode (HELLO in compat) */
    if (l->q_len + n > l->q_cap) { /* whole message dropped; compat deltas not lost */
        l->ctx = keep;
        l->st.tx_dropped++;
        return;
    }
    for (size_t i = 0; i < n; i++) l->q[(l->q_head + l->q_len + i) % l->q_cap] = b[i];
    l->q_len += n;
    l->st.tx_msgs++;
}

/* an EMITTER: the robot lights the groups and samples every IR sensor at
 * once (in->ir_sample); the IR frame goes out this step */
static void answer_emitter(link_t *l, const link_io_t *in, uint8_t groups)
{
    uint16_t raw[WIRE_IR_MAX] = { 0 };
    wire_msg_t m;
    memset(&m, 0, sizeof m);
    l->st.emitters++;
    if (in->ir_sample) in->ir_sample(in->ctx, groups, raw);
    m.type = WIRE_IR;
    m.u.ir.seq = ++l->ir_seq;
    m.u.ir.emitters = groups;
    m.u.ir.count = in->ir_count <= WIRE_IR_MAX ? in->ir_count : WIRE_IR_MAX;
    for (uint8_t i = 0; i < m.u.ir.count; i++) wire_ir_set(&m, i, raw[i]);
    uint64_t dropped = l->st.tx_dropped;
    enqueue(l, &m);
    if (l->st.tx_dropped != dropped) return;
    l->st.ir_frames++;
    l->flush = 1;
    if (l->st.ir_frames > LINK_IR_REPORT) return;
    char line[120];
    int n = snprintf(line, sizeof line, "IR seq %u, emitters 0x%x:", m.u.ir.seq, m.u.ir.emitters);
    for (uint8_t i = 0; i < m.u.ir.count; i++) n += snprintf(line + n, sizeof line - (size_t)n, " %u", wire_ir_get(&m, i));
    if (!m.u.ir.count) snprintf(line + n, sizeof line - (size_t)n, " (no IR sensors)");
    say(l, line);
}

static void handle(link_t *l, const link_io_t *in, const wire_msg_t *m)
{
    char line[160];
    l->st.rx_msgs++;
    l->last_rx_step = l->step;
    if (l->silent) {
        l->silent = 0;
        say(l, "MCU talking again");
    }
    switch (m->type) {
    case WIRE_MOTOR:
        if (!l->running && l->o.protocol == LINK_COMPAT) { /* stopped: ignored, not kept for start */
            l->crx.motor[0] = l->crx.motor[1] = 0;
            break;
        }
        l->motor[0] = m->u.motor.left;
        l->motor[1] = m->u.motor.right;
        break;
    case WIRE_HELLO:
        if (m->u.hello.role != WIRE_ROLE_MCU) break;
        if (m->u.hello.version < WIRE_VERSION_MIN || m->u.hello.version > WIRE_VERSION) {
            snprintf(line, sizeof line, "MCU speaks protocol version %u, we speak %u to %u: motors stay off",
                     m->u.hello.version, WIRE_VERSION_MIN, WIRE_VERSION);
            say(l, line);
            l->hello_ok = 0;
            break;
        }
        if (!l->hello_ok) {
            snprintf(line, sizeof line, "hello from the MCU: protocol %u, ToF range %u mm, %.2f counts/turn, tick %u Hz%s",
                     m->u.hello.version, m->u.hello.tof_range_mm, m->u.hello.counts_per_rev_x100 / 100.0,
                     m->u.hello.tick_hz,
                     m->u.hello.tof_range_mm != l->tof_range_mm || m->u.hello.counts_per_rev_x100 != l->counts_per_rev_x100
                         ? " (MISMATCH with the simulator's robot)" : "");
            say(l, line);
            l->hello_reply = 1; /* an MCU that missed our first HELLO (still booting) gets one now */
        }
        l->hello_ok = 1;
        l->mcu_version = m->u.hello.version;
        l->robot_due = m->u.hello.version >= 2; /* after every HELLO: an MCU that was reset asks again */
        /* no point sending encoders faster than the MCU's control tick */
        l->enc_every = m->u.hello.tick_hz ? (uint32_t)lround(1.0 / (l->step_s * m->u.hello.tick_hz)) : 1;
        if (l->enc_every < 1) l->enc_every = 1;
        break;
    case WIRE_SENSORS: l->sensors_on = m->u.flag.on; break;
    case WIRE_EMITTER: answer_emitter(l, in, m->u.emitter.groups); break;
    case WIRE_RUN:
        l->running = m->u.flag.on;
        if (m->u.flag.on) break;
        if (l->o.protocol == LINK_COMPAT) { /* the paper's stop: the robot, not the simulator */
            /* both sides' last commands forgotten: after start, a side not
             * commanded again stays at 0 */
            l->motor[0] = l->motor[1] = 0;
            l->crx.motor[0] = l->crx.motor[1] = 0;
            l->st.halts++;
            say(l, "MCU stopped the robot: motors off until start");
        } else {
            l->st.stops++;
            say(l, "MCU stopped the run");
        }
        break;
    case WIRE_LOG:
        l->st.logs++;
        if (l->report) { /* the MCU's text cannot forge or hide a line of ours */
            char text[IO_ESCAPE_MAX(WIRE_LOG_MAX)];
            io_escape(text, sizeof text, m->u.log.text, m->u.log.len);
            fprintf(l->report, "mcu: %s\n", text);
        }
        break;
    default: break;
    }
}

static void check_connection(link_t *l)
{
    if (l->o.pty) {
        int peer = serial_pty_peer(l->fd);
        if (peer && !l->connected) on_connect(l);
        else if (!peer && l->connected) on_disconnect(l);
        return;
    }
    if (l->connected && l->fd >= 0 && l->o.device && serial_hung_up(l->fd)) {
        on_disconnect(l);
        return;
    }
    if (l->connected || !l->o.device || l->step < l->next_retry_step) return;
    char err[300];
    l->fd = serial_open(l->o.device, l->o.baud, err, sizeof err);
    if (l->fd >= 0) on_connect(l);
    else l->next_retry_step = l->step + steps_of(l, LINK_RETRY_S);
}

static int io_failed(int e) { return e != EAGAIN && e != EWOULDBLOCK && e != EINTR; }

/* sim -> MCU: at most the credit's whole bytes; -1 if the device failed (disconnected) */
static int move_tx(link_t *l)
{
    while (l->q_len > 0 && l->credit_tx >= BYTE_COST) {
        size_t n = l->q_cap - l->q_head;
        if (n > l->q_len) n = l->q_len;
        uint64_t allow = l->credit_tx / BYTE_COST;
        if (n > allow) n = (size_t)allow;
        ssize_t k = write(l->fd, l->q + l->q_head, n);
        if (k < 0) {
            if (io_failed(errno)) {
                on_disconnect(l);
                return -1;
            }
            l->st.tx_blocked_bytes += n;
            break;
        }
        l->q_head = (l->q_head + (size_t)k) % l->q_cap;
        l->q_len -= (size_t)k;
        l->credit_tx -= (uint64_t)k * BYTE_COST;
        l->st.tx_bytes += (uint64_t)k;
        if ((size_t)k < n) {
            l->st.tx_blocked_bytes += n - (size_t)k;
            break;
        }
    }
    return 0;
}

/* a version-2 MCU's extra sensor messages this step: ROBOT after its
 * HELLO, GYRO with ENCODER (enc_now), BATTERY every LINK_BATTERY_S */
static void queue_v2(link_t *l, const link_io_t *in, int enc_now)
{
    wire_msg_t m;
    if (l->mcu_version < 2) return;
    uint8_t ir_count = in->ir_count <= WIRE_IR_MAX ? in->ir_count : WIRE_IR_MAX;
    if (l->robot_due) {
        l->robot_due = 0;
        memset(&m, 0, sizeof m);
        m.type = WIRE_ROBOT;
        m.u.robot.ir_count = ir_count;
        m.u.robot.flags = (uint8_t)((in->has_gyro ? WIRE_ROBOT_GYRO : 0) | (in->battery_mv ? WIRE_ROBOT_BATTERY : 0));
        enqueue(l, &m);
        l->st.robot_frames++;
        if (!l->robot_reported) {
            char line[120];
            snprintf(line, sizeof line, "robot for the MCU: %u IR sensors, gyro %s, battery %u mV", ir_count,
                     in->has_gyro ? "yes" : "no", in->battery_mv);
            say(l, line);
            l->robot_reported = 1;
        }
    }
    if (enc_now && in->has_gyro) {
        memset(&m, 0, sizeof m);
        m.type = WIRE_GYRO;
        m.u.gyro.t_us = in->t_us;
        m.u.gyro.mdps = in->gyro_mdps;
        enqueue(l, &m);
        l->st.gyro_frames++;
    }
    uint64_t every = steps_of(l, LINK_BATTERY_S);
    if (in->battery_mv && l->step % (every ? every : 1) == 0) {
        memset(&m, 0, sizeof m);
        m.type = WIRE_BATTERY;
        m.u.battery.t_us = in->t_us;
        m.u.battery.mv = in->battery_mv;
        enqueue(l, &m);
        l->st.battery_frames++;
    }
}

/* This step's messages to the MCU, queued: HELLO (framed, until answered),
 * the encoder counts at their rate, new ToF readings, the v2 sensors;
 * nothing in the paper's protocol before the MCU asks for sensors. */
static void queue_step(link_t *l, const link_io_t *in)
{
    wire_msg_t m;
    if (l->ctx.enc_sent[0] == INT32_MIN) { /* compat deltas start from the counts at connection */
        l->ctx.enc_sent[0] = in->encoder[0];
        l->ctx.enc_sent[1] = in->encoder[1];
    }
    if (l->o.protocol == LINK_FRAMED && ((!l->hello_ok && l->step >= l->next_hello_step) || l->hello_reply)) {
        l->hello_reply = 0;
        memset(&m, 0, sizeof m);
        m.type = WIRE_HELLO;
        m.u.hello.version = WIRE_VERSION;
        m.u.hello.role = WIRE_ROLE_SIM;
        m.u.hello.tof_range_mm = l->tof_range_mm;
        m.u.hello.counts_per_rev_x100 = l->counts_per_rev_x100;
        m.u.hello.tick_hz = (uint16_t)llround(1.0 / l->step_s);
        enqueue(l, &m);
        l->next_hello_step = l->step + steps_of(l, LINK_RETRY_S);
    }
    int enc_now = l->enc_every <= 1 || l->step % l->enc_every == 0;
    if (l->o.protocol == LINK_COMPAT && !l->sensors_on) return; /* the paper's sim sends nothing */
    if (enc_now) {
        memset(&m, 0, sizeof m);
        m.type = WIRE_ENCODER;
        m.u.encoder.t_us = in->t_us;
        m.u.encoder.left = in->encoder[0];
        m.u.encoder.right = in->encoder[1];
        enqueue(l, &m);
    }
    for (uint8_t i = 0; i < 3; i++) {
        if (!in->tof_new[i]) continue;
        memset(&m, 0, sizeof m);
        m.type = WIRE_DISTANCE;
        m.u.distance.t_us = in->t_us;
        m.u.distance.sensor = i;
        m.u.distance.timeout = in->tof_timeout[i] ? 1 : 0;
        m.u.distance.mm = in->tof_mm[i];
        if (l->o.protocol == LINK_COMPAT && in->tof_m[i] > 0) { /* from metres, not mm */
            double v = round(in->tof_m[i] / l->compat_range_m * 65535.0);
            if (in->tof_m[i] >= l->compat_range_m) m.u.distance.timeout = 1; /* beyond the compat range */
            else m.u.distance.compat = (uint16_t)(v > 65534.0 ? 65534.0 : v); /* 0 (under 8 um) scales mm: 0 too */
        }
        enqueue(l, &m);
    }
    queue_v2(l, in, enc_now);
}

/* MCU -> sim: at most the credit's whole bytes (the rest waits in the OS),
 * each decoded message handled. -1 if the link went down. */
static int receive(link_t *l, const link_io_t *in)
{
    uint8_t buf[2048];
    wire_msg_t m;
    uint64_t allow = l->credit_rx / BYTE_COST;
    size_t want = allow < sizeof buf ? (size_t)allow : sizeof buf;
    if (want == 0) return 0;
    ssize_t k = read(l->fd, buf, want);
    if (k < 0 && io_failed(errno)) {
        on_disconnect(l);
        return -1;
    }
    for (ssize_t i = 0; i < k; i++) {
        int got = l->o.protocol == LINK_COMPAT ? wire_compat_decode_byte(&l->crx, buf[i], &m)
                                               : wire_decode_byte(&l->dec, buf[i], &m);
        if (got) handle(l, in, &m);
    }
    if (k > 0) {
        l->credit_rx -= (uint64_t)k * BYTE_COST;
        l->st.rx_bytes += (uint64_t)k;
    }
    return 0;
}

int link_step_io(link_t *l, const link_io_t *in, int16_t motor_out[2])
{
    l->step++;
    l->st.steps++;
    motor_out[0] = motor_out[1] = 0;
    check_connection(l);
    if (!l->connected) return l->sensors_on;
    l->credit_tx = l->credit_tx + l->credit_step < l->credit_cap ? l->credit_tx + l->credit_step : l->credit_cap;
    l->credit_rx = l->credit_rx + l->credit_step < l->credit_cap ? l->credit_rx + l->credit_step : l->credit_cap;

    queue_step(l, in);
    if (move_tx(l) != 0) return l->sensors_on;
    if (receive(l, in) != 0) return l->sensors_on;

    if (l->flush) { /* IR answers go out this step, with the credit left */
        l->flush = 0;
        if (move_tx(l) != 0) return l->sensors_on;
    }
    if (l->o.silence_s > 0 && !l->silent && l->step - l->last_rx_step > steps_of(l, l->o.silence_s)) {
        l->silent = 1;
        l->st.silences++;
        say(l, "MCU silent: motors off");
    }
    if (l->hello_ok && l->running && !l->silent) {
        motor_out[0] = l->motor[0];
        motor_out[1] = l->motor[1];
    }
    return l->sensors_on;
}

double link_util_over(const link_t *l, uint64_t bytes, uint64_t steps)
{
    double allowed = (double)steps * (double)l->credit_step / (double)BYTE_COST;
    return allowed > 0 ? (double)bytes / allowed : 0.0;
}
double link_util_tx(const link_t *l) { return link_util_over(l, l->st.tx_bytes, l->st.steps); }
double link_util_rx(const link_t *l) { return link_util_over(l, l->st.rx_bytes, l->st.steps); }
const wire_stats_t *link_decoder_stats(const link_t *l)
{
    return l->o.protocol == LINK_COMPAT ? &l->crx.stats : &l->dec.stats;
}

json_t *link_json(const link_t *l)
{
    const wire_stats_t *d = link_decoder_stats(l);
    json_t *dec = json_pack("{s:I, s:I, s:I, s:I, s:I, s:I, s:I, s:I}", "bytes", (json_int_t)d->bytes, "frames_ok",
                            (json_int_t)d->frames_ok, "crc", (json_int_t)d->crc, "cobs", (json_int_t)d->cobs,
                            "overflow", (json_int_t)d->overflow, "unknown", (json_int_t)d->unknown, "length",
                            (json_int_t)d->length, "value", (json_int_t)d->value);
    json_t *j = json_pack("{s:s, s:s, s:I, s:I, s:I, s:I, s:I, s:I, s:I, s:f, s:f, s:i, s:i, s:i, s:i, s:o}",
                          "device", l->path, "protocol", l->o.protocol == LINK_COMPAT ? "compat" : "framed", "baud",
                          (json_int_t)l->o.baud, "tx_bytes", (json_int_t)l->st.tx_bytes, "rx_bytes",
                          (json_int_t)l->st.rx_bytes, "tx_msgs", (json_int_t)l->st.tx_msgs, "rx_msgs",
                          (json_int_t)l->st.rx_msgs, "tx_dropped", (json_int_t)l->st.tx_dropped, "tx_blocked_bytes",
                          (json_int_t)l->st.tx_blocked_bytes, "tx_utilisation", round(link_util_tx(l) * 1000) / 1000,
                          "rx_utilisation", round(link_util_rx(l) * 1000) / 1000, "silences", (int)l->st.silences,
                          "disconnects", (int)l->st.disconnects, "connects", (int)l->st.connects, "mcu_log_lines",
                          (int)l->st.logs, "decoder", dec);
    json_object_set_new(j, "silence_ms", json_integer(llround(l->o.silence_s * 1000.0))); /* 0 = no watchdog */
    if (l->o.protocol == LINK_COMPAT) json_object_set_new(j, "compat_range_m", json_real(l->compat_range_m));
    json_object_set_new(j, "handshake", json_boolean(l->hello_ok));
    json_object_set_new(j, "mcu_stops", json_integer(l->st.stops + l->st.halts));
    json_object_set_new(j, "sensors_on", json_boolean(l->sensors_on));
    json_object_set_new(j, "mcu_version", json_integer(l->mcu_version));
    json_object_set_new(j, "v2", json_pack("{s:I, s:I, s:I, s:I, s:I}", "emitter_msgs", (json_int_t)l->st.emitters,
                                           "ir_frames", (json_int_t)l->st.ir_frames, "gyro_frames",
                                           (json_int_t)l->st.gyro_frames, "battery_frames",
                                           (json_int_t)l->st.battery_frames, "robot_frames",
                                           (json_int_t)l->st.robot_frames));
    return j;
}

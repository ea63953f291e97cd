/* mmlog - read an LCM log (mmsim --lcm-log, lcm-logger): per-channel
 * summary, or one channel's messages decoded as JSON lines.
 *
 *   mmlog [--json] LOG           count, rate, first and last time per channel
 *   mmlog --dump CHANNEL LOG     decoded mmlcm messages, one JSON object a line
 *
 * Times are the messages' utime (simulation time) for the mmlcm channels,
 * the log's event timestamp for any other channel. A message of an mmlcm
 * channel that does not decode is counted as bad.
 * Exit codes: 0 ok, 2 bad input (unreadable, not an LCM log, bad messages,
 * a truncated or corrupt event: what came before it is still summed up),
 * 3 stdout could not be written. */
#include <jansson.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "io/stdstream.h"
#include "telemetry/lcmlog.h"
#include "mmlcm_belief_t.h"
#include "mmlcm_link_t.h"
#include "mmlcm_maze_t.h"
#include "mmlcm_motors_t.h"
#include "mmlcm_parts_t.h"
#include "mmlcm_pose_t.h"
#include "mmlcm_race_event_t.h"
#include "mmlcm_race_t.h"
#include "mmlcm_sensors_t.h"
#include "mmlcm_watch_t.h"

#define MAX_CHANNELS 256

static json_t *darr(const double *v, int n)
{
    json_t *a = json_array();
    for (int i = 0; i < n; i++) json_array_append_new(a, json_real(v[i]));
    return a;
}

static json_t *iarr16(const int16_t *v, int n)
{
    json_t *a = json_array();
    for (int i = 0; i < n; i++) json_array_append_new(a, json_integer(v[i]));
    return a;
}

static int dec_pose(const void *data, int len, int64_t *ut, json_t **j)
{
    mmlcm_pose_t m;
    if (mmlcm_pose_t_decode(data, 0, len, &m) != len) return -1;
    *ut = m.utime;
    if (j) *j = json_pack("{s:I, s:f, s:f, s:f, s:f, s:f}", "utime", (json_int_t)m.utime, "x_m", m.x_m, "y_m", m.y_m,
                         "heading_rad", m.heading_rad, "v_m_s", m.v_m_s, "omega_rad_s", m.omega_rad_s);
    return 0;
}

static int dec_motors(const void *data, int len, int64_t *ut, json_t **j)
{
    mmlcm_motors_t m;
    if (mmlcm_motors_t_decode(data, 0, len, &m) != len) return -1;
    *ut = m.utime;
    if (j) *j = json_pack("{s:I, s:o, s:o, s:o, s:o, s:o}", "utime", (json_int_t)m.utime, "command",
                         iarr16(m.command, 2), "voltage_v", darr(m.voltage_v, 2), "current_a", darr(m.current_a, 2),
                         "wheel_rad_s", darr(m.wheel_rad_s, 2), "torque_nm", darr(m.torque_nm, 2));
    return 0;
}

static int dec_sensors(const void *data, int len, int64_t *ut, json_t **j)
{
    mmlcm_sensors_t m;
    if (mmlcm_sensors_t_decode(data, 0, len, &m) != len) return -1;
    *ut = m.utime;
    if (j) {
        json_t *to = json_array();
        for (int i = 0; i < 3; i++) json_array_append_new(to, json_boolean(m.tof_timeout[i]));
        *j = json_pack("{s:I, s:[i,i], s:o, s:o, s:o}", "utime", (json_int_t)m.utime, "encoder", (int)m.encoder[0],
                      (int)m.encoder[1], "tof_mm", iarr16(m.tof_mm, 3), "tof_timeout", to, "tof_true_m",
                      darr(m.tof_true_m, 3));
    }
    return 0;
}

/* MM_PARTS through the checked decoder (arrays and strings: lcmlog.h). */
static int dec_parts(const void *data, int len, int64_t *ut, json_t **j)
{
    mmlcm_parts_t m;
    if (lcmlog_decode_parts(data, len, &m) != 0) return -1;
    *ut = m.utime;
    if (j) {
        json_t *parts = json_array(), *em = json_array();
        for (int i = 0; i < m.nparts; i++) {
            const mmlcm_part_t *p = &m.parts[i];
            json_array_append_new(parts, json_pack("{s:s, s:s, s:o, s:s}", "kind", p->kind, "name", p->name, "values",
                                                   darr(p->values, p->nvalues), "units", p->units));
        }
        for (int g = 0; g < m.nemitters; g++) json_array_append_new(em, json_boolean(m.emitter[g]));
        *j = json_pack("{s:I, s:o, s:f, s:f, s:o}", "utime", (json_int_t)m.utime, "parts", parts, "battery_v",
                      m.battery_v, "battery_soc", m.battery_soc, "emitter", em);
    }
    mmlcm_parts_t_decode_cleanup(&m);
    return 0;
}

static int dec_race(const void *data, int len, int64_t *ut, json_t **j)
{
    mmlcm_race_t m;
    if (mmlcm_race_t_decode(data, 0, len, &m) != len) return -1;
    *ut = m.utime;
    if (j) *j = json_pack("{s:I, s:b, s:f, s:b, s:f, s:b, s:i, s:i, s:f}", "utime", (json_int_t)m.utime, "started",
                         m.started, "global_s", m.global_s, "in_run", m.in_run, "lap_s", m.lap_s, "over_time",
                         m.over_time, "laps", (int)m.laps, "best_lap", (int)m.best_lap, "best_run_s", m.best_run_s);
    return 0;
}

static int dec_race_event(const void *data, int len, int64_t *ut, json_t **j)
{
    mmlcm_race_event_t m;
    if (mmlcm_race_event_t_decode(data, 0, len, &m) != len) return -1;
    *ut = m.utime;
    if (j) *j = json_pack("{s:I, s:s, s:i, s:f, s:f, s:f, s:b, s:b}", "utime", (json_int_t)m.utime, "kind",
                         m.kind == MMLCM_RACE_EVENT_T_LAP_START ? "lap_start"
                         : m.kind == MMLCM_RACE_EVENT_T_LAP_END ? "lap_end"
                         : m.kind == MMLCM_RACE_EVENT_T_CONTACT ? "contact" : "unknown",
                         "lap", (int)m.lap, "start_s", m.start_s, "end_s", m.end_s, "run_s", m.run_s, "over_time",
                         m.over_time, "best", m.best);
    return 0;
}

static int dec_belief(const void *data, int len, int64_t *ut, json_t **j)
{
    mmlcm_belief_t m;
    if (lcmlog_decode_belief(data, len, &m) != 0) return -1;
    *ut = m.utime;
    if (j) {
        json_t *w = json_array();
        for (int i = 0; i < m.ncells; i++) json_array_append_new(w, json_integer((uint8_t)m.walls[i]));
        *j = json_pack("{s:I, s:i, s:i, s:o, s:o, s:i, s:i, s:i, s:o}", "utime", (json_int_t)m.utime, "width",
                      (int)(uint8_t)m.width, "height", (int)(uint8_t)m.height, "walls", w, "cost",
                      iarr16(m.cost, m.ncells), "cell", (int)m.cell, "heading", (int)m.heading, "state",
                      (int)m.state, "path", iarr16(m.path, m.path_len));
    }
    mmlcm_belief_t_decode_cleanup(&m);
    return 0;
}

static int dec_link(const void *data, int len, int64_t *ut, json_t **j)
{
    mmlcm_link_t m;
    if (mmlcm_link_t_decode(data, 0, len, &m) != len) return -1;
    *ut = m.utime;
    if (j)
        *j = json_pack("{s:I, s:I, s:I, s:f, s:f, s:i, s:I, s:i, s:b, s:b}", "utime", (json_int_t)m.utime,
                      "bytes_to_mcu", (json_int_t)m.bytes_to_mcu, "bytes_from_mcu", (json_int_t)m.bytes_from_mcu,
                      "util_to_mcu", m.util_to_mcu, "util_from_mcu", m.util_from_mcu, "frame_errors",
                      (int)m.frame_errors, "dropped_to_mcu", (json_int_t)m.dropped_to_mcu, "baud", (int)m.baud,
                      "connected", (int)m.connected, "handshake", (int)m.handshake);
    return 0;
}

static int dec_maze(const void *data, int len, int64_t *ut, json_t **j)
{
    mmlcm_maze_t m;
    if (lcmlog_decode_maze(data, len, &m) != 0) return -1;
    *ut = m.utime;
    if (j) {
        json_t *w = json_array();
        for (int i = 0; i < m.ncells; i++) json_array_append_new(w, json_integer((uint8_t)m.walls[i]));
        *j = json_pack("{s:I, s:s, s:i, s:i, s:o, s:i, s:i, s:o, s:b, s:I, s:s}", "utime", (json_int_t)m.utime,
                      "path", m.path, "width", (int)(uint8_t)m.width, "height", (int)(uint8_t)m.height, "walls", w,
                      "start", (int)m.start, "start_heading", (int)m.start_heading, "goals",
                      iarr16(m.goals, m.ngoals), "centre_post", m.centre_post, "seed", (json_int_t)m.seed, "config",
                      m.config);
    }
    mmlcm_maze_t_decode_cleanup(&m);
    return 0;
}

/* MM_WATCH through the checked decoder: the names, types and values as arrays in --watch's order. */
static int dec_watch(const void *data, int len, int64_t *ut, json_t **j)
{
    mmlcm_watch_t m;
    if (lcmlog_decode_watch(data, len, &m) != 0) return -1;
    *ut = m.utime;
    if (j) {
        json_t *names = json_array(), *types = json_array();
        for (int i = 0; i < m.nvars; i++) {
            json_array_append_new(names, json_string(m.name[i]));
            json_array_append_new(types, json_string(m.type[i]));
        }
        *j = json_pack("{s:I, s:o, s:o, s:o}", "utime", (json_int_t)m.utime, "name", names, "type", types, "value",
                      darr(m.value, m.nvars));
    }
    mmlcm_watch_t_decode_cleanup(&m);
    return 0;
}

typedef struct {
    const char *channel;
    int (*decode)(const void *data, int len, int64_t *ut, json_t **j);
} decoder_t;

static const decoder_t decoders[] = {
    { "MM_POSE", dec_pose },
    { "MM_MOTORS", dec_motors },
    { "MM_SENSORS", dec_sensors },
    { "MM_PARTS", dec_parts },
    { "MM_RACE", dec_race },
    { "MM_RACE_EVENT", dec_race_event },
    { "MM_BELIEF", dec_belief },
    { "MM_LINK", dec_link },
    { "MM_WATCH", dec_watch },
    { "MM_MAZE", dec_maze },
};

/* Decode one message of a known channel: its utime in *ut and, if j is not
 * NULL, the message as JSON. Returns 0, -1 if it does not decode, 1 if the
 * channel is not an mmlcm one. */
static int decode(const char *ch, const void *data, int len, int64_t *ut, json_t **j)
{
    for (size_t i = 0; i < sizeof decoders / sizeof decoders[0]; i++)
        if (!strcmp(ch, decoders[i].channel)) return decoders[i].decode(data, len, ut, j);
    return 1;
}

static int known_channel(const char *ch)
{
    for (size_t i = 0; i < sizeof decoders / sizeof decoders[0]; i++)
        if (!strcmp(ch, decoders[i].channel)) return 1;
    return 0;
}

typedef struct {
    char *name;
    long count, bad;
    int64_t first_us, last_us;
} chan_t;

typedef struct {
    chan_t *ch;
    int nch;
    const char *dump, *path;
} read_t;

/* One event: decoded (and printed if dumped), counted on its channel. */
static int on_event(void *ctx, const lcm_eventlog_event_t *ev)
{
    read_t *r = ctx;
    int64_t ut = ev->timestamp;
    json_t *j = NULL;
    int d = decode(ev->channel, ev->data, ev->datalen, &ut, r->dump && !strcmp(r->dump, ev->channel) ? &j : NULL);
    if (j) {
        char *s = json_dumps(j, JSON_COMPACT | JSON_REAL_PRECISION(17));
        if (s) puts(s);
        free(s);
        json_decref(j);
    }
    int k = 0;
    while (k < r->nch && strcmp(r->ch[k].name, ev->channel)) k++;
    if (k == r->nch) {
        if (r->nch == MAX_CHANNELS) {
            fprintf(stderr, "%s: more than %d channels\n", r->path, MAX_CHANNELS);
            return 1;
        }
        r->ch[r->nch].name = strdup(ev->channel);
        r->ch[r->nch].first_us = ut;
        r->nch++;
    }
    chan_t *c = &r->ch[k];
    if (d < 0) {
        c->bad++;
    } else {
        if (c->count == 0) c->first_us = ut;
        c->count++;
        c->last_us = ut;
    }
    return 0;
}

static int usage(void)
{
    fputs("usage: mmlog [--json] LOG\n"
          "       mmlog --dump CHANNEL LOG\n"
          "Per-channel count, rate and first/last time of an LCM log, or one channel's mmlcm messages as JSON lines.\n",
          stderr);
    return 2;
}

static int run(int argc, char **argv)
{
    int as_json = 0;
    const char *dump = NULL, *path = NULL;
    for (int i = 1; i < argc; i++) {
        if (!strcmp(argv[i], "--json")) as_json = 1;
        else if (!strcmp(argv[i], "--dump") && i + 1 < argc) dump = argv[++i];
        else if (!strcmp(argv[i], "--help") || !strcmp(argv[i], "-h")) return usage(), 0;
        else if (argv[i][0] == '-' || path) {
            fprintf(stderr, "mmlog: unexpected argument '%s' (try 'mmlog --help')\n", argv[i]);
            return 2;
        } else path = argv[i];
    }
    if (!path) return usage();
    if (dump && !known_channel(dump)) {
        fprintf(stderr, "mmlog: --dump %s: not a channel mmlog decodes; the channels are", dump);
        for (size_t i = 0; i < sizeof decoders / sizeof decoders[0]; i++)
            fprintf(stderr, "%s %s", i ? "," : "", decoders[i].channel);
        fputc('\n', stderr);
        return 2;
    }
    static chan_t ch[MAX_CHANNELS];
    read_t rd = { ch, 0, dump, path };
    char err[4200];
    long events;
    int rc = lcmlog_each(path, on_event, &rd, &events, err, sizeof err);
    int nch = rd.nch;
    if (rc < 0) {
        if (events == 0) {
            fprintf(stderr, "%s\n", err);
            return 2;
        }
        fprintf(stderr, "%s (summary of the %ld events before it)\n", err, events);
    }
    rc = rc ? 2 : 0;
    json_t *out = json_object();
    if (!dump && !as_json) printf("%-16s %8s %10s %12s %12s %6s\n", "channel", "count", "rate_hz", "first_s", "last_s", "bad");
    for (int k = 0; k < nch; k++) {
        chan_t *c = &ch[k];
        double first = c->first_us * 1e-6, last = c->last_us * 1e-6;
        double rate = c->count > 1 && last > first ? (c->count - 1) / (last - first) : 0.0;
        if (c->bad) {
            fprintf(stderr, "%s: %s: %ld message%s do not decode as mmlcm types\n", path, c->name, c->bad,
                    c->bad == 1 ? "" : "s");
            rc = 2;
        }
        if (as_json)
            json_object_set_new(out, c->name, json_pack("{s:I, s:f, s:f, s:f, s:I}", "count", (json_int_t)c->count,
                                                        "rate_hz", rate, "first_s", first, "last_s", last, "bad",
                                                        (json_int_t)c->bad));
        else if (!dump)
            printf("%-16s %8ld %10.3f %12.6f %12.6f %6ld\n", c->name, c->count, rate, first, last, c->bad);
        free(c->name);
    }
    if (as_json && !dump) {
        char *s = json_dumps(out, JSON_COMPACT | JSON_SORT_KEYS | JSON_REAL_PRECISION(17));
        if (s) puts(s);
        free(s);
    }
    json_decref(out);
    return rc;
}

int main(int argc, char **argv)
{
    io_stdout_open("mmlog");
    int rc = run(argc, argv);
    return io_stdout_close("mmlog") != 0 ? 3 : rc;
}

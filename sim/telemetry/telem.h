/* telem.h - LCM telemetry of a running simulation (types in the lcm/ folder,
 * package mmlcm, generated with lcm-gen at build time).
 *
 * Channels (every message carries utime = simulation time, microseconds):
 *   MM_POSE, MM_MOTORS, MM_SENSORS  at the high rate (rate_hz, default 100 Hz)
 *   MM_PARTS                        with them: every sensor component of the
 *                                   robot file (kind, name, values, units),
 *                                   the battery and the emitter groups
 *   MM_RACE                         at TELEM_RACE_HZ
 *   MM_RACE_EVENT                   on the step a lap starts or ends, and
 *                                   on the step the body starts touching
 *                                   a wall (kind CONTACT)
 *   MM_BELIEF                       when the firmware calls hal_belief
 *                                   (in-process firmware only: the belief
 *                                   the run's driver gives telem_step)
 *   MM_LINK                         at TELEM_LINK_HZ, HIL/PIL runs only (opts.link)
 *   MM_MAZE                         once, first (utime 0): the true maze,
 *                                   its file, the seed and the config, so
 *                                   the log alone replays (mmview)
 *   MM_WATCH                        with MM_POSE, when the run's driver
 *                                   hands telem_watch the firmware's
 *                                   variables (mmsim --watch: --board, --avr)
 * A channel's messages go out on the physics steps that are multiples of its
 * period (rate rounded to a whole number of steps), and once more at the end
 * (telem_finish) unless the last step was one of them.
 *
 * Outputs: a live LCM URL (lcm_create; "" = LCM's default, udpm with ttl=0;
 * tcpq:// must reach its hub at the start, and a hub lost later stops the
 * live output with one error at the end instead of liblcm's reconnection
 * messages on every publish) and/or a log file written with LCM's
 * event-log API (the format of lcm-logger and the file:// provider) whose
 * event timestamps are the simulation time, so a log replays at contest
 * speed whatever the simulation speed and the same run gives the same log
 * bytes. The log is written to a temporary beside it and renamed over the
 * target at telem_close (sim/io/outfile.h): a failed or killed run never
 * leaves a half log at the path nor spoils an existing one (a killed run
 * leaves its temporary PATH.tmp.XXXXXX; a device or a pipe as the target
 * is written directly).
 * Telemetry only reads the simulation: a run is the same with or without it.
 */
#ifndef TELEM_H
#define TELEM_H

#include <stddef.h>
#include <stdint.h>

#include "io/outfile.h"
#include "world/belief.h"
#include "world/sim.h"

#define TELEM_RATE_HZ 100.0 /* default rate of the high-rate channels, Hz */
#define TELEM_RACE_HZ 10.0  /* rate of MM_RACE, Hz */
#define TELEM_LINK_HZ 10.0  /* rate of MM_LINK, Hz */
#define TELEM_WATCH_MAX 16   /* variables on MM_WATCH */
#define TELEM_BUF_BYTES 65536 /* one encoded message, bytes: MM_MAZE carries the config and the robot file as printed (an IR robot ~17 KB; 16 parts with their sources ~35 KB); a 32x32 belief is ~5.2 KB */

typedef struct {
    const char *url;      /* live LCM URL; NULL = none, "" = LCM's default */
    const char *log_path; /* log file; NULL = none */
    double rate_hz;       /* high-rate channels, Hz; <= 0 = TELEM_RATE_HZ */
    const struct link_s *link; /* HIL/PIL: the serial link whose statistics go on MM_LINK; NULL = none */
    const char *maze_path; /* the maze file, for MM_MAZE; NULL = "" */
} telem_opts_t;

typedef struct {
    void *lcm;            /* lcm_t *, NULL = no live output */
    void *log;            /* lcm_eventlog_t *, NULL = no log */
    outfile_t log_out;    /* the log's temporary (renamed over the target at the end) */
    int log_in_place;     /* the target is a device or a pipe: written directly */
    int log_errno;        /* errno of the first failed log write, 0 = unknown */
    const char *url;      /* the live URL (o->url) */
    int tcpq;             /* the live URL is tcpq:// (one hub connection) */
    int live_lost;        /* tcpq: the hub connection was lost: live output stopped */
    double live_lost_s;   /* sim time it was lost */
    int live_errno;       /* why (errno of the failed publish), 0 = unknown */
    int quiet_fd;         /* tcpq: /dev/null, liblcm's stderr during a publish; -1 none */
    uint64_t fast_steps;  /* period of the high-rate channels, physics steps */
    uint64_t race_steps;  /* period of MM_RACE, physics steps */
    uint64_t link_steps;  /* period of MM_LINK, physics steps */
    const struct link_s *link;
    uint64_t last_link;   /* step of the last MM_LINK, UINT64_MAX = none */
    uint64_t link_tx0, link_rx0, link_steps0; /* the link's counters at the last MM_LINK */
    uint64_t step_us;     /* physics step, microseconds */
    uint64_t last_fast, last_race; /* step of the last publication, UINT64_MAX = none */
    int nlaps;            /* laps already announced */
    unsigned contacts;    /* wall contacts already announced (world_collisions) */
    int in_run;           /* the run under way was announced */
    double run_start_s;
    uint32_t belief_seq;  /* last belief published */
    int watch_n;          /* variables on MM_WATCH (0: no channel) */
    const char *const *watch_names, *const *watch_types; /* theirs (telem_watch), valid to telem_finish */
    double watch_v[TELEM_WATCH_MAX]; /* their latest values */
    uint64_t watch_step;  /* the step they were read after */
    int failed;           /* a log write or an encoding failed */
    uint64_t live_errors; /* live messages lcm_publish could not send */
    uint64_t published;   /* messages published (per output) */
    uint8_t buf[TELEM_BUF_BYTES];
} telem_t;

/* Open the outputs for a run of simulation s (its step sets the periods)
 * and publish MM_MAZE. Returns 0, or -1 with one line in err (nothing is left open or written). */
int telem_open(telem_t *t, const telem_opts_t *o, const sim_state_t *s, char *err, size_t errlen);
/* After every physics step (and the firmware's tick and loop, if any). b:
 * the firmware's belief as the run's driver reports it (a new seq = a new
 * report, published once), NULL if the driver has none (an MCU keeps its
 * map to itself, the scripted driver has no map). */
void telem_step(telem_t *t, const sim_state_t *s, const sim_belief_t *b);
/* After the driver's part of the step (an AVR's cycles run to the step's
 * end): the firmware's variables now, n names with their types and values
 * (n at most TELEM_WATCH_MAX; the strings are the caller's and must live
 * until telem_finish). Published on MM_WATCH if the high-rate channels went
 * out this step, and kept for telem_finish. */
void telem_watch(telem_t *t, const sim_state_t *s, int n, const char *const *names, const char *const *types,
                 const double *values);
/* At the end of the run: the last state of every periodic channel and any
 * belief in b not yet sent (b as for telem_step). */
void telem_finish(telem_t *t, const sim_state_t *s, const sim_belief_t *b);
/* Close the outputs; the log's temporary becomes the log. Returns 0, or -1
 * with one line in err if a log write failed (the temporary is removed, an
 * older log at the path stays) or a tcpq hub was lost during the run. */
int telem_close(telem_t *t, char *err, size_t errlen);

/* Classic flood on m (a mouse's map as truebelief.h's truemaze_from_belief
 * gives it, unknown walls open): cell distances to the goal cells through
 * open sides; -1 = unreachable. cost has truemaze_cells(m) entries. */
void telem_cost_field(const truemaze_t *m, int16_t *cost);

#endif

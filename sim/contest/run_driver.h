/* run_driver.h - inside a run (run.c): what the contest loop holds, and what
 * a driver adds to it. A driver is a table of functions and its own state
 * (self, made by its open); it supplies control only. The loop in run.c is
 * the same for all of them and owns "advance one step, then publish to
 * every observer", so a driver cannot leave an observer out. One iteration:
 *
 *   the hands' actions due now (--input, the HUD's board panel)
 *   before(r, self)     control for the coming step, or why the run ends
 *   sim_step
 *   exchange(r, self)   the step's readings to an outside controller and
 *                       its commands back, before the observers see them
 *   telemetry
 *   after(r, self)      the controller's own time: the firmware's tick, the
 *                       AVR's cycles; or why the run ends
 *   report, viewer, the contest's limits, the stall watch, real-time pacing
 *
 * A new way to drive the robot = a new run_driver_t in its own run_*.c
 * file and one line in run.c's pick_driver. */
#ifndef RUN_DRIVER_H
#define RUN_DRIVER_H

#include <stdio.h>
#include <string.h>

#include "board/watch.h"
#include "contest/run.h"
#include "view/report.h"
#include "world/belief.h"
#include "world/sim.h"

typedef struct run_s run_t;

typedef struct {
    const char *name; /* the JSON's "driver" */
    /* set up after the world; *self = its state. 0, or RUN_EXTERNAL
     * (RUN_BAD_INPUT: bad input) after one error line, nothing left open */
    int (*open)(run_t *r, void **self);
    /* before each step: NULL, or why the run ends now (NULL hook: nothing) */
    const char *(*before)(run_t *r, void *self);
    /* after sim_step, before telemetry (NULL: nothing) */
    void (*exchange)(run_t *r, void *self);
    /* after telemetry: NULL, or why the run ends now (NULL hook: nothing) */
    const char *(*after)(run_t *r, void *self);
    void (*stop)(run_t *r, void *self);                /* the loop has ended (NULL: nothing to do) */
    void (*results)(run_t *r, void *self, json_t *j);  /* its keys after "driver" (NULL: none) */
    void (*close)(run_t *r, void *self);               /* release what self holds: at the end, or a later set-up step failed (NULL: nothing) */
    void (*headline)(const run_t *r, const void *self); /* the text report's first line */
    /* from the reason and laps (NULL: a lap, and done or mcu_stopped) */
    int (*exit_code)(const run_t *r, const void *self);
    /* the serial link it drives over, for MM_LINK and the HUD's port (NULL: none) */
    const link_t *(*link)(const void *self);
    /* the belief its firmware last reported, for MM_BELIEF and the viewer's overlay: a pointer
     * valid until close whose contents follow the reports (NULL hook or NULL: none, an MCU keeps
     * its map to itself) */
    const sim_belief_t *(*belief)(const void *self);
    /* its part of the report: the mms cells, the map it believes (NULL: none, an MCU keeps its
     * map to itself) and the maze its final path is drawn on (NULL: no path) */
    void (*report)(const run_t *r, void *self, report_t *rep, const maze_t **belief, const truemaze_t **path_on);
    void (*show)(run_t *r, void *self, view_t *v); /* its part of the viewer: board panel, mms cells (NULL: none) */
    /* a hand's action on the board: switches, button, reset, send (NULL: no board to act on) */
    void (*hands)(run_t *r, void *self, const input_action_t *a);
    /* the loop ends a run whose robot has made no progress for RUN_STALL_S ("crash_stop"); 0: the
     * driver may wait for an MCU or a person, or has a stall check of its own */
    int watch_stall;
    /* a run under way at the time limit may finish RUN_OVERTIME_S later, its lap flagged over time
     * (the mouse's own laps); 0: time is up at the limit (an MCU's image on a board or a link) */
    int overtime;
} run_driver_t;

struct run_s {
    const run_opts_t *o;
    const char *maze_path;
    simcfg_t cfg;       /* the config and robot file as loaded (the model points into it) */
    char hash[65];      /* config_hash */
    truemaze_t maze;
    sim_model_t model;  /* the run's robot and world, built once from cfg and the seed: const after set-up */
    sim_state_t sim;    /* all that changes as the run steps */
    /* the driver the run began with (its name, results, headline and exit code) and its state */
    const run_driver_t *drv;
    void *self;
    /* the driver in control of the steps and its state: drv, or the serial link since the HUD's Connect */
    const run_driver_t *ctl;
    void *ctl_self;
    telem_t tel;
    int tel_on;
    report_t *rep;
    view_t *view;
    const char *reason; /* the JSON's exit_reason */
    double t0;          /* wall clock at the start, s */
    input_t input;      /* --input's actions, consumed as they fall due */
};

extern const run_driver_t run_firmware, run_mms, run_scripted, run_serial, run_avr, run_board, run_armboard;

/* The HUD's Connect: the serial link to port at baud opened for the run
 * under way (run_link.c), its run_serial state in *self. 0, or -1 with
 * the reason in err. */
int run_link_connect(run_t *r, const char *port, long baud, void **self, char *err, size_t errlen);
/* --gdb PORT: after the stub's start (err NULL) the line that says where
 * it waits, else the reason it did not start; RUN_OK or RUN_EXTERNAL. */
static inline int run_gdb_said(unsigned port, const char *err)
{
    if (err) {
        fprintf(stderr, "mmsim: --gdb %u: %s\n", port, err);
        return RUN_EXTERNAL;
    }
    fprintf(stderr, "mmsim: --gdb: the firmware is halted until avr-gdb attaches to 127.0.0.1:%u (target remote :%u) and continues\n",
            port, port);
    return RUN_OK;
}

/* A board's console text (NUL-terminated at n) as a JSON string; bytes above 0x7F as '?' when it is not UTF-8 (run_console.c). */
json_t *run_console_json(const char *text, size_t n);

/* --watch (run_watch.c): the firmware's variables, their latest values and
 * how the driver's processor reads them (the AVR's SRAM, the ARM core's). */
typedef void (*run_watch_sample_t)(const watch_list_t *w, void *ctx, double *values);
typedef struct {
    watch_list_t list;         /* list.n 0: no --watch */
    double values[WATCH_MAX];
    run_watch_sample_t sample; /* values[0..list.n) now, from ctx's memory */
    void *ctx;
} run_watch_t;
/* --watch's names looked up in the image r->o->avr_elf run on avr: 0 (also
 * without --watch), or RUN_BAD_INPUT after one line. */
int run_watch_open(run_t *r, run_watch_t *w, const struct avr_t *avr);
/* After a driver's own lookup into w->list (lookup_rc 0, or -1 with the
 * reason in err): the sampler kept; 0, or RUN_BAD_INPUT after one line. */
int run_watch_started(run_watch_t *w, int lookup_rc, const char *err, run_watch_sample_t sample, void *ctx);
/* After the processor's cycles of the step: the variables read, to the
 * telemetry and the report (nothing without --watch). */
void run_watch_step(run_t *r, run_watch_t *w);

/* RUN_OK if a lap was completed and the run ended for one of the two
 * reasons given (or NULL), else RUN_NOT_REACHED. */
static inline int run_exit_laps(const run_t *r, const char *ok1, const char *ok2)
{
    int ok = !strcmp(r->reason, ok1) || (ok2 && !strcmp(r->reason, ok2));
    return r->sim.race.nlaps > 0 && ok ? RUN_OK : RUN_NOT_REACHED;
}

/* Is the contest's time up? One clock for laps and the limit: the contest
 * clock, which starts when the mouse first leaves the start cell (race.h),
 * as laps are timed; before that, simulation time. Time is up when the
 * clock reaches config's sim.time_limit_s (--time-limit) with no run under
 * way, or overtime_s later if one is (that lap is flagged over time). */
int run_time_up(const run_t *r, double overtime_s);

#endif

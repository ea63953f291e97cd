/* run_driver.h - inside a run (run.c): its state, and what a driver adds to
 * the contest loop. A driver is a table of functions; the loop in run.c is
 * the same for all of them. A new way to drive the robot = a new
 * run_driver_t in its own run_*.c file and one line in run_pick_driver. */
#ifndef RUN_DRIVER_H
#define RUN_DRIVER_H

#include "board/board.h"
#include "board/pil.h"
#include "contest/driver.h"
#include "contest/run.h"
#include "view/report.h"
#include "world/sim.h"

typedef struct run_s run_t;

typedef struct {
    const char *name; /* the JSON's "driver" */
    /* set up after the world: 0, or RUN_EXTERNAL (RUN_BAD_INPUT: bad input) after one error line */
    int (*open)(run_t *r);
    /* one physics step with this driver: NULL, or why the run ends now */
    const char *(*step)(run_t *r);
    void (*stop)(run_t *r);               /* the loop has ended (NULL: nothing to do) */
    void (*results)(run_t *r, json_t *j); /* its keys after "driver" (NULL: none) */
    void (*undo)(run_t *r);               /* a later set-up step failed (NULL: nothing) */
    void (*headline)(const run_t *r);     /* the text report's first line */
    int (*exit_code)(const run_t *r);     /* from the reason and laps (NULL: a lap, and done or mcu_stopped) */
} run_driver_t;

struct run_s {
    const run_opts_t *o;
    const char *maze_path;
    const run_driver_t *drv;
    simcfg_t cfg;
    char hash[65];      /* config_hash */
    maze_t maze;
    sim_t sim;
    driver_t script;    /* the scripted driver (drv == &run_scripted) */
    mms_t mms;
    link_t lnk;
    pil_t pil;
    board_t *board;     /* --board */
    telem_t tel;
    int tel_on;
    report_t *rep;
    view_t *view;
    int hil;            /* an MCU drives: from the start, or since the HUD's Connect */
    long steps_per_tick, tick_steps; /* the firmware's control tick */
    const char *reason; /* the JSON's exit_reason */
    double t0;          /* wall clock at the start, s */
    input_t input;      /* --input's actions, consumed as they fall due */
    int console_fd;     /* --console pty: the pty's master, -1 none */
    size_t console_sent; /* console bytes written to it so far */
    /* the board's side of a hand's action (switches, button, reset, send); NULL: no board */
    void (*hands)(run_t *r, const input_action_t *a);
    /* the board as the viewer's panel shows it (view_board_fill_t, ctx = the run); NULL: no board */
    view_board_fill_t *panel;
};

extern const run_driver_t run_firmware, run_mms, run_scripted, run_serial, run_avr, run_board;

/* The in-process firmware after a physics step: its control tick at
 * HAL_TICK_HZ, then its background loop (run_firmware.c). */
void run_firmware_tick(run_t *r);
/* One step while an MCU drives over the link (run_link.c): NULL or why the run ends. */
const char *run_link_step(run_t *r);
/* The HUD's Connect button: an MCU drives from now on (run_link.c). */
void run_link_connect(run_t *r, const char *port, long baud);
/* "link" and "avr" into j (run_link.c). */
void run_link_results(run_t *r, json_t *j);
/* RUN_OK if a lap was completed and the run ended for one of the two
 * reasons given (or NULL), else RUN_NOT_REACHED. */
int run_exit_laps(const run_t *r, const char *ok1, const char *ok2);

#endif

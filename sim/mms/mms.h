/* mms.h - run an mms maze algorithm (any program speaking the text API of
 * mackorone/mms release v1.2.0, README at commit 3054142: moveForward [N],
 * moveForwardHalf, turn*45, getStat; wallBack, the half-step argument of
 * the wall queries, the cell boundaries and the diagonals between their
 * middles as mms's Window.cpp at 9ec759a) on the simulated robot.
 *
 * The algorithm runs as /bin/sh -c COMMAND in its own process group, under
 * a guardian process (guard.h), with its stdin, stdout and stderr on pipes;
 * its stderr comes out on ours a line at a time as "algo: LINE", control
 * bytes escaped (sim/io/escape.h), as does the --verbose trace.
 * Each line it prints is one command. Queries are answered at once from the
 * firmware's map (walls it sensed itself) or, with ideal walls, from the
 * maze file; moves are handed to the firmware's command mode (mouse.h
 * mouse_cmd_*) and answered when the robot has physically finished them.
 * Simulation time only advances while a move runs: the same algorithm gives
 * the same run however long it thinks. Invalid commands are ignored.
 *
 * An algorithm that polls wasReset MMS_IDLE_POLLS times without a move
 * idles, waiting for the Reset button (a common mms idiom after the goal):
 * then Reset is pressed at once (reset_on_idle), or the contest clock runs,
 * the robot at rest, until the reset time (reset_at_s) or until the viewer's
 * Reset button (idle_wait); with none of these the run ends (mms_idle).
 *
 * The run ends when the algorithm exits, fails (non-zero exit, signal), is
 * silent for longer than the per-command timeout, prints a line longer than
 * MMS_LINE_MAX or MMS_FLOOD_LIMIT commands without a move, idles with no
 * Reset coming, or the robot is stuck; then everything the algorithm
 * started is killed (SIGKILL) and reaped, also what it started in a new
 * session or left orphaned. */
#ifndef MMS_H
#define MMS_H

#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <sys/types.h>

#include "maze/truemaze.h"
#include "guard.h"
#include "io/escape.h"

struct sim_state_s;

#define MMS_LINE_MAX 1024         /* bytes per command line */
#define MMS_FLOOD_LIMIT 1000000L  /* commands in a row without a move */
#define MMS_IDLE_POLLS 10         /* wasReset answered false this often without a move = idle, waiting for
                                     Reset (ours: an algorithm that checks it once per move never gets there) */
#define MMS_TEXT_MAX 10           /* characters of cell text (mms) */
#define MMS_MOVE_MAX_S 30.0       /* sim seconds a move may take: longer = stuck (a 32-cell straight takes ~12 s) */

/* mms's Stats tab (Stats.cpp, README): distances in cells (kept in half
 * cells: a half step counts half a cell), effective distance counts every
 * cell of a move after the second as 0.5. */
typedef struct {
    int total_halves, total_turns;
    int cur_halves, cur_turns;
    int best_halves, best_turns;
    float total_eff, cur_eff, best_eff;
    int has_best;   /* a start-to-goal run was completed */
    int in_run;     /* a run started (a move from the start cell) */
    int solved;     /* the goal was reached */
    float penalty;  /* added to the next run (ackReset: 15) */
} mms_stats_t;

void mms_stats_init(mms_stats_t *s);
void mms_stats_start_run(mms_stats_t *s);
/* A move of `halves` half cells (moveForward N: 2N). */
void mms_stats_distance(mms_stats_t *s, int halves);
void mms_stats_turn(mms_stats_t *s);
void mms_stats_finish_run(mms_stats_t *s);
void mms_stats_end_unfinished(mms_stats_t *s);
void mms_stats_reset_penalty(mms_stats_t *s);
/* best run turns + best run effective distance + 0.1 * (total turns +
 * total effective distance); 2000 if the goal was never reached. */
float mms_stats_score(const mms_stats_t *s);
/* getStat's answer for the stat named `name` into out ("-1" if it has no
 * value yet; distances in whole cells, a half rounded down: mms's are
 * integers); -1 if the name is not a stat. */
int mms_stats_get(const mms_stats_t *s, const char *name, char *out, size_t len);

enum { MMS_STEP = 0, MMS_END = 1 };

typedef struct {
    const char *command;  /* the shell command */
    int ideal_walls;      /* answer wall queries from the maze file */
    int timeout_ms;       /* per command */
    double reset_at_s;    /* wasReset turns true at this sim time (an idle algorithm: the clock runs
                             to it); < 0 never */
    FILE *trace;          /* every command and answer, with sim time (NULL: none) */
    int reset_on_idle;    /* Reset pressed each time the algorithm idles (--mms-reset-at idle) */
    int idle_wait;        /* an idle algorithm with no reset due: the clock runs until the Reset button
                             (the viewer) or the contest's end, instead of ending the run */
} mms_opts_t;

typedef struct mms_s {
    mms_opts_t o;
    const truemaze_t *truth;
    guard_t guard;         /* the algorithm's process tree (guard.h) */
    int exited;            /* the shell has exited: status below */
    int to_child, from_child;
    int err_fd;            /* the algorithm's stderr (read end), -1 none */
    char errbuf[MMS_LINE_MAX]; /* its stderr line so far */
    size_t errlen;
    char buf[MMS_LINE_MAX + 1];
    size_t len;
    int pending;           /* a move is under way (MMS_MOVE_*) */
    double move_start_s;   /* sim time the move under way began */
    int was_reset;
    int exit_code;         /* the shell's exit status, -1 if none (yet, or killed) */
    int exit_signal;       /* the signal that killed it, 0 if none */
    const char *reason;    /* exit_reason for the JSON */
    char message[300];     /* one line for stderr, "" = none */
    char shown[IO_ESCAPE_MAX(64)]; /* the command as messages print it: control bytes escaped, at most 64 bytes */
    long commands, invalid, since_move, moves, crashes, resets;
    long idle_polls;       /* wasReset answered false since the last move */
    int idle;              /* it idles and no Reset is coming: the run ends (mms_idle) */
    mms_stats_t stats;
    /* what the algorithm drew: colour letter (0 = none), text, walls it set */
    char color[TRUEMAZE_MAX_CELLS];
    char text[TRUEMAZE_MAX_CELLS][MMS_TEXT_MAX + 1];
    uint8_t drawn_walls[TRUEMAZE_MAX_CELLS]; /* bit d = setWall on side d */
} mms_t;

/* RGB (0xRRGGBB) of an mms colour letter (kbacgorwyBCAGRY: Qt's named
 * colours, orange #ffa500); 0 for anything else. */
uint32_t mms_colour_rgb(char letter);

/* Set up the state without a child (mms_start does it; unit tests). */
void mms_init(mms_t *m, const mms_opts_t *o, const truemaze_t *truth);
/* Start the algorithm; the firmware must be set up (fw_setup) first. 0, or
 * -1 with one line in err. */
int mms_start(mms_t *m, const mms_opts_t *o, const truemaze_t *truth, char *err, size_t len);
/* Serve commands until a move needs the simulation to step (MMS_STEP: step
 * once, fw_tick, fw_loop, call again) or the run is over (MMS_END: m->reason,
 * m->message). s is the running simulation (struct sim_state_s). */
int mms_service(mms_t *m, struct sim_state_s *s);
/* End the algorithm: its guardian kills (SIGKILL) and reaps every process
 * the algorithm started (its group, and whatever left it: background
 * processes of a shell that has exited, new sessions, orphans); the rest of
 * its stderr is printed. */
void mms_stop(mms_t *m);
/* Execute one command line; the answer (without newline) into resp, "" for
 * none. Returns 1 if a move was started or an idle wasReset waits for the
 * reset time (the answer comes later). Exposed for the unit tests; needs the
 * firmware in command mode only for moves. */
int mms_execute(mms_t *m, struct sim_state_s *s, const char *line, char *resp, size_t len);
/* The JSON object of the run's mms part (a json_t *, jansson). */
void *mms_json(const mms_t *m);
/* 1 if the algorithm failed (the run's exit code is then 3). */
int mms_failed(const mms_t *m);

#endif

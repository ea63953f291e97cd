/* input.h - a person's hands on the robot, scripted: `--input "T ACTION;
 * T ACTION; ..."` (T in simulation seconds, ascending or not). Actions:
 *   switches=N      the function switches to N (0..15)
 *   button          pressed for 100 ms (a down now and an up 0.1 s later)
 *   button=SECONDS  pressed for SECONDS (0.01-60): a short or a long press
 *   button=down     button=up
 *   reset           the reset button
 *   occlude=NAME    an object ~20 mm ahead of the robot file's [ir.NAME] or
 *                   [tof.NAME] sensor for 0.3 s; `left` and `right` (when no
 *                   sensor has that name) mean the forward-facing IR sensor
 *                   left or right of the centre line. Checked against the
 *                   robot before the run starts (run.c): an unknown name is
 *                   an error there, as the parser has no robot.
 *   push=DX_MM[,DYAW_DEG[,SECONDS]]
 *                   the robot rolled by hand along the floor: its axle's
 *                   middle DX_MM forward (negative: back) and turned DYAW_DEG
 *                   counter-clockwise over SECONDS (default 1 s), the wheels
 *                   rolling on the floor (sim.h sim_push); ignored while lifted
 *   lift            the robot carried: held still 50 mm up, wheels free
 *   place           put back down where it was lifted
 *   send=TEXT       TEXT and a newline typed on the console (to ';' or the end)
 *   end             the run stops there
 * Several --input flags add up: their actions merged in time order (equal times
 * in the order given).
 * Errors: "--input:N:COL: reason" (N: the flag's number, 1 for the first; COL:
 * the action's first character). */
#ifndef INPUT_H
#define INPUT_H

#include <stddef.h>

#define INPUT_MAX 64          /* actions after expanding `button` */
#define INPUT_TEXT_MAX 80     /* bytes of a send's text */
#define INPUT_NAME_MAX 16     /* bytes of an occluded sensor's name with the NUL (as the robot file's names) */
#define INPUT_BUTTON_S 0.1    /* s a `button` press lasts */
#define INPUT_PRESS_MIN_S 0.01 /* s: the shortest button=SECONDS */
#define INPUT_PRESS_MAX_S 60.0 /* s: the longest button=SECONDS */
#define INPUT_OCCLUDE_S 0.3   /* s an occlusion lasts */
#define INPUT_OCCLUDE_M 0.020 /* m from the sensor to the object */
#define INPUT_PUSH_S 1.0      /* s a push lasts when SECONDS is not given */
#define INPUT_PUSH_MIN_S 0.05 /* s: the shortest push */
#define INPUT_PUSH_MAX_S 60.0 /* s: the longest push */
#define INPUT_PUSH_MAX_MM 5000.0     /* mm: the longest push (|DX_MM|) */
#define INPUT_PUSH_MAX_DEG 3600.0    /* deg: the largest turn (|DYAW_DEG|) */
#define INPUT_PUSH_MAX_M_S 1.0       /* m/s: a hand's top speed (a push peaks at 2 DX / SECONDS) */
#define INPUT_PUSH_MAX_DEG_S 1440.0  /* deg/s: a hand's top turn rate (peaks at 2 DYAW / SECONDS) */

typedef enum {
    INPUT_SWITCHES, INPUT_BUTTON_DOWN, INPUT_BUTTON_UP, INPUT_RESET, INPUT_OCCLUDE, INPUT_SEND, INPUT_END,
    INPUT_PUSH, INPUT_LIFT, INPUT_PLACE
} input_kind_t;

typedef struct {
    double t_s;
    input_kind_t kind;
    int value;                 /* switches: N; occlude: the robot part's index once run.c resolved text */
    char text[INPUT_TEXT_MAX]; /* send: the text; occlude: the sensor's name */
    double push[3];            /* push: mm forward, deg counter-clockwise, s */
    int spec, col;             /* where it was written: the --input flag's number and column (from 1) */
} input_action_t;

typedef struct {
    input_action_t a[INPUT_MAX]; /* in time order (stable for equal times) */
    int n, next;
    int specs;                   /* --input texts added so far */
} input_t;

/* Parse spec into in: 0, or -1 with one line in err. */
int input_parse(input_t *in, const char *spec, char *err, size_t errlen);
/* Add spec's actions to in's (several --input flags): 0, or -1 with one line in err. */
int input_add(input_t *in, const char *spec, char *err, size_t errlen);
/* The next action due at t_s (and advance), or NULL. */
const input_action_t *input_due(input_t *in, double t_s);
/* 1 if any action needs a board (all but occlude, push, lift, place and end). */
int input_needs_board(const input_t *in);

#endif

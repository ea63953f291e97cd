/* view.h - the 3D viewer (GLFW 3 window, legacy OpenGL): the scene
 * (scene.h) with the HUD (hud.h), three cameras, live with the simulation
 * or one frame to a PNG file.
 *
 * Live: call view_step after every physics step. It keeps the simulation
 * at `speed` times real time (wall clock for pacing only: the physics and
 * firmware see simulation time alone, so a run is the same with or without
 * the viewer), draws about 60 frames a second and handles input:
 *   1/2/3 or the buttons   bird's view, follow from behind, close-up top
 *   drag / scroll          orbit / zoom the current camera; R resets it
 *   space, S (or .)        pause, one physics step while paused
 *   + / -                  speed x2 / /2 (x1 .. x64)
 *   O                      discovered walls and planned path overlay
 *   P or "Toggle post"     add/remove the centre post in the physics world
 *   X or "Reset"           mms runs: press mms's Reset button (wasReset)
 *   Esc or Q               close
 *   click Port / Baud      type a serial port and baud (Tab: the other
 *                          field, Backspace, Esc: done); Connect or Enter
 *                          asks the caller to open the link (HIL); shown
 *                          only where a link can be made (view_set_link_ok)
 * A board (--board, view_set_board): under the timers its function
 * switches (click: toggle), BUTTON (down while the mouse is held, at least
 * VIEW_BUTTON_MIN_S of simulation time), RESET, its LEDs and the last lines
 * of its console; the clicks come back as view_hands_request.
 * Replay (mmview): view_set_replay gives the view a loaded log (replay.h),
 * drawn from its model and its snapshots, no simulation; view_play runs
 * it at `speed` with a time slider
 * (click or drag to seek) and these keys instead of the physics ones:
 *   space or "Pause"       play / pause (at the end: play from the start)
 *   S (or .) / ,           one logged pose forward / back, paused
 *   + / -                  speed x2 / /2 (x1 .. x64)
 *   Left / Right           one second back / forward; Home / End
 * (P or "Toggle post" shows or hides the centre post in the replay.)
 * The UI actions work without a window too (view_button, view_click,
 * view_key), which is how they are tested; their sim_state_t is NULL in a
 * replay. Each frame is drawn from a snapshot (snap.h): a live run's
 * taken from its sim_state_t just before the frame. */
#ifndef VIEW_H
#define VIEW_H

#include <stddef.h>

#include "hud.h"
#include "replay.h"
#include "scene.h"
#include "world/belief.h"
#include "world/sim.h"

#define VIEW_SPEED_MAX 64.0
#define VIEW_SLIDER 100 /* view_click's answer for the replay slider */
#define VIEW_FIELD 200  /* view_click's answer for a HUD field: + HUD_FIELD_* */
#define VIEW_BOARD 300  /* view_click's answer for a board control: + HUD_BOARD_* */

typedef struct {
    int width, height; /* window or picture, pixels */
    double speed;      /* sim seconds per wall second, 1..VIEW_SPEED_MAX */
    int camera;        /* 1..3 (SCENE_BIRD..) */
    const char *port;  /* serial port shown in the HUD ("" or NULL: none) */
    long baud;
} view_opts_t;

typedef struct view view_t;

/* UI state only, no window. NULL out of memory. */
view_t *view_new(const view_opts_t *o);
/* Open the window (hidden for pictures). Returns 0, or -1 with one line in
 * err (no X display, no GL). */
int view_open(view_t *v, int visible, char *err, size_t errlen);
/* Close the window if open and free. */
void view_free(view_t *v);

/* Live: after every sim_step. Returns 1 once the window has been closed. */
int view_step(view_t *v, sim_state_t *s);
/* After the run: show the final state until the window is closed. */
void view_hold(view_t *v, sim_state_t *s);
/* Draw one frame of s (a replay's: NULL; window opened hidden or not) and
 * write it as PNG of the window's size. Returns 0, or -1 with one line in
 * err. */
int view_screenshot(view_t *v, sim_state_t *s, const char *path, char *err, size_t errlen);

/* HIL at run time: the port and baud typed into the HUD's fields when
 * Connect was pressed (or Enter in a field), once: returns 1 and sets
 * them (valid until the next call), else 0. The caller opens the link and
 * reports the outcome with view_set_status. */
int view_connect_request(view_t *v, const char **port, long *baud);
/* Whether a serial link can be made now (a live run whose driver the link
 * could replace): the Port, Baud and Connect controls are shown and take
 * clicks only then. Default 0: none (a replay never has them). */
void view_set_link_ok(view_t *v, int ok);
void view_set_status(view_t *v, const char *text);

/* A live run's mouse belief for the overlay (walls discovered, planned
 * path): b is read at each frame and must outlive the view; its contents
 * are what the firmware last reported (seq 0: nothing yet, no overlay).
 * NULL (the default): the run's driver has no belief to show. */
void view_set_belief(view_t *v, const sim_belief_t *b);

/* A board's panel (plain data: hud.h's hud_board_t). fill(ctx, out) is
 * called just before each frame is drawn (only then: nothing per step),
 * and must only read; what out points to must stay valid until the frame
 * is drawn. NULL: no board. */
typedef hud_board_t view_board_t;
typedef void view_board_fill_t(void *ctx, view_board_t *out);
void view_set_board(view_t *v, view_board_fill_t *fill, void *ctx);

/* A person's hand on the board, from a click on the HUD. */
typedef enum { VIEW_HAND_SWITCHES, VIEW_HAND_BUTTON_DOWN, VIEW_HAND_BUTTON_UP, VIEW_HAND_RESET } view_hand_kind_t;
typedef struct {
    view_hand_kind_t kind;
    unsigned switches; /* VIEW_HAND_SWITCHES: the new setting, 0..15 */
} view_hand_t;
#define VIEW_BUTTON_MIN_S 0.1 /* a click on BUTTON holds it this long (simulation time) */
/* The oldest request not yet taken (call after view_step): 1 and *out, or
 * 0. A BUTTON released early comes up VIEW_BUTTON_MIN_S after it went down. */
int view_hands_request(view_t *v, view_hand_t *out);

/* Replay: show the loaded log r (which must outlive the view) from time 0. */
void view_set_replay(view_t *v, replay_t *r);
/* Replay: run the log in the window until it is closed. */
void view_play(view_t *v);
/* Replay: go to t_s (clamped to the log). */
void view_seek(view_t *v, double t_s);
/* The time shown, s (replay time, or the simulation's). */
double view_time(const view_t *v);

/* UI actions. */
void view_button(view_t *v, sim_state_t *s, int button);             /* HUD_BTN_* */
int view_click(view_t *v, sim_state_t *s, double x, double y);       /* the button hit, VIEW_SLIDER, VIEW_FIELD + f, VIEW_BOARD + c, or -1 */
void view_char(view_t *v, unsigned codepoint);                 /* a typed character (into the field being edited) */
void view_drag(view_t *v, double x, double y);                 /* mouse moved (slider drag, or orbit after a click on the scene) */
void view_release(view_t *v);                                  /* mouse button up */
void view_scroll(view_t *v, double dy);                        /* scroll notches: zoom the current camera */
const scene_orbit_t *view_orbit(const view_t *v);              /* the current camera's orbit */
void view_key(view_t *v, sim_state_t *s, int key);                   /* GLFW_KEY_* */
/* An mms run: the floor shows the algorithm's cell colours (mms letters per
 * cell, 0 none) and texts (text_stride bytes per cell; the arrays must
 * outlive the view), and the Reset button (or
 * the X key) sets *reset to 1 (mms wasReset). */
void view_set_mms(view_t *v, const char *colours, const char *texts, size_t text_stride, int *reset);
int view_camera(const view_t *v);
double view_speed(const view_t *v);
int view_paused(const view_t *v);
int view_overlay(const view_t *v);

#endif

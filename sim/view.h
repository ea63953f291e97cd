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
 * The UI actions work without a window too (view_button, view_click,
 * view_key), which is how they are tested. */
#ifndef VIEW_H
#define VIEW_H

#include <stddef.h>

#include "sim.h"

#define VIEW_SPEED_MAX 64.0

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
int view_step(view_t *v, sim_t *s);
/* After the run: show the final state until the window is closed. */
void view_hold(view_t *v, sim_t *s);
/* Draw one frame of s (window opened hidden or not) and write it as PNG of
 * the window's size. Returns 0, or -1 with one line in err. */
int view_screenshot(view_t *v, sim_t *s, const char *path, char *err, size_t errlen);

/* UI actions. */
void view_button(view_t *v, sim_t *s, int button);             /* HUD_BTN_* */
int view_click(view_t *v, sim_t *s, double x, double y);       /* the button hit, or -1 */
void view_key(view_t *v, sim_t *s, int key);                   /* GLFW_KEY_* */
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

/* hud.h - the viewer's 2D overlay: timers at the upper left (red after
 * the contest limit), serial port and baud fields with a Connect button at
 * the upper right, camera and overlay buttons at the lower left, run
 * controls at the bottom centre, "Toggle post" at the lower right.
 * Layout and hit tests need no GL (the viewer's tests use them); drawing
 * needs a current GL context. Pixel coordinates: origin top-left. */
#ifndef HUD_H
#define HUD_H

#include "sim.h"

enum {
    HUD_BTN_BIRD, HUD_BTN_FOLLOW, HUD_BTN_TOP, HUD_BTN_OVERLAY,
    HUD_BTN_SLOWER, HUD_BTN_PAUSE, HUD_BTN_STEP, HUD_BTN_FASTER,
    HUD_BTN_POST, HUD_BTN_CONNECT,
    HUD_BTN_RESET, /* mms runs only: the Reset button (wasReset) */
    HUD_BTN_COUNT
};

#define HUD_TEXT_SCALE 2 /* screen pixels per font pixel */

typedef struct {
    int x, y, w, h;    /* pixels, top-left origin */
    const char *label;
} hud_button_t;

/* What the HUD shows besides the simulation itself. */
typedef struct {
    int camera;           /* 1..3 */
    int overlay, paused;
    double speed;         /* sim seconds per wall second */
    const char *port;     /* serial port text ("" none) */
    long baud;
    const char *status;   /* one line of status text, or NULL */
    int mms;              /* an mms algorithm drives: show Reset */
} hud_info_t;

/* Where the buttons sit in a win_w x win_h window. */
void hud_layout(int win_w, int win_h, hud_button_t out[HUD_BTN_COUNT]);
/* The button under (x, y), or -1. */
int hud_hit(int win_w, int win_h, double x, double y);
/* The global and current lap timer texts ("m:ss.mmm") and whether they are over the contest limit. */
void hud_timers(const sim_t *s, char global[16], char lap[16], int *over_time);
/* Draw the overlay (GL, orthographic, over whatever is drawn). */
void hud_draw(const sim_t *s, const hud_info_t *info, int win_w, int win_h);

#endif

/* hud.h - the viewer's 2D overlay: timers at the upper left (red after
 * the contest limit), serial port and baud fields (editable, see view.h)
 * with a Connect button at the upper right, camera and overlay buttons at
 * the lower left, run controls at the bottom centre, "Toggle post" at
 * the lower right; when replaying a log, a time slider above the bottom
 * row.
 * Layout and hit tests need no GL (the viewer's tests use them); drawing
 * needs a current GL context. Pixel coordinates: origin top-left. */
#ifndef HUD_H
#define HUD_H

#include "world/sim.h"

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
    int replay;           /* a log replay (mmview): the time slider is shown */
    double replay_s, replay_end_s; /* its time and length, s */
    int editing;          /* the field being typed in (HUD_FIELD_*), -1 none */
    const char *baud_text; /* the baud field's text, or NULL: baud */
    int mms;              /* an mms algorithm drives: show Reset */
} hud_info_t;

enum { HUD_FIELD_PORT = 0, HUD_FIELD_BAUD = 1, HUD_FIELDS = 2 };

/* Where the buttons sit in a win_w x win_h window. */
void hud_layout(int win_w, int win_h, hud_button_t out[HUD_BTN_COUNT]);
/* The button under (x, y), or -1. */
int hud_hit(int win_w, int win_h, double x, double y);
/* Where the port and baud fields sit; the field under (x, y), or -1. */
void hud_fields(int win_w, int win_h, hud_button_t out[HUD_FIELDS]);
int hud_field_hit(int win_w, int win_h, double x, double y);
/* The replay's time slider: a bar across the window above the bottom row. */
void hud_slider(int win_w, int win_h, hud_button_t *out);
/* Is (x, y) on the slider? */
int hud_slider_hit(int win_w, int win_h, double x, double y);
/* The time at x along the slider of a replay end_s long (clamped to 0..end_s). */
double hud_slider_time(int win_w, int win_h, double x, double end_s);
/* The global and current lap timer texts ("m:ss.mmm") and whether they are over the contest limit. */
void hud_timers(const sim_t *s, char global[16], char lap[16], int *over_time);
/* Draw the overlay (GL, orthographic, over whatever is drawn). */
void hud_draw(const sim_t *s, const hud_info_t *info, int win_w, int win_h);

#endif

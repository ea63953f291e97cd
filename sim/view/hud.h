/* hud.h - the viewer's 2D overlay. The window is split so that no 3D
 * geometry ever shows under text: a side panel on the left (opaque) holds
 * the timers (red after the contest limit), the speed, the mouse's state,
 * the lap table and, with a board (--board), its four function switches,
 * BUTTON and RESET, its LEDs and a console panel (the last lines the
 * firmware printed); a bar along the bottom (opaque) holds the camera and
 * overlay buttons (lower left), the run controls (bottom centre), "Toggle
 * post" (lower right), the status line and, when replaying a log, a time
 * slider; the 3D scene fills the rest (hud_scene_rect). Where a serial
 * link can be made, the serial port and baud fields (editable, see
 * view.h) with a Connect button sit at the scene's upper right, on opaque
 * boxes.
 * Layout and hit tests need no GL (the viewer's tests use them); drawing
 * needs a current GL context. Pixel coordinates: origin top-left. */
#ifndef HUD_H
#define HUD_H

#include <stddef.h>

#include "snap.h"

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

/* A board's panel: plain data (the viewer knows no board types). */
#define HUD_BOARD_LEDS 4
#define HUD_CONSOLE_LINES 12 /* console rows shown at most */
#define HUD_CONSOLE_TEXT 0x60F060u /* the console's text colour */
#define HUD_LED_LIT 0xFF5020u      /* an LED lit, and dark */
#define HUD_LED_DARK 0x402018u
typedef struct {
    unsigned switches;                   /* 0..15, bit k: switch k */
    int button;                          /* 1: held down */
    int nleds;                           /* 0..HUD_BOARD_LEDS */
    int led[HUD_BOARD_LEDS];             /* 1: lit */
    const char *led_name[HUD_BOARD_LEDS];
    const char *console;                 /* everything the firmware printed (NULL: nothing) */
    size_t console_len;
} hud_board_t;

/* The panel's controls: switch k toggles bit k (labelled by its weight 1, 2, 4, 8). */
enum { HUD_BOARD_SW0, HUD_BOARD_SW1, HUD_BOARD_SW2, HUD_BOARD_SW3, HUD_BOARD_BUTTON, HUD_BOARD_RESET, HUD_BOARD_COUNT };

typedef struct {
    hud_button_t ctl[HUD_BOARD_COUNT];
    hud_button_t leds;    /* the LED row */
    hud_button_t console; /* the console panel at its tallest (drawn as tall as its text) */
    int console_scale;    /* screen pixels per font pixel there */
    int ctl_scale;        /* and on the controls and the LEDs' names */
    int cols, rows;       /* console text that fits */
} hud_board_layout_t;

/* Where the board's panel sits in a win_w x win_h window. */
void hud_board_layout(int win_w, int win_h, hud_board_layout_t *out); /* (within the side panel) */
/* The board control under (x, y) (HUD_BOARD_*), or -1. */
int hud_board_hit(int win_w, int win_h, double x, double y);
/* The last `rows` rows of console text c (n bytes) wrapped at `cols`
 * (cols <= 128): printable ASCII, a tab as a space, other bytes '?', CRs
 * dropped; row i into out[i] (NUL-terminated). Returns the rows filled. */
int hud_console_rows(const char *c, size_t n, int cols, int rows, char out[][129]);

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
    const hud_board_t *board; /* a board's panel, or NULL */
    int link_ok;          /* a serial link can be made: show Port, Baud and Connect */
    int mouse_state;      /* the firmware's state (belief.h: mouse.h MOUSE_*), -1 not published */
    double v_m_s;         /* the robot's speed along its heading, m/s */
} hud_info_t;

/* The side panel's width in a W-pixel-wide window (wider with a board). */
int hud_panel_w(int win_w, int board);
/* Where the 3D scene is drawn (top-left origin): right of the side panel,
 * above the bottom bar (the same in a live run and a replay). */
void hud_scene_rect(int win_w, int win_h, int board, hud_button_t *out);
#define HUD_INFO_LINES 11 /* the side panel's text lines above the board's controls */
#define HUD_LAP_ROWS 4    /* laps listed (the latest) */
/* The lap table's rows for race r: "Lap  Run time" then the latest
 * HUD_LAP_ROWS laps ("N  m:ss.mmm", "*" the best, "!" over time), then
 * "Best m:ss.mmm" (or "Best -"); rows into out[i]. Returns the rows filled. */
int hud_lap_rows(const race_t *r, char out[][32]);

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
/* The global and current lap timer texts ("m:ss.mmm") of snapshot s and
 * whether they are over the contest limit. */
void hud_timers(const snap_t *s, char global[16], char lap[16], int *over_time);
/* Draw the overlay of snapshot s (GL, orthographic, over whatever is drawn). */
void hud_draw(const snap_t *s, const hud_info_t *info, int win_w, int win_h);

#endif

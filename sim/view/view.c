/* view.c - the viewer's window, pacing and input (see view.h). */
#include "view.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <GL/gl.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "hud.h"
#include "image.h"
#include "replay.h"
#include "scene.h"
#include "snap.h"
#include "link/serial.h"

#define FRAME_S (1.0 / 60)   /* wall time between drawn frames */
#define MAX_LAG_S 0.25       /* sim time behind the wall clock before the backlog is dropped */
#define DRAG_RAD_PER_PX 0.008 /* orbit per pixel dragged, rad */
#define DPITCH_MAX_RAD 1.6    /* orbit pitch limit either way, rad (just past vertical) */
#define ZOOM_PER_NOTCH 0.9    /* camera distance factor per scroll notch (towards the target) */
#define ZOOM_MIN 0.1          /* camera distance factor limits */
#define ZOOM_MAX 10.0
#define VIEW_HANDS_MAX 32     /* board clicks queued between two physics steps */

struct view {
    view_opts_t o;
    GLFWwindow *win;
    int camera, paused, overlay, step_req, closed;
    double speed;
    scene_orbit_t orbit[SCENE_CAMERAS + 1];
    double sim0, wall0;      /* pacing: sim time at wall time */
    double next_frame;       /* wall time of the next frame */
    int dragging;
    double drag_x, drag_y;
    char status[96];
    sim_state_t *sim;              /* the simulation being shown (for callbacks); NULL in a replay */
    replay_t *rp;            /* a log replayed (mmview), or NULL */
    double rp_t;             /* replay time, s */
    int rp_drag;             /* the slider is being dragged */
    char port[256], baud[24]; /* the HUD's fields, as typed */
    int editing;             /* HUD_FIELD_* being typed in, -1 none */
    int connect_req;         /* Connect pressed with a valid port and baud */
    const char *mms_colours; /* view_set_mms: cell colours, or NULL */
    const char *mms_texts;   /* and texts, mms_stride bytes per cell */
    size_t mms_stride;
    int *mms_reset;          /* set to 1 by the Reset button, or NULL */
    const sim_belief_t *belief; /* view_set_belief: the firmware's belief, or NULL: none */
    view_board_fill_t *board_fill; /* view_set_board, or NULL: no board */
    void *board_ctx;
    view_board_t board;      /* as last filled */
    view_hand_t hands[VIEW_HANDS_MAX]; /* clicks on the board not yet taken */
    int hands_head, hands_len;
    int sw_pending;          /* a switches request not yet taken: sw_want */
    unsigned sw_want;
    int btn_held;            /* the mouse holds BUTTON down */
    int link_ok;             /* view_set_link_ok: Port, Baud and Connect shown and taking clicks */
    int btn_up_due;          /* released early: up at btn_down_s + VIEW_BUTTON_MIN_S */
    double btn_down_s;       /* simulation time it went down */
};

static int glfw_users;

static double wall_now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + (double)ts.tv_nsec * 1e-9;
}

static void orbit_reset(scene_orbit_t *o)
{
    o->dyaw_rad = o->dpitch_rad = 0;
    o->zoom = 1;
}

view_t *view_new(const view_opts_t *o)
{
    view_t *v = calloc(1, sizeof *v);
    if (!v) return NULL;
    v->o = *o;
    v->camera = o->camera >= 1 && o->camera <= SCENE_CAMERAS ? o->camera : SCENE_BIRD;
    v->speed = o->speed >= 1 && o->speed <= VIEW_SPEED_MAX ? o->speed : 1;
    v->overlay = 1;
    for (int i = 0; i <= SCENE_CAMERAS; i++) orbit_reset(&v->orbit[i]);
    snprintf(v->port, sizeof v->port, "%s", o->port ? o->port : "");
    if (o->baud > 0) snprintf(v->baud, sizeof v->baud, "%ld", o->baud); /* else empty: typed in */
    v->editing = -1;
    if (v->o.width <= 0) v->o.width = 1024;
    if (v->o.height <= 0) v->o.height = 720;
    return v;
}

int view_camera(const view_t *v) { return v->camera; }
double view_speed(const view_t *v) { return v->speed; }
int view_paused(const view_t *v) { return v->paused; }
int view_overlay(const view_t *v) { return v->overlay; }

static void resync(view_t *v)
{
    v->sim0 = v->rp ? v->rp_t : v->sim ? sim_time_s(v->sim) : 0;
    v->wall0 = wall_now();
}

void view_set_replay(view_t *v, replay_t *r)
{
    v->rp = r;
    v->sim = NULL;
    if (v->win) glfwSetWindowTitle(v->win, "mmview");
    v->rp_t = 0;
    v->paused = 0;
    resync(v);
}

void view_seek(view_t *v, double t_s)
{
    if (!v->rp) return;
    double end = replay_end_s(v->rp);
    v->rp_t = t_s < 0 ? 0 : t_s > end ? end : t_s;
    resync(v);
}

double view_time(const view_t *v) { return v->rp ? v->rp_t : v->sim ? sim_time_s(v->sim) : 0; }

/* One logged pose forward (dir 1) or back (-1), paused. */
static void replay_step(view_t *v, int dir)
{
    v->paused = 1;
    view_seek(v, replay_next_s(v->rp, v->rp_t, dir));
}

void view_button(view_t *v, sim_state_t *s, int button)
{
    if (v->rp) { /* replay: the run controls drive the log's clock */
        switch (button) {
        case HUD_BTN_PAUSE:
            if (v->paused && v->rp_t >= replay_end_s(v->rp)) view_seek(v, 0); /* play again from the start */
            v->paused = !v->paused;
            resync(v);
            return;
        case HUD_BTN_STEP: replay_step(v, 1); return;
        case HUD_BTN_CONNECT: snprintf(v->status, sizeof v->status, "replaying a log: no serial link"); return;
        default: break;
        }
    }
    switch (button) {
    case HUD_BTN_BIRD: case HUD_BTN_FOLLOW: case HUD_BTN_TOP: v->camera = button - HUD_BTN_BIRD + 1; break;
    case HUD_BTN_OVERLAY: v->overlay = !v->overlay; break;
    case HUD_BTN_SLOWER: if (v->speed > 1) v->speed /= 2; resync(v); break;
    case HUD_BTN_FASTER: if (v->speed < VIEW_SPEED_MAX) v->speed *= 2; resync(v); break;
    case HUD_BTN_PAUSE: v->paused = !v->paused; resync(v); break;
    case HUD_BTN_STEP: v->paused = 1; v->step_req = 1; break;
    case HUD_BTN_POST:
        if (v->rp) {
            v->rp->centre_post = !v->rp->centre_post;
            snprintf(v->status, sizeof v->status, "centre post %s", v->rp->centre_post ? "on" : "off");
        } else if (s) {
            world_set_centre_post(s->world, !world_has_centre_post(s->world));
            snprintf(v->status, sizeof v->status, "centre post %s", world_has_centre_post(s->world) ? "on" : "off");
        }
        break;
    case HUD_BTN_RESET:
        if (v->mms_reset) {
            *v->mms_reset = 1;
            snprintf(v->status, sizeof v->status, "reset pressed: waiting for the algorithm's ackReset");
        }
        break;
    case HUD_BTN_CONNECT: {
        char *end;
        long b = strtol(v->baud, &end, 10);
        v->editing = -1;
        if (!v->port[0]) snprintf(v->status, sizeof v->status, "type the serial port first (click the Port field)");
        else if (!v->baud[0] || *end || b < 50 || b > (long)SERIAL_BAUD_MAX)
            snprintf(v->status, sizeof v->status, "baud: 50 to %lu", (unsigned long)SERIAL_BAUD_MAX);
        else {
            v->connect_req = 1;
            snprintf(v->status, sizeof v->status, "connecting to %.60s at %ld baud", v->port, b);
        }
        break;
    }
    default: break;
    }
}

static double sim_now(const view_t *v) { return v->sim ? sim_time_s(v->sim) : 0; }

static void push_hand(view_t *v, view_hand_kind_t kind, unsigned switches)
{
    if (v->hands_len == VIEW_HANDS_MAX) return; /* a person cannot click that fast: dropped */
    view_hand_t *h = &v->hands[(v->hands_head + v->hands_len++) % VIEW_HANDS_MAX];
    h->kind = kind;
    h->switches = switches;
}

/* A click on the board's control c (HUD_BOARD_*). */
static void board_click(view_t *v, int c)
{
    if (c >= HUD_BOARD_SW0 && c <= HUD_BOARD_SW3) {
        unsigned now = v->sw_pending ? v->sw_want : v->board.switches;
        v->sw_want = (now ^ (1u << (c - HUD_BOARD_SW0))) & 15u;
        v->sw_pending = 1;
        push_hand(v, VIEW_HAND_SWITCHES, v->sw_want);
        snprintf(v->status, sizeof v->status, "switches %u", v->sw_want);
    } else if (c == HUD_BOARD_BUTTON) {
        push_hand(v, VIEW_HAND_BUTTON_DOWN, 0);
        v->btn_held = 1;
        v->btn_up_due = 0;
        v->btn_down_s = sim_now(v);
        snprintf(v->status, sizeof v->status, "button down");
    } else if (c == HUD_BOARD_RESET) {
        push_hand(v, VIEW_HAND_RESET, 0);
        snprintf(v->status, sizeof v->status, "reset pressed");
    }
}

int view_hands_request(view_t *v, view_hand_t *out)
{
    if (v->hands_len) {
        *out = v->hands[v->hands_head];
        v->hands_head = (v->hands_head + 1) % VIEW_HANDS_MAX;
        v->hands_len--;
        if (out->kind == VIEW_HAND_SWITCHES && out->switches == v->sw_want) v->sw_pending = 0;
        return 1;
    }
    if (v->btn_up_due && sim_now(v) >= v->btn_down_s + VIEW_BUTTON_MIN_S - 1e-9) {
        v->btn_up_due = 0;
        out->kind = VIEW_HAND_BUTTON_UP;
        out->switches = 0;
        snprintf(v->status, sizeof v->status, "button up");
        return 1;
    }
    return 0;
}

void view_set_board(view_t *v, view_board_fill_t *fill, void *ctx)
{
    v->board_fill = fill;
    v->board_ctx = ctx;
    memset(&v->board, 0, sizeof v->board);
}

int view_click(view_t *v, sim_state_t *s, double x, double y)
{
    if (s) v->sim = s;
    if (v->rp && hud_slider_hit(v->o.width, v->o.height, x, y)) {
        v->rp_drag = 1;
        view_seek(v, hud_slider_time(v->o.width, v->o.height, x, replay_end_s(v->rp)));
        return VIEW_SLIDER;
    }
    int f = v->link_ok && !v->rp ? hud_field_hit(v->o.width, v->o.height, x, y) : -1;
    if (f >= 0) {
        v->editing = f;
        return VIEW_FIELD + f;
    }
    v->editing = -1;
    int c = v->board_fill && !v->rp ? hud_board_hit(v->o.width, v->o.height, x, y) : -1;
    if (c >= 0) {
        board_click(v, c);
        return VIEW_BOARD + c;
    }
    int b = hud_hit(v->o.width, v->o.height, x, y);
    if ((b == HUD_BTN_CONNECT && (!v->link_ok || v->rp)) || (b == HUD_BTN_RESET && !v->mms_reset)) b = -1; /* not shown */
    if (b >= 0) {
        view_button(v, s, b);
    } else { /* on the scene: a drag from here orbits the current camera */
        v->dragging = 1;
        v->drag_x = x;
        v->drag_y = y;
    }
    return b;
}

void view_drag(view_t *v, double x, double y)
{
    if (v->rp && v->rp_drag) view_seek(v, hud_slider_time(v->o.width, v->o.height, x, replay_end_s(v->rp)));
    if (!v->dragging) return;
    scene_orbit_t *o = &v->orbit[v->camera];
    o->dyaw_rad -= (x - v->drag_x) * DRAG_RAD_PER_PX;
    o->dpitch_rad += (y - v->drag_y) * DRAG_RAD_PER_PX;
    if (o->dpitch_rad > DPITCH_MAX_RAD) o->dpitch_rad = DPITCH_MAX_RAD;
    if (o->dpitch_rad < -DPITCH_MAX_RAD) o->dpitch_rad = -DPITCH_MAX_RAD;
    v->drag_x = x;
    v->drag_y = y;
}

void view_release(view_t *v)
{
    if (v->btn_held) { /* BUTTON up now, or once it has been down VIEW_BUTTON_MIN_S */
        v->btn_held = 0;
        if (sim_now(v) >= v->btn_down_s + VIEW_BUTTON_MIN_S - 1e-9) {
            push_hand(v, VIEW_HAND_BUTTON_UP, 0);
            snprintf(v->status, sizeof v->status, "button up");
        } else {
            v->btn_up_due = 1;
        }
    }
    v->rp_drag = 0;
    v->dragging = 0;
}

void view_scroll(view_t *v, double dy)
{
    scene_orbit_t *o = &v->orbit[v->camera];
    o->zoom *= pow(ZOOM_PER_NOTCH, dy);
    if (o->zoom < ZOOM_MIN) o->zoom = ZOOM_MIN;
    if (o->zoom > ZOOM_MAX) o->zoom = ZOOM_MAX;
}

const scene_orbit_t *view_orbit(const view_t *v) { return &v->orbit[v->camera]; }

void view_char(view_t *v, unsigned codepoint)
{
    if (v->editing < 0 || codepoint <= ' ' || codepoint > '~') return; /* printable ASCII, no spaces */
    char *buf = v->editing == HUD_FIELD_PORT ? v->port : v->baud;
    size_t cap = v->editing == HUD_FIELD_PORT ? sizeof v->port : sizeof v->baud, n = strlen(buf);
    if (v->editing == HUD_FIELD_BAUD && (codepoint < '0' || codepoint > '9')) return;
    if (n + 1 < cap) {
        buf[n] = (char)codepoint;
        buf[n + 1] = '\0';
    }
}

int view_connect_request(view_t *v, const char **port, long *baud)
{
    if (!v->connect_req) return 0;
    v->connect_req = 0;
    *port = v->port;
    *baud = strtol(v->baud, NULL, 10);
    return 1;
}

void view_set_status(view_t *v, const char *text) { snprintf(v->status, sizeof v->status, "%s", text ? text : ""); }

void view_key(view_t *v, sim_state_t *s, int key)
{
    if (v->editing >= 0) { /* typing in a field: the characters come through view_char */
        char *buf = v->editing == HUD_FIELD_PORT ? v->port : v->baud;
        size_t n = strlen(buf);
        switch (key) {
        case GLFW_KEY_BACKSPACE: if (n) buf[n - 1] = '\0'; break;
        case GLFW_KEY_TAB: v->editing = v->editing == HUD_FIELD_PORT ? HUD_FIELD_BAUD : HUD_FIELD_PORT; break;
        case GLFW_KEY_ENTER: case GLFW_KEY_KP_ENTER: view_button(v, s, HUD_BTN_CONNECT); break;
        case GLFW_KEY_ESCAPE: v->editing = -1; break;
        default: break;
        }
        return;
    }
    if (v->rp) {
        switch (key) {
        case GLFW_KEY_COMMA: replay_step(v, -1); return;
        case GLFW_KEY_LEFT: view_seek(v, v->rp_t - 1); return;
        case GLFW_KEY_RIGHT: view_seek(v, v->rp_t + 1); return;
        case GLFW_KEY_HOME: view_seek(v, 0); return;
        case GLFW_KEY_END: view_seek(v, replay_end_s(v->rp)); return;
        default: break;
        }
    }
    switch (key) {
    case GLFW_KEY_1: case GLFW_KEY_KP_1: view_button(v, s, HUD_BTN_BIRD); break;
    case GLFW_KEY_2: case GLFW_KEY_KP_2: view_button(v, s, HUD_BTN_FOLLOW); break;
    case GLFW_KEY_3: case GLFW_KEY_KP_3: view_button(v, s, HUD_BTN_TOP); break;
    case GLFW_KEY_O: view_button(v, s, HUD_BTN_OVERLAY); break;
    case GLFW_KEY_SPACE: view_button(v, s, HUD_BTN_PAUSE); break;
    case GLFW_KEY_S: case GLFW_KEY_PERIOD: view_button(v, s, HUD_BTN_STEP); break;
    case GLFW_KEY_EQUAL: case GLFW_KEY_KP_ADD: view_button(v, s, HUD_BTN_FASTER); break;
    case GLFW_KEY_MINUS: case GLFW_KEY_KP_SUBTRACT: view_button(v, s, HUD_BTN_SLOWER); break;
    case GLFW_KEY_P: view_button(v, s, HUD_BTN_POST); break;
    case GLFW_KEY_X: view_button(v, s, HUD_BTN_RESET); break;
    case GLFW_KEY_R: orbit_reset(&v->orbit[v->camera]); break;
    case GLFW_KEY_ESCAPE: case GLFW_KEY_Q: v->closed = 1; break;
    default: break;
    }
}

/* ---- GLFW callbacks ---- */

static void on_key(GLFWwindow *w, int key, int scancode, int action, int mods)
{
    (void)scancode, (void)mods;
    view_t *v = glfwGetWindowUserPointer(w);
    if (action == GLFW_PRESS || action == GLFW_REPEAT) view_key(v, v->sim, key);
}

static void on_char(GLFWwindow *w, unsigned codepoint)
{
    view_char(glfwGetWindowUserPointer(w), codepoint);
}

static void on_button(GLFWwindow *w, int button, int action, int mods)
{
    (void)mods;
    view_t *v = glfwGetWindowUserPointer(w);
    if (button != GLFW_MOUSE_BUTTON_LEFT) return;
    double x, y;
    glfwGetCursorPos(w, &x, &y);
    if (action == GLFW_PRESS)
        view_click(v, v->sim, x, y);
    else
        view_release(v);
}

static void on_cursor(GLFWwindow *w, double x, double y)
{
    view_drag(glfwGetWindowUserPointer(w), x, y);
}

static void on_scroll(GLFWwindow *w, double dx, double dy)
{
    (void)dx;
    view_scroll(glfwGetWindowUserPointer(w), dy);
}

static void on_size(GLFWwindow *w, int width, int height)
{
    view_t *v = glfwGetWindowUserPointer(w);
    v->o.width = width;
    v->o.height = height;
}

/* What to do when there is no display to open: a headless machine runs the
 * viewer under a virtual X server. */
static const char *no_display_hint(void)
{
    const char *d = getenv("DISPLAY"), *w = getenv("WAYLAND_DISPLAY");
    return (d && *d) || (w && *w) ? "" : " (no display: DISPLAY is not set; run it under xvfb-run -a, e.g. xvfb-run -a build/mmsim ...)";
}

int view_open(view_t *v, int visible, char *err, size_t errlen)
{
    if (glfw_users == 0 && !glfwInit()) {
        const char *d = NULL;
        glfwGetError(&d);
        snprintf(err, errlen, "cannot start the viewer: %s%s", d ? d : "GLFW init failed", no_display_hint());
        return -1;
    }
    glfw_users++;
    glfwDefaultWindowHints();
    glfwWindowHint(GLFW_VISIBLE, visible ? GLFW_TRUE : GLFW_FALSE);
    glfwWindowHint(GLFW_RESIZABLE, visible ? GLFW_TRUE : GLFW_FALSE);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 2);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 1);
    glfwWindowHint(GLFW_DEPTH_BITS, 24);
    v->win = glfwCreateWindow(v->o.width, v->o.height, "mmsim", NULL, NULL);
    if (!v->win) {
        const char *d = NULL;
        glfwGetError(&d);
        snprintf(err, errlen, "cannot open the viewer window: %s%s", d ? d : "unknown GLFW error", no_display_hint());
        if (--glfw_users == 0) glfwTerminate();
        return -1;
    }
    glfwMakeContextCurrent(v->win);
    glfwSwapInterval(0); /* pacing is ours */
    glfwSetWindowUserPointer(v->win, v);
    glfwSetKeyCallback(v->win, on_key);
    glfwSetCharCallback(v->win, on_char);
    glfwSetMouseButtonCallback(v->win, on_button);
    glfwSetCursorPosCallback(v->win, on_cursor);
    glfwSetScrollCallback(v->win, on_scroll);
    glfwSetWindowSizeCallback(v->win, on_size);
    glfwGetWindowSize(v->win, &v->o.width, &v->o.height);
    return 0;
}

void view_free(view_t *v)
{
    if (!v) return;
    if (v->win) {
        glfwDestroyWindow(v->win);
        if (--glfw_users == 0) glfwTerminate();
    }
    free(v);
}

/* The overlay's message: only where a map can come (an in-process
 * firmware that publishes one, or a log that holds one), none yet. */
static const char *status_text(const view_t *v, const scene_belief_t *b)
{
    if (v->status[0]) return v->status;
    int can_map = v->rp ? v->rp->nbelief > 0 : v->belief != NULL;
    return v->overlay && can_map && !b->map ? "no mouse map to overlay yet" : NULL;
}

/* One frame of the live run s, or of the replay at its time (s NULL): the
 * scene in its rectangle, then the HUD over the rest. */
static void draw(view_t *v, sim_state_t *s)
{
    int fw, fh;
    glfwGetFramebufferSize(v->win, &fw, &fh);
    scene_belief_t b = { NULL, 0, 0, -1 };
    const sim_belief_t *hb = v->belief;
    static snap_t snap; /* what this frame draws */
    const sim_model_t *model;
    const truemaze_t *maze;
    if (v->rp) {
        replay_snap(v->rp, v->rp_t, &snap);
        model = &v->rp->model;
        maze = &v->rp->maze;
        replay_belief(v->rp, v->rp_t, &b);
    } else {
        snap_from_sim(&snap, s);
        model = s->model;
        maze = s->maze;
        if (hb && hb->seq) { /* the overlay once the firmware has reported a belief */
            b.map = &hb->map;
            b.cell = hb->cell;
            b.heading = hb->heading;
            b.state = hb->state;
        }
    }
    int board = v->board_fill && !v->rp;
    hud_button_t sc; /* the scene's rectangle, window pixels from the top left; GL's from the bottom left */
    hud_scene_rect(v->o.width, v->o.height, board, &sc);
    double kx = (double)fw / v->o.width, ky = (double)fh / v->o.height;
    int vx = (int)lround(sc.x * kx), vw = (int)lround(sc.w * kx), vh = (int)lround(sc.h * ky), vy = fh - vh;
    scene_draw(model, maze, &snap, v->camera, &v->orbit[v->camera], &b, v->overlay, vx, vy, vw, vh);
    if (v->mms_colours)
        scene_draw_cells(model, maze, &snap, v->camera, &v->orbit[v->camera], v->mms_colours, v->mms_texts, v->mms_stride);
    hud_info_t in = { v->camera, v->overlay, v->paused, v->speed, v->port, v->o.baud, status_text(v, &b), v->rp != NULL,
                      v->rp_t, v->rp ? replay_end_s(v->rp) : 0, v->editing, v->baud,
                      v->mms_reset != NULL, NULL, v->link_ok && !v->rp, b.state, snap.v_m_s };
    if (board) { /* the board as it is now, and what the person's hands asked for */
        v->board_fill(v->board_ctx, &v->board);
        view_board_t shown = v->board;
        if (v->sw_pending) shown.switches = v->sw_want;
        shown.button = shown.button || v->btn_held;
        in.board = &shown;
        hud_draw(&snap, &in, v->o.width, v->o.height);
        return;
    }
    hud_draw(&snap, &in, v->o.width, v->o.height);
}

static void frame(view_t *v, sim_state_t *s)
{
    draw(v, s);
    glfwSwapBuffers(v->win);
    v->next_frame = wall_now() + FRAME_S;
}

int view_step(view_t *v, sim_state_t *s)
{
    if (!v->win) return 0;
    if (v->sim != s) {
        v->sim = s;
        resync(v);
    }
    if (v->closed) return 1;
    double now = wall_now();
    if (!v->paused && !v->step_req && sim_time_s(s) < v->sim0 + (now - v->wall0) * v->speed && now < v->next_frame)
        return 0; /* behind the wall clock and no frame due: keep stepping */
    for (;;) {
        now = wall_now();
        if (now >= v->next_frame) frame(v, s);
        glfwPollEvents();
        if (glfwWindowShouldClose(v->win)) v->closed = 1;
        if (v->closed) return 1;
        if (v->step_req) {
            v->step_req = 0;
            resync(v);
            return 0; /* one physics step */
        }
        if (v->paused) {
            glfwWaitEventsTimeout(FRAME_S);
            resync(v);
            continue;
        }
        double target = v->sim0 + (now - v->wall0) * v->speed, t = sim_time_s(s);
        if (target - t > MAX_LAG_S) { /* cannot keep up: drop the backlog */
            resync(v);
            return 0;
        }
        if (t < target) return 0;
        double wait = (t - target) / v->speed, to_frame = v->next_frame - now;
        if (to_frame < wait) wait = to_frame;
        if (wait > 0) glfwWaitEventsTimeout(wait);
    }
}

void view_hold(view_t *v, sim_state_t *s)
{
    if (!v->win) return;
    v->sim = s;
    if (!v->status[0]) snprintf(v->status, sizeof v->status, "run over: close the window to exit");
    while (!v->closed && !glfwWindowShouldClose(v->win)) {
        frame(v, s);
        glfwWaitEventsTimeout(FRAME_S * 4);
        v->step_req = 0;
    }
    v->closed = 1;
}

void view_play(view_t *v)
{
    if (!v->win || !v->rp) return;
    resync(v);
    while (!v->closed && !glfwWindowShouldClose(v->win)) {
        if (!v->paused && !v->rp_drag) {
            double end = replay_end_s(v->rp), t = v->sim0 + (wall_now() - v->wall0) * v->speed;
            if (t >= end) {
                t = end;
                v->paused = 1;
            }
            v->rp_t = t < 0 ? 0 : t;
        }
        frame(v, NULL);
        /* a frame's time, or until the user acts when paused */
        if (v->paused) glfwWaitEventsTimeout(FRAME_S * 4);
        else glfwWaitEventsTimeout(FRAME_S);
        v->step_req = 0;
    }
    v->closed = 1;
}

int view_screenshot(view_t *v, sim_state_t *s, const char *path, char *err, size_t errlen)
{
    if (!v->win) {
        snprintf(err, errlen, "%s: no viewer window", path);
        return -1;
    }
    v->sim = s;
    err[0] = '\0';
    int fw, fh;
    glfwGetFramebufferSize(v->win, &fw, &fh);
    glDrawBuffer(GL_BACK);
    draw(v, s);
    glFinish();
    uint8_t *px = malloc((size_t)fw * (size_t)fh * 3);
    if (!px) {
        snprintf(err, errlen, "%s: out of memory", path);
        return -1;
    }
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadBuffer(GL_BACK);
    glReadPixels(0, 0, fw, fh, GL_RGB, GL_UNSIGNED_BYTE, px);
    int rc = glGetError() == GL_NO_ERROR ? image_write_png_rows(px, fw, fh, 1, path, err, errlen) : -1;
    if (rc != 0 && !err[0]) snprintf(err, errlen, "%s: cannot read the frame back from OpenGL", path);
    free(px);
    return rc;
}

void view_set_belief(view_t *v, const sim_belief_t *b) { v->belief = b; }

void view_set_link_ok(view_t *v, int ok) { v->link_ok = ok != 0; }

void view_set_mms(view_t *v, const char *colours, const char *texts, size_t text_stride, int *reset)
{
    v->mms_colours = colours;
    v->mms_texts = texts;
    v->mms_stride = text_stride;
    v->mms_reset = reset;
}

/* test_view.c - the viewer's UI actions without a window: the "Toggle
 * post" button adds and removes the centre post in the physics world (a
 * ray across the centre hits it or not), camera keys and buttons, speed
 * limits, pause and single step; the HUD timers (from the run's snapshot)
 * turn over-time after the limit; the port and baud fields and Connect; a board's panel (switches,
 * Button, Reset as requests; the console's last rows). */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <cmocka.h>

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "world/config.h"
#include "view/hud.h"
#include "view/scene.h"
#include "view/snap.h"
#include "world/sim.h"
#include "view/view.h"

static truemaze_t maze;
static sim_state_t sim;
static view_t *view;
static const view_opts_t opts = { 800, 600, 1, 1, "", 115200 };

static int setup(void **state)
{
    (void)state;
    static simcfg_t c; /* the sim's model reads it */
    config_defaults(&c);
    truemaze_init(&maze, 4, 4); /* even size: a post at the centre (2, 2) */
    for (uint16_t k = 0; k < 16; k++) /* open every inner wall so only posts stand */
        for (uint8_t d = 0; d < 4; d++) truemaze_set_wall(&maze, (truemaze_cell_t)k, d, 0);
    static sim_model_t sim_model;
    sim_model_build(&sim_model, &c, 1);
    if (sim_init(&sim, &sim_model, &maze, 1) != 0) return -1;
    view = view_new(&opts);
    return view ? 0 : -1;
}

static int teardown(void **state)
{
    (void)state;
    view_free(view);
    sim_free(&sim);
    return 0;
}

/* A diagonal ray from the centre of cell (1,1) to the north-east: meets
 * the centre post (at (2,2) cells) corner first, or runs on to the post at
 * (3,3). */
static double ray_across_centre(void)
{
    double cell = sim.model->cfg->world.cell_m;
    return world_ray(sim.world, 1.5 * cell, 1.5 * cell, 0.02, M_PI / 4, 1.0);
}

/* The live run's snapshot now, as the viewer draws it. */
static const snap_t *now(void)
{
    static snap_t snap;
    snap_from_sim(&snap, &sim);
    return &snap;
}

static void click_button(int b)
{
    hud_button_t bt[HUD_BTN_COUNT];
    hud_layout(opts.width, opts.height, bt);
    assert_int_equal(view_click(view, &sim, bt[b].x + bt[b].w / 2.0, bt[b].y + bt[b].h / 2.0), b);
}

static void test_toggle_post_button(void **state)
{
    (void)state;
    double cell = sim.model->cfg->world.cell_m, half = sim.model->cfg->world.post_m / 2;
    assert_true(world_has_centre_post(sim.world));
    assert_true(fabs(ray_across_centre() - M_SQRT2 * (0.5 * cell - half)) < 0.001);
    assert_true(now()->centre_post);
    click_button(HUD_BTN_POST);
    assert_false(world_has_centre_post(sim.world));
    assert_false(now()->centre_post); /* the scene draws what the world has */
    assert_true(fabs(ray_across_centre() - M_SQRT2 * (1.5 * cell - half)) < 0.001); /* the next post */
    view_key(view, &sim, GLFW_KEY_P);
    assert_true(world_has_centre_post(sim.world));
    assert_true(fabs(ray_across_centre() - M_SQRT2 * (0.5 * cell - half)) < 0.001);
    /* a click on no button does nothing */
    assert_int_equal(view_click(view, &sim, opts.width / 2.0, opts.height / 2.0), -1);
    assert_true(world_has_centre_post(sim.world));
}

static void test_cameras(void **state)
{
    (void)state;
    assert_int_equal(view_camera(view), 1);
    view_key(view, &sim, GLFW_KEY_2);
    assert_int_equal(view_camera(view), 2);
    view_key(view, &sim, GLFW_KEY_3);
    assert_int_equal(view_camera(view), 3);
    click_button(HUD_BTN_BIRD);
    assert_int_equal(view_camera(view), 1);
    click_button(HUD_BTN_FOLLOW);
    assert_int_equal(view_camera(view), 2);
    int on = view_overlay(view);
    click_button(HUD_BTN_OVERLAY);
    assert_int_equal(view_overlay(view), !on);
}

#define assert_near(a, b, eps) assert_true(fabs((double)(a) - (double)(b)) <= (eps))

static double dist3(const double a[3], const double b[3])
{
    return sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) + (a[2] - b[2]) * (a[2] - b[2]));
}

/* Drag on the scene orbits the current camera about its target, scroll
 * zooms it, R resets it; the other cameras keep their own orbits. */
static void test_orbit_zoom(void **state)
{
    (void)state;
    double eye0[3], eye[3], tgt0[3], tgt[3], up[3];
    view_key(view, &sim, GLFW_KEY_1);
    scene_camera(sim.model, &maze, now(), 1, view_orbit(view), eye0, tgt0, up);
    double d0 = dist3(eye0, tgt0);
    /* a drag of 100 px to the right and 20 px down, starting on the scene */
    assert_int_equal(view_click(view, &sim, opts.width / 2.0, opts.height / 2.0), -1);
    view_drag(view, opts.width / 2.0 + 50, opts.height / 2.0 + 10);
    view_drag(view, opts.width / 2.0 + 100, opts.height / 2.0 + 20);
    view_release(view);
    assert_near(view_orbit(view)->dyaw_rad, -0.8, 1e-9);
    assert_near(view_orbit(view)->dpitch_rad, 0.16, 1e-9);
    scene_camera(sim.model, &maze, now(), 1, view_orbit(view), eye, tgt, up);
    assert_near(dist3(tgt, tgt0), 0, 1e-9);       /* orbit about the same target */
    assert_near(dist3(eye, tgt), d0, 1e-6 * d0);   /* at the same distance */
    assert_true(dist3(eye, eye0) > 0.1 * d0);              /* from elsewhere */
    view_drag(view, 0, 0); /* released: moving the mouse does nothing */
    assert_near(view_orbit(view)->dyaw_rad, -0.8, 1e-9);
    /* three notches in: 0.9^3 of the distance; the limit holds */
    view_scroll(view, 3);
    scene_camera(sim.model, &maze, now(), 1, view_orbit(view), eye, tgt, up);
    assert_near(dist3(eye, tgt), d0 * 0.729, 1e-6 * d0);
    view_scroll(view, -1000);
    assert_near(view_orbit(view)->zoom, 10.0, 1e-9);
    /* a drag that starts on a button does not orbit */
    click_button(HUD_BTN_OVERLAY);
    view_drag(view, 0, 0);
    view_release(view);
    view_key(view, &sim, GLFW_KEY_O); /* the overlay back as it was */
    assert_near(view_orbit(view)->dyaw_rad, -0.8, 1e-9);
    /* camera 2 has its own orbit; R resets only the current one */
    view_key(view, &sim, GLFW_KEY_2);
    assert_near(view_orbit(view)->zoom, 1.0, 0);
    assert_near(view_orbit(view)->dyaw_rad, 0, 0);
    view_key(view, &sim, GLFW_KEY_1);
    view_key(view, &sim, GLFW_KEY_R);
    assert_near(view_orbit(view)->zoom, 1.0, 0);
    assert_near(view_orbit(view)->dyaw_rad, 0, 0);
    scene_camera(sim.model, &maze, now(), 1, view_orbit(view), eye, tgt, up);
    assert_near(dist3(eye, eye0), 0, 1e-9);
}

static void test_speed_pause_step(void **state)
{
    (void)state;
    for (int i = 0; i < 10; i++) view_key(view, &sim, GLFW_KEY_EQUAL);
    assert_true(view_speed(view) == VIEW_SPEED_MAX);
    click_button(HUD_BTN_SLOWER);
    assert_true(view_speed(view) == VIEW_SPEED_MAX / 2);
    for (int i = 0; i < 10; i++) view_key(view, &sim, GLFW_KEY_MINUS);
    assert_true(view_speed(view) == 1);
    assert_false(view_paused(view));
    view_key(view, &sim, GLFW_KEY_SPACE);
    assert_true(view_paused(view));
    click_button(HUD_BTN_PAUSE);
    assert_false(view_paused(view));
    click_button(HUD_BTN_STEP); /* a step pauses */
    assert_true(view_paused(view));
    /* without a window, view_step never blocks */
    assert_int_equal(view_step(view, &sim), 0);
}

static void test_hud_timers(void **state)
{
    (void)state;
    char g[16], l[16];
    int over;
    hud_timers(now(), g, l, &over);
    assert_string_equal(g, "0:00.000");
    assert_false(over);
    sim.race.started = 1;
    sim.race.global_start_s = 0;
    sim.step = (uint64_t)llround((sim.race.limit_s + 1.5) / sim.model->cfg->sim.step_s);
    hud_timers(now(), g, l, &over);
    assert_true(over);
    sim.step = 0;
    sim.race.started = 0;
}

/* The port and baud fields take typing (not the viewer's keys) and
 * Connect hands a valid pair to the caller once. */
static void test_connect_fields(void **state)
{
    (void)state;
    const char *port;
    long baud;
    hud_button_t f[HUD_FIELDS];
    hud_fields(opts.width, opts.height, f);
    hud_button_t bt[HUD_BTN_COUNT];
    hud_layout(opts.width, opts.height, bt);
    /* no link can be made (the default, and any replay): neither Connect nor the fields take clicks */
    assert_int_equal(view_click(view, &sim, bt[HUD_BTN_CONNECT].x + 5.0, bt[HUD_BTN_CONNECT].y + 5.0), -1);
    view_release(view);
    assert_int_equal(view_click(view, &sim, f[0].x + 5.0, f[0].y + 5.0), -1);
    view_release(view);
    view_set_link_ok(view, 1);
    /* no port yet: Connect only says so */
    click_button(HUD_BTN_CONNECT);
    assert_int_equal(view_connect_request(view, &port, &baud), 0);
    assert_int_equal(view_click(view, &sim, f[0].x + 5.0, f[0].y + 5.0), VIEW_FIELD + HUD_FIELD_PORT);
    int cam = view_camera(view);
    for (const char *c = "/dev/ttyq1"; *c; c++) view_char(view, (unsigned char)*c);
    view_key(view, &sim, GLFW_KEY_2); /* a key while typing: not the camera */
    view_key(view, &sim, GLFW_KEY_Q); /* nor quit */
    assert_int_equal(view_camera(view), cam);
    view_char(view, 'X');
    view_key(view, &sim, GLFW_KEY_BACKSPACE);
    view_key(view, &sim, GLFW_KEY_TAB); /* to the baud field: digits only */
    for (int i = 0; i < 6; i++) view_key(view, &sim, GLFW_KEY_BACKSPACE);
    for (const char *c = "5x7600"; *c; c++) view_char(view, (unsigned char)*c);
    view_key(view, &sim, GLFW_KEY_ENTER); /* Enter = Connect */
    assert_int_equal(view_connect_request(view, &port, &baud), 1);
    assert_string_equal(port, "/dev/ttyq1");
    assert_int_equal(baud, 57600);
    assert_int_equal(view_connect_request(view, &port, &baud), 0); /* once */
    /* a bad baud is refused */
    assert_int_equal(view_click(view, &sim, f[1].x + 5.0, f[1].y + 5.0), VIEW_FIELD + HUD_FIELD_BAUD);
    for (int i = 0; i < 6; i++) view_key(view, &sim, GLFW_KEY_BACKSPACE);
    view_char(view, '9');
    view_key(view, &sim, GLFW_KEY_ESCAPE); /* done typing */
    click_button(HUD_BTN_CONNECT);
    assert_int_equal(view_connect_request(view, &port, &baud), 0);
    /* keys work again after Esc */
    view_key(view, &sim, GLFW_KEY_3);
    assert_int_equal(view_camera(view), 3);
    view_key(view, &sim, GLFW_KEY_1);
    view_set_link_ok(view, 0);
}

/* mms runs: the Reset button (and X) set the algorithm's wasReset flag;
 * it sits clear of every other button */
static void test_mms_reset_button(void **state)
{
    (void)state;
    int reset = 0;
    char colours[TRUEMAZE_MAX_CELLS] = { 0 };
    view_key(view, &sim, GLFW_KEY_X); /* no mms run: nothing to press */
    view_set_mms(view, colours, NULL, 0, &reset);
    click_button(HUD_BTN_RESET);
    assert_int_equal(reset, 1);
    reset = 0;
    view_key(view, &sim, GLFW_KEY_X);
    assert_int_equal(reset, 1);
    hud_button_t bt[HUD_BTN_COUNT];
    hud_layout(opts.width, opts.height, bt);
    for (int i = 0; i < HUD_BTN_RESET; i++)
        assert_true(bt[i].x + bt[i].w <= bt[HUD_BTN_RESET].x || bt[HUD_BTN_RESET].x + bt[HUD_BTN_RESET].w <= bt[i].x ||
                    bt[i].y + bt[i].h <= bt[HUD_BTN_RESET].y || bt[HUD_BTN_RESET].y + bt[HUD_BTN_RESET].h <= bt[i].y);
    view_set_mms(view, NULL, NULL, 0, NULL);
}

static int fills;
static void fill_board(void *ctx, view_board_t *out)
{
    (void)ctx;
    memset(out, 0, sizeof *out);
    fills++;
}

static void click_board(int c)
{
    hud_board_layout_t l;
    hud_board_layout(opts.width, opts.height, &l);
    assert_int_equal(view_click(view, &sim, l.ctl[c].x + l.ctl[c].w / 2.0, l.ctl[c].y + l.ctl[c].h / 2.0), VIEW_BOARD + c);
}

static void want_hand(view_hand_kind_t kind, unsigned switches)
{
    view_hand_t h;
    assert_int_equal(view_hands_request(view, &h), 1);
    assert_int_equal(h.kind, kind);
    if (kind == VIEW_HAND_SWITCHES) assert_int_equal(h.switches, switches);
}

/* A board's panel: switch k toggles bit k (two clicks before the run takes
 * them add up), Button is down while held and at least 0.1 s of simulation
 * time, Reset; without a board the panel takes no clicks */
static void test_board_panel(void **state)
{
    (void)state;
    view_hand_t h;
    hud_board_layout_t l;
    hud_board_layout(opts.width, opts.height, &l);
    /* where test/cli/cli_view_board.sh clicks in an 800x600 window */
    assert_int_equal(l.ctl[HUD_BOARD_SW0].x, 8), assert_int_equal(l.ctl[HUD_BOARD_SW0].y, 236);
    assert_int_equal(l.ctl[HUD_BOARD_SW0].w, 28), assert_int_equal(l.ctl[HUD_BOARD_BUTTON].x, 140);
    assert_int_equal(l.rows, HUD_CONSOLE_LINES);
    /* clear of the HUD's buttons (the fields and Connect share the place but
     * are never shown with a board: no link can be made there) */
    for (int i = 0; i < HUD_BOARD_COUNT; i++) {
        int b = hud_hit(opts.width, opts.height, l.ctl[i].x + 1, l.ctl[i].y + 1);
        assert_true(b == -1 || b == HUD_BTN_CONNECT);
    }
    assert_int_equal(view_click(view, &sim, l.ctl[0].x + 5, l.ctl[0].y + 5), -1); /* no board: the scene */
    view_release(view);
    assert_int_equal(view_hands_request(view, &h), 0);
    view_set_board(view, fill_board, NULL);
    click_board(HUD_BOARD_SW1);
    click_board(HUD_BOARD_SW0);
    click_board(HUD_BOARD_SW1);
    want_hand(VIEW_HAND_SWITCHES, 2);
    want_hand(VIEW_HAND_SWITCHES, 3);
    want_hand(VIEW_HAND_SWITCHES, 1);
    click_board(HUD_BOARD_RESET);
    want_hand(VIEW_HAND_RESET, 0);
    assert_int_equal(view_hands_request(view, &h), 0);
    /* a click: down now, up 0.1 s later */
    double t0 = sim_time_s(&sim);
    click_board(HUD_BOARD_BUTTON);
    view_release(view);
    want_hand(VIEW_HAND_BUTTON_DOWN, 0);
    while (sim_time_s(&sim) < t0 + 0.099) {
        assert_int_equal(view_hands_request(view, &h), 0);
        sim_step(sim.model, &sim);
    }
    while (sim_time_s(&sim) < t0 + 0.1 - 1e-9) sim_step(sim.model, &sim);
    want_hand(VIEW_HAND_BUTTON_UP, 0);
    /* held: up when released */
    click_board(HUD_BOARD_BUTTON);
    want_hand(VIEW_HAND_BUTTON_DOWN, 0);
    for (int i = 0; i < 300; i++) sim_step(sim.model, &sim);
    assert_int_equal(view_hands_request(view, &h), 0);
    view_release(view);
    want_hand(VIEW_HAND_BUTTON_UP, 0);
    assert_int_equal(fills, 0); /* no window, no frame: the board is never read */
    view_set_board(view, NULL, NULL);
}

/* the console's last rows: CRs dropped, long lines wrapped, odd bytes as '?' */
static void test_console_rows(void **state)
{
    (void)state;
    char rows[HUD_CONSOLE_LINES][129];
    const char *c = "one\r\ntwo\r\nthree-long\r\n";
    assert_int_equal(hud_console_rows(c, strlen(c), 5, 3, rows), 3);
    assert_string_equal(rows[0], "two"), assert_string_equal(rows[1], "three"), assert_string_equal(rows[2], "-long");
    c = "a\tb\x01\nlast";
    assert_int_equal(hud_console_rows(c, strlen(c), 10, 12, rows), 2);
    assert_string_equal(rows[0], "a b?"), assert_string_equal(rows[1], "last");
    assert_int_equal(hud_console_rows("", 0, 10, 12, rows), 0);
    assert_int_equal(hud_console_rows("\n\n", 2, 10, 12, rows), 2); /* two empty lines */
    assert_string_equal(rows[0], ""), assert_string_equal(rows[1], "");
    static char big[10000]; /* one long line */
    memset(big, 'x', sizeof big - 1);
    big[sizeof big - 2] = 'y';
    assert_int_equal(hud_console_rows(big, strlen(big), 40, 12, rows), 12);
    assert_int_equal((int)strlen(rows[11]), (int)((sizeof big - 1) % 40 ? (sizeof big - 1) % 40 : 40));
}

static int apart(const hud_button_t *a, const hud_button_t *b)
{
    return a->x + a->w <= b->x || b->x + b->w <= a->x || a->y + a->h <= b->y || b->y + b->h <= a->y;
}

/* The 3D scene's rectangle never meets a HUD control: the buttons shown,
 * the fields and Connect (no board), the board's controls, LEDs and
 * console, the replay's slider; in every window size and kind of run */
static void test_scene_apart(void **state)
{
    (void)state;
    static const int size[][2] = { { 800, 600 }, { 1024, 720 }, { 320, 240 }, { 1920, 1080 } };
    for (size_t z = 0; z < sizeof size / sizeof size[0]; z++)
        for (int kind = 0; kind < 8; kind++) {
            int W = size[z][0], H = size[z][1], board = kind & 1, replay = kind >> 1 & 1, mms = kind >> 2 & 1;
            hud_button_t sc, bt[HUD_BTN_COUNT], f[HUD_FIELDS], sl;
            hud_scene_rect(W, H, board, &sc);
            assert_true(sc.x >= hud_panel_w(W, board) && sc.w > W / 2 && sc.h > H * 2 / 5); /* a 320x240 replay: 110 px high */
            hud_layout(W, H, bt);
            for (int i = 0; i < HUD_BTN_COUNT; i++)
                if ((i != HUD_BTN_RESET || mms) && (i != HUD_BTN_CONNECT || (!board && !replay))) assert_true(apart(&sc, &bt[i]));
            hud_fields(W, H, f);
            for (int i = 0; i < HUD_FIELDS && !board && !replay; i++) assert_true(apart(&sc, &f[i]));
            hud_slider(W, H, &sl);
            if (replay) assert_true(apart(&sc, &sl));
            if (!board) continue;
            hud_board_layout_t l;
            hud_board_layout(W, H, &l);
            for (int i = 0; i < HUD_BOARD_COUNT; i++) assert_true(apart(&sc, &l.ctl[i]));
            assert_true(apart(&sc, &l.leds) && apart(&sc, &l.console));
        }
}

/* The HUD's lap table: the latest laps, the best marked, a Best line */
static void test_lap_rows(void **state)
{
    (void)state;
    race_t r;
    char rows[HUD_LAP_ROWS + 2][32];
    memset(&r, 0, sizeof r);
    r.best = -1;
    assert_int_equal(hud_lap_rows(&r, rows), 2);
    assert_string_equal(rows[0], "Lap  Run time");
    assert_string_equal(rows[1], "Best -");
    for (int i = 0; i < 6; i++) r.laps[i] = (race_lap_t){ 10.0 * i, 10.0 * i + 7 + (i == 2 ? -1.5 : 0), 0 };
    r.nlaps = 6;
    r.best = 2;
    assert_int_equal(hud_lap_rows(&r, rows), HUD_LAP_ROWS + 2);
    assert_string_equal(rows[1], " 3  0:05.500 *");
    assert_string_equal(rows[4], " 6  0:07.000");
    assert_string_equal(rows[5], "Best 0:05.500");
}

/* The mms cell palette: every letter tinted, none close to the overlay's
 * discovered-wall colours (some channel more than 0x50 apart), the letters
 * told apart from each other */
static void test_cell_palette(void **state)
{
    (void)state;
    static const char letters[] = "kbacgorwyBCAGRY";
    static const uint32_t over[] = { SCENE_OVERLAY_WALL, SCENE_OVERLAY_WRONG };
    for (int i = 0; letters[i]; i++) {
        uint32_t c = scene_cell_rgb(letters[i]);
        assert_true(c != 0);
        for (int o = 0; o < 2; o++) {
            int far = 0;
            for (int sh = 0; sh <= 16; sh += 8) far |= abs((int)(c >> sh & 255) - (int)(over[o] >> sh & 255)) > 0x50;
            assert_true(far);
        }
        for (int j = 0; j < i; j++) assert_true(scene_cell_rgb(letters[j]) != c);
    }
    assert_int_equal(scene_cell_rgb(0), 0);
    assert_int_equal(scene_cell_rgb('z'), 0);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_toggle_post_button),
        cmocka_unit_test(test_cameras),
        cmocka_unit_test(test_orbit_zoom),
        cmocka_unit_test(test_speed_pause_step),
        cmocka_unit_test(test_hud_timers),
        cmocka_unit_test(test_connect_fields),
        cmocka_unit_test(test_mms_reset_button),
        cmocka_unit_test(test_board_panel),
        cmocka_unit_test(test_console_rows),
        cmocka_unit_test(test_scene_apart),
        cmocka_unit_test(test_lap_rows),
        cmocka_unit_test(test_cell_palette),
    };
    return cmocka_run_group_tests(tests, setup, teardown);
}

/* run_board.c - an AVR image on an emulated board (--board NAME --avr
 * FIRMWARE.elf|.hex, sim/board): the board file's MCU in simavr, in
 * lockstep with the physics, its pins and ADC wired to the robot. The run
 * lasts the time limit (or until the AVR stops); --watch reads its
 * variables (run_watch.c); --input's hands act on
 * its switches, button, reset and console; the JSON gets "board" (what its parts saw) and
 * "console" (everything the firmware printed). */
#include "run_driver.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "board/board.h"
#include "link/serial.h"

typedef struct {
    board_t *board;
    int console_fd;      /* --console pty: the pty's master, -1 none */
    uint64_t console_sent; /* console bytes written to it so far */
    uint64_t console_lost; /* bytes the pty's reader fell too far behind for (io/console.h's tail) */
    int eeprom_written;  /* the firmware wrote its EEPROM (--eeprom) */
    int eeprom_changed;  /* ... and its contents differ from power-on */
    int eeprom_failed;   /* --eeprom's file could not be saved */
    run_watch_t watch;   /* --watch: the firmware's variables */
} board_run_t;

/* One contest per process (run_one): the driver's state is static, as
 * run_one's run_t is, so what it holds stays reachable to the end. */
static board_run_t board_state;

/* --input's actions on the board: the switches, the button, the reset
 * button and the console (a newline after the text, as a serial monitor
 * sends it). */
static void board_hands(run_t *r, void *self, const input_action_t *a)
{
    board_t *b = ((board_run_t *)self)->board;
    char line[INPUT_TEXT_MAX + 2];
    switch (a->kind) {
    case INPUT_SWITCHES: board_set_switches(b, (unsigned)a->value); break;
    case INPUT_BUTTON_DOWN: board_button(b, 1); break;
    case INPUT_BUTTON_UP: board_button(b, 0); break;
    case INPUT_RESET: board_reset(b); break;
    case INPUT_SEND:
        snprintf(line, sizeof line, "%s\n", a->text);
        if (board_send(b, line) != 0) fprintf(stderr, "mmsim: --input send: the UART's input queue is full: '%s' dropped\n", a->text);
        break;
    default: break;
    }
}

/* --console pty: the UART on a pseudo-terminal whose path goes to
 * stderr; 0, or RUN_EXTERNAL after a line. */
static int console_open(run_t *r, board_run_t *b)
{
    char path[256], err[300];
    b->console_fd = -1;
    b->console_sent = 0;
    if (!r->o->console_pty) return 0;
    b->console_fd = serial_open_pty(path, sizeof path, err, sizeof err);
    if (b->console_fd < 0) {
        fprintf(stderr, "mmsim: --console pty: %s\n", err);
        return RUN_EXTERNAL;
    }
    fprintf(stderr, "mmsim: the board's console (UART0) is on %s\n", path);
    return 0;
}

/* What the person typed to the board, what the firmware printed to the person. */
static void console_pump(board_run_t *b)
{
    char in[64];
    if (b->console_fd < 0) return;
    ssize_t n = read(b->console_fd, in, sizeof in - 1);
    if (n > 0) {
        in[n] = '\0';
        board_send(b->board, in);
    }
    char out[4096];
    uint64_t from = b->console_sent;
    size_t k;
    while ((k = console_read(board_console_stream(b->board), &from, out, sizeof out, &b->console_lost)) > 0) {
        b->console_sent = from - k; /* where out starts (past any bytes the tail no longer holds) */
        ssize_t w = write(b->console_fd, out, k);
        if (w <= 0) break; /* nobody reading yet (or a full buffer): the rest next time */
        b->console_sent += (uint64_t)w;
        if ((size_t)w < k) break;
    }
}

/* The viewer's panel, just before it draws a frame (reads only: the run is
 * the same with or without the viewer). ctx: the board_run_t. */
static void board_panel_fill(void *ctx, view_board_t *out)
{
    const board_run_t *b = ctx;
    board_panel_t p;
    board_panel(b->board, &p);
    memset(out, 0, sizeof *out);
    out->switches = p.switches;
    out->button = p.button;
    out->nleds = p.nleds < HUD_BOARD_LEDS ? p.nleds : HUD_BOARD_LEDS;
    for (int i = 0; i < out->nleds; i++) {
        out->led[i] = p.led[i];
        out->led_name[i] = p.led_name[i];
    }
    out->console = board_console(b->board, &out->console_len);
}

static void board_show(run_t *r, void *self, view_t *v) { view_set_board(v, board_panel_fill, self); }

static void board_close_run(run_t *r, void *self)
{
    board_run_t *b = self;
    if (b->console_fd >= 0) close(b->console_fd);
    b->console_fd = -1;
    board_close(b->board);
}

static int board_open_run(run_t *r, void **self)
{
    char path[512], err[600];
    board_spec_t spec;
    if (r->o->board_spec) {
        spec = *r->o->board_spec;
    } else if (board_find(r->o->board, path, sizeof path, err, sizeof err) != 0 || board_load(&spec, path, err, sizeof err) != 0) {
        fprintf(stderr, "%s\n", err);
        return RUN_BAD_INPUT;
    }
    board_run_t *b = &board_state;
    memset(b, 0, sizeof *b);
    b->console_fd = -1;
    b->board = board_open(&spec, r->o->avr_elf, &r->sim, err, sizeof err);
    if (!b->board) {
        fprintf(stderr, "mmsim: %s\n", err);
        return RUN_BAD_INPUT;
    }
    if (r->o->eeprom_path && board_eeprom_keep(b->board, r->o->eeprom_path, err, sizeof err) != 0) {
        fprintf(stderr, "mmsim: %s\n", err);
        board_close(b->board);
        return RUN_BAD_INPUT;
    }
    if (run_watch_open(r, &b->watch, board_host(b->board)->avr) != 0) {
        board_close(b->board);
        return RUN_BAD_INPUT;
    }
    if (r->o->verbose) board_set_echo(b->board, stderr);
    if (r->o->end_on) console_look_for(board_console_stream(b->board), r->o->end_on);
    *self = b;
    int rc = console_open(r, b);
    if (!rc && r->o->gdb_port)
        rc = run_gdb_said(r->o->gdb_port, board_gdb(b->board, r->o->gdb_port, err, sizeof err) ? err : NULL);
    if (rc) board_close_run(r, b);
    return rc;
}

/* after the step: the console every 10 ms, then the AVR's cycles of the step */
static const char *board_after(run_t *r, void *self)
{
    char err[400];
    const run_opts_t *o = r->o;
    board_run_t *b = self;
    if (r->sim.step % 10 == 0) console_pump(b);
    if (board_step(b->board, err, sizeof err) != 0) {
        fprintf(stderr, "mmsim: %s: %s\n", o->avr_elf, err);
        if (board_host(b->board)->crash) return "firmware_crashed";
        return strstr(err, "auto-trigger") ? "board_unsupported" : "avr_stopped";
    }
    run_watch_step(r, &b->watch); /* --watch: after the AVR's cycles */
    if (o->end_on && r->sim.step % 10 == 0 && console_seen(board_console_stream(b->board))) return "console_end";
    return NULL;
}

/* {"NAME": n, ...} of the non-zero counts */
static json_t *counts(const char *const *names, const uint64_t *n, int k)
{
    json_t *j = json_object();
    for (int i = 0; i < k; i++)
        if (n[i] && names[i]) json_object_set_new(j, names[i], json_integer((json_int_t)n[i]));
    return j;
}

static void board_results(run_t *r, void *self, json_t *j)
{
    board_t *bd = ((board_run_t *)self)->board;
    const board_stats_t *st = board_stats(bd);
    const char *vnames[BOARD_VECTORS_MAX], *adc[BOARD_ADC_CHANNELS] = { "A0", "A1", "A2", "A3", "A4", "A5", "A6", "A7" };
    for (int v = 0; v < BOARD_VECTORS_MAX; v++) vnames[v] = board_vector_name(bd, (unsigned)v);
    json_t *leds = json_object();
    const board_spec_t *spec = board_spec(bd);
    for (int i = 0; i < spec->nleds; i++) json_object_set_new(leds, spec->led_name[i], json_integer(st->led_changes[i]));
    json_t *b = json_pack("{s:s, s:s, s:I}", "file", spec->path, "image", r->o->avr_elf, "cycles", (json_int_t)st->cycles);
    json_object_set_new(b, "led_changes", leds);
    json_object_set_new(b, "interrupts", counts(vnames, st->interrupts, BOARD_VECTORS_MAX));
    json_object_set_new(b, "adc_conversions", counts(adc, st->adc_conversions, BOARD_ADC_CHANNELS));
    json_object_set_new(b, "pwm_duty", json_pack("{s:[f,f], s:[f,f]}", "left", st->duty_min[0], st->duty_max[0], "right",
                                                 st->duty_min[1], st->duty_max[1]));
    json_object_set_new(b, "encoder_edges", json_pack("{s:I, s:I}", "left", (json_int_t)st->encoder_edges[0], "right",
                                                      (json_int_t)st->encoder_edges[1]));
    /* the physics' own counts (the robot file's encoder_ppr x gear per wheel turn) and battery, to check the board's against */
    json_object_set_new(b, "sim_encoder_counts", json_pack("{s:i, s:i}", "left", (int)r->sim.encoder[WORLD_LEFT].count, "right",
                                                           (int)r->sim.encoder[WORLD_RIGHT].count));
    json_object_set_new(b, "battery_v", json_real(round(sim_battery_v(&r->sim) * 1000.0) / 1000.0));
    json_object_set_new(b, "uart_bytes_out", json_integer((json_int_t)st->uart_bytes_out));
    json_object_set_new(b, "uart_bytes_in", json_integer((json_int_t)st->uart_bytes_in));
    json_object_set_new(b, "resets", json_integer(st->resets));
    /* what was lost, present only when something was: the console past its limit, bytes typed before the receiver was on */
    if (st->console_dropped) json_object_set_new(b, "console_dropped", json_integer((json_int_t)st->console_dropped));
    if (st->uart_bytes_dropped)
        json_object_set_new(b, "uart_bytes_dropped", json_integer((json_int_t)st->uart_bytes_dropped));
    const board_run_t *br = self;
    if (r->o->eeprom_path)
        json_object_set_new(b, "eeprom", json_pack("{s:s, s:b, s:b, s:b}", "file", r->o->eeprom_path, "written",
                                                   br->eeprom_written, "changed", br->eeprom_changed, "saved",
                                                   !br->eeprom_failed));
    const avrhost_t *h = board_host(bd);
    if (h->wdt_resets) json_object_set_new(b, "watchdog_resets", json_integer((json_int_t)h->wdt_resets));
    /* every reset by its cause: the run's power-on, the reset button (--input reset, the HUD), the
     * watchdog; brown-out never (the board's VCC is its file's vcc_v, held by the regulator) */
    json_object_set_new(b, "reset_causes", json_pack("{s:i, s:I, s:I, s:i}", "power_on", 1, "external", (json_int_t)st->resets,
                                                     "watchdog", (json_int_t)h->wdt_resets, "brown_out", 0));
    if (h->crash) json_object_set_new(b, "crash", json_pack("{s:I, s:s}", "pc", (json_int_t)h->crash_pc, "cause", h->crash));
    json_object_set_new(j, "board", b);
    size_t n;
    const char *con = board_console(bd, &n);
    json_object_set_new(j, "console", run_console_json(con, n));
}

static void board_stop(run_t *r, void *self)
{
    board_run_t *b = self;
    char err[600];
    console_pump(b); /* the last words */
    if (board_eeprom_end(b->board, &b->eeprom_written, &b->eeprom_changed, err, sizeof err) != 0) {
        fprintf(stderr, "mmsim: --eeprom: %s\n", err);
        b->eeprom_failed = 1;
    }
    const board_stats_t *st = board_stats(b->board);
    if (st->console_dropped)
        fprintf(stderr, "mmsim: the console kept its first %u bytes; %llu more not kept (board.console_dropped)\n",
                BOARD_CONSOLE_MAX - 1, (unsigned long long)st->console_dropped);
    if (b->console_lost)
        fprintf(stderr, "mmsim: --console pty: %llu bytes not delivered (its reader fell more than %u bytes behind)\n",
                (unsigned long long)b->console_lost, CONSOLE_TAIL);
}

static void board_headline(const run_t *r, const void *self)
{
    const board_stats_t *st = board_stats(((const board_run_t *)self)->board);
    printf("%s: %ux%u, seed %llu, %s on board %s: %llu cycles, UART %llu B out, %llu B in\n", r->maze_path, r->maze.width,
           r->maze.height, (unsigned long long)r->o->seed, r->o->avr_elf, r->o->board, (unsigned long long)st->cycles,
           (unsigned long long)st->uart_bytes_out, (unsigned long long)st->uart_bytes_in);
}

/* the firmware crashed: not reached; the AVR stopped otherwise: external; an ADC mode simavr lacks: the
 * image's (bad input); else was a lap made */
static int board_exit(const run_t *r, const void *self)
{
    if (!strcmp(r->reason, "firmware_crashed")) return RUN_NOT_REACHED;
    if (!strcmp(r->reason, "avr_stopped") || ((const board_run_t *)self)->eeprom_failed) return RUN_EXTERNAL;
    if (!strcmp(r->reason, "board_unsupported")) return RUN_BAD_INPUT;
    return r->sim.race.nlaps > 0 ? RUN_OK : RUN_NOT_REACHED;
}

/* no stall watch: a board may wait for a person (switches, button, console) */
const run_driver_t run_board = {
    .name = "board", .open = board_open_run, .after = board_after, .stop = board_stop, .results = board_results,
    .close = board_close_run, .headline = board_headline, .exit_code = board_exit, .show = board_show,
    .hands = board_hands,
};

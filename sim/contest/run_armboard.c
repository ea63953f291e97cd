/* run_armboard.c - an ARM image on an emulated STM32 board (--board NAME
 * --firmware IMAGE.elf, sim/arm/armboard.c): the board file's STM32F103 on
 * the Cortex-M core, in lockstep with the physics, its pins, timers, ADC,
 * gyro and console wired to the robot. The run lasts the time limit (or
 * until the firmware crashes or --end-on's text is printed); --input's
 * button presses act on its buttons, occlude (a hand before a sensor) on
 * the world; the JSON gets "board" (cycles, interrupt requests per NVIC
 * line, console bytes, the registers no model implements, a crash) and
 * "console". --gdb PORT runs the core under the gdb stub (sim/arm/armgdb.h,
 * frozen lockstep: the same JSON); --watch reads the image's variables
 * from the core's SRAM each step (run_watch.c); --no-skip sleeps WFI and
 * runs wait loops cycle by cycle (the same JSON but "skipped"). */
#include "run_driver.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "arm/armboard.h"
#include "arm/armwatch.h"
#include "arm/stm32board.h"
#include "board/board.h"

typedef struct {
    armboard_t *board;
    int flash_failed;    /* --flash's file could not be saved */
    run_watch_t watch;   /* --watch: the firmware's variables */
} armboard_run_t;

static armboard_run_t arm_state; /* one contest per process, as run_board.c's */

/* --input's button (every [button.*] of the board: bulebule reads one) and
 * send: the text alone typed on the console's USART (no newline: bulebule's
 * commands end where the line goes idle, its USART's IDLE interrupt) */
static void arm_hands(run_t *r, void *self, const input_action_t *a)
{
    armboard_t *b = ((armboard_run_t *)self)->board;
    switch (a->kind) {
    case INPUT_BUTTON_DOWN: armboard_button(b, -1, 1); break;
    case INPUT_BUTTON_UP: armboard_button(b, -1, 0); break;
    case INPUT_SEND:
        if (armboard_send(b, a->text) != 0) fprintf(stderr, "mmsim: --input send: no console or its input queue is full: '%s' dropped\n", a->text);
        break;
    case INPUT_RESET: stm32f1_soc_reset_pin(armboard_soc(b)); break;
    default: fprintf(stderr, "mmsim: --input: switches have no effect on an STM32 board\n"); break;
    }
}

/* --watch's sampler: the variables from the core's SRAM */
static void arm_sample(const watch_list_t *w, void *board, double *values)
{
    armwatch_sample(w, armboard_soc(board)->core, armboard_mcu(board), values);
}

/* --watch and --gdb on the open board: RUN_OK, or the run's exit code after one line */
static int arm_debug(run_t *r, armboard_run_t *a)
{
    char err[600];
    if (r->o->watch) {
        int rc = armwatch_open(&a->watch.list, r->o->arm_elf, r->o->watch, armboard_mcu(a->board), stderr, err, sizeof err);
        if (run_watch_started(&a->watch, rc, err, arm_sample, a->board) != 0) return RUN_BAD_INPUT;
    }
    if (!r->o->gdb_port) return RUN_OK;
    if (armboard_gdb(a->board, r->o->gdb_port, err, sizeof err) != 0) {
        fprintf(stderr, "mmsim: --gdb %u: %s\n", r->o->gdb_port, err);
        return RUN_EXTERNAL;
    }
    fprintf(stderr, "mmsim: --gdb: the firmware is halted until gdb-multiarch attaches to 127.0.0.1:%u (target remote :%u) and continues\n",
            r->o->gdb_port, r->o->gdb_port);
    return RUN_OK;
}

static int arm_open(run_t *r, void **self)
{
    static stm32board_spec_t spec;
    char path[512], err[1200];
    if (r->o->arm_board_spec) {
        spec = *r->o->arm_board_spec;
    } else if (board_find(r->o->board, path, sizeof path, err, sizeof err) != 0 || stm32board_load(&spec, path, err, sizeof err) != 0) {
        fprintf(stderr, "%s\n", err);
        return RUN_BAD_INPUT;
    }
    armboard_run_t *a = &arm_state;
    memset(a, 0, sizeof *a);
    unsigned flags = (r->o->verbose ? ARMBOARD_VERBOSE : 0u) | (r->o->no_skip ? ARMBOARD_NO_SKIP : 0u);
    a->board = armboard_open(&spec, r->o->arm_elf, r->o->flash_path, &r->sim, r->cfg.sim.step_s, flags, err, sizeof err);
    if (!a->board) {
        fprintf(stderr, "%s\n", err);
        return RUN_BAD_INPUT;
    }
    int rc = arm_debug(r, a);
    if (rc != RUN_OK) {
        armboard_close(a->board);
        a->board = NULL;
        return rc;
    }
    if (r->o->verbose) armboard_set_echo(a->board, stderr);
    if (r->o->end_on) console_look_for(armboard_console_stream(a->board), r->o->end_on);
    *self = a;
    return RUN_OK;
}

static void arm_close(run_t *r, void *self)
{
    armboard_run_t *a = self;
    armboard_close(a->board);
    a->board = NULL;
}

static const char *arm_after(run_t *r, void *self)
{
    armboard_run_t *a = self;
    if (armboard_step(a->board) != 0) {
        uint32_t pc;
        const char *cause;
        if (armcore_crashed(armboard_soc(a->board)->core, &pc, &cause))
            fprintf(stderr, "mmsim: %s: the firmware crashed at 0x%08x: %s\n", r->o->arm_elf, pc, cause);
        return "firmware_crashed";
    }
    run_watch_step(r, &a->watch); /* --watch: after the core's cycles */
    if (r->o->end_on && r->sim.step % 10 == 0 && console_seen(armboard_console_stream(a->board))) return "console_end";
    return NULL;
}

/* {"NAME": n} of the NVIC lines that were raised (RM0008 table 63's names) */
static json_t *irq_counts(const stm32f1_soc_t *s)
{
    json_t *j = json_object();
    char name[16];
    for (unsigned i = 0; i < CORTEXM_IRQ_MAX; i++) {
        if (!s->irq_count[i]) continue;
        const char *n = stm32f1_irq_name(i);
        if (!n) snprintf(name, sizeof name, "IRQ%u", i), n = name;
        json_object_set_new(j, n, json_integer((json_int_t)s->irq_count[i]));
    }
    return j;
}

/* {"INn": samples} of the ADC channels sampled (ADC12_INn; 16 the temperature sensor, 17 VREFINT) */
static json_t *adc_counts(const armboard_stats_t *st)
{
    json_t *j = json_object();
    char name[8];
    for (unsigned ch = 0; ch < 18; ch++)
        if (st->adc_samples[ch]) snprintf(name, sizeof name, "IN%u", ch), json_object_set_new(j, name, json_integer((json_int_t)st->adc_samples[ch]));
    return j;
}

static json_t *unmodeled_list(armcore_t *c)
{
    int n;
    const armcore_unmodeled_t *u = armcore_unmodeled(c, &n);
    json_t *j = json_array();
    char addr[16];
    for (int i = 0; i < n; i++) {
        snprintf(addr, sizeof addr, "0x%08x", u[i].addr);
        json_array_append_new(j, json_pack("{s:s, s:s, s:I, s:I}", "addr", addr, "region", u[i].region, "reads",
                                           (json_int_t)u[i].reads, "writes", (json_int_t)u[i].writes));
    }
    return j;
}

static void arm_results(run_t *r, void *self, json_t *j)
{
    const armboard_run_t *a = self;
    armboard_t *bd = a->board;
    const armboard_stats_t *st = armboard_stats(bd);
    const stm32board_spec_t *spec = armboard_spec(bd);
    stm32f1_soc_t *soc = armboard_soc(bd);
    char addr[16];
    json_t *leds = json_object();
    for (int i = 0; i < spec->nleds; i++) json_object_set_new(leds, spec->led[i].name, json_integer(st->led_changes[i]));
    json_t *b = json_pack("{s:s, s:s, s:s, s:I}", "file", spec->path, "mcu", spec->mcu, "image", r->o->arm_elf, "cycles",
                          (json_int_t)st->cycles);
    armcore_stats_t cs = armcore_stats(soc->core);
    json_object_set_new(b, "exceptions", json_integer((json_int_t)cs.exceptions)); /* entered, SysTick and faults included */
    json_object_set_new(b, "idle_cycles", json_integer((json_int_t)cs.idle_cycles));
    /* the cycles jumped over rather than run one by one (none with --no-skip: the rest of the JSON is the same) */
    json_object_set_new(b, "skipped", json_pack("{s:I, s:I, s:I}", "sleep_cycles", (json_int_t)cs.idle_jumped,
                                                "wait_loops", (json_int_t)cs.loop_skips, "wait_loop_cycles", (json_int_t)cs.loop_cycles));
    json_object_set_new(b, "interrupt_requests", irq_counts(soc));
    json_object_set_new(b, "adc_samples", adc_counts(st));
    json_object_set_new(b, "led_changes", leds);
    json_object_set_new(b, "pwm_duty", json_pack("{s:[f,f], s:[f,f]}", "left", st->duty_min[0], st->duty_max[0], "right",
                                                 st->duty_min[1], st->duty_max[1]));
    json_object_set_new(b, "encoder_edges", json_pack("{s:I, s:I}", "left", (json_int_t)st->encoder_edges[0], "right",
                                                      (json_int_t)st->encoder_edges[1]));
    json_object_set_new(b, "battery_v", json_real(round(sim_battery_v(&r->sim) * 1000.0) / 1000.0));
    json_object_set_new(b, "console_bytes", json_integer((json_int_t)st->console_bytes));
    if (st->console_dropped) json_object_set_new(b, "console_dropped", json_integer((json_int_t)st->console_dropped));
    json_object_set_new(b, "resets", json_integer((json_int_t)soc->resets));
    json_object_set_new(b, "gated_accesses", json_integer((json_int_t)soc->rcc.gated));
    json_object_set_new(b, "unmodeled", unmodeled_list(soc->core));
    if (r->o->flash_path)
        json_object_set_new(b, "flash", json_pack("{s:s, s:b, s:b}", "file", r->o->flash_path, "changed", soc->flash.changed != 0,
                                                  "saved", !a->flash_failed));
    uint32_t pc;
    const char *cause;
    snprintf(addr, sizeof addr, "0x%08x", stm32f1_soc_pc(soc)); /* where the firmware is at the end */
    json_object_set_new(b, "pc", json_string(addr));
    if (armcore_crashed(soc->core, &pc, &cause)) json_object_set_new(b, "crash", json_pack("{s:I, s:s}", "pc", (json_int_t)pc, "cause", cause));
    json_object_set_new(j, "board", b);
    size_t n;
    const char *con = armboard_console(bd, &n);
    json_object_set_new(j, "console", run_console_json(con, n));
}

static void arm_stop(run_t *r, void *self)
{
    armboard_run_t *a = self;
    char err[600];
    if (armboard_end(a->board, err, sizeof err) != 0) {
        fprintf(stderr, "mmsim: --flash: %s\n", err);
        a->flash_failed = 1;
    }
}

static void arm_headline(const run_t *r, const void *self)
{
    const armboard_stats_t *st = armboard_stats(((const armboard_run_t *)self)->board);
    printf("%s: %ux%u, seed %llu, %s on board %s: %llu cycles, console %llu B\n", r->maze_path, r->maze.width, r->maze.height,
           (unsigned long long)r->o->seed, r->o->arm_elf, r->o->board, (unsigned long long)st->cycles,
           (unsigned long long)st->console_bytes);
}

static int arm_exit(const run_t *r, const void *self)
{
    if (!strcmp(r->reason, "firmware_crashed")) return RUN_NOT_REACHED;
    if (((const armboard_run_t *)self)->flash_failed) return RUN_EXTERNAL;
    return r->sim.race.nlaps > 0 ? RUN_OK : RUN_NOT_REACHED;
}

/* no stall watch: the firmware may wait for a person (a button, a hand) */
const run_driver_t run_armboard = {
    .name = "board", .open = arm_open, .after = arm_after, .stop = arm_stop, .results = arm_results, .close = arm_close,
    .headline = arm_headline, .exit_code = arm_exit, .hands = arm_hands,
};

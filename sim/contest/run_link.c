/* run_link.c - an MCU drives over the serial link (sim/link): a device or a
 * pseudo-terminal (--serial/--pty, in real time) or an AVR image in simavr
 * (--avr, sim/board, in lockstep); and the HUD's Connect, which hands a
 * running contest to an MCU. The contest lasts the time limit or until the
 * MCU sends RUN stop. */
#include "run_driver.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#include "board/pil.h"

typedef struct {
    link_t lnk;
    pil_t pil; /* --avr: the image in simavr whose UART0 is the link */
    run_watch_t watch; /* --avr --watch: the firmware's variables */
} link_run_t;

/* An EMITTER from the MCU (link_step_io calls it): light the groups it
 * names, then sample every IR sensor with them so. */
static void ir_sample(void *ctx, uint8_t groups, uint16_t raw[WIRE_IR_MAX])
{
    sim_state_t *s = ctx;
    for (unsigned g = 0; g < SIM_EMITTER_GROUPS && g < WIRE_EMITTER_GROUPS; g++) sim_emitter_set(s, g, (groups >> g) & 1u);
    int n = sim_ir_count(s);
    for (int i = 0; i < n && i < WIRE_IR_MAX; i++) {
        unsigned v = sim_ir_read(s, (unsigned)i);
        raw[i] = (uint16_t)(v > 1023u ? 1023u : v);
    }
}

/* The robot's other sensors for a version-2 MCU (docs/PROTOCOL.md) */
static void link_v2_io(link_io_t *io, sim_state_t *s)
{
    int n = sim_ir_count(s);
    io->ir_count = (uint8_t)(n < 0 ? 0 : n > WIRE_IR_MAX ? WIRE_IR_MAX : n);
    io->has_gyro = sim_has_gyro(s) ? 1 : 0;
    double mdps = io->has_gyro ? sim_gyro_rad_s(s) * 180.0 / M_PI * 1000.0 : 0.0;
    io->gyro_mdps = (int32_t)lround(mdps > 2e9 ? 2e9 : mdps < -2e9 ? -2e9 : mdps);
    double mv = sim_battery_v(s) * 1000.0;
    io->battery_mv = (uint16_t)lround(mv < 0 ? 0 : mv > 65535 ? 65535 : mv);
    io->ir_sample = ir_sample;
    io->ctx = s;
}

/* The link's view of the robot: after each physics step its encoder counts,
 * the ToF readings that are new since the last step and (to a version-2
 * MCU) gyro, battery and IR go to the MCU; the MCU's motor commands and
 * emitter switches come back. */
static void link_exchange(link_t *l, sim_state_t *s)
{
    link_io_t io;
    memset(&io, 0, sizeof io);
    io.t_us = (uint32_t)(s->step * (uint64_t)llround(s->model->cfg->sim.step_s * 1e6));
    io.encoder[0] = s->encoder[WORLD_LEFT].count;
    io.encoder[1] = s->encoder[WORLD_RIGHT].count;
    for (int i = 0; i < 3; i++) { /* a new reading bumped the sensor's count */
        if (l->tof_seen[i] != UINT64_MAX && s->tof_count[i] != l->tof_seen[i]) {
            io.tof_new[i] = 1;
            io.tof_mm[i] = (uint16_t)lround(s->tof_last[i].dist_m * 1000.0);
            io.tof_m[i] = s->tof_last[i].dist_m;
            io.tof_timeout[i] = (uint8_t)s->tof_last[i].timeout;
        }
        l->tof_seen[i] = (uint64_t)s->tof_count[i];
    }
    link_v2_io(&io, s);
    int16_t mo[2];
    s->tof_enabled = link_step_io(l, &io, mo);
    s->cmd[WORLD_LEFT] = mo[0];
    s->cmd[WORLD_RIGHT] = mo[1];
}

static uint16_t tof_range_mm(const run_t *r) { return (uint16_t)lround(robot_tof_range_m(&r->cfg) * 1000.0); }

/* the command line's link options with the config's compat distance scale */
static link_opts_t link_opts(const run_t *r)
{
    link_opts_t lo = r->o->link;
    lo.compat_range_m = r->cfg.link.compat_range_m;
    return lo;
}
static uint32_t counts_x100(const run_t *r)
{
    const drive_spec_t *d = &r->cfg.robot.drive[0];
    return (uint32_t)lround(d->encoder_ppr * d->gear_ratio * 100.0);
}

static void link_exchange_run(run_t *r, void *self) { link_exchange(&((link_run_t *)self)->lnk, &r->sim); }

/* the MCU ended the contest (RUN stop), or the time is up */
static const char *link_after(run_t *r, void *self)
{
    if (((link_run_t *)self)->lnk.st.stops) return "mcu_stopped";
    return NULL;
}

/* the AVR's cycles of this step, then as link_after */
static const char *avr_after(run_t *r, void *self)
{
    char err[400];
    if (pil_step(&((link_run_t *)self)->pil, err, sizeof err) != 0) {
        fprintf(stderr, "mmsim: %s: %s\n", r->o->avr_elf, err);
        return ((link_run_t *)self)->pil.host.crash ? "firmware_crashed" : "avr_stopped";
    }
    run_watch_step(r, &((link_run_t *)self)->watch); /* --watch */
    return link_after(r, self);
}

static const link_t *link_of(const void *self) { return &((const link_run_t *)self)->lnk; }

/* One contest per process (run_one): the driver's state is static, as
 * run_one's run_t is, so what it holds stays reachable to the end. */
static link_run_t link_state;

/* *self = the zeroed link_run_t */
static link_run_t *new_self(void **self)
{
    memset(&link_state, 0, sizeof link_state);
    *self = &link_state;
    return &link_state;
}

int run_link_connect(run_t *r, const char *port, long baud, void **self, char *err, size_t errlen)
{
    link_opts_t lo = link_opts(r);
    lo.device = port;
    lo.pty = 0;
    lo.baud = (uint32_t)baud;
    link_run_t *l = new_self(self);
    return link_open(&l->lnk, &lo, r->cfg.sim.step_s, tof_range_mm(r), counts_x100(r), stderr, err, errlen) == 0 ? 0 : -1;
}

static void link_results(run_t *r, void *self, json_t *j)
{
    link_run_t *l = self;
    json_object_set_new(j, "link", link_json(&l->lnk));
}

static void avr_results(run_t *r, void *self, json_t *j)
{
    link_results(r, self, j);
    uint32_t stack_max, free_min;
    const pil_t *p = &((link_run_t *)self)->pil;
    pil_stack(p, &stack_max, &free_min);
    json_t *a = json_pack("{s:s, s:s, s:I, s:I, s:I, s:I, s:I, s:I}", "elf", r->o->avr_elf, "mcu", p->mcu, "f_cpu_hz",
                          (json_int_t)p->f_cpu, "cycles", (json_int_t)p->cycles, "uart_bytes_in", (json_int_t)p->bytes_in,
                          "uart_bytes_out", (json_int_t)p->bytes_out, "stack_max_bytes", (json_int_t)stack_max,
                          "sram_free_min_bytes", (json_int_t)free_min);
    const avrhost_t *h = &p->host;
    if (h->wdt_resets) json_object_set_new(a, "watchdog_resets", json_integer((json_int_t)h->wdt_resets));
    if (h->crash) json_object_set_new(a, "crash", json_pack("{s:I, s:s}", "pc", (json_int_t)h->crash_pc, "cause", h->crash));
    if (p->bytes_dropped) /* present only when something was lost */
        json_object_set_new(a, "uart_bytes_dropped", json_integer((json_int_t)p->bytes_dropped));
    json_object_set_new(j, "avr", a);
}

static int serial_open(run_t *r, void **self)
{
    char err[400];
    link_opts_t lo = link_opts(r);
    link_run_t *l = new_self(self);
    if (link_open(&l->lnk, &lo, r->cfg.sim.step_s, tof_range_mm(r), counts_x100(r), stderr, err, sizeof err) == 0) return 0;
    fprintf(stderr, "mmsim: %s\n", err);
    return RUN_EXTERNAL;
}

static void serial_close(run_t *r, void *self) { link_close(&((link_run_t *)self)->lnk); }

static int avr_open(run_t *r, void **self)
{
    char err[400];
    int fd;
    link_run_t *l = new_self(self);
    int rc = pil_open(&l->pil, r->o->avr_elf, r->o->avr_mcu, r->o->avr_f_cpu, r->cfg.sim.step_s, &fd, err, sizeof err);
    if (rc != 0) {
        fprintf(stderr, "mmsim: %s\n", err);
        return rc == -2 ? RUN_BAD_INPUT : RUN_EXTERNAL;
    }
    link_opts_t lo = link_opts(r);
    link_open_fd(&l->lnk, fd, "simavr UART0", &lo, r->cfg.sim.step_s, tof_range_mm(r), counts_x100(r),
                 r->o->verbose ? stderr : NULL);
    if (run_watch_open(r, &l->watch, l->pil.host.avr) != 0) {
        link_close(&l->lnk);
        pil_close(&l->pil);
        return RUN_BAD_INPUT;
    }
    if (!r->o->gdb_port) return 0;
    rc = run_gdb_said(r->o->gdb_port, avrhost_gdb(&l->pil.host, r->o->gdb_port, err, sizeof err) ? err : NULL);
    if (rc) {
        link_close(&l->lnk);
        pil_close(&l->pil);
    }
    return rc;
}

static void avr_close(run_t *r, void *self)
{
    link_run_t *l = self;
    link_close(&l->lnk);
    pil_close(&l->pil);
}

/* the firmware crashed: not reached; the processor stopped otherwise: an external failure; else as every MCU */
static int avr_exit(const run_t *r, const void *self)
{
    if (!strcmp(r->reason, "firmware_crashed")) return RUN_NOT_REACHED;
    return !strcmp(r->reason, "avr_stopped") ? RUN_EXTERNAL : run_exit_laps(r, "done", "mcu_stopped");
}

static void link_headline(const run_t *r, const void *self)
{
    const link_t *l = link_of(self);
    int compat = r->o->link.protocol == LINK_COMPAT;
    printf("%s: %ux%u, seed %llu, MCU over %s (%s, %u baud): sent %llu B (%.0f %%), received %llu B (%.0f %%), "
           "dropped %llu messages, %u decode errors, %u silences, %u disconnects\n",
           r->maze_path, r->maze.width, r->maze.height, (unsigned long long)r->o->seed, l->path,
           compat ? "compat" : "framed", (unsigned)l->o.baud, (unsigned long long)l->st.tx_bytes,
           link_util_tx(l) * 100, (unsigned long long)l->st.rx_bytes, link_util_rx(l) * 100,
           (unsigned long long)l->st.tx_dropped, (unsigned)wire_stats_errors(compat ? &l->crx.stats : &l->dec.stats),
           (unsigned)l->st.silences, (unsigned)l->st.disconnects);
}

/* an MCU keeps its map to itself (no report hook) and may wait (no stall watch) */
const run_driver_t run_serial = {
    .name = "serial", .open = serial_open, .exchange = link_exchange_run, .after = link_after,
    .results = link_results, .close = serial_close, .headline = link_headline, .link = link_of,
};

const run_driver_t run_avr = {
    .name = "serial", .open = avr_open, .exchange = link_exchange_run, .after = avr_after,
    .results = avr_results, .close = avr_close, .headline = link_headline, .exit_code = avr_exit, .link = link_of,
};

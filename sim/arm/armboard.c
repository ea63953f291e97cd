/* armboard.c - an STM32F1 board in lockstep with the physics (see armboard.h). */
#include "armboard.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "arm/armgdb.h"
#include "arm/mpu6500.h"
#include "world/analog.h"
#include "world/robot.h"
#include "world/sensors/ir.h"
#include "world/world.h"

#define ADC_CHANNELS 16
#define REST_POS 0.5 /* edges: a disc at rest sits between two edges (board_encoder.c's reason) */

struct armboard {
    stm32board_spec_t spec;
    armimage_t img;
    stm32f1_soc_t *soc;
    armgdb_t *gdb;                   /* --gdb: the stub the core runs under (NULL: none) */
    sim_state_t *sim;
    mpu6500_t gyro;
    uint64_t step_ps, t_ps;          /* the physics step; the core's time at the last step's end */
    int ir_of_channel[ADC_CHANNELS]; /* the robot's IR sensor on each ADC channel, -1 none */
    int emitter_on[SIM_EMITTER_GROUPS];
    int led_level[STM32BOARD_LEDS_MAX];
    double enc_per_rad[2], enc_pos[2], enc_last_rad[2];
    int64_t enc_q[2];                /* the edge count each encoder timer was last given */
    console_t console;
    armboard_stats_t st;
};

/* The host changed a model between runs (a byte queued, an encoder's edges, a pin driven): the core
 * looks at every model's next event again before its next block (its cached one may be later). */
static void poke(armboard_t *b) { armcore_cortexm(b->soc->core)->attention = true; }

static int pin_is(stm32_pin_t p, unsigned port, unsigned pin) { return p.port && (unsigned)(p.port - 'A') == port && p.bit == pin; }

/* ---- the chip's outside: pins, ADC, console, gyro ---- */
static void on_pin(void *ctx, unsigned port, unsigned pin, int level)
{
    armboard_t *b = ctx;
    const stm32board_spec_t *sp = &b->spec;
    for (int e = 0; e < sp->nemitters; e++)
        if (pin_is(sp->emitter[e].pin, port, pin)) b->emitter_on[e] = level;
    for (int i = 0; i < sp->nleds; i++)
        if (pin_is(sp->led[i].pin, port, pin) && level != b->led_level[i]) b->led_level[i] = level, b->st.led_changes[i]++;
    if (sp->gyro_spi && pin_is(sp->gyro_cs_pin, port, pin)) mpu6500_select(&b->gyro, level != 0);
}

/* An ADC channel's voltage at the sample's cycle (the physics is the step's). */
static double on_volts(void *ctx, unsigned ch, uint64_t cycle)
{
    armboard_t *b = ctx;
    const stm32board_spec_t *sp = &b->spec;
    if (ch < 18) b->st.adc_samples[ch]++;
    if ((int)ch == sp->bat_channel) return analog_divider_v(b->sim, sp->bat_r_top_ohm, sp->bat_r_bottom_ohm);
    int ir = ch < ADC_CHANNELS ? b->ir_of_channel[ch] : -1;
    if (ir < 0) return 0.0; /* an analog pin no part drives: read as grounded (stated limit) */
    for (int e = 0; e < sp->nemitters; e++) sim_emitter_set(b->sim, (unsigned)sp->emitter[e].group, b->emitter_on[e]);
    return analog_ir_mv(b->sim, (unsigned)ir, sp->vdda_v, analog_ir_full_counts(b->sim, (unsigned)ir)) / 1000.0;
}

static void on_console(void *ctx, uint8_t byte, uint64_t cycle)
{
    armboard_t *b = ctx;
    b->st.console_bytes++;
    console_byte(&b->console, byte);
    b->st.console_dropped = b->console.dropped;
}

/* The true yaw rate the MPU-6500's z axis turns at (the world's, not the robot file's gyro model). */
static double on_rate(void *ctx, uint64_t cycle)
{
    armboard_t *b = ctx;
    double v, omega;
    world_velocity(b->sim->world, &v, &omega);
    return omega;
}

/* ---- motors and encoders ---- */
/* The fraction of the PWM period input k of motor m is high. */
static double input_high(armboard_t *b, const stm32_motor_t *m, int k)
{
    stm32f1_tim_t *t = &b->soc->tim[m->in[k].timer - 1];
    stm32_tim_advance(t, armcore_cycles(b->soc->core)); /* preloaded CCRx and ARR take effect at an update the model makes when advanced */
    stm32f1_tim_out_t o = stm32f1_tim_output(t, m->in[k].channel);
    if (o.enabled && o.running && o.pwm) return o.high;
    if (o.enabled) return o.level > 0 ? 1.0 : 0.0;
    stm32_pin_t p = m->in_pin[k];
    return stm32f1_gpio_pin(&b->soc->gpio[p.port - 'A'], p.bit).level ? 1.0 : 0.0;
}

static void motors(armboard_t *b)
{
    for (int i = 0; i < 2; i++) {
        const stm32_motor_t *m = &b->spec.motor[i];
        double h1 = input_high(b, m, 0), h2 = input_high(b, m, 1);
        double d = m->forward_in == 0 ? h1 - h2 : h2 - h1;
        if (d < b->st.duty_min[i]) b->st.duty_min[i] = d;
        if (d > b->st.duty_max[i]) b->st.duty_max[i] = d;
        long c = lround(d * 1023.0);
        b->sim->cmd[i] = (int)(c > 1023 ? 1023 : c < -1023 ? -1023 : c);
    }
}

/* The wheels' positions, edges, at fraction f of the way from the last step's angles to these. */
static void encoders(armboard_t *b, const double d_rad[2], double f, uint64_t now)
{
    for (int w = 0; w < 2; w++) {
        const stm32_encoder_t *e = &b->spec.enc[w];
        double pos = b->enc_pos[w] + f * d_rad[w] * b->enc_per_rad[w];
        int64_t q = (int64_t)floor(pos);
        b->st.encoder_edges[w] += (uint64_t)llabs(q - b->enc_q[w]);
        b->enc_q[w] = q;
        stm32f1_tim_encoder(&b->soc->tim[e->a.timer - 1], now, e->ch1_leads > 0 ? q : -q);
        if (f >= 1.0) b->enc_pos[w] = pos;
    }
    poke(b);
}

int armboard_step(armboard_t *b)
{
    armcore_t *c = b->soc->core;
    double d[2];
    for (int w = 0; w < 2; w++) {
        double a = world_wheel_angle(b->sim->world, w);
        d[w] = a - b->enc_last_rad[w];
        while (d[w] > M_PI) d[w] -= 2.0 * M_PI; /* the hinge angle wraps at +-pi */
        while (d[w] < -M_PI) d[w] += 2.0 * M_PI;
        b->enc_last_rad[w] = a;
    }
    /* the step's motion spread over its time: the position at fraction k/SLICES at that time */
    uint64_t t0 = b->t_ps;
    for (int k = 1; k <= ARMBOARD_SLICES; k++) {
        uint64_t to = t0 + b->step_ps * (uint64_t)k / ARMBOARD_SLICES;
        int rc = b->gdb ? armgdb_run_until_ps(b->gdb, to) : armcore_run_until_ps(c, to);
        b->st.cycles = armcore_cycles(c);
        if (rc) return -1;
        encoders(b, d, (double)k / ARMBOARD_SLICES, armcore_cycles(c));
    }
    b->t_ps = t0 + b->step_ps;
    motors(b);
    return 0;
}

/* ---- set-up ---- */
static int map_ir(armboard_t *b, char *err, size_t errn)
{
    if (stm32board_fits_robot(&b->spec, b->sim->model->cfg, err, errn) != 0) return -1;
    for (int ch = 0; ch < ADC_CHANNELS; ch++) b->ir_of_channel[ch] = -1;
    const simcfg_t *c = b->sim->model->cfg;
    for (int i = 0; i < sim_ir_count(b->sim); i++) {
        int k = robot_part_of_kind(c, "ir", (unsigned)i);
        const ir_part_spec_t *ps = (const ir_part_spec_t *)(const void *)c->robot.part[k].spec;
        int ch = (int)ps->adc_channel;
        if (ch >= 0 && ch < ADC_CHANNELS) b->ir_of_channel[ch] = i;
    }
    return 0;
}

static void wire(armboard_t *b, stm32f1_soc_cfg_t *cfg)
{
    const stm32board_spec_t *sp = &b->spec;
    cfg->hse_hz = sp->hse_hz, cfg->vdda_v = sp->vdda_v;
    cfg->volts = on_volts, cfg->volts_ctx = b;
    if (sp->console_usart) cfg->sink[sp->console_usart - 1] = on_console, cfg->sink_ctx[sp->console_usart - 1] = b;
    if (sp->gyro_spi) cfg->spi_slave[sp->gyro_spi - 1] = (stm32_spi_slave_t){ mpu6500_exchange, &b->gyro };
    cfg->pin_cb = on_pin, cfg->pin_ctx = b;
}

static void start_parts(armboard_t *b, double step_s)
{
    const stm32board_spec_t *sp = &b->spec;
    stm32f1_soc_t *s = b->soc;
    mpu6500_init(&b->gyro, stm32f1_rcc_clocks(&s->rcc), on_rate, b, b->sim->seed, 0);
    mpu6500_select(&b->gyro, true);
    for (int i = 0; i < sp->nbuttons; i++) armboard_button(b, i, 0);
    for (int i = 0; i < sp->nleds; i++) b->led_level[i] = stm32f1_gpio_pin(&s->gpio[sp->led[i].pin.port - 'A'], sp->led[i].pin.bit).level;
    for (int w = 0; w < 2; w++) {
        const drive_spec_t *d = &b->sim->model->drive[w];
        b->enc_per_rad[w] = d->encoder_ppr * d->gear_ratio / (2.0 * M_PI);
        b->enc_pos[w] = REST_POS, b->enc_q[w] = 0;
        b->enc_last_rad[w] = world_wheel_angle(b->sim->world, w);
    }
    b->step_ps = (uint64_t)llround(step_s * 1e12);
    sim_set_supply_drop(b->sim, sp->bat_diode_drop_v);
}

armboard_t *armboard_open(const stm32board_spec_t *spec, const char *image, const char *flash_path, sim_state_t *s,
                          double step_s, unsigned flags, char *err, size_t errn)
{
    char mcu[16];
    snprintf(mcu, sizeof mcu, "stm32f103x%c", spec->mcu[10]); /* stm32f103c8 -> stm32f103x8 (the table's density) */
    armboard_t *b = calloc(1, sizeof *b);
    if (!b) return snprintf(err, errn, "mmsim: out of memory"), NULL;
    if (console_init(&b->console, err, errn) != 0) return free(b), NULL;
    b->spec = *spec, b->sim = s;
    if (map_ir(b, err, errn) != 0) return armboard_close(b), NULL;
    if (armimage_read(image, armimage_mcu(mcu), &b->img, err, errn) != 0) return armboard_close(b), NULL;
    stm32f1_soc_cfg_t cfg = { .image = &b->img, .flash_path = flash_path, .verbose = (flags & ARMBOARD_VERBOSE) != 0,
                              .no_idle_skip = (flags & ARMBOARD_NO_SKIP) != 0 };
    wire(b, &cfg);
    b->soc = stm32f1_soc_new(&cfg, err, errn);
    if (!b->soc) return armboard_close(b), NULL;
    start_parts(b, step_s);
    return b;
}

int armboard_end(armboard_t *b, char *err, size_t errn)
{
    armgdb_free(b->gdb); /* a waiting gdb is told the run ended (before the flash file: nothing left to debug) */
    b->gdb = NULL;
    return stm32f1_soc_save(b->soc, err, errn);
}

int armboard_gdb(armboard_t *b, unsigned port, char *err, size_t errn)
{
    if (b->gdb) return snprintf(err, errn, "the gdb stub is already on"), -1;
    b->gdb = armgdb_new(b->soc->core, port, err, errn);
    return b->gdb ? 0 : -1;
}

void armboard_close(armboard_t *b)
{
    if (!b) return;
    armgdb_free(b->gdb);
    stm32f1_soc_free(b->soc);
    if (b->img.flash) armimage_free(&b->img);
    console_free(&b->console);
    free(b);
}

void armboard_button(armboard_t *b, int i, int down)
{
    for (int k = 0; k < b->spec.nbuttons; k++) {
        if (i >= 0 && k != i) continue;
        const stm32_gpio_part_t *p = &b->spec.button[k];
        stm32f1_drive_t d = down ? (p->level ? STM32F1_DRIVE_HIGH : STM32F1_DRIVE_LOW) : STM32F1_DRIVE_FLOAT;
        stm32f1_gpio_drive(&b->soc->gpio[p->pin.port - 'A'], p->pin.bit, d);
    }
    poke(b);
}

int armboard_send(armboard_t *b, const char *text)
{
    if (!b->spec.console_usart) return -1;
    stm32_usart_t *u = &b->soc->usart[b->spec.console_usart - 1];
    for (const char *p = text; *p; p++)
        if (!stm32_usart_push(u, (uint8_t)*p, armcore_cycles(b->soc->core))) return poke(b), -1;
    poke(b);
    return 0;
}

const char *armboard_console(const armboard_t *b, size_t *len) { return *len = b->console.len, b->console.text; }

console_t *armboard_console_stream(armboard_t *b) { return &b->console; }
void armboard_set_echo(armboard_t *b, FILE *f) { b->console.echo = f; }
const armboard_stats_t *armboard_stats(const armboard_t *b) { return &b->st; }
stm32f1_soc_t *armboard_soc(armboard_t *b) { return b->soc; }
const armimage_mcu_t *armboard_mcu(const armboard_t *b) { return b->img.mcu; }
const stm32board_spec_t *armboard_spec(const armboard_t *b) { return &b->spec; }

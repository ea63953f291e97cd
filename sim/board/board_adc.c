/* board_adc.c - the analogue front end. simavr raises ADC_IRQ_OUT_TRIGGER
 * when a conversion starts (a single conversion, the next one of an
 * interrupt-driven chain or of free running) with the mux it samples; the
 * board answers at once with that channel's voltage, so each conversion
 * samples the world at its own moment:
 *   - an IR detector (the robot file's [ir.*] adc_channel): sim_ir_read with
 *     the emitter groups lit as their pins are at that moment;
 *   - the switch ladder: the voltage for the switches and button now;
 *   - the battery: its terminal voltage through the divider.
 * simavr 1.6 has no timer or external auto-trigger: a firmware that selects
 * one is stopped with one line (board_adc_check). */
#include "board_int.h"

#include <math.h>
#include <stdio.h>

#include <simavr/avr_adc.h>
#include <simavr/sim_avr.h>
#include <simavr/sim_io.h>
#include <simavr/sim_irq.h>

#include "world/sensors/ir.h"

enum { ADCSRA = 0x7A, ADCSRB = 0x7B };

double board_switch_volts(const board_spec_t *sp, unsigned n, int button)
{
    if (button) return sp->vcc_v; /* the button ties the pin to VCC */
    double below = sp->sw_r_ground_ohm;
    for (int k = 0; k < 4; k++)
        if (!(n >> k & 1u)) below += sp->sw_r_ohm[k]; /* a closed switch shorts its resistor */
    return sp->vcc_v * below / (sp->sw_r_top_ohm + below);
}

/* channel ch's voltage now, V */
static double channel_volts(board_t *b, unsigned ch)
{
    const board_spec_t *sp = &b->spec;
    if ((int)ch == sp->sw_channel) return board_switch_volts(sp, b->switches, b->button);
    if ((int)ch == sp->bat_channel) return sim_battery_v(b->sim) * sp->bat_r_bottom_ohm / (sp->bat_r_top_ohm + sp->bat_r_bottom_ohm);
    int ir = b->ir_of_channel[ch];
    if (ir < 0) return 0.0;
    for (int e = 0; e < sp->nemitters; e++) sim_emitter_set(b->sim, (unsigned)sp->emitter_group[e], b->emitter_level[e]);
    /* counts -> the voltage that converts back to the same count (rounded up to the mV) */
    unsigned c = sim_ir_read(b->sim, (unsigned)ir);
    return ceil(c * sp->vcc_v * 1000.0 / 1023.0) / 1000.0;
}

static void on_trigger(struct avr_irq_t *irq, uint32_t value, void *param)
{
    board_t *b = param;
    union {
        avr_adc_mux_t mux;
        uint32_t v;
    } e = { .v = value };
    (void)irq;
    if (e.mux.kind != ADC_MUX_SINGLE || e.mux.src >= BOARD_ADC_CHANNELS) return;
    unsigned ch = e.mux.src;
    b->st.adc_conversions[ch]++;
    double mv = ceil(channel_volts(b, ch) * 1000.0 - 1e-9);
    if (mv < 0) mv = 0;
    if (mv > b->spec.vcc_v * 1000.0) mv = b->spec.vcc_v * 1000.0;
    avr_raise_irq(b->adc_in[ch], (uint32_t)mv);
}

int board_adc_init(board_t *b, char *err, size_t errn)
{
    const simcfg_t *c = b->sim->model->cfg;
    for (int ch = 0; ch < BOARD_ADC_CHANNELS; ch++) {
        b->ir_of_channel[ch] = -1;
        b->adc_in[ch] = avr_io_getirq(b->avr, AVR_IOCTL_ADC_GETIRQ, ch);
    }
    int nir = sim_ir_count(b->sim);
    for (int i = 0; i < nir; i++) {
        int k = robot_part_of_kind(c, "ir", (unsigned)i);
        const ir_part_spec_t *ps = (const ir_part_spec_t *)(const void *)c->part[k].spec;
        int ch = (int)ps->adc_channel;
        if (ch < 0) continue;
        if (ch >= BOARD_ADC_CHANNELS || ch == b->spec.sw_channel || ch == b->spec.bat_channel) {
            snprintf(err, errn, "%s: ir.%s.adc_channel %d: the board %s has no free ADC channel %d (switches on %d, battery on %d)",
                     c->robot_path, c->part[k].name, ch, b->spec.name, ch, b->spec.sw_channel, b->spec.bat_channel);
            return -1;
        }
        b->ir_of_channel[ch] = i;
    }
    avr_irq_t *trig = avr_io_getirq(b->avr, AVR_IOCTL_ADC_GETIRQ, ADC_IRQ_OUT_TRIGGER);
    if (!trig || !b->adc_in[0]) {
        snprintf(err, errn, "the MCU '%s' has no ADC in simavr", b->spec.mcu);
        return -1;
    }
    avr_irq_register_notify(trig, on_trigger, b);
    return 0;
}

int board_adc_check(board_t *b, char *err, size_t errn)
{
    const uint8_t *d = b->avr->data;
    if (!(d[ADCSRA] & 0x20u)) return 0; /* ADATE off */
    unsigned adts = d[ADCSRB] & 7u;
    if (adts == 0) return 0;            /* free running: simavr does it */
    static const char *names[8] = { "free running", "analog comparator", "external interrupt 0", "timer0 compare A",
                                    "timer0 overflow", "timer1 compare B", "timer1 overflow", "timer1 capture" };
    snprintf(err, errn, "the firmware selects ADC auto-trigger source %u (%s, ADCSRB.ADTS), which simavr 1.6 does not emulate",
             adts, names[adts]);
    return -1;
}

/* board_adc.c - the analogue front end part (board_adc.h). simavr raises
 * ADC_IRQ_OUT_TRIGGER when a conversion starts (a single conversion, the next one of an
 * interrupt-driven chain or of free running) with the mux it samples; the
 * board answers at once with that channel's voltage, so each conversion
 * samples the world at its own moment:
 *   - an IR detector (the robot file's [ir.*] adc_channel): sim_ir_read with
 *     the emitter groups lit as their pins are at that moment (the emitter
 *     part's output IRQs, which board.c connects to this part's inputs);
 *   - the switch ladder: the voltage for the switches and button now (the
 *     switches part's output IRQ, connected likewise);
 *   - the battery: its terminal voltage through the divider;
 *   - A4/A5 with no IR sensor on them: the board file's [analog] voltage,
 *     or for an `open` (unconnected) pin its own state: driven as an output,
 *     its level; input with the pull-up on, VCC (the pull-up's 20-50 kohm
 *     against the ADC's ~100 Mohm input); floating, the last conversion's
 *     input, whatever channel it was, held on the sample-and-hold capacitor
 *     (ATmega328P datasheet 24.6.1, analog input circuitry: the 14 pF
 *     capacitor is all a floating pin offers; 0 V after power-on). A
 *     deterministic stand-in for a real floating pin's drifting reading.
 * simavr 1.6 has no timer or external auto-trigger: a firmware that selects
 * one is stopped with one line (board_adc_check). No IRQ tells the
 * auto-trigger bits: they are read through simavr's description of the
 * ADC (avr_adc_t: its ADATE and ADTS register bits). */
#include "board_adc.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#include <simavr/avr_adc.h>
#include <simavr/avr_ioport.h>
#include <simavr/sim_avr.h>
#include <simavr/sim_io.h>
#include <simavr/sim_irq.h>
#include <simavr/sim_regbit.h>

#include "world/analog.h"
#include "world/sensors/ir.h"

/* An ADC pin no part drives (channel ch, see the top of the file), V. */
static double undriven_volts(board_adc_t *a, unsigned ch)
{
    int i = (int)ch - BOARD_ANALOG_FIRST;
    if (i < 0 || i >= BOARD_ANALOG_N) return 0.0;
    if (a->spec->analog[i].wired) return a->spec->analog[i].v;
    avr_ioport_state_t st;
    if (avr_ioctl(a->avr, AVR_IOCTL_IOPORT_GETSTATE('C'), &st) < 0) return a->held_mv / 1000.0;
    unsigned bit = 1u << ch; /* ADC4/ADC5 are PC4/PC5 */
    if (st.ddr & bit) return st.port & bit ? a->spec->vcc_v : 0.0;
    if (st.port & bit) return a->spec->vcc_v;
    return a->held_mv / 1000.0;
}

/* channel ch's voltage now (not the ladder's), V */
static double channel_volts(board_adc_t *a, unsigned ch)
{
    const board_spec_t *sp = a->spec;
    if ((int)ch == sp->bat_channel) /* the supply after the diode (board.c sets its drop on the sim), divided */
        return analog_divider_v(a->sim, sp->bat_r_top_ohm, sp->bat_r_bottom_ohm);
    int ir = a->ir_of_channel[ch];
    if (ir < 0) return undriven_volts(a, ch);
    for (int e = 0; e < sp->nemitters; e++) sim_emitter_set(a->sim, (unsigned)sp->emitter_group[e], (int)a->emitter_on[e]);
    /* counts -> the voltage that converts back to the same count (rounded up to the mV) */
    return ceil(analog_ir_mv(a->sim, (unsigned)ir, sp->vcc_v, 1023.0)) / 1000.0;
}

/* channel ch's input now, mV rounded up (the ladder's as its part gives it) */
static double channel_mv(board_adc_t *a, unsigned ch)
{
    if ((int)ch == a->spec->sw_channel) return (double)a->ladder_mv;
    return ceil(channel_volts(a, ch) * 1000.0 - 1e-9);
}

/* the inputs from the other parts (board.c connects their outputs) */
static void on_input(struct avr_irq_t *irq, uint32_t value, void *param)
{
    board_adc_t *a = param;
    if (irq->irq == BOARD_ADC_IN_LADDER) a->ladder_mv = value;
    else if (irq->irq - BOARD_ADC_IN_EMITTER < BOARD_ADC_EMITTERS) a->emitter_on[irq->irq - BOARD_ADC_IN_EMITTER] = value != 0;
}

static void on_trigger(struct avr_irq_t *irq, uint32_t value, void *param)
{
    board_adc_t *a = param;
    union {
        avr_adc_mux_t mux;
        uint32_t v;
    } e = { .v = value };
    (void)irq;
    if (e.mux.kind != ADC_MUX_SINGLE || e.mux.src >= BOARD_ADC_CHANNELS) return;
    unsigned ch = e.mux.src;
    a->st->adc_conversions[ch]++;
    double mv = channel_mv(a, ch);
    if (mv < 0) mv = 0;
    if (mv > a->spec->vcc_v * 1000.0) mv = a->spec->vcc_v * 1000.0;
    a->held_mv = mv;
    avr_raise_irq(a->in[ch], (uint32_t)mv);
}

/* the robot's IR sensors onto the channels their adc_channel names */
static int map_ir(board_adc_t *a, char *err, size_t errn)
{
    const simcfg_t *c = a->sim->model->cfg; /* the robot file as given: its path and names for the message */
    int nir = sim_ir_count(a->sim);
    for (int i = 0; i < nir; i++) {
        int k = robot_part_of_kind(c, "ir", (unsigned)i);
        const ir_part_spec_t *ps = (const ir_part_spec_t *)(const void *)c->robot.part[k].spec;
        int ch = (int)ps->adc_channel;
        if (ch < 0) continue;
        if (ch >= BOARD_ADC_CHANNELS || ch == a->spec->sw_channel || ch == a->spec->bat_channel) {
            snprintf(err, errn, "%s: ir.%s.adc_channel %d: the board %s has no free ADC channel %d (switches on %d, battery on %d)",
                     c->robot.path, c->robot.part[k].name, ch, a->spec->name, ch, a->spec->sw_channel, a->spec->bat_channel);
            return -1;
        }
        a->ir_of_channel[ch] = i;
    }
    return 0;
}

int board_adc_init(board_adc_t *a, avr_t *avr, const board_spec_t *spec, sim_state_t *sim, board_stats_t *st, char *err,
                   size_t errn)
{
    static const char *names[BOARD_ADC_INPUTS] = { "adc.ladder_mv", "adc.emitter0", "adc.emitter1", "adc.emitter2", "adc.emitter3",
                                                   "adc.emitter4", "adc.emitter5", "adc.emitter6", "adc.emitter7" };
    memset(a, 0, sizeof *a);
    a->avr = avr;
    a->spec = spec;
    a->sim = sim;
    a->st = st;
    a->input = avr_alloc_irq(&avr->irq_pool, 0, BOARD_ADC_INPUTS, names);
    for (int i = 0; i < BOARD_ADC_INPUTS; i++) avr_irq_register_notify(&a->input[i], on_input, a);
    for (int ch = 0; ch < BOARD_ADC_CHANNELS; ch++) {
        a->ir_of_channel[ch] = -1;
        a->in[ch] = avr_io_getirq(avr, AVR_IOCTL_ADC_GETIRQ, ch);
    }
    if (map_ir(a, err, errn) != 0) return -1;
    for (avr_io_t *io = avr->io_port; io; io = io->next)
        if (io->kind && !strcmp(io->kind, "adc")) a->adc = (const avr_adc_t *)(const void *)io; /* simavr's ADC starts with its avr_io_t */
    avr_irq_t *trig = avr_io_getirq(avr, AVR_IOCTL_ADC_GETIRQ, ADC_IRQ_OUT_TRIGGER);
    if (!trig || !a->in[0] || !a->adc) {
        snprintf(err, errn, "the MCU '%s' has no ADC in simavr", spec->mcu);
        return -1;
    }
    avr_irq_register_notify(trig, on_trigger, a);
    return 0;
}

int board_adc_check(const board_adc_t *a, char *err, size_t errn)
{
    avr_adc_t *adc = (avr_adc_t *)(void *)a->adc; /* simavr's regbit readers take it non-const; they only read */
    if (!avr_regbit_get(a->avr, adc->adate)) return 0; /* ADATE off */
    unsigned adts = avr_regbit_get_array(a->avr, adc->adts, ARRAY_SIZE(adc->adts));
    if (adts == 0) return 0;            /* free running: simavr does it */
    static const char *names[8] = { "free running", "analog comparator", "external interrupt 0", "timer0 compare A",
                                    "timer0 overflow", "timer1 compare B", "timer1 overflow", "timer1 capture" };
    snprintf(err, errn, "the firmware selects ADC auto-trigger source %u (%s, ADCSRB.ADTS), which simavr 1.6 does not emulate",
             adts, adts < 8 ? names[adts] : "?");
    return -1;
}

/* board_motor.c - the motor driver part (board_motor.h).
 *
 * The pins: the direction pin's level, and whether the PWM pin is an
 * output, come from the ports' IRQs (IOPORT_IRQ_DIRECTION_ALL and
 * IOPORT_IRQ_REG_PORT: every write to DDRx, PORTx or PINx raises them with
 * the register's new value); the level a pin drives is PORT if it is an
 * output, else 0 (floating: the driver's pull-down).
 *
 * The duty is sampled once per physics step (board_motor_step, after the
 * step's cycles) from Timer1's state: waveform mode, TOP, compare value,
 * COM bits and clock select. simavr 1.6 has no IRQ for most of that: its
 * TIMER_IRQ_OUT_PWM0/1 carry OCR1A/B only when the firmware writes an OCR
 * while the timer is already in a PWM mode, and nothing is raised when
 * TCCR1A/B (mode, COM, clock) or ICR1 change. So the part reads them
 * through simavr's own description of Timer1 (avr_timer_t: its wgm, cs and
 * COM register bits, its OCR and ICR addresses), as simavr's timer does,
 * rather than through fixed register addresses. The waveform modes' TOP
 * and slope are the datasheet's table below, not simavr's: simavr 1.6's
 * table for the ATmega48/88/168/328 (avr_timer_t.wgm_op) has no phase
 * correct modes 1-3, 10 and 11 and gives the fast PWM modes 14 and 15 its
 * phase correct kind. */
#include "board_motor.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#include <simavr/avr_ioport.h>
#include <simavr/avr_timer.h>
#include <simavr/sim_avr.h>
#include <simavr/sim_io.h>
#include <simavr/sim_irq.h>
#include <simavr/sim_regbit.h>

static void on_ddr(struct avr_irq_t *irq, uint32_t value, void *param)
{
    (void)irq;
    *(uint8_t *)param = (uint8_t)value;
}

static void on_port(struct avr_irq_t *irq, uint32_t value, void *param)
{
    (void)irq;
    *(uint8_t *)param = (uint8_t)value;
}

int board_motor_init(board_motor_t *m, avr_t *avr, const board_spec_t *spec, board_stats_t *st, char *err, size_t errn)
{
    memset(m, 0, sizeof *m);
    m->avr = avr;
    m->st = st;
    for (int i = 0; i < 2; i++) {
        m->dir[i] = spec->motor_dir[i];
        m->pwm[i] = spec->motor_pwm[i];
        m->oc[i] = spec->motor_oc[i];
        m->fwd_level[i] = spec->motor_fwd_level[i];
        st->duty_min[i] = st->duty_max[i] = 0.0;
    }
    for (avr_io_t *io = avr->io_port; io; io = io->next)
        if (io->kind && !strcmp(io->kind, "timer") && io->irq_ioctl_get == AVR_IOCTL_TIMER_GETIRQ('1'))
            m->timer1 = (const avr_timer_t *)(const void *)io; /* simavr's timer starts with its avr_io_t */
    if (!m->timer1) return snprintf(err, errn, "the MCU '%s' has no Timer1 in simavr", avr->mmcu), -1;
    for (int p = 0; p < BOARD_PORTS; p++) {
        char name = (char)('B' + p);
        avr_irq_register_notify(avr_io_getirq(avr, AVR_IOCTL_IOPORT_GETIRQ(name), IOPORT_IRQ_DIRECTION_ALL), on_ddr, &m->ports[p].ddr);
        avr_irq_register_notify(avr_io_getirq(avr, AVR_IOCTL_IOPORT_GETIRQ(name), IOPORT_IRQ_REG_PORT), on_port, &m->ports[p].port);
    }
    return 0;
}

static int is_output(const board_motor_t *m, board_pin_t p) { return m->ports[p.port - 'B'].ddr >> p.bit & 1; }
static int pin_level(const board_motor_t *m, board_pin_t p) { return is_output(m, p) && (m->ports[p.port - 'B'].port >> p.bit & 1); }

/* a 16-bit register of Timer1 (low byte, high byte: 0 if none) */
static unsigned reg16(const avr_t *avr, avr_io_addr_t lo, avr_io_addr_t hi) { return avr->data[lo] | (hi ? (unsigned)avr->data[hi] << 8 : 0u); }

/* TOP of waveform mode wgm, and whether it is phase correct (1), fast (0) or no PWM (-1) */
static int timer1_top(const board_motor_t *m, unsigned wgm, unsigned *top)
{
    static const int kind[16] = { -1, 1, 1, 1, -1, 0, 0, 0, 1, 1, 1, 1, -1, -1, 0, 0 };
    static const unsigned fixed[16] = { 0xFFFF, 0xFF, 0x1FF, 0x3FF, 0, 0xFF, 0x1FF, 0x3FF };
    const avr_timer_t *t = m->timer1;
    if (wgm == 8 || wgm == 10 || wgm == 12 || wgm == 14) *top = reg16(m->avr, t->r_icr, t->r_icrh);
    else if (wgm == 4 || wgm == 9 || wgm == 11 || wgm == 15) *top = reg16(m->avr, t->comp[0].r_ocr, t->comp[0].r_ocrh);
    else *top = fixed[wgm];
    return kind[wgm];
}

double board_motor_duty(const board_motor_t *m, int i)
{
    avr_timer_t *t = (avr_timer_t *)(void *)m->timer1; /* simavr's regbit readers take it non-const; they only read */
    int oc = m->oc[i];
    unsigned com = avr_regbit_get(m->avr, t->comp[oc].com);
    unsigned wgm = avr_regbit_get_array(m->avr, t->wgm, ARRAY_SIZE(t->wgm));
    unsigned cs = avr_regbit_get_array(m->avr, t->cs, ARRAY_SIZE(t->cs)), top;
    int kind = timer1_top(m, wgm, &top);
    unsigned ocr = reg16(m->avr, t->comp[oc].r_ocr, t->comp[oc].r_ocrh);
    double duty;
    if (com == 0 || cs == 0) duty = pin_level(m, m->pwm[i]); /* a plain pin (analogWrite 0 or 255), or the timer stopped */
    else if (!is_output(m, m->pwm[i])) duty = 0.0;          /* the timer drives a pin that is not an output */
    else if (kind < 0 || com == 1) duty = com == 1 ? 0.5 : com == 3 ? 1.0 : 0.0; /* toggle on match: a square wave; set/clear: a level */
    else {
        double on = kind == 0 ? (ocr >= top ? 1.0 : (ocr + 1.0) / (top + 1.0)) : (ocr >= top ? 1.0 : (double)ocr / (top ? top : 1));
        duty = com == 2 ? on : 1.0 - on;
    }
    int fwd = pin_level(m, m->dir[i]) == m->fwd_level[i];
    return fwd ? duty : -duty;
}

void board_motor_step(board_motor_t *m, int cmd[2])
{
    for (int i = 0; i < 2; i++) {
        double d = board_motor_duty(m, i);
        if (d < m->st->duty_min[i]) m->st->duty_min[i] = d;
        if (d > m->st->duty_max[i]) m->st->duty_max[i] = d;
        long c = lround(d * 1023.0);
        cmd[i] = (int)(c > 1023 ? 1023 : c < -1023 ? -1023 : c);
    }
}

/* board_motor.c - the motor driver (a TB6612FNG on UKMARSBOT): each motor's
 * PWM input is a Timer1 output (OC1A or OC1B), its direction a plain pin.
 * At each physics step the duty is read from Timer1's registers as they
 * are (waveform mode, TOP, compare value, COM bits; a pin the timer does
 * not drive is its port level), and the H-bridge applies that fraction of
 * the battery: sim_t.cmd = +-duty x 1023, the sign from the direction pin
 * (the board file says which level turns the wheel forward). ATmega48/88/
 * 168/328 register addresses. */
#include "board_int.h"

#include <math.h>

#include <simavr/sim_avr.h>

enum { TCCR1A = 0x80, TCCR1B = 0x81, ICR1L = 0x86, OCR1AL = 0x88, OCR1BL = 0x8A };

static unsigned reg16(const avr_t *avr, unsigned lo) { return avr->data[lo] | (unsigned)avr->data[lo + 1] << 8; }

/* the level a port pin drives: PORT if it is an output, else 0 (floating: the driver's pull-down) */
static int pin_level(const avr_t *avr, board_pin_t p)
{
    unsigned base = 0x23u + 3u * (unsigned)(p.port - 'B'); /* PINx, DDRx, PORTx */
    return (avr->data[base + 1] >> p.bit & 1) && (avr->data[base + 2] >> p.bit & 1);
}

/* TOP of waveform mode wgm, and whether it is phase correct (1), fast (0) or no PWM (-1) */
static int timer1_top(const avr_t *avr, unsigned wgm, unsigned *top)
{
    static const int kind[16] = { -1, 1, 1, 1, -1, 0, 0, 0, 1, 1, 1, 1, -1, -1, 0, 0 };
    static const unsigned fixed[16] = { 0xFFFF, 0xFF, 0x1FF, 0x3FF, 0, 0xFF, 0x1FF, 0x3FF };
    if (wgm == 8 || wgm == 10 || wgm == 12 || wgm == 14) *top = reg16(avr, ICR1L);
    else if (wgm == 4 || wgm == 9 || wgm == 11 || wgm == 15) *top = reg16(avr, OCR1AL);
    else *top = fixed[wgm];
    return kind[wgm];
}

double board_motor_duty(board_t *b, int m)
{
    const avr_t *avr = b->avr;
    const board_spec_t *sp = &b->spec;
    int oc = sp->motor_oc[m];
    unsigned a = avr->data[TCCR1A], bb = avr->data[TCCR1B];
    unsigned com = (a >> (oc ? 4 : 6)) & 3u, wgm = (a & 3u) | ((bb >> 3) & 3u) << 2, top;
    int kind = timer1_top(avr, wgm, &top);
    unsigned ocr = reg16(avr, oc ? OCR1BL : OCR1AL);
    unsigned ddr = avr->data[0x24u + 3u * (unsigned)(sp->motor_pwm[m].port - 'B')] >> sp->motor_pwm[m].bit & 1;
    double duty;
    if (com == 0 || (bb & 7u) == 0) duty = pin_level(avr, sp->motor_pwm[m]); /* a plain pin (analogWrite 0 or 255), or the timer stopped */
    else if (!ddr) duty = 0.0;                                               /* the timer drives a pin that is not an output */
    else if (kind < 0 || com == 1) duty = com == 1 ? 0.5 : com == 3 ? 1.0 : 0.0; /* toggle on match: a square wave; set/clear: a level */
    else {
        double on = kind == 0 ? (ocr >= top ? 1.0 : (ocr + 1.0) / (top + 1.0)) : (ocr >= top ? 1.0 : (double)ocr / (top ? top : 1));
        duty = com == 2 ? on : 1.0 - on;
    }
    int fwd = pin_level(avr, sp->motor_dir[m]) == sp->motor_fwd_level[m];
    return fwd ? duty : -duty;
}

void board_motor_step(board_t *b)
{
    for (int m = 0; m < 2; m++) {
        double d = board_motor_duty(b, m);
        if (d < b->st.duty_min[m]) b->st.duty_min[m] = d;
        if (d > b->st.duty_max[m]) b->st.duty_max[m] = d;
        long c = lround(d * 1023.0);
        b->sim->cmd[m] = (int)(c > 1023 ? 1023 : c < -1023 ? -1023 : c);
    }
}

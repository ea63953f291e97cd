/* board_switch.c - the switches part (board_switch.h). */
#include "board_switch.h"

#include <math.h>

#include <simavr/sim_avr.h>
#include <simavr/sim_irq.h>

double board_switch_volts(const board_spec_t *sp, unsigned n, int button)
{
    if (button) return sp->vcc_v; /* the button ties the pin to VCC */
    double below = sp->sw_r_ground_ohm;
    for (int k = 0; k < 4; k++)
        if (!(n >> k & 1u)) below += sp->sw_r_ohm[k]; /* a closed switch shorts its resistor */
    return sp->vcc_v * below / (sp->sw_r_top_ohm + below);
}

void board_switches_init(board_switches_t *s, avr_t *avr, const board_spec_t *spec)
{
    s->spec = spec;
    s->switches = 0;
    s->button = 0;
    static const char *names[1] = { "switches.ladder_mv" };
    s->out = avr_alloc_irq(&avr->irq_pool, 0, 1, names);
}

void board_switches_set(board_switches_t *s, unsigned switches, int button)
{
    s->switches = switches;
    s->button = button;
    avr_raise_irq(s->out, (uint32_t)ceil(board_switches_volts(s) * 1000.0 - 1e-9));
}

double board_switches_volts(const board_switches_t *s) { return board_switch_volts(s->spec, s->switches, s->button); }

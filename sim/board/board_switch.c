/* board_switch.c - the switches part (board_switch.h). */
#include "board_switch.h"

double board_switch_volts(const board_spec_t *sp, unsigned n, int button)
{
    if (button) return sp->vcc_v; /* the button ties the pin to VCC */
    double below = sp->sw_r_ground_ohm;
    for (int k = 0; k < 4; k++)
        if (!(n >> k & 1u)) below += sp->sw_r_ohm[k]; /* a closed switch shorts its resistor */
    return sp->vcc_v * below / (sp->sw_r_top_ohm + below);
}

void board_switches_init(board_switches_t *s, const board_spec_t *spec)
{
    s->spec = spec;
    s->switches = 0;
    s->button = 0;
}

double board_switches_volts(const board_switches_t *s) { return board_switch_volts(s->spec, s->switches, s->button); }

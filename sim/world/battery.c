/* battery.c - open-circuit voltage table, sag and charge (see battery.h). */
#include "battery.h"

#define COULOMB_PER_MAH 3.6  /* 1 mAh = 1e-3 A * 3600 s */

/* The UKMARSBOT's documents name "the rechargeable PP3 sized pack running at
 * 8.4 Volts or 9 Volts" (ukmarsbot README.md, "Power Supply") within "7 and
 * 12 volts" (docs/requirements.md); mazerunner-core's battery divider is
 * 10k/10k on a 5 V ADC, up to 10 V (config-robot-orion.h, BATTERY_R1/R2).
 * An "8.4 V" PP3 is either seven NiMH cells (8.4 V nominal) or two Li-ion
 * cells (8.4 V full); ours: the two Li-ion cells (the README's "LiPo ... as
 * part of a regulated and protected pack"), a table of cell voltages: */
void battery_spec_default(battery_spec_t *s)
{
    /* ours: a typical Li-ion/LiPo cell's resting voltage every 10 % of charge,
     * 3.30 V empty .. 4.20 V full (4.20 V is the cells' charge voltage, 8.4 V
     * for two, as the README names), doubled for two cells; no pack
     * datasheet names the curve */
    static const double cell_v[BATTERY_OCV_MAX] = {
        3.30, 3.60, 3.68, 3.72, 3.75, 3.78, 3.83, 3.89, 3.96, 4.06, 4.20 };
    s->ocv_n = BATTERY_OCV_MAX;
    for (int i = 0; i < BATTERY_OCV_MAX; i++) s->ocv_v[i] = 2.0 * cell_v[i];
    s->r_ohm = 0.3;          /* ours: two small cells plus the pack's protection switch; no datasheet */
    s->capacity_mah = 500.0; /* ours: the order of rechargeable PP3 Li-ion packs; no datasheet */
    s->divider = 0.5;        /* mazerunner-core config-robot-orion.h: BATTERY_R1 = BATTERY_R2 = 10k */
}

void battery_init(battery_t *b, const battery_spec_t *s)
{
    b->spec = s;
    b->drawn_c = 0.0;
}

double battery_soc(const battery_t *b)
{
    double cap_c = b->spec->capacity_mah * COULOMB_PER_MAH;
    double soc = cap_c > 0.0 ? 1.0 - b->drawn_c / cap_c : 1.0;
    return soc < 0.0 ? 0.0 : soc > 1.0 ? 1.0 : soc;
}

double battery_ocv(const battery_t *b)
{
    const battery_spec_t *s = b->spec;
    if (s->ocv_n <= 1) return s->ocv_v[0];
    double x = battery_soc(b) * (s->ocv_n - 1);
    int i = (int)x;
    int last = s->ocv_n - 1;
    if (i >= last) return s->ocv_v[last];
    return s->ocv_v[i] + (x - i) * (s->ocv_v[i + 1] - s->ocv_v[i]);
}

double battery_voltage(battery_t *b, double current_a)
{
    return battery_ocv(b) - b->spec->r_ohm * current_a;
}

void battery_draw(battery_t *b, double current_a, double dt_s)
{
    b->drawn_c += current_a * dt_s;
}

double battery_drawn_mah(const battery_t *b) { return b->drawn_c / COULOMB_PER_MAH; }

double battery_spec_full_v(const battery_spec_t *s) { return s->ocv_v[s->ocv_n >= 1 ? s->ocv_n - 1 : 0]; }

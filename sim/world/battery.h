/* battery.h - the robot's battery: open-circuit voltage by state of charge,
 * internal resistance, charge drawn. The robot file's [battery.*] section
 * sets it up; sim.c steps it with the H-bridges' currents and feeds the
 * motors its voltage; the firmware reads it through hal_battery_mv.
 *
 *   soc = 1 - Q / C                    Q = charge drawn (C), C = capacity (C);
 *                                      clamped to 0..1 for the voltage
 *   Voc(soc) = linear interpolation in ocv_v[], ocv_n points evenly spaced
 *              from soc 0 (ocv_v[0]) to soc 1 (ocv_v[ocv_n-1]); one point =
 *              a constant voltage
 *   V = Voc(soc) - R * I               I > 0 = discharge, A
 *   battery_draw: Q += I * dt          (I < 0 charges)
 * No noise, so no rng stream. */
#ifndef BATTERY_H
#define BATTERY_H

#define BATTERY_OCV_MAX 11  /* ours: 11 points = every 10 % of charge */

typedef struct {
    int ocv_n;                       /* points in ocv_v, 1..BATTERY_OCV_MAX */
    double ocv_v[BATTERY_OCV_MAX];   /* open-circuit voltage at soc = i/(ocv_n-1), V */
    double r_ohm;                    /* internal resistance, ohm */
    double capacity_mah;             /* capacity, mAh */
    double divider;                  /* what the robot's ADC sees of it: V_adc / V_battery (hal_battery_mv reports V) */
} battery_spec_t;

typedef struct {
    const battery_spec_t *spec;      /* battery_init's (the caller's: it outlives the battery) */
    double drawn_c;                  /* charge drawn since full, coulombs */
} battery_t;

/* The defaults: a 2-cell Li-ion/LiPo pack, 8.4 V full (values and sources in battery.c). */
void battery_spec_default(battery_spec_t *s);
/* The open-circuit voltage when full, V. */
double battery_spec_full_v(const battery_spec_t *s);
/* Full at init (soc 1). */
void battery_init(battery_t *b, const battery_spec_t *s);
/* State of charge, 0..1 (clamped). */
double battery_soc(const battery_t *b);
/* The open-circuit voltage at the present state of charge, V. */
double battery_ocv(const battery_t *b);
/* The terminal voltage while current_a flows out, V: Voc(soc) - R * I. */
double battery_voltage(battery_t *b, double current_a);
/* current_a flowing for dt_s: the charge drawn grows by I * dt. */
void battery_draw(battery_t *b, double current_a, double dt_s);
/* The charge drawn since full, mAh. */
double battery_drawn_mah(const battery_t *b);

#endif

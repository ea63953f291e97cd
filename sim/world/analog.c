/* analog.c - the voltages a board's ADC pins see (see analog.h). */
#include "analog.h"

#include "world/robot.h"
#include "world/sensors/ir.h"

double analog_ir_mv(sim_state_t *s, unsigned i, double full_scale_v, double full_counts)
{
    unsigned c = sim_ir_read(s, i);
    return c * full_scale_v * 1000.0 / full_counts;
}

double analog_ir_full_counts(const sim_state_t *s, unsigned i)
{
    const simcfg_t *c = s->model->cfg;
    int k = robot_part_of_kind(c, "ir", i);
    if (k < 0) return 1023.0;
    const ir_part_spec_t *ps = (const ir_part_spec_t *)(const void *)c->robot.part[k].spec;
    return (double)((1 << (int)ps->model.adc_bits) - 1);
}

double analog_divider_v(const sim_state_t *s, double r_top_ohm, double r_bottom_ohm)
{
    return sim_supply_v(s) * r_bottom_ohm / (r_top_ohm + r_bottom_ohm);
}

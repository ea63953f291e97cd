/* bench.c - the validation benches (bench.h): an open field or a
 * corridor of cells, step counts, and the table a check is added to. */
#include "validate/bench.h"

#include <math.h>

#include "world/robot.h"
#include "world/sensors/ir.h"

bench_t bench; /* one at a time; maze_t and sim_state_t are large */

void bench_field(maze_t *m, uint8_t w, uint8_t h, uint8_t sx)
{
    maze_init(m, w, h);
    maze_close_unknown(m);
    for (uint8_t y = 0; y < h; y++)
        for (uint8_t x = 0; x < w; x++) {
            maze_cell_t c = maze_cell(m, x, y);
            if (x + 1 < w) maze_set_wall(m, c, MAZE_EAST, MAZE_WALL_OPEN);
            if (y + 1 < h) maze_set_wall(m, c, MAZE_NORTH, MAZE_WALL_OPEN);
        }
    m->start = maze_cell(m, sx, 0);
    m->start_heading = MAZE_NORTH;
}

void bench_corridor(maze_t *m, uint8_t n)
{
    maze_init(m, n, 1);
    maze_close_unknown(m);
    for (uint8_t x = 0; x + 1 < n; x++) maze_set_wall(m, maze_cell(m, x, 0), MAZE_EAST, MAZE_WALL_OPEN);
    m->start = maze_cell(m, 0, 0);
    m->start_heading = MAZE_EAST;
}

int bench_init(const simcfg_t *c)
{
    sim_model_build(&bench.model, c, 1);
    return sim_init(&bench.sim, &bench.model, &bench.maze, 1);
}

long bench_steps(const simcfg_t *c, double seconds) { return lround(seconds / c->sim.step_s); }

void bench_add(validate_check_t *v, int *n, const char *name, double expected, double measured, const char *unit,
                double tol_pct, int bound, const char *source)
{
    validate_check_t *k = &v[(*n)++];
    k->name = name;
    k->expected = expected;
    k->measured = measured;
    k->unit = unit;
    k->tolerance_pct = tol_pct;
    k->bound = bound;
    k->source = source;
    k->kind = VALIDATE_PREDICTED;
    if (bound == VALIDATE_NEAR) k->pass = fabs(measured - expected) <= tol_pct / 100.0 * fabs(expected);
    else if (bound == VALIDATE_MAX) k->pass = measured <= expected;
    else k->pass = 1;
}

void bench_fit(validate_check_t *v, int *n, const char *name, double expected, double measured, const char *unit,
               const char *source)
{
    bench_add(v, n, name, expected, measured, unit, 0, VALIDATE_REPORT, source);
    v[*n - 1].kind = VALIDATE_FITTED;
}

/* Sensor i's mean lit-minus-dark over 64 samples, the robot where it is. */
double bench_lit_minus_dark(sim_state_t *s, unsigned i)
{
    const robot_part_t *p = &s->model->cfg->robot.part[robot_part_of_kind(s->model->cfg, "ir", i)];
    unsigned g = (unsigned)((const ir_part_spec_t *)p->spec)->emitter;
    double sum = 0;
    for (int k = 0; k < 64; k++) {
        sim_emitter_set(s, g, 0);
        double dark = sim_ir_read(s, i);
        sim_emitter_set(s, g, 1);
        sum += sim_ir_read(s, i) - dark;
    }
    sim_emitter_set(s, g, 0);
    return sum / 64;
}

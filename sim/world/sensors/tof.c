/* tof.c - ToF noise and clamps, and the [tof.NAME] sensor kind (see tof.h). */
#include "tof.h"

#include <math.h>

#include "sensor.h"

void tof_init(tof_t *t, const tof_spec_t *s, uint64_t seed, unsigned index)
{
    t->spec = s;
    rng_init(&t->rng, seed, RNG_STREAM_TOF + index);
}

double tof_gauss(tof_t *t) { return rng_gauss(&t->rng); }

tof_reading_t tof_measure(tof_t *t, double true_m)
{
    tof_reading_t out = { t->spec->range_m, 1 };
    if (true_m < 0.0 || true_m >= t->spec->range_m) return out;
    double d = true_m < t->spec->blind_m ? t->spec->blind_m : true_m;
    d += t->spec->cv * d * tof_gauss(t);
    if (d < 0.0) d = 0.0;
    if (d >= t->spec->range_m) return out; /* at or beyond the range: a timeout, as the paper's Unity sensor */
    out.dist_m = d;
    out.timeout = 0;
    return out;
}

/* ---- the sensor kind ---- */

#define T(name, field, def, min, max, per, unit, src) \
    { NULL, #name, offsetof(tof_spec_t, field), def, min, max, unit, src, NULL, 0, per, 0, KEYTAB_DOUBLE, 0, NULL }
static const keytab_t keys[] = {
    T(range_mm, range_m, 1200, 50, 10000, 1000, "mm", "VL53L0X long range, as the paper's simulator (its Arduino side assumed 1.0 m)"),
    T(blind_mm, blind_m, 0, 0, 500, 1000, "mm", "paper: no blind spot modelled"),
    T(cv, cv, 0.05, 0, 1, 0, "1", "noise sigma = cv * distance (paper)"),
    T(period_ms, period_s, 30, 1, 1000, 1000, "ms", "VL53L0X default timing budget ~30 ms"),
};

static void init(void *state, const robot_part_t *p, const sim_model_t *md, uint64_t seed, unsigned index, unsigned count)
{
    tof_state_t *t = state;
    const tof_spec_t *s = (const tof_spec_t *)p->spec;
    tof_init(&t->tof, s, seed, index);
    t->period_steps = (uint64_t)llround(s->period_s / md->cfg->sim.step_s);
    if (t->period_steps == 0) t->period_steps = 1;
    t->next_step = (uint64_t)index * t->period_steps / count; /* staggered */
    t->last.dist_m = s->range_m;
    t->last.timeout = 1;
    t->true_m = -1;
    t->count = 0;
    t->enabled = 1;
}

/* The ray: from the sensor along its heading (the chassis' tilt aside). */
static double ray(const sim_pose_t *pose, world_t *w, double max_m)
{
    double pos[3], axis[3], left[3], up[3];
    sensor_frame(w, pose, pos, axis, left, up);
    return world_ray(w, pos[0], pos[1], pos[2], atan2(axis[1], axis[0]), max_m);
}

static void step(void *state, const robot_part_t *p, const sensor_ctx_t *x)
{
    tof_state_t *t = state;
    if (x->step < t->next_step) return;
    t->next_step += t->period_steps;
    if (!t->enabled) return;
    /* rays only when the sensor updates: one ray per 30 ms, not per step */
    if (x->t_s < t->object_until_s) t->true_m = t->object_m; /* a hand before it */
    else t->true_m = ray(sensor_pose(x->model, p), x->world, t->tof.spec->range_m);
    t->last = tof_measure(&t->tof, t->true_m);
    t->count++;
}

static int read(void *state, const robot_part_t *p, const sensor_ctx_t *x, double v[SENSOR_VALUES])
{
    const tof_state_t *t = state;
    v[0] = t->last.dist_m * 1000.0;
    v[1] = t->last.timeout;
    v[2] = t->true_m < 0 ? -1 : t->true_m * 1000.0;
    return 3;
}

const sensor_kind_t sensor_tof = {
    "tof", "time-of-flight distance sensor (the paper's model: a ray, Gaussian noise of cv * distance, timeout at range)",
    keys, sizeof keys / sizeof keys[0], NULL, sizeof(tof_state_t), init, step, read, "mm timeout true_mm",
};

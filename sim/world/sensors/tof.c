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
    if (true_m < 0.0 || true_m > t->spec->range_m) return out; /* no return signal: a timeout */
    double d = true_m < t->spec->blind_m ? t->spec->blind_m : true_m;
    d += t->spec->cv * d * tof_gauss(t);
    out.dist_m = d < 0.0 ? 0.0 : d;
    out.timeout = 0;
    return out;
}

/* ---- the sensor kind ---- */

/* The ranging profiles of ST's VL53L0X datasheet (DocID029104 Rev 1,
 * Table 13 "Range profiles"), in the order of the `profile` key's words:
 * the timing budget (the period of continuous ranging) and the typical
 * range on a white (88 %) target filling the cone indoors (Table 11:
 * 120 cm at 33 ms with at least 94 % of readings valid; 200 cm+ with the
 * long range profile), as the maze's white wall faces are. Their accuracy
 * is not taken from the table: tof_cv_at gives it from the budget. */
static const char *const profile_names[] = { "default", "high_accuracy", "long_range", "high_speed" };
static const struct {
    double period_ms, range_mm;
} profiles[] = {
    { 30, 1200 },
    { 200, 1200 },
    { 33, 2000 },
    { 20, 1200 },
};

/* The one accuracy figure the model is built from: DocID029104 Table 12,
 * a white (88 %) target at 120 cm indoors with a 33 ms timing budget,
 * 4 % as one standard deviation (section 5.3.1 characterises the ranging
 * accuracy by its standard deviation). */
#define CV_REF 0.04
#define BUDGET_REF_S 0.033

double tof_cv_at(double budget_s) { return CV_REF * sqrt(BUDGET_REF_S / budget_s); }

#define T(name, field, def, min, max, per, unit, src) \
    { NULL, #name, offsetof(tof_spec_t, field), def, min, max, unit, src, NULL, 0, per, 0, KEYTAB_DOUBLE, 0, NULL }
static const keytab_t keys[] = {
    { NULL, "profile", offsetof(tof_spec_t, profile), 0, 0, 3, "word",
      "VL53L0X datasheet DocID029104 Table 13: the ranging profile; sets period_ms, range_mm and cv unless given "
      "(docs/ROBOTS.md)",
      profile_names, 0, 0, 0, KEYTAB_DOUBLE, 0, NULL },
    T(range_mm, range_m, 1200, 50, 10000, 1000, "mm",
      "the profile's unless given: a white target farther than this is a timeout (DocID029104 Tables 11, 13)"),
    T(blind_mm, blind_m, 0, 0, 500, 1000, "mm", "paper: no blind spot modelled"),
    T(cv, cv, 0.04 * 1.0488088481701516 /* x sqrt(33 / 30): the default period */, 0, 1, 0, "1",
      "unless given 0.04 x sqrt(33 ms / period): noise sigma = cv * distance (DocID029104 Table 12; the paper's Unity model: 0.05)"),
    T(period_ms, period_s, 30, 1, 1000, 1000, "ms", "the profile's unless given: its timing budget (DocID029104 Table 13)"),
    T(fov_deg, fov_rad, 0, 0, 90, 180.0 / M_PI, "deg", "the cone's full angle; VL53L0X datasheet DocID029104: 25 deg field of view; 0: the paper's one ray"),
    T(rays, rays, 5, 1, 61, 0, "1", "ours: rays across the cone (5: 6.25 deg apart at 25 deg)"),
};
#define NKEYS (sizeof keys / sizeof keys[0])

extern const sensor_kind_t sensor_tof;

/* The key's bit in a part's given mask is its index in keys[]. */
static int given_key(uint64_t given, const char *key)
{
    const keytab_t *k = keytab_find(keys, NKEYS, NULL, key);
    return k && (given >> (k - keys) & 1u);
}

void tof_complete(robot_part_t *p, uint64_t given)
{
    if (p->kind != &sensor_tof) return;
    tof_spec_t *s = (tof_spec_t *)(void *)p->spec;
    int i = (int)s->profile;
    if (!given_key(given, "period_ms")) s->period_s = profiles[i].period_ms / 1000.0;
    if (!given_key(given, "range_mm")) s->range_m = profiles[i].range_mm / 1000.0;
    if (!given_key(given, "cv")) s->cv = tof_cv_at(s->period_s);
}

static void init(void *state, const robot_part_t *p, const sim_model_t *md, uint64_t seed, unsigned index, unsigned count)
{
    tof_state_t *t = state;
    const tof_spec_t *s = (const tof_spec_t *)p->spec;
    tof_init(&t->tof, s, seed, index);
    t->period_steps = (uint64_t)llround(s->period_s / md->step_s);
    if (t->period_steps == 0) t->period_steps = 1;
    t->next_step = (uint64_t)index * t->period_steps / count; /* staggered */
    t->last.dist_m = s->range_m;
    t->last.timeout = 1;
    t->true_m = -1;
    t->count = 0;
    t->enabled = 1;
}

/* The cone: rays from the sensor at its heading (the chassis' tilt aside)
 * plus angles spread evenly over [-fov/2, +fov/2]; the nearest hit, m (-1:
 * none within max_m). */
static double cone(const sim_pose_t *pose, const tof_spec_t *s, world_t *w, double max_m)
{
    double pos[3], axis[3], left[3], up[3];
    sensor_frame(w, pose, pos, axis, left, up);
    double heading = atan2(axis[1], axis[0]), best = -1.0;
    int n = s->fov_rad > 0.0 ? (int)lround(s->rays) : 1;
    for (int i = 0; i < n; i++) {
        double a = n > 1 ? s->fov_rad * ((double)i / (n - 1) - 0.5) : 0.0;
        double d = world_ray(w, pos[0], pos[1], pos[2], heading + a, max_m);
        if (d >= 0.0 && (best < 0.0 || d < best)) best = d;
    }
    return best;
}

static void step(void *state, const robot_part_t *p, const sensor_ctx_t *x)
{
    tof_state_t *t = state;
    if (x->step < t->next_step) return;
    t->next_step += t->period_steps;
    if (!t->enabled) return;
    /* rays only when the sensor updates: one ray per 30 ms, not per step */
    if (x->t_s < t->object_until_s) t->true_m = t->object_m; /* a hand before it */
    else t->true_m = cone(sensor_pose(x->model, p), t->tof.spec, x->world, t->tof.spec->range_m);
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
    "tof", "time-of-flight distance sensor: the nearest surface in its cone (fov_deg, rays; 0: the paper's one ray), a ranging profile's period, range (beyond it a timeout) and Gaussian noise of cv * distance",
    keys, NKEYS, NULL, sizeof(tof_state_t), init, step, read, "mm timeout true_mm",
};

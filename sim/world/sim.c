/* sim.c - one run's state stepped through its model (see sim.h). */
#include "sim.h"

#include <assert.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "world/sensors/gyro.h"
#include "world/sensors/ir.h"
#include "world/sensors/sensor.h"

static double start_heading(uint8_t d)
{
    static const double a[4] = { M_PI / 2, 0.0, -M_PI / 2, M_PI };
    return a[d & 3];
}

static sensor_ctx_t ctx(const sim_state_t *s)
{
    sensor_ctx_t x;
    double v;
    x.world = s->world;
    x.model = s->model;
    x.step = s->step;
    x.t_s = sim_time_s(s);
    x.emitter = s->emitter;
    world_velocity(s->world, &v, &x.yaw_rate_rad_s);
    return x;
}

/* The sensors' states, each from its kind; ToF sensors also the HAL's. */
static int parts_init(sim_state_t *s, uint64_t seed)
{
    const sim_model_t *m = s->model;
    s->ntof = 0;
    s->tof_range_m = 1.2;
    for (int i = 0; i < m->nparts; i++) {
        const robot_part_t *p = &m->part[i];
        const sensor_kind_t *k = p->kind;
        unsigned n = 0, kind_index = 0;
        for (int j = 0; j < m->nparts; j++) {
            n += m->part[j].kind == k;
            kind_index += j < i && m->part[j].kind == k;
        }
        s->part_state[i] = calloc(1, k->state_size);
        if (!s->part_state[i]) return -1;
        k->init(s->part_state[i], p, s->model, seed, kind_index, n);
        if (k == sensor_kind("tof") && s->ntof < WORLD_TOF_COUNT) {
            if (s->ntof == 0) s->tof_range_m = ((const tof_spec_t *)p->spec)->range_m;
            s->tof_part[s->ntof++] = i;
        }
    }
    return 0;
}

/* The HAL's copy of the ToF sensors' state. */
static void tof_mirror(sim_state_t *s)
{
    for (int i = 0; i < s->ntof; i++) {
        tof_state_t *t = s->part_state[s->tof_part[i]];
        s->tof_last[i] = t->last;
        s->tof_true_m[i] = t->true_m;
        s->tof_count[i] = t->count;
    }
}

int sim_init(sim_state_t *s, const sim_model_t *model, const truemaze_t *m, uint64_t seed)
{
    memset(s->part_state, 0, sizeof s->part_state);
    s->world = NULL;
    s->model = model;
    double cell = model->arena.cell_m;
    s->maze = m;
    s->seed = seed;
    double h = start_heading(m->start_heading), back = 0; /* m behind the cell's centre */
    if (model->start == ROBOT_START_BACK_TO_WALL) back = cell / 2 - model->arena.wall_thick_m / 2 - model->chassis.body_l_m / 2 - ROBOT_START_GAP_M;
    s->world = world_create(model, m, (truemaze_x(m, m->start) + 0.5) * cell - back * cos(h),
                            (truemaze_y(m, m->start) + 0.5) * cell - back * sin(h), h);
    if (!s->world) {
        sim_free(s);
        return -1;
    }
    battery_init(&s->battery, &model->battery);
    for (int i = 0; i < 2; i++) {
        const drive_spec_t *d = &model->drive[i];
        motor_init(&s->motor[i], d, battery_ocv(&s->battery), model->battery.r_ohm, model->motor_k_scale[i]);
        encoder_init(&s->encoder[i], d->encoder_ppr * d->gear_ratio, world_wheel_angle(s->world, i));
        s->cmd[i] = 0;
    }
    for (int g = 0; g < SIM_EMITTER_GROUPS; g++) s->emitter[g] = 0;
    for (int i = 0; i < WORLD_TOF_COUNT; i++) {
        s->tof_last[i].dist_m = 0;
        s->tof_last[i].timeout = 1;
        s->tof_true_m[i] = -1;
        s->tof_count[i] = 0;
    }
    s->tof_enabled = 1;
    s->diverged = 0;
    s->step = 0;
    s->push_from = s->push_steps = 0;
    s->push_m = s->push_rad = 0;
    s->supply_drop_v = 0;
    if (parts_init(s, seed) != 0) {
        sim_free(s);
        return -1;
    }
    tof_mirror(s);
    race_init(&s->race, m, cell, model->time_limit_s);
    return 0;
}

void sim_free(sim_state_t *s)
{
    world_destroy(s->world);
    s->world = NULL;
    for (int i = 0; i < ROBOT_MAX_PARTS; i++) {
        free(s->part_state[i]);
        s->part_state[i] = NULL;
    }
}

double sim_time_s(const sim_state_t *s) { return (double)s->step * s->model->step_s; }

/* The battery: each motor sees the open-circuit voltage less the other
 * motor's share of the sag (its own is solved in its circuit, motor.c);
 * the charge drawn is the H-bridges' input current. */
/* The current an H-bridge draws from the battery: duty x the motor's, A
 * (v_applied = duty x the supply it saw). */
static double bridge_in_a(const motor_t *m) { return fabs(m->v_applied * m->i_a) / (m->battery_v > 0 ? m->battery_v : 1); }

static void battery_step(sim_state_t *s, double dt)
{
    double i_in[2] = { bridge_in_a(&s->motor[0]), bridge_in_a(&s->motor[1]) };
    battery_draw(&s->battery, i_in[0] + i_in[1], dt);
    double ocv = battery_ocv(&s->battery), r = s->model->battery.r_ohm;
    for (int i = 0; i < 2; i++) s->motor[i].battery_v = fmax(ocv - r * i_in[1 - i] - s->supply_drop_v, 0.0);
}

void sim_set_supply_drop(sim_state_t *s, double drop_v)
{
    s->supply_drop_v = drop_v > 0 ? drop_v : 0;
    for (int i = 0; i < 2; i++) s->motor[i].battery_v = fmax(battery_ocv(&s->battery) - s->supply_drop_v, 0.0);
}

double sim_supply_v(const sim_state_t *s) { return fmax(sim_battery_v(s) - s->supply_drop_v, 0.0); }

int sim_push(sim_state_t *s, double dx_m, double dyaw_rad, double dur_s)
{
    if (world_carried(s->world)) return -1;
    double n = round(dur_s / s->model->step_s);
    s->push_from = s->step;
    s->push_steps = n < 1 ? 1 : (uint64_t)n;
    s->push_m = dx_m;
    s->push_rad = dyaw_rad;
    return 0;
}

void sim_lift(sim_state_t *s)
{
    s->push_steps = 0;
    world_carry(s->world, 1);
}

void sim_place(sim_state_t *s) { world_carry(s->world, 0); }

/* The hand's grip for this step of a push (sim_push), or let go after it. */
static void hand_step(sim_state_t *s, double dt)
{
    if (!s->push_steps) return;
    if (s->step >= s->push_from + s->push_steps) {
        world_hand(s->world, 0, 0, 0);
        s->push_steps = 0;
        return;
    }
    double T = (double)s->push_steps * dt, t = ((double)(s->step - s->push_from) + 0.5) * dt;
    double shape = 1 - cos(2 * M_PI * t / T); /* averages 1 over the push */
    world_hand(s->world, 1, s->push_m / T * shape, s->push_rad / T * shape);
}

void sim_step(const sim_model_t *m, sim_state_t *s)
{
    assert(m == s->model);
    double dt = m->step_s;
    if (s->diverged) return;
    motor_drive_t d[2];
    for (int i = 0; i < 2; i++) d[i] = motor_drive(&s->motor[i], s->cmd[i], world_wheel_rate(s->world, i), dt);
    hand_step(s, dt);
    world_step(s->world, d);
    s->step++;
    if (!world_sane(s->world)) {
        s->diverged = 1;
        return;
    }
    for (int i = 0; i < 2; i++) motor_after(&s->motor[i], &d[i], world_wheel_rate(s->world, i), dt);
    for (int i = 0; i < 2; i++) encoder_update(&s->encoder[i], world_wheel_angle(s->world, i));
    battery_step(s, dt);
    sensor_ctx_t x = ctx(s);
    for (int i = 0; i < s->ntof; i++) ((tof_state_t *)s->part_state[s->tof_part[i]])->enabled = s->tof_enabled;
    for (int i = 0; i < m->nparts; i++)
        if (m->part[i].kind->step) m->part[i].kind->step(s->part_state[i], &m->part[i], &x);
    tof_mirror(s);
    double px, py, h;
    world_pose(s->world, &px, &py, &h);
    race_update(&s->race, sim_time_s(s), px, py);
}

int sim_ir_count(const sim_state_t *s) { return (int)sensor_count(s->model, "ir"); }

void sim_emitter_set(sim_state_t *s, unsigned group, int on)
{
    if (group < SIM_EMITTER_GROUPS) s->emitter[group] = on != 0;
}

int sim_emitter(const sim_state_t *s, unsigned group) { return group < SIM_EMITTER_GROUPS ? s->emitter[group] : 0; }

unsigned sim_ir_read(sim_state_t *s, unsigned i)
{
    int k = sensor_of_kind(s->model, "ir", i);
    if (k < 0) return 0;
    sensor_ctx_t x = ctx(s);
    return (unsigned)ir_sample(s->part_state[k], &s->model->part[k], &x);
}

/* A sensor an object can be held before: IR or ToF. */
static int occludable(const robot_part_t *p) { return !strcmp(p->kind->name, "ir") || !strcmp(p->kind->name, "tof"); }

int sim_occlude_find(const sim_state_t *s, const char *name)
{
    const sim_model_t *m = s->model;
    for (int k = 0; k < m->nparts; k++)
        if (occludable(&m->part[k]) && !strcmp(m->part[k].name, name)) return k;
    int side = !strcmp(name, "left") ? 0 : !strcmp(name, "right") ? 1 : -1;
    for (int k = 0; side >= 0 && k < m->nparts; k++) { /* the aliases: a forward IR sensor off the centre line */
        const robot_part_t *p = &m->part[k];
        if (strcmp(p->kind->name, "ir") != 0 || fabs(p->yaw_deg) > 30 || (side ? p->x_m <= 0 : p->x_m >= 0)) continue;
        return k;
    }
    return -1;
}

void sim_occlude_names(const sim_state_t *s, char *out, size_t len)
{
    const sim_model_t *m = s->model;
    size_t used = 0;
    out[0] = '\0';
    for (int k = 0; k < m->nparts && used < len; k++)
        if (occludable(&m->part[k])) {
            int n = snprintf(out + used, len - used, "%s%s", used ? ", " : "", m->part[k].name);
            if (n > 0) used += (size_t)n;
        }
    if (!out[0]) snprintf(out, len, "none");
}

void sim_occlude(sim_state_t *s, int part, double d_m, double dur_s)
{
    if (part < 0 || part >= s->model->nparts) return;
    const robot_part_t *p = &s->model->part[part];
    double until_s = sim_time_s(s) + dur_s;
    if (!strcmp(p->kind->name, "ir")) {
        ir_state_t *st = s->part_state[part];
        st->object_m = d_m;
        st->object_until_s = until_s;
    } else if (!strcmp(p->kind->name, "tof")) {
        tof_state_t *st = s->part_state[part];
        st->object_m = d_m;
        st->object_until_s = until_s;
    }
}

int sim_has_gyro(const sim_state_t *s) { return sensor_count(s->model, "gyro") > 0; }

double sim_gyro_rad_s(const sim_state_t *s)
{
    int k = sensor_of_kind(s->model, "gyro", 0);
    return k < 0 ? 0.0 : ((const gyro_t *)s->part_state[k])->held_rad_s;
}

double sim_battery_v(const sim_state_t *s)
{
    /* the terminal voltage: the open-circuit voltage less the sag of both motors' input currents */
    double i_in = bridge_in_a(&s->motor[0]) + bridge_in_a(&s->motor[1]);
    return battery_ocv(&s->battery) - s->model->battery.r_ohm * i_in;
}

void sim_tof_origin(const sim_state_t *s, int i, double pos_m[3], double *dir_rad)
{
    double axis[3], left[3], up[3];
    sensor_frame(s->world, &s->model->pose[s->tof_part[i]], pos_m, axis, left, up);
    *dir_rad = atan2(axis[1], axis[0]);
}

int sim_part_values(const sim_state_t *s, int i, double v[4])
{
    if (i < 0 || i >= s->model->nparts) return 0;
    sensor_ctx_t x = ctx(s);
    return s->model->part[i].kind->read(s->part_state[i], &s->model->part[i], &x, v);
}

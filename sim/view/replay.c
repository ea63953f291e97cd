/* replay.c - an LCM log loaded for replay (see replay.h). */
#include "replay.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "maze/truebelief.h"
#include "telemetry/lcmlog.h"
#include "mmlcm_belief_t.h"
#include "mmlcm_maze_t.h"

typedef struct {
    replay_t *r;
    const char *path;
    char *err;
    size_t errlen;
    size_t cap_pose, cap_sensors, cap_race, cap_event, cap_belief, cap_walls, cap_parts;
    long n;             /* events read */
} load_t;

/* Room for one more element in *arr (n used, *cap allocated). */
static int grow(void **arr, size_t n, size_t *cap, size_t size)
{
    if (n < *cap) return 0;
    size_t c = *cap ? *cap * 2 : 256;
    void *p = realloc(*arr, c * size);
    if (!p) return -1;
    *arr = p;
    *cap = c;
    return 0;
}

static int fail(load_t *l, const char *why, const char *channel)
{
    snprintf(l->err, l->errlen, "%s: event %ld (%s): %s", l->path, l->n, channel, why);
    return -1;
}

/* The logged maze and config. */
static int take_maze(load_t *l, const mmlcm_maze_t *m)
{
    replay_t *r = l->r;
    int w = (uint8_t)m->width, h = (uint8_t)m->height;
    if (r->have_maze) return 0; /* the first one counts */
    if (w < 1 || h < 1 || w > TRUEMAZE_MAX_SIZE || h > TRUEMAZE_MAX_SIZE || m->ncells != w * h)
        return fail(l, "maze size out of range", "MM_MAZE");
    if (m->start < 0 || m->start >= m->ncells || m->start_heading < 0 || m->start_heading > 3 || m->ngoals < 1)
        return fail(l, "bad start cell, heading or goals", "MM_MAZE");
    truemaze_init(&r->maze, (uint8_t)w, (uint8_t)h);
    for (int c = 0; c < m->ncells; c++) r->maze.cell[c] = (uint8_t)m->walls[c] & 0x0F; /* bit d: wall on side d */
    truemaze_clear_goals(&r->maze);
    for (int i = 0; i < m->ngoals; i++) {
        if (m->goals[i] < 0 || m->goals[i] >= m->ncells) return fail(l, "goal cell out of the maze", "MM_MAZE");
        truemaze_set_goal(&r->maze, (truemaze_cell_t)m->goals[i], 1);
    }
    r->maze.start = (truemaze_cell_t)m->start;
    r->maze.start_heading = (uint8_t)m->start_heading;
    snprintf(r->path, sizeof r->path, "%s", m->path);
    config_defaults(&r->cfg);
    char cerr[600];
    if (config_load_string(&r->cfg, m->config, "MM_MAZE config", cerr, sizeof cerr) != 0)
        return fail(l, cerr, "MM_MAZE");
    if (robot_load_string(&r->cfg, m->robot, "MM_MAZE robot", cerr, sizeof cerr) != 0) return fail(l, cerr, "MM_MAZE");
    r->seed = (uint64_t)m->seed;
    r->centre_post = m->centre_post != 0;
    r->have_maze = 1;
    return 0;
}

#define PUSH(field, count, cap, msg)                                                                        \
    do {                                                                                                    \
        if (grow((void **)&r->field, r->count, &l->cap, sizeof *r->field) != 0) return fail(l, "out of memory", ch); \
        if (r->count && msg.utime < r->field[r->count - 1].utime) return fail(l, "message out of time order", ch); \
        r->field[r->count++] = msg;                                                                         \
    } while (0)

/* An MM_PARTS message: its time and the emitter groups' states. */
static int take_parts(load_t *l, const lcm_eventlog_event_t *ev, int64_t *ut)
{
    replay_t *r = l->r;
    const char *ch = ev->channel;
    mmlcm_parts_t m;
    if (lcmlog_decode_parts(ev->data, ev->datalen, &m) != 0) return fail(l, "does not decode", ch);
    replay_parts_t p = { m.utime, 0 };
    for (int g = 0; g < m.nemitters && g < 8; g++) p.emitters |= (uint8_t)((m.emitter[g] != 0) << g);
    mmlcm_parts_t_decode_cleanup(&m);
    PUSH(parts, nparts, cap_parts, p);
    *ut = p.utime;
    return 0;
}

static int on_event(void *ctx, const lcm_eventlog_event_t *ev)
{
    load_t *l = ctx;
    replay_t *r = l->r;
    const char *ch = ev->channel;
    int len = ev->datalen;
    int64_t ut = -1;
    l->n++;
    if (!strcmp(ch, "MM_POSE")) {
        mmlcm_pose_t m;
        if (mmlcm_pose_t_decode(ev->data, 0, len, &m) != len) return fail(l, "does not decode", ch);
        PUSH(pose, npose, cap_pose, m);
        ut = m.utime;
    } else if (!strcmp(ch, "MM_SENSORS")) {
        mmlcm_sensors_t m;
        if (mmlcm_sensors_t_decode(ev->data, 0, len, &m) != len) return fail(l, "does not decode", ch);
        PUSH(sensors, nsensors, cap_sensors, m);
        ut = m.utime;
    } else if (!strcmp(ch, "MM_PARTS")) {
        if (take_parts(l, ev, &ut) != 0) return -1;
    } else if (!strcmp(ch, "MM_RACE")) {
        mmlcm_race_t m;
        if (mmlcm_race_t_decode(ev->data, 0, len, &m) != len) return fail(l, "does not decode", ch);
        PUSH(race, nrace, cap_race, m);
        ut = m.utime;
    } else if (!strcmp(ch, "MM_RACE_EVENT")) {
        mmlcm_race_event_t m;
        if (mmlcm_race_event_t_decode(ev->data, 0, len, &m) != len) return fail(l, "does not decode", ch);
        if (m.lap < 1 || m.lap > RACE_MAX_LAPS) return fail(l, "lap number out of range", ch);
        PUSH(event, nevent, cap_event, m);
        ut = m.utime;
    } else if (!strcmp(ch, "MM_BELIEF")) {
        mmlcm_belief_t m;
        if (lcmlog_decode_belief(ev->data, len, &m) != 0) return fail(l, "does not decode", ch);
        int rc = 0;
        size_t n = r->nbelief, cells = (size_t)r->maze.width * r->maze.height;
        if (!r->have_maze) rc = fail(l, "belief before MM_MAZE", ch);
        else if ((uint8_t)m.width != r->maze.width || (uint8_t)m.height != r->maze.height || (size_t)m.ncells != cells)
            rc = fail(l, "belief map size differs from the maze", ch);
        else if (n && m.utime < r->belief[n - 1].utime) rc = fail(l, "message out of time order", ch);
        else if (grow((void **)&r->belief, n, &l->cap_belief, sizeof *r->belief) ||
                 grow((void **)&r->belief_walls, n, &l->cap_walls, cells))
            rc = fail(l, "out of memory", ch);
        else {
            r->belief[n].utime = m.utime;
            r->belief[n].cell = m.cell;
            r->belief[n].heading = (uint8_t)(m.heading & 3);
            r->belief[n].state = m.state;
            memcpy(r->belief_walls + n * cells, m.walls, cells);
            r->nbelief++;
            ut = m.utime;
        }
        mmlcm_belief_t_decode_cleanup(&m);
        if (rc) return rc;
    } else if (!strcmp(ch, "MM_MAZE")) {
        mmlcm_maze_t m;
        if (lcmlog_decode_maze(ev->data, len, &m) != 0) return fail(l, "does not decode", ch);
        int rc = take_maze(l, &m);
        mmlcm_maze_t_decode_cleanup(&m);
        if (rc) return rc;
    }
    if (ut > r->end_us) r->end_us = ut;
    return 0;
}

void replay_free(replay_t *r)
{
    free(r->pose);
    free(r->sensors);
    free(r->parts);
    free(r->race);
    free(r->event);
    free(r->belief);
    free(r->belief_walls);
    memset(r, 0, sizeof *r);
}

int replay_load(replay_t *r, const char *path, char *err, size_t errlen)
{
    memset(r, 0, sizeof *r);
    load_t l = { r, path, err, errlen, 0, 0, 0, 0, 0, 0, 0, 0 };
    int rc = lcmlog_each(path, on_event, &l, NULL, err, errlen);
    if (rc == 0 && !r->have_maze) {
        snprintf(err, errlen, "%s: no MM_MAZE message (a log of mmsim --lcm-log before mmview existed?)", path);
        rc = -1;
    } else if (rc == 0 && r->npose == 0) {
        snprintf(err, errlen, "%s: no MM_POSE message", path);
        rc = -1;
    }
    if (rc == 0) sim_model_build(&r->model, &r->cfg, r->seed);
    return rc ? -1 : 0;
}

double replay_end_s(const replay_t *r) { return (double)r->end_us * 1e-6; }

long replay_index(const int64_t *times, size_t stride, size_t n, int64_t t_us)
{
    /* the first element whose time is > t_us, minus one */
    size_t lo = 0, hi = n;
    while (lo < hi) {
        size_t mid = lo + (hi - lo) / 2;
        const int64_t *tm = (const int64_t *)((const char *)times + mid * stride);
        if (*tm <= t_us) lo = mid + 1;
        else hi = mid;
    }
    return (long)lo - 1;
}

/* The last element of arr[0..n) with utime <= t, or -1. */
#define LAST_AT(arr, n, t) ((n) ? replay_index(&(arr)[0].utime, sizeof *(arr), (n), (t)) : -1)

static int64_t clamp_us(const replay_t *r, double t_s)
{
    int64_t t = (int64_t)llround(t_s * 1e6);
    return t < 0 ? 0 : t > r->end_us ? r->end_us : t;
}

/* The contest timers at t_us, from the lap events (exact) and the timer
 * messages (when the global timer started, the over-time flag). */
static void rebuild_race(const replay_t *r, race_t *rc, int64_t t_us)
{
    double t = (double)t_us * 1e-6;
    rc->started = 0;
    rc->global_start_s = 0;
    for (size_t i = 0; i < r->nrace; i++)
        if (r->race[i].started) { /* the timer ran global_s at that message */
            double g0 = (double)r->race[i].utime * 1e-6 - r->race[i].global_s;
            rc->started = t >= g0 - 1e-9;
            rc->global_start_s = g0;
            break;
        }
    long k = LAST_AT(r->race, r->nrace, t_us);
    rc->over_time = k >= 0 && r->race[k].over_time;
    rc->nlaps = 0;
    rc->best = -1;
    rc->in_run = 0;
    rc->run_start_s = 0;
    long e = LAST_AT(r->event, r->nevent, t_us);
    for (long i = 0; i <= e; i++) {
        const mmlcm_race_event_t *ev = &r->event[i];
        if (ev->kind == MMLCM_RACE_EVENT_T_LAP_START) {
            rc->in_run = 1;
            rc->run_start_s = ev->start_s + rc->global_start_s; /* sim time */
        } else if (ev->kind == MMLCM_RACE_EVENT_T_LAP_END && rc->nlaps < RACE_MAX_LAPS) {
            race_lap_t *lp = &rc->laps[rc->nlaps];
            lp->start_s = ev->start_s;
            lp->end_s = ev->end_s;
            lp->over_time = ev->over_time != 0;
            if (ev->best) rc->best = rc->nlaps;
            rc->nlaps++;
            rc->in_run = 0;
        }
    }
}

void replay_snap(const replay_t *r, double t_s, snap_t *out)
{
    const simcfg_t *c = &r->cfg;
    int64_t t_us = clamp_us(r, t_s);
    double cpr = c->robot.drive[0].encoder_ppr * c->robot.drive[0].gear_ratio; /* encoder counts per wheel turn */
    long i = LAST_AT(r->pose, r->npose, t_us);
    long j = LAST_AT(r->sensors, r->nsensors, t_us);
    double wheel[2] = { 0, 0 };
    if (j >= 0)
        for (int k = 0; k < 2; k++) wheel[k] = (double)r->sensors[j].encoder[k] * 2 * M_PI / cpr;
    memset(out, 0, sizeof *out);
    if (i >= 0) {
        snap_place(out, &r->model, &r->maze, r->centre_post, r->pose[i].x_m, r->pose[i].y_m, r->pose[i].heading_rad, wheel);
        out->v_m_s = r->pose[i].v_m_s;
    } else { /* before the first pose: at the start cell's centre */
        static const double a[4] = { M_PI / 2, 0.0, -M_PI / 2, M_PI };
        const truemaze_t *m = &r->maze;
        snap_place(out, &r->model, m, r->centre_post, (truemaze_x(m, m->start) + 0.5) * c->world.cell_m,
                   (truemaze_y(m, m->start) + 0.5) * c->world.cell_m, a[m->start_heading & 3], wheel);
    }
    for (int k = 0; k < out->ntof; k++) out->tof[k].hit_m = j >= 0 ? r->sensors[j].tof_true_m[k] : -1;
    long e = LAST_AT(r->parts, r->nparts, t_us);
    for (unsigned g = 0; g < SIM_EMITTER_GROUPS; g++) out->emitter[g] = e >= 0 && (r->parts[e].emitters >> g & 1);
    out->time_s = (double)llround((double)t_us * 1e-6 / c->sim.step_s) * c->sim.step_s; /* whole steps, as sim_time_s */
    race_init(&out->race, &r->maze, c->world.cell_m, c->sim.time_limit_s);
    rebuild_race(r, &out->race, t_us);
}

void replay_belief(replay_t *r, double t_s, scene_belief_t *b)
{
    long k = LAST_AT(r->belief, r->nbelief, clamp_us(r, t_s));
    b->map = NULL;
    b->cell = 0;
    b->heading = 0;
    b->state = -1;
    if (k < 0) return;
    size_t cells = truemaze_cells(&r->maze);
    truemaze_to_belief(&r->maze, &r->bmap); /* size, start and goals of the truth; the walls the mouse knew */
    memcpy(r->bmap.cell, r->belief_walls + (size_t)k * cells, cells);
    b->map = &r->bmap;
    b->cell = (uint16_t)r->belief[k].cell;
    b->heading = r->belief[k].heading;
    b->state = r->belief[k].state;
}

double replay_next_s(const replay_t *r, double t_s, int dir)
{
    int64_t t = clamp_us(r, t_s);
    long i = LAST_AT(r->pose, r->npose, t); /* pose[i].utime <= t < pose[i + 1].utime */
    if (dir > 0) return i + 1 < (long)r->npose ? (double)r->pose[i + 1].utime * 1e-6 : t_s;
    if (i >= 0 && r->pose[i].utime < t) return (double)r->pose[i].utime * 1e-6;
    return i >= 1 ? (double)r->pose[i - 1].utime * 1e-6 : 0.0;
}

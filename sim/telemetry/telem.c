/* telem.c - LCM telemetry of a running simulation (see telem.h). */
#include "telem.h"

#include <errno.h>
#include <fcntl.h>
#include <lcm/eventlog.h>
#include <lcm/lcm.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "link/link.h"
#include "mmlcm_belief_t.h"
#include "mmlcm_link_t.h"
#include "mmlcm_maze_t.h"
#include "mmlcm_motors_t.h"
#include "mmlcm_parts_t.h"
#include "mmlcm_pose_t.h"
#include "mmlcm_race_event_t.h"
#include "mmlcm_race_t.h"
#include "mmlcm_watch_t.h"
#include "mmlcm_sensors_t.h"
#include "maze/solve.h"
#include "maze/truebelief.h"
#include "world/sensors/sensor.h"

#define NONE UINT64_MAX

static uint64_t period_steps(double hz, double step_s)
{
    double p = round(1.0 / (hz * step_s));
    return p < 1.0 ? 1 : (uint64_t)p;
}

/* lcm_create, with what LCM prints on stderr caught and summed up in why
 * (one error line in all, for the caller to print). */
static lcm_t *create_quiet(const char *url, char *why, size_t whylen)
{
    snprintf(why, whylen, "unknown provider, bad address or no multicast route");
    FILE *tmp = tmpfile();
    int saved = tmp ? dup(STDERR_FILENO) : -1;
    if (saved >= 0) {
        fflush(stderr);
        dup2(fileno(tmp), STDERR_FILENO);
    }
    lcm_t *l = lcm_create(url);
    /* tcpq's create succeeds without its hub (and every publish would then
     * try again, printing three lines): a hub is needed now */
    int no_hub = l && url && !strncmp(url, "tcpq://", 7) && lcm_get_fileno(l) < 0;
    if (no_hub) {
        lcm_destroy(l);
        l = NULL;
    }
    if (saved >= 0) {
        fflush(stderr);
        dup2(saved, STDERR_FILENO);
        close(saved);
        /* LCM's "Error: ..." line (tcpq: its connect error) if any; its
         * multi-line multicast advice in one line; else its first line */
        char line[200];
        int first = !no_hub, have_error = 0;
        if (no_hub) snprintf(why, whylen, "cannot connect to its hub");
        rewind(tmp);
        while (fgets(line, sizeof line, tmp)) {
            line[strcspn(line, "\r\n")] = '\0';
            if (!line[0] || have_error) continue;
            const char *c = no_hub ? strstr(line, "connect: ") : NULL;
            if (c) {
                snprintf(why, whylen, "cannot connect to its hub: %s", c + 9);
                have_error = 1;
            } else if (!strncmp(line, "Error: ", 7)) {
                snprintf(why, whylen, "%s", line + 7);
                have_error = 1;
            } else if (strstr(line, "requires a valid multicast route")) {
                snprintf(why, whylen, "no multicast route (see http://lcm-proj.github.io/multicast_setup.html)");
                first = 0;
            } else if (first) {
                snprintf(why, whylen, "%s", line);
                first = 0;
            }
        }
    }
    if (tmp) fclose(tmp);
    return l;
}

static void emit(telem_t *t, const char *channel, int64_t utime, int len); /* below */

/* lcm_publish; for tcpq with liblcm's stderr lines (two on a lost hub)
 * silenced: the reason goes into live_errno, for the one line at the end. */
static int publish_live(telem_t *t, const char *channel, int len)
{
    if (!t->tcpq || t->quiet_fd < 0) return lcm_publish(t->lcm, channel, t->buf, (unsigned)len);
    fflush(stderr);
    int saved = dup(STDERR_FILENO);
    if (saved >= 0) dup2(t->quiet_fd, STDERR_FILENO);
    errno = 0;
    int r = lcm_publish(t->lcm, channel, t->buf, (unsigned)len), e = errno;
    if (saved >= 0) {
        dup2(saved, STDERR_FILENO);
        close(saved);
    }
    if (r != 0 && !t->live_errno) t->live_errno = e;
    return r;
}

/* The true maze, the seed and the config, once at the start. */
static void pub_maze(telem_t *t, const sim_state_t *s, const char *path)
{
    static int8_t walls[TRUEMAZE_MAX_CELLS];
    static int16_t goals[TRUEMAZE_MAX_CELLS];
    const truemaze_t *m = s->maze;
    uint16_t n = truemaze_cells(m);
    int16_t ng = 0;
    for (uint16_t c = 0; c < n; c++) {
        walls[c] = (int8_t)(m->cell[c] | 0xF0); /* MM_MAZE's byte: bit d wall, bit 4+d known (all, the truth) */
        if (truemaze_is_goal(m, (truemaze_cell_t)c)) goals[ng++] = (int16_t)c;
    }
    char *ini = NULL;
    size_t len = 0;
    FILE *mem = open_memstream(&ini, &len);
    if (!mem) {
        t->failed = 1;
        return;
    }
    config_print(s->model->cfg, mem);
    fclose(mem);
    char *robot = NULL;
    mem = open_memstream(&robot, &len);
    if (!mem) {
        free(ini);
        t->failed = 1;
        return;
    }
    robot_print(s->model->cfg, mem);
    fclose(mem);
    mmlcm_maze_t mz;
    mz.utime = 0;
    mz.path = (char *)(path ? path : "");
    mz.width = (int8_t)m->width;
    mz.height = (int8_t)m->height;
    mz.ncells = (int16_t)n;
    mz.walls = walls;
    mz.start = (int16_t)m->start;
    mz.start_heading = (int8_t)m->start_heading;
    mz.ngoals = ng;
    mz.goals = goals;
    mz.centre_post = (int8_t)(world_has_centre_post(s->world) != 0);
    mz.seed = (int64_t)s->seed;
    mz.config = ini ? ini : (char *)"";
    mz.robot = robot ? robot : (char *)"";
    emit(t, "MM_MAZE", 0, mmlcm_maze_t_encode(t->buf, 0, TELEM_BUF_BYTES, &mz));
    free(ini);
    free(robot);
}

static void close_quiet(telem_t *t)
{
    if (t->quiet_fd >= 0) close(t->quiet_fd);
    t->quiet_fd = -1;
}

/* The log: a temporary beside path, renamed over it at the end, or a
 * device or a pipe itself. 0, or -1 with one line in err (nothing left). */
static int open_log(telem_t *t, const char *path, char *err, size_t errlen)
{
    struct stat st;
    char why[700];
    int exists = stat(path, &st) == 0;
    t->log_in_place = exists && !S_ISREG(st.st_mode) && !S_ISDIR(st.st_mode);
    t->log_out.f = NULL;
    t->log_out.tmp[0] = '\0';
    snprintf(t->log_out.path, sizeof t->log_out.path, "%s", path);
    if (exists && S_ISDIR(st.st_mode)) {
        snprintf(err, errlen, "%s: cannot write the LCM log: %s", path, strerror(EISDIR));
        return -1;
    }
    if (!t->log_in_place) {
        if (outfile_open(&t->log_out, path, why, sizeof why) != 0) {
            const char *reason = strrchr(why, ':'); /* outfile's "PATH: cannot write: REASON" */
            snprintf(err, errlen, "%s: cannot write the LCM log: %s", path, reason ? reason + 2 : why);
            return -1;
        }
        fclose(t->log_out.f); /* liblcm opens it by name */
        t->log_out.f = NULL;
    }
    errno = 0;
    t->log = lcm_eventlog_create(t->log_in_place ? path : t->log_out.tmp, "w");
    if (!t->log) {
        snprintf(err, errlen, "%s: cannot write the LCM log: %s", path, errno ? strerror(errno) : "unknown error");
        outfile_abort(&t->log_out);
        return -1;
    }
    return 0;
}

int telem_open(telem_t *t, const telem_opts_t *o, const sim_state_t *s, char *err, size_t errlen)
{
    double hz = o->rate_hz > 0 ? o->rate_hz : TELEM_RATE_HZ;
    t->lcm = NULL;
    t->log = NULL;
    t->log_out.tmp[0] = t->log_out.path[0] = '\0';
    t->log_errno = 0;
    t->url = o->url;
    t->tcpq = o->url && !strncmp(o->url, "tcpq://", 7);
    t->live_lost = 0;
    t->live_lost_s = 0;
    t->live_errno = 0;
    t->quiet_fd = t->tcpq ? open("/dev/null", O_WRONLY | O_CLOEXEC) : -1;
    t->step_us = (uint64_t)llround(s->model->cfg->sim.step_s * 1e6);
    t->fast_steps = period_steps(hz, s->model->cfg->sim.step_s);
    t->race_steps = period_steps(TELEM_RACE_HZ, s->model->cfg->sim.step_s);
    t->link_steps = period_steps(TELEM_LINK_HZ, s->model->cfg->sim.step_s);
    t->last_fast = t->last_race = t->last_link = NONE;
    t->link = o->link;
    t->link_tx0 = t->link_rx0 = t->link_steps0 = 0;
    t->nlaps = 0;
    t->contacts = world_collisions(s->world);
    t->in_run = 0;
    t->run_start_s = 0;
    t->belief_seq = 0;
    t->failed = 0;
    t->live_errors = 0;
    t->published = 0;
    if (o->log_path && strlen(o->log_path) + 16 >= sizeof t->log_out.path) {
        snprintf(err, errlen, "%.200s...: log file name too long", o->log_path);
        close_quiet(t);
        return -1;
    }
    /* the URL first: a bad URL leaves an existing log file untouched */
    if (o->url) {
        char why[200];
        t->lcm = create_quiet(o->url[0] ? o->url : NULL, why, sizeof why);
        if (!t->lcm) {
            snprintf(err, errlen, "%s: cannot open the LCM URL: %s", o->url[0] ? o->url : "LCM's default URL", why);
            close_quiet(t);
            return -1;
        }
    }
    if (o->log_path && open_log(t, o->log_path, err, errlen) != 0) {
        if (t->lcm) lcm_destroy(t->lcm);
        t->lcm = NULL;
        close_quiet(t);
        return -1;
    }
    pub_maze(t, s, o->maze_path);
    return 0;
}

/* One encoded message to every output. */
static void emit(telem_t *t, const char *channel, int64_t utime, int len)
{
    if (len < 0) {
        t->failed = 1;
        return;
    }
    /* a live message lost (udpm buffers full) is counted, not fatal; a
     * tcpq hub lost stops the live output (liblcm would try to reconnect,
     * printing three lines, on every publish) */
    if (t->lcm && !t->live_lost && publish_live(t, channel, len) != 0) {
        t->live_errors++;
        if (t->tcpq && lcm_get_fileno(t->lcm) < 0) {
            t->live_lost = 1;
            t->live_lost_s = (double)utime * 1e-6;
        }
    }
    if (t->log) {
        lcm_eventlog_event_t ev;
        ev.eventnum = 0; /* numbered by the log */
        ev.timestamp = utime;
        ev.channellen = (int32_t)strlen(channel);
        ev.datalen = len;
        ev.channel = (char *)channel;
        ev.data = t->buf;
        errno = 0;
        if (lcm_eventlog_write_event(t->log, &ev) != 0) {
            if (!t->failed) t->log_errno = errno;
            t->failed = 1;
        }
    }
    t->published++;
}

static int64_t utime_of(const telem_t *t, const sim_state_t *s) { return (int64_t)(s->step * t->step_us); }

/* Every sensor component's latest values (sim_part_values: no noise
 * drawn), the battery and the emitter groups. */
static void pub_parts(telem_t *t, const sim_state_t *s, int64_t ut)
{
    static mmlcm_part_t part[ROBOT_MAX_PARTS];
    static double values[ROBOT_MAX_PARTS][SENSOR_VALUES];
    static int8_t emitter[SIM_EMITTER_GROUPS];
    mmlcm_parts_t m;
    m.utime = ut;
    m.nparts = 0;
    for (int i = 0; i < s->model->cfg->robot.nparts && i < ROBOT_MAX_PARTS; i++) {
        const robot_part_t *p = &s->model->cfg->robot.part[i];
        mmlcm_part_t *q = &part[m.nparts++];
        q->kind = (char *)p->kind->name;
        q->name = (char *)p->name;
        q->nvalues = (int8_t)sim_part_values(s, i, values[i]);
        q->values = values[i];
        q->units = (char *)p->kind->units;
    }
    m.parts = part;
    m.battery_v = sim_battery_v(s);
    m.battery_soc = battery_soc(&s->battery);
    m.nemitters = SIM_EMITTER_GROUPS;
    for (int g = 0; g < SIM_EMITTER_GROUPS; g++) emitter[g] = (int8_t)(sim_emitter(s, (unsigned)g) != 0);
    m.emitter = emitter;
    emit(t, "MM_PARTS", ut, mmlcm_parts_t_encode(t->buf, 0, TELEM_BUF_BYTES, &m));
}

static void pub_fast(telem_t *t, const sim_state_t *s)
{
    int64_t ut = utime_of(t, s);
    mmlcm_pose_t p;
    p.utime = ut;
    world_pose(s->world, &p.x_m, &p.y_m, &p.heading_rad);
    world_velocity(s->world, &p.v_m_s, &p.omega_rad_s);
    emit(t, "MM_POSE", ut, mmlcm_pose_t_encode(t->buf, 0, TELEM_BUF_BYTES, &p));

    mmlcm_motors_t m;
    m.utime = ut;
    for (int i = 0; i < 2; i++) {
        m.command[i] = (int16_t)s->cmd[i];
        m.voltage_v[i] = motor_terminal_v(&s->motor[i]);
        m.current_a[i] = s->motor[i].i_a;
        m.wheel_rad_s[i] = world_wheel_rate(s->world, i);
        m.torque_nm[i] = s->motor[i].torque_nm; /* at the output shaft, friction excluded */
    }
    emit(t, "MM_MOTORS", ut, mmlcm_motors_t_encode(t->buf, 0, TELEM_BUF_BYTES, &m));

    mmlcm_sensors_t r;
    r.utime = ut;
    for (int i = 0; i < 2; i++) r.encoder[i] = s->encoder[i].count;
    for (int i = 0; i < 3; i++) {
        r.tof_mm[i] = (int16_t)lround(s->tof_last[i].dist_m * 1000.0); /* as hal_distance rounds */
        r.tof_timeout[i] = (int8_t)(s->tof_last[i].timeout != 0);
        r.tof_true_m[i] = s->tof_true_m[i];
    }
    emit(t, "MM_SENSORS", ut, mmlcm_sensors_t_encode(t->buf, 0, TELEM_BUF_BYTES, &r));
    pub_parts(t, s, ut);
    t->last_fast = s->step;
}

static void pub_race(telem_t *t, const sim_state_t *s)
{
    const race_t *rc = &s->race;
    double now = sim_time_s(s);
    mmlcm_race_t m;
    m.utime = utime_of(t, s);
    m.started = (int8_t)(rc->started != 0);
    m.global_s = race_global_s(rc, now);
    m.in_run = (int8_t)(rc->in_run != 0);
    m.lap_s = rc->in_run ? now - rc->run_start_s : 0.0;
    m.over_time = (int8_t)(rc->over_time != 0);
    m.laps = rc->nlaps;
    m.best_lap = rc->best + 1;
    m.best_run_s = rc->best >= 0 ? rc->laps[rc->best].end_s - rc->laps[rc->best].start_s : 0.0;
    emit(t, "MM_RACE", m.utime, mmlcm_race_t_encode(t->buf, 0, TELEM_BUF_BYTES, &m));
    t->last_race = s->step;
}

/* The link's counters; utilisation over the steps since the last MM_LINK. */
static void pub_link(telem_t *t, const sim_state_t *s)
{
    const link_t *l = t->link;
    mmlcm_link_t m;
    m.utime = utime_of(t, s);
    m.bytes_to_mcu = (int64_t)l->st.tx_bytes;
    m.bytes_from_mcu = (int64_t)l->st.rx_bytes;
    uint64_t steps = l->st.steps - t->link_steps0;
    m.util_to_mcu = link_util_over(l, l->st.tx_bytes - t->link_tx0, steps);
    m.util_from_mcu = link_util_over(l, l->st.rx_bytes - t->link_rx0, steps);
    m.frame_errors = (int32_t)wire_stats_errors(link_decoder_stats(l));
    m.dropped_to_mcu = (int64_t)l->st.tx_dropped;
    m.baud = (int32_t)l->o.baud;
    m.connected = (int8_t)(l->connected != 0);
    m.handshake = (int8_t)(l->hello_ok != 0);
    emit(t, "MM_LINK", m.utime, mmlcm_link_t_encode(t->buf, 0, TELEM_BUF_BYTES, &m));
    t->link_tx0 = l->st.tx_bytes;
    t->link_rx0 = l->st.rx_bytes;
    t->link_steps0 = l->st.steps;
    t->last_link = s->step;
}

/* Wall contacts begun since the last step, one CONTACT event each. */
static void pub_contacts(telem_t *t, const sim_state_t *s)
{
    unsigned n = world_collisions(s->world);
    mmlcm_race_event_t e;
    memset(&e, 0, sizeof e);
    e.utime = utime_of(t, s);
    e.kind = MMLCM_RACE_EVENT_T_CONTACT;
    while (t->contacts < n) {
        e.lap = (int32_t)++t->contacts;
        emit(t, "MM_RACE_EVENT", e.utime, mmlcm_race_event_t_encode(t->buf, 0, TELEM_BUF_BYTES, &e));
    }
}

/* Lap starts and ends, and wall contacts, since the last step. */
static void pub_events(telem_t *t, const sim_state_t *s)
{
    const race_t *rc = &s->race;
    mmlcm_race_event_t e;
    memset(&e, 0, sizeof e);
    e.utime = utime_of(t, s);
    while (t->nlaps < rc->nlaps) {
        const race_lap_t *l = &rc->laps[t->nlaps];
        e.kind = MMLCM_RACE_EVENT_T_LAP_END;
        e.lap = t->nlaps + 1;
        e.start_s = l->start_s;
        e.end_s = l->end_s;
        e.run_s = l->end_s - l->start_s;
        e.over_time = (int8_t)(l->over_time != 0);
        e.best = (int8_t)(rc->best == t->nlaps);
        emit(t, "MM_RACE_EVENT", e.utime, mmlcm_race_event_t_encode(t->buf, 0, TELEM_BUF_BYTES, &e));
        t->nlaps++;
        t->in_run = 0;
    }
    if (rc->in_run && (!t->in_run || rc->run_start_s != t->run_start_s)) {
        memset(&e, 0, sizeof e);
        e.utime = utime_of(t, s);
        e.kind = MMLCM_RACE_EVENT_T_LAP_START;
        e.lap = rc->nlaps + 1;
        e.start_s = race_global_s(rc, rc->run_start_s);
        emit(t, "MM_RACE_EVENT", e.utime, mmlcm_race_event_t_encode(t->buf, 0, TELEM_BUF_BYTES, &e));
    }
    t->in_run = rc->in_run;
    t->run_start_s = rc->run_start_s;
    pub_contacts(t, s);
}

void telem_cost_field(const truemaze_t *m, int16_t *cost)
{
    static truemaze_cell_t queue[TRUEMAZE_MAX_CELLS];
    uint16_t n = truemaze_cells(m), head = 0, tail = 0;
    for (uint16_t c = 0; c < n; c++) {
        cost[c] = -1;
        if (truemaze_is_goal(m, (truemaze_cell_t)c)) {
            cost[c] = 0;
            queue[tail++] = (truemaze_cell_t)c;
        }
    }
    while (head < tail) {
        truemaze_cell_t c = queue[head++];
        for (uint8_t d = 0; d < 4; d++) {
            truemaze_cell_t nb;
            if (truemaze_wall(m, c, d) || !truemaze_neighbour(m, c, d, &nb) || cost[nb] >= 0) continue;
            cost[nb] = (int16_t)(cost[c] + 1);
            queue[tail++] = nb;
        }
    }
}

static void pub_belief(telem_t *t, const sim_belief_t *b)
{
    static int8_t walls[TRUEMAZE_MAX_CELLS];
    static int16_t cost[TRUEMAZE_MAX_CELLS], path[TRUEMAZE_MAX_CELLS + 1];
    static solve_path_t best;
    static truemaze_t from_here;
    uint16_t n = maze_cells(&b->map);
    for (uint16_t c = 0; c < n; c++) walls[c] = (int8_t)b->map.cell[c];
    truemaze_from_belief(&from_here, &b->map, 1); /* unknown walls open: the mouse's optimistic view */
    telem_cost_field(&from_here, cost);
    from_here.start = (truemaze_cell_t)b->cell;
    from_here.start_heading = b->heading;
    int16_t len = 0;
    if (b->cell < n && solve_best(&from_here, &best) == 0)
        for (uint16_t i = 0; i < best.len; i++) path[len++] = (int16_t)best.path[i];

    mmlcm_belief_t m;
    m.utime = (int64_t)b->t_us;
    m.width = (int8_t)b->map.width;
    m.height = (int8_t)b->map.height;
    m.ncells = (int16_t)n;
    m.walls = walls;
    m.cost = cost;
    m.cell = (int16_t)b->cell;
    m.heading = (int8_t)b->heading;
    m.state = (int8_t)b->state;
    m.path_len = len;
    m.path = path;
    emit(t, "MM_BELIEF", m.utime, mmlcm_belief_t_encode(t->buf, 0, TELEM_BUF_BYTES, &m));
    t->belief_seq = b->seq;
}

/* A belief to publish: one the driver has, reported since the last one
 * published (seq counts the firmware's reports). */
static int belief_new(const telem_t *t, const sim_belief_t *b) { return b && b->seq != t->belief_seq; }

void telem_step(telem_t *t, const sim_state_t *s, const sim_belief_t *b)
{
    /* the belief reported during the last firmware loop comes first: its
     * time is the previous step's, so the log stays in time order */
    if (belief_new(t, b)) pub_belief(t, b);
    pub_events(t, s);
    if (s->step % t->fast_steps == 0) pub_fast(t, s);
    if (s->step % t->race_steps == 0) pub_race(t, s);
    if (t->link && s->step % t->link_steps == 0) pub_link(t, s);
}

/* The firmware's variables as telem_watch last had them. */
static void pub_watch(telem_t *t, const sim_state_t *s)
{
    int64_t ut = utime_of(t, s);
    mmlcm_watch_t m;
    m.utime = ut;
    m.nvars = (int16_t)t->watch_n;
    m.name = (char **)t->watch_names;
    m.type = (char **)t->watch_types;
    m.value = t->watch_v;
    emit(t, "MM_WATCH", ut, mmlcm_watch_t_encode(t->buf, 0, TELEM_BUF_BYTES, &m));
}

void telem_watch(telem_t *t, const sim_state_t *s, int n, const char *const *names, const char *const *types,
                 const double *values)
{
    t->watch_n = n < 0 ? 0 : n > TELEM_WATCH_MAX ? TELEM_WATCH_MAX : n;
    t->watch_names = names;
    t->watch_types = types;
    memcpy(t->watch_v, values, (size_t)t->watch_n * sizeof *values);
    t->watch_step = s->step;
    if (t->watch_n && t->last_fast == s->step) pub_watch(t, s);
}

void telem_finish(telem_t *t, const sim_state_t *s, const sim_belief_t *b)
{
    if (belief_new(t, b)) pub_belief(t, b);
    pub_events(t, s);
    if (t->last_fast != s->step) {
        pub_fast(t, s);
        if (t->watch_n && t->watch_step == s->step) pub_watch(t, s); /* read after this last step */
    }
    if (t->last_race != s->step) pub_race(t, s);
    if (t->link && t->last_link != s->step) pub_link(t, s);
}

/* Flush, sync and close the log, then rename its temporary over the
 * target: 0, or -1 with one line in err (the temporary removed). */
static int close_log(telem_t *t, char *err, size_t errlen)
{
    FILE *f = ((lcm_eventlog_t *)t->log)->f;
    errno = 0;
    if (fflush(f) != 0 || ferror(f) || (!t->log_in_place && fsync(fileno(f)) != 0)) {
        if (!t->failed) t->log_errno = errno;
        t->failed = 1;
    }
    lcm_eventlog_destroy(t->log);
    t->log = NULL;
    if (!t->failed && !t->log_in_place && rename(t->log_out.tmp, t->log_out.path) != 0) {
        t->log_errno = errno;
        t->failed = 1;
    }
    if (!t->log_in_place && t->failed) unlink(t->log_out.tmp);
    t->log_out.tmp[0] = '\0';
    if (!t->failed) return 0;
    snprintf(err, errlen, "%s: writing the LCM log failed: %s%s", t->log_out.path,
             t->log_errno ? strerror(t->log_errno) : "write error",
             t->log_in_place ? "" : " (the file there is unchanged)");
    return -1;
}

int telem_close(telem_t *t, char *err, size_t errlen)
{
    int rc = 0;
    if (t->log) rc = close_log(t, err, errlen);
    if (t->lcm) {
        if (rc == 0 && t->live_lost) {
            snprintf(err, errlen, "%s: the connection to the LCM hub was lost at %.3f s (%s): live telemetry stopped there",
                     t->url, t->live_lost_s, t->live_errno ? strerror(t->live_errno) : "send failed");
            rc = -1;
        }
        lcm_destroy(t->lcm);
        t->lcm = NULL;
    }
    close_quiet(t);
    return rc;
}

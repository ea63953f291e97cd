/* sensor.h - sensor kinds: what a robot file's [KIND.NAME] section may
 * say (the kind's schema) and how such a sensor reads the world.
 *
 * Adding a kind = one module in this folder with its schema and these
 * functions, and one line in sensor.c's list; nothing else changes: the
 * robot file loader (robot.c) parses any listed kind's section, the
 * simulation (sim.c) steps and reads every sensor through this table, and
 * telemetry carries every sensor's values (MM_PARTS). */
#ifndef SENSOR_H
#define SENSOR_H

#include <stdint.h>

#include "world/config.h"
#include "world/keytab.h"
#include "world/world.h"

#define SENSOR_VALUES 4   /* values a sensor reports at most */

/* What a sensor sees of the simulation when it steps or is read. */
typedef struct {
    world_t *world;
    const sim_model_t *model;
    uint64_t step;          /* physics steps done */
    double t_s;             /* simulation time, s */
    const int *emitter;     /* emitter groups' states (SIM_EMITTER_GROUPS) */
    double yaw_rate_rad_s;  /* the chassis' true yaw rate, CCW positive */
} sensor_ctx_t;

typedef struct sensor_kind_s {
    const char *name;                /* the section's KIND, e.g. "ir" */
    const char *doc;                 /* one line: what it models */
    const keytab_t *keys;            /* its schema: offsets into robot_part_t.spec */
    size_t nkeys;
    /* cross-key checks of a parsed section: 0, or -1 with "key: reason" */
    int (*check)(const robot_part_t *p, char *reason, size_t len);
    size_t state_size;               /* bytes of its run-time state */
    /* index: this sensor's number among its kind's; count: how many there are */
    void (*init)(void *state, const robot_part_t *p, const sim_model_t *m, uint64_t seed, unsigned index, unsigned count);
    /* every physics step, after the world moved (NULL: samples only when read) */
    void (*step)(void *state, const robot_part_t *p, const sensor_ctx_t *x);
    /* the reading now into v (the kind's units, as `units` names them); returns how many */
    int (*read)(void *state, const robot_part_t *p, const sensor_ctx_t *x, double v[SENSOR_VALUES]);
    const char *units;               /* e.g. "mm timeout" */
} sensor_kind_t;

/* The kind named `name`, NULL if none. */
const sensor_kind_t *sensor_kind(const char *name);
/* The i-th kind, NULL past the end. */
const sensor_kind_t *sensor_kind_at(unsigned i);

/* The index in m->part of the i-th sensor of a kind ("ir", "tof",
 * "gyro"), -1 if there is none; how many of that kind m has. */
int sensor_of_kind(const sim_model_t *m, const char *kind, unsigned i);
unsigned sensor_count(const sim_model_t *m, const char *kind);
/* Part p's pose in model m (p is one of m->part). */
const sim_pose_t *sensor_pose(const sim_model_t *m, const robot_part_t *p);
/* Where a sensor at this pose sits in the world now and its frame: axis
 * (where it looks: yaw then pitch), left and up, unit vectors. */
void sensor_frame(const world_t *w, const sim_pose_t *pose, double pos_m[3], double axis[3], double left[3], double up[3]);

#endif

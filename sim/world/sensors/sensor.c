/* sensor.c - the list of sensor kinds and the chassis-to-world frame of a
 * sensor (see sensor.h). */
#include "sensor.h"

#include <string.h>

extern const sensor_kind_t sensor_tof, sensor_ir, sensor_gyro;

/* A new kind: its module in this folder, and its line here. */
static const sensor_kind_t *const kinds[] = { &sensor_tof, &sensor_ir, &sensor_gyro };
#define NKINDS (sizeof kinds / sizeof kinds[0])

const sensor_kind_t *sensor_kind(const char *name)
{
    for (size_t i = 0; i < NKINDS; i++)
        if (!strcmp(kinds[i]->name, name)) return kinds[i];
    return NULL;
}

const sensor_kind_t *sensor_kind_at(unsigned i) { return i < NKINDS ? kinds[i] : NULL; }

int sensor_of_kind(const sim_model_t *m, const char *kind, unsigned i)
{
    for (int k = 0; k < m->nparts; k++)
        if (!strcmp(m->part[k].kind->name, kind) && i-- == 0) return k;
    return -1;
}

unsigned sensor_count(const sim_model_t *m, const char *kind)
{
    unsigned n = 0;
    for (int k = 0; k < m->nparts; k++) n += !strcmp(m->part[k].kind->name, kind);
    return n;
}

const sim_pose_t *sensor_pose(const sim_model_t *m, const robot_part_t *p) { return &m->pose[p - m->part]; }

void sensor_frame(const world_t *w, const sim_pose_t *pose, double pos_m[3], double axis[3], double left[3], double up[3])
{
    world_body_point(w, pose->pos_m, pos_m);
    world_body_vector(w, pose->axis, axis);
    world_body_vector(w, pose->left, left);
    world_body_vector(w, pose->up, up);
}

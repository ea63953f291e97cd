/* sensor.c - the list of sensor kinds and the chassis-to-world frame of a
 * sensor (see sensor.h). */
#include "sensor.h"

#include <math.h>
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

void sensor_frame(const world_t *w, const robot_part_t *p, double pos_m[3], double axis[3], double left[3], double up[3])
{
    /* the robot frame's forward is +y: a yaw a turns it to (cos(pi/2 + a), sin(pi/2 + a)) */
    double yaw = M_PI / 2 + p->yaw_deg * M_PI / 180, pitch = p->pitch_deg * M_PI / 180;
    const double local[3] = { p->x_m, p->y_m, p->z_m };
    double ax[3] = { cos(yaw) * cos(pitch), sin(yaw) * cos(pitch), sin(pitch) };
    double lf[3] = { -sin(yaw), cos(yaw), 0 };
    double upl[3] = { -cos(yaw) * sin(pitch), -sin(yaw) * sin(pitch), cos(pitch) };
    world_body_point(w, local, pos_m);
    world_body_vector(w, ax, axis);
    world_body_vector(w, lf, left);
    world_body_vector(w, upl, up);
}

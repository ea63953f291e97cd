/* snap.h - what the viewer draws of a run at one moment, as plain data:
 * the robot's pose and wheels, where each ToF and IR sensor sits and how
 * far its ray reaches, the emitter groups, the centre post, the contest
 * timers and the simulation time. The scene and the HUD draw from the
 * run's const model (model.h), a snapshot and the maze; they never read
 * the ODE world.
 *
 * A live run fills one from its sim_state_t before each frame (snap_from_sim:
 * the world's own pose, rays and posts); a replay fills one from its log
 * (replay.h: the logged pose with snap_place, which casts the rays
 * against the maze's geometry with snap_maze_ray). */
#ifndef SNAP_H
#define SNAP_H

#include "maze/truemaze.h"
#include "world/model.h"
#include "world/race.h"
#include "world/sim.h"
#include "world/world.h"

/* One sensor's frame in the world and its ray along the axis. */
typedef struct {
    double pos_m[3];             /* where it sits, m */
    double axis[3], left[3], up[3]; /* unit axes: where it looks, its left, its up */
    double hit_m;                /* the first wall or post along the axis, m; -1 none within the sensor's range */
} snap_ray_t;

typedef struct {
    double time_s;               /* simulation time, s */
    double x_m, y_m;             /* the body's centre over the floor, m (world.h's frame) */
    double heading_rad;          /* world.h's heading */
    double v_m_s;                /* speed along the heading, m/s */
    double wheel_rad[2];         /* each wheel's hinge angle (rad, positive = forward; WORLD_LEFT, WORLD_RIGHT) */
    double wheel_hub_z_m[2];     /* each wheel's axle above the floor, m (drawn as the robot stands level on it) */
    int ntof;                    /* the robot's ToF sensors (sim.h's order: left, front, right) */
    snap_ray_t tof[WORLD_TOF_COUNT]; /* hit_m: the true distance behind the last reading, -1 none */
    double tof_range_m;          /* the first ToF's range: a ray with no hit is drawn this long */
    snap_ray_t part[ROBOT_MAX_PARTS]; /* each IR sensor's beam (model->cfg->part's order; other kinds unused) */
    int emitter[SIM_EMITTER_GROUPS]; /* emitter groups lit (1) or dark */
    int centre_post;             /* the post in the middle of the maze is there */
    race_t race;                 /* the contest timers */
} snap_t;

/* The live run s now: its world's pose, wheels, sensor frames and rays
 * (world_ray_normal: no noise drawn, no state changed), emitters, post,
 * timers and time. */
void snap_from_sim(snap_t *out, const sim_state_t *s);

/* The pose part of a snapshot for a robot standing level on the floor of
 * maze m (model's config) with its body centre over (x_m, y_m) facing
 * heading_rad and its wheels at these hinge angles: each wheel's axle at
 * its own radius, each sensor's frame, each IR beam's reach cast with
 * snap_maze_ray (centre_post: the middle post is there). The ToF rays'
 * hit_m, the emitters, timers and time are the caller's. */
void snap_place(snap_t *out, const sim_model_t *model, const truemaze_t *m, int centre_post, double x_m, double y_m,
                double heading_rad, const double wheel_rad[2]);

/* The distance (m) from pos_m along dir (need not be unit length) to the
 * first wall or post of maze m as the ODE world builds them (world.c's
 * build_maze: every post and wall an axis-aligned box from the floor to
 * wall_height_m, the centre post if centre_post), or -1 if none within
 * max_m. A ray that starts inside a box hits where it leaves it, as
 * ODE's ray-box test does. */
double snap_maze_ray(const simcfg_t *c, const truemaze_t *m, int centre_post, const double pos_m[3], const double dir[3],
                     double max_m);

#endif

/* world.h - the ODE world: floor, walls and posts of a maze, the robot
 * (body box with its casters, two wheels: bodies on hinges, or each wheel's
 * spin a body of its own, [sim] wheels), contacts, rays.
 *
 * Frame: x east, y north, z up, metres; origin at the outer south-west
 * corner of the maze's post grid (post centres at multiples of cell_m).
 * The robot's own frame: x right, y forward, z up. A heading is the math
 * angle of the robot's forward direction from +x, counter-clockwise, so
 * facing north is pi/2.
 *
 * Static geoms (floor category 1, walls and posts category 1) sit in a
 * quadtree space and collide only with the robot (category 2): no
 * static-static pairs (platform facts: one hash space for everything costs
 * ~200 us per 1 ms step, a wall quadtree 16-18 us). The robot's parts
 * meet the walls and posts of the cells their bounds overlap (wallgrid),
 * in the order the quadtree's walk would meet them, and only while some
 * part comes within a micrometre of one; the tyre spheres meet only the
 * floor. Rays (IR, ToF) walk the same cells. */
#ifndef WORLD_H
#define WORLD_H

#include "config.h"
#include "maze/truemaze.h"
#include "model.h"
#include "motor.h"

enum { WORLD_LEFT = 0, WORLD_RIGHT = 1 };
enum { WORLD_TOF_LEFT = 0, WORLD_TOF_FRONT = 1, WORLD_TOF_RIGHT = 2, WORLD_TOF_COUNT = 3 };

typedef struct world world_t;

/* Build the world of model for maze m with the robot's body centre over
 * (x_m, y_m) facing heading_rad. The world reads the model (which must
 * outlive it) by pointer. NULL if ODE fails. */
world_t *world_create(const sim_model_t *model, const truemaze_t *m, double x_m, double y_m, double heading_rad);
void world_destroy(world_t *w);

/* One physics step of the config's sim.step_s with each wheel's motor drive (output
 * shaft, positive drives forward; motor.h): the chassis gets the reaction
 * torques. The solver is the config's (sim.solver). */
void world_step(world_t *w, const motor_drive_t drive[2]);
/* For the validation bench: the chassis held 50 mm above the floor (the
 * wheels spin free), and with lock_wheels the wheels fixed to it (stall). */
void world_lift(world_t *w, int lock_wheels);
/* A person's hands. world_hand: the chassis gripped (on) so that its
 * axle's middle moves v_m_s along its heading and it turns omega_rad_s
 * counter-clockwise, over the floor on its own wheels (they roll, and the
 * encoders count as they turn), with at most WORLD_HAND_FORCE_N and
 * WORLD_HAND_TORQUE_NM (a wall stops it); on = 0 lets go. Set again each
 * step as the heading turns. world_carry: lifted WORLD_CARRY_M and held
 * still there, the wheels free (on), or put back down level, resting where
 * it was lifted, its wheel angles kept (off). */
#define WORLD_HAND_FORCE_N 20.0   /* N: a firm push; the robot weighs ~1.5 N */
#define WORLD_HAND_TORQUE_NM 1.0  /* N*m: a firm twist */
#define WORLD_CARRY_M 0.05        /* m: the wheels clear the floor */
void world_hand(world_t *w, int on, double v_m_s, double omega_rad_s);
void world_carry(world_t *w, int on);
int world_carried(const world_t *w);
/* For the bench: a brake of load_nm against each wheel's motion, this step. */
void world_brake(world_t *w, double load_nm);
/* For the bench: a dynamometer that holds each wheel at rate_rad_s
 * (positive = forward) from now on. */
void world_dyno(world_t *w, double rate_rad_s);

/* Body centre and heading; speed along the heading (m/s) and yaw rate. */
void world_pose(const world_t *w, double *x_m, double *y_m, double *heading_rad);
void world_velocity(const world_t *w, double *v_m_s, double *omega_rad_s);
/* Height of the body centre above the floor, m (to check it stays down). */
double world_body_z(const world_t *w);

/* The lowest point of a wheel's tyre above the floor, m (0 = resting on
 * it; the floor's contact softness presses it in by a few micrometres). */
double world_wheel_floor_gap(const world_t *w, int side);
/* A wheel's angle about its axle, relative to the chassis (wraps at +-pi),
 * and its rate (positive = forward). */
double world_wheel_angle(const world_t *w, int side);
double world_wheel_rate(const world_t *w, int side);

/* A point (m) and a direction of the robot's chassis frame (origin at
 * the body's centre on the floor, x right, y forward, z up) in the world. */
void world_body_point(const world_t *w, const double p_m[3], double out_m[3]);
void world_body_vector(const world_t *w, const double v[3], double out[3]);
/* Cast a ray from any point in any horizontal direction (for tests). */
double world_ray(world_t *w, double x_m, double y_m, double z_m, double dir_rad, double max_m);
/* The same for a ray from pos_m along any direction dir (need not be unit
 * length), also giving the unit surface normal of the nearest hit, facing
 * the ray (normal . dir < 0; the IR sensor's angle of incidence). Distance
 * in m, -1 (normal 0) if nothing within max_m. */
double world_ray_normal(world_t *w, const double pos_m[3], const double dir[3], double max_m, double normal[3]);
/* One ray of a sensor's: its direction (world frame, unit length), the
 * distance to the nearest surface along it (m; -1: none within the ray's
 * length) and that surface's unit normal, facing the ray. */
typedef struct {
    double dir[3], d_m, normal[3];
} world_hit_t;
/* A sensor's n rays, each given in its own frame (off[i]: x along its
 * axis, y left, z up), max_m long, cast from its place `at` (world frame):
 * hit[i], what world_ray_normal returns for each. */
void world_cast(world_t *w, const sim_pose_t *at, int n, const double (*off)[3], double max_m, world_hit_t *hit);
/* The same for a sensor at `pose` on the chassis (its frame): where the
 * chassis puts it now into *at (world frame), then its rays. */
void world_body_cast(world_t *w, const sim_pose_t *pose, int n, const double (*off)[3], double max_m, sim_pose_t *at,
                     world_hit_t *hit);

/* Put the robot, at rest and level, with its body centre over (x_m, y_m)
 * facing heading_rad and its wheels at these angles (rad, positive =
 * forward; NULL = keep the current ones, so the encoders do not jump),
 * each wheel on the floor at its own radius:
 * a logged pose replayed (mmview), the robot carried back to the start
 * (mms ackReset). */
void world_place(world_t *w, double x_m, double y_m, double heading_rad, const double wheel_rad[2]);

/* Robot-wall contact: how many separate contact episodes so far. */
unsigned world_collisions(const world_t *w);
/* Contact episodes by the part of the robot that touched: its body's front
 * face (or a skid), its sides (or a wheel's), its rear face at under
 * WORLD_REAR_SOFT_M_S (a robot that backs into the wall behind it on
 * purpose, as UKMARSBOT's firmware does) or faster. An episode with two
 * kinds counts once for each; the ongoing one counts. */
enum { WORLD_CONTACT_FRONT, WORLD_CONTACT_SIDE, WORLD_CONTACT_REAR_SOFT, WORLD_CONTACT_REAR, WORLD_CONTACT_KINDS };
#define WORLD_REAR_SOFT_M_S 0.1 /* m/s: a touch of the rear below this is not an error */
unsigned world_contacts(const world_t *w, int kind);
/* For tests: the robot rolling straight ahead at v_m_s (the chassis and
 * the wheels' centres at v_m_s, the wheels turning to roll), not turning. */
void world_set_speed(world_t *w, double v_m_s);
/* The deepest a wall or post went into the robot (body or wheel) in the
 * last world_step, as ODE's contacts found it, m (0: no wall contact). */
double world_wall_depth(const world_t *w);
/* 0 once the robot's state has left what any run in the config's ranges
 * reaches (a position beyond WORLD_SANE_M, a speed beyond
 * WORLD_SANE_M_S, a spin beyond WORLD_SANE_RAD_S, or not a number): the
 * integration diverged, and ODE's next steps would abort the process. */
#define WORLD_SANE_M 1e4       /* m */
#define WORLD_SANE_M_S 1e5     /* m/s */
#define WORLD_SANE_RAD_S 1e7   /* rad/s; a free wheel's top speed is at most 5e6 */
int world_sane(const world_t *w);

/* The post in the middle of the maze (the goal's centre post). */
void world_set_centre_post(world_t *w, int on);
int world_has_centre_post(const world_t *w);

#endif

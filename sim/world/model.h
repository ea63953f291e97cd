/* model.h - the robot and world as one run simulates them, MuJoCo's
 * compiled model: built once by sim_model_build from the loaded config and
 * robot file (simcfg_t, as the files give them) and the run's seed, and
 * const after that.
 *
 * Every number the physics reads (world.c, sim.c, the sensors) is here, in
 * the unit the physics uses: the step and solver, the arena, the chassis,
 * each wheel's radius, each motor's drive and constant factor, each tyre's
 * friction and the body's centre of mass after this seed's [asymmetry] and
 * [variation], the battery, the sensors with their poses as vectors. The
 * config it was built from stays the caller's (cfg): the observers print
 * and draw from it (telemetry's MM_MAZE, the viewer), the physics never
 * reads it. Everything that changes during a run is in sim_state_t (sim.h). */
#ifndef MODEL_H
#define MODEL_H

#include <stdint.h>

#include "config.h"

/* A sensor's pose in the chassis frame (origin at the body's centre on
 * the floor, x right, y forward, z up): where it sits (m) and its unit
 * axes: where it looks (yaw then pitch), its left and its up. */
typedef struct {
    double pos_m[3];
    double axis[3], left[3], up[3];
} sim_pose_t;

/* The chassis as the physics builds it (the robot file's [chassis.NAME]). */
typedef struct {
    double body_w_m, body_l_m, body_h_m, body_mass_kg;
    double body_clearance_m;      /* floor to the underside of the body */
    double body_yaw_inertia_kgm2; /* about the vertical axis; 0 = a uniform box's */
    double wheel_w_m, wheel_mass_kg;
    double wheel_x_m;             /* wheel centre plane from the body's centre line */
    double axle_y_m;              /* axle position along the body, from its centre */
    double caster_r_m, caster_mass_kg;
    double caster_y_m[2];         /* each skid's place along the body (the second's only with casters 2) */
    double skid_mu;               /* Coulomb friction, skid on floor */
    double tyre_slip_m_s;         /* contact slip speed above which a tyre's sliding friction applies */
    double body_drag_n_s_m;       /* N per m/s against the axle midpoint's horizontal velocity (a translation's load) */
} sim_chassis_t;

typedef struct sim_model_s {
    const simcfg_t *cfg;        /* the config and robot as loaded (the caller's: it outlives the model), for the observers; the physics reads none of it */
    /* [sim] */
    double step_s;              /* the physics step, s */
    int solver;                 /* SIM_SOLVER_* */
    int solver_iterations;      /* quickstep's iterations per step */
    int wheels;                 /* SIM_WHEELS_*: the wheels' form in the physics */
    double time_limit_s;        /* the contest's limit, s */
    /* [world] */
    simcfg_world_t arena;       /* the maze's geometry, the walls' friction and reflectance, the contact springs */
    /* the robot's word and count keys */
    int start;                  /* ROBOT_START_* */
    int casters;                /* 1, or 2 (a second skid at chassis.caster_y_m[1]) */
    int motor_model[2];         /* MOTOR_MODEL_*, WORLD_LEFT and WORLD_RIGHT */
    sim_chassis_t chassis;
    drive_spec_t drive[2];      /* each wheel's motor, gearbox, H-bridge and encoder, as the robot file gives them */
    double rotor_j_kgm2[2];     /* each motor's rotor reflected to its wheel (J N^2, kg*m^2); 0 where the motor model leaves it out */
    battery_spec_t battery;
    /* this robot: the robot file with the seed's asymmetries */
    double wheel_r_m[2];        /* each wheel's radius, m */
    double motor_k_scale[2];    /* each motor's constant (back-EMF and torque) relative to the file's, 1 */
    double tyre_mu[2];          /* each tyre's static friction on the floor (Coulomb, 1) */
    double tyre_mu_dynamic[2];  /* each tyre's sliding friction, above chassis.tyre_slip_m_s (1) */
    double body_com_m[3];       /* the body's centre of mass in the chassis frame, before the casters' mass, m */
    /* the sensors, in the robot file's order */
    int nparts;
    robot_part_t part[ROBOT_MAX_PARTS];
    sim_pose_t pose[ROBOT_MAX_PARTS]; /* each sensor's */
} sim_model_t;

/* Build m from the loaded c (which must outlive m) and the run's seed:
 * the per-seed [variation] is drawn from its own stream (rng.h). */
void sim_model_build(sim_model_t *m, const simcfg_t *c, uint64_t seed);

#endif

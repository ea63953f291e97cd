/* model.h - the robot and world as one run simulates them: built once by
 * sim_model_build from the loaded config and robot file (simcfg_t, as the
 * files give them) and the run's seed, and const after that.
 *
 * The file's numbers stay in the config the model points to; the model
 * holds what is derived from them, once, in the unit the physics uses:
 * each wheel's radius, each motor's constant factor, each tyre's friction
 * and the body's centre of mass after this seed's [asymmetry] and
 * [variation]; the sensors' poses as vectors; the solver, the start and
 * the casters as the config gives them. Everything that changes during a run
 * is in sim_state_t (sim.h). */
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

typedef struct sim_model_s {
    const simcfg_t *cfg;        /* the config and robot as loaded (the caller's: it outlives the model) */
    /* [sim] */
    int solver;                 /* SIM_SOLVER_* */
    int solver_iterations;      /* quickstep's iterations per step */
    /* the robot's word and count keys */
    int start;                  /* ROBOT_START_* */
    int casters;                /* 1, or 2 (a second skid at caster2_y_m) */
    int motor_model[2];         /* MOTOR_MODEL_*, WORLD_LEFT and WORLD_RIGHT */
    /* this robot: the robot file with the seed's asymmetries */
    double wheel_r_m[2];        /* each wheel's radius, m */
    double motor_k_scale[2];    /* each motor's constant (back-EMF and torque) relative to the file's, 1 */
    double tyre_mu[2];          /* each tyre's static friction on the floor (Coulomb, 1) */
    double tyre_mu_dynamic[2];  /* each tyre's sliding friction, above cfg->robot.tyre_slip_m_s (1) */
    double body_com_m[3];       /* the body's centre of mass in the chassis frame, before the casters' mass, m */
    sim_pose_t pose[ROBOT_MAX_PARTS]; /* each sensor's, in cfg->robot.part's order (cfg->robot.nparts of them) */
} sim_model_t;

/* Build m from the loaded c (which must outlive m) and the run's seed:
 * the per-seed [variation] is drawn from its own stream (rng.h). */
void sim_model_build(sim_model_t *m, const simcfg_t *c, uint64_t seed);

#endif

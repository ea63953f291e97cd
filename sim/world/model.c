/* model.c - the run's model from the config, the robot file and the seed
 * (see model.h). */
#include "model.h"

#include <math.h>

#include "rng.h"

/* The seed's asymmetries: the configured ones plus the [variation]'s
 * draws (one stream, drawn in this order), right minus left. */
typedef struct {
    double wheel_d_m, motor_k_pct, tyre_mu, com_x_m, com_y_m;
} asym_t;

static asym_t asymmetry(const simcfg_t *c, uint64_t seed)
{
    rng_t r;
    rng_init(&r, seed, RNG_STREAM_VARIATION);
    double g[5];
    for (int i = 0; i < 5; i++) g[i] = rng_gauss(&r);
    asym_t a = { c->asym.wheel_d_diff_m, c->asym.motor_k_diff_pct, c->asym.tyre_mu_diff, c->asym.com_x_m, c->asym.com_y_m };
    a.wheel_d_m += c->var.wheel_d_sigma_m * g[0];
    a.motor_k_pct += c->var.motor_k_sigma_pct * g[1];
    a.tyre_mu += c->var.tyre_mu_sigma * g[2];
    a.com_x_m += c->var.com_sigma_m * g[3];
    a.com_y_m += c->var.com_sigma_m * g[4];
    return a;
}

/* Each wheel's radius from the robot file's two diameters (their mean,
 * and their right-minus-left difference plus the config's asymmetry); each tyre's friction, at least
 * 0.01, its sliding friction in the same ratio to it as the file's. */
static void wheels(sim_model_t *m, const simcfg_t *c, const asym_t *a)
{
    double rw = (c->robot.wheel_left_d_m + c->robot.wheel_right_d_m) / 2 / 2; /* the mean diameter's half */
    double diff = a->wheel_d_m + (c->robot.wheel_right_d_m - c->robot.wheel_left_d_m);
    for (int s = 0; s < 2; s++) {
        double half = s == 0 ? -0.5 : 0.5; /* left, right */
        m->wheel_r_m[s] = rw + (s == 0 ? -0.25 : 0.25) * diff;
        m->tyre_mu[s] = c->robot.tyre_mu + half * a->tyre_mu;
        if (m->tyre_mu[s] < 0.01) m->tyre_mu[s] = 0.01;
        m->tyre_mu_dynamic[s] = m->tyre_mu[s] * c->robot.tyre_mu_dynamic / c->robot.tyre_mu;
        /* right minus left, in per cent of the mean */
        m->motor_k_scale[s] = 1.0 + (s == 0 ? -0.005 : 0.005) * a->motor_k_pct;
        m->motor_model[s] = c->robot.drive[s].motor_model;
        const drive_spec_t *dr = &c->robot.drive[s];
        m->drive[s] = *dr;
        m->rotor_j_kgm2[s] = dr->rotor_inertia_kgm2 > 0 && dr->motor_model != MOTOR_MODEL_PAPER ? dr->rotor_inertia_kgm2 * dr->gear_ratio * dr->gear_ratio : 0;
    }
}

static void sensor_poses(sim_model_t *m, const simcfg_t *c)
{
    for (int i = 0; i < c->robot.nparts; i++) {
        const robot_part_t *p = &c->robot.part[i];
        sim_pose_t *q = &m->pose[i];
        /* the robot frame's forward is +y: a yaw a turns it to (cos(pi/2 + a), sin(pi/2 + a)) */
        double yaw = M_PI / 2 + p->yaw_deg * M_PI / 180, pitch = p->pitch_deg * M_PI / 180;
        const double pos[3] = { p->x_m, p->y_m, p->z_m };
        const double ax[3] = { cos(yaw) * cos(pitch), sin(yaw) * cos(pitch), sin(pitch) };
        const double lf[3] = { -sin(yaw), cos(yaw), 0 };
        const double up[3] = { -cos(yaw) * sin(pitch), -sin(yaw) * sin(pitch), cos(pitch) };
        for (int k = 0; k < 3; k++) {
            q->pos_m[k] = pos[k];
            q->axis[k] = ax[k];
            q->left[k] = lf[k];
            q->up[k] = up[k];
        }
    }
}

/* The chassis' numbers as the robot file gives them. */
static void chassis(sim_chassis_t *ch, const simcfg_robot_t *r)
{
    ch->body_w_m = r->body_w_m;
    ch->body_l_m = r->body_l_m;
    ch->body_h_m = r->body_h_m;
    ch->body_mass_kg = r->body_mass_kg;
    ch->body_clearance_m = r->body_clearance_m;
    ch->body_yaw_inertia_kgm2 = r->body_yaw_inertia_kgm2;
    ch->wheel_w_m = r->wheel_w_m;
    ch->wheel_mass_kg = r->wheel_mass_kg;
    ch->wheel_x_m = r->wheel_x_m;
    ch->axle_y_m = r->axle_y_m;
    ch->caster_r_m = r->caster_r_m;
    ch->caster_mass_kg = r->caster_mass_kg;
    ch->caster_y_m[0] = r->caster_y_m;
    ch->caster_y_m[1] = r->caster2_y_m;
    ch->skid_mu = r->skid_mu;
    ch->tyre_slip_m_s = r->tyre_slip_m_s;
    ch->body_drag_n_s_m = r->body_drag_n_s_m;
}

void sim_model_build(sim_model_t *m, const simcfg_t *c, uint64_t seed)
{
    asym_t a = asymmetry(c, seed);
    m->cfg = c;
    m->step_s = c->sim.step_s;
    m->solver = c->sim.solver;
    m->solver_iterations = c->sim.solver_iterations;
    m->wheels = c->sim.wheels;
    m->time_limit_s = c->sim.time_limit_s;
    m->arena = c->world;
    m->start = c->robot.start;
    m->casters = c->robot.casters;
    chassis(&m->chassis, &c->robot);
    m->battery = c->robot.battery;
    wheels(m, c, &a);
    /* the body's mass may sit off its geometric centre (asymmetry, and the robot file's) */
    m->body_com_m[0] = 0.0 + a.com_x_m;
    m->body_com_m[1] = 0.0 + a.com_y_m + c->robot.body_com_y_m;
    m->body_com_m[2] = c->robot.body_clearance_m + c->robot.body_h_m / 2;
    m->nparts = c->robot.nparts;
    for (int i = 0; i < c->robot.nparts; i++) m->part[i] = c->robot.part[i];
    sensor_poses(m, c);
}

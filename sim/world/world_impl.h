/* world_impl.h - the inside of the ODE world (world.h), shared by world.c
 * (the maze, the chassis, contacts, the step), the two forms a wheel may
 * take in it (world_wheel_spin.c, world_wheel_hinge.c: each the same table
 * of operations, world_wheels_t), which all use world_body.h. Nothing
 * outside those files includes it. */
#ifndef WORLD_IMPL_H
#define WORLD_IMPL_H

#include <ode/ode.h>

#include "world.h"
#include "world_body.h"
#include "wallgrid.h"

#define CAT_STATIC 1u
#define CAT_ROBOT 2u
#define CAT_RAY 4u
#define CAT_FLOOR 8u
#define CAT_TYRE 16u       /* wheel-floor contact sphere */
#define CAT_WHEEL_SIDE 32u /* wheel cylinder, against walls only */
/* ODE pairs two geoms when either one's category meets the other's collide
 * bits, so each kind that must not meet another has its own category */
#define WORLD_PARTS 8 /* most geoms the robot has: body, two skids, two tyres, two wheel sides */

/* A form of the wheels in the physics ([sim] wheels): how a wheel is built
 * and driven, and what the chassis takes from it. s is WORLD_LEFT or
 * WORLD_RIGHT; a rate or torque is about the axle, + turning the wheel
 * forward. world.c calls these and never asks which form it has. */
typedef struct {
    /* building (world_create): the wheels' share of the chassis' mass
     * (about its centre of mass in the chassis frame, before the chassis
     * body is made); the body box put on the chassis; wheel s's bodies,
     * geoms and joints for a robot at (x_m, y_m) facing heading_rad */
    void (*chassis_mass)(const world_t *w, dMass *mb);
    void (*attach_box)(world_t *w);
    void (*build)(world_t *w, int s, double x_m, double y_m, double heading_rad);
    /* the wheel's spin relative to the chassis (rad/s) and its angle (rad, wraps at +-pi) */
    double (*rate)(const world_t *w, int s);
    double (*angle)(const world_t *w, int s);
    /* driving, each ODE step: a torque between chassis and wheel; the
     * motor's row toward vel_rad_s with at most fmax_nm and softness cfm,
     * or off; what the chassis and the wheel hand each other besides (after
     * the wheel's own torques) */
    void (*torque)(world_t *w, int s, double t_nm);
    void (*motor_row)(world_t *w, int s, double vel_rad_s, double fmax_nm, double cfm);
    void (*motor_off)(world_t *w, int s);
    void (*couple)(world_t *w, int s);
    /* around each ODE step */
    void (*before_ode)(world_t *w);
    void (*after_ode)(world_t *w);
    /* contacts: the second body of a contact of robot part `part` with
     * geom `other` (its own body, or what stands for it); the speed of the
     * wheel's rim at world point p, which the tyre's slip subtracts */
    dBodyID (*contact_body)(const world_t *w, dGeomID part, dGeomID other);
    void (*rim_vel)(const world_t *w, int s, const dReal *p, dVector3 v);
    /* the bench and the hands: an angular motor row that holds the wheel's
     * spin (world_dyno); the wheel raised with a lifted chassis; fixed to
     * the chassis (a stall); put down at rest at angle_rad under a chassis
     * placed at (x_m, y_m, heading_rad); rolling at v_m_s */
    dJointID (*dyno_row)(world_t *w, int s);
    void (*hold_up)(world_t *w, int s);
    void (*lock)(world_t *w, int s);
    void (*place)(world_t *w, int s, double x_m, double y_m, double heading_rad, double angle_rad);
    void (*set_speed)(world_t *w, int s, double v_m_s);
} world_wheels_t;

extern const world_wheels_t world_wheel_spin, world_wheel_hinge;

struct world {
    const sim_model_t *model; /* the caller's: outlives the world */
    dWorldID world;
    dSpaceID top, statics, robot;
    dJointGroupID contacts;
    dGeomID floor, centre_post, box, caster, caster2, wheel_geom[2], wheel_side[2], ray;
    const world_wheels_t *wheels; /* the wheels' form ([sim] wheels): world_wheel_spin or world_wheel_hinge */
    dBodyID chassis, wheel[2]; /* each wheel's body, or its spin body */
    dJointID hinge[2];     /* hinged wheels: each wheel's hinge (its motor row the motor's damper) */
    dJointID motor[2];     /* spin bodies: the motor's damper row on each (an angular motor) */
    dJointID friction[2];  /* the gearbox's stiction on each wheel (an angular motor, target speed 0) */
    double motor_set[2][3]; /* what drive_wheel last gave each spin body's motor row: its dParamVel (rad/s), dParamFMax (N*m), dParamCFM (rad/s per N*m); NaN: not yet */
    double friction_set[2]; /* what drive_wheel last gave each friction row's dParamFMax, N*m; NaN: not yet */
    double spin_j[2];      /* each spin body's inertia about its axle, kg*m^2 */
    double spin_before[2]; /* each wheel's spin before the ODE step in progress, rad/s */
    double wheel_j[2];     /* each wheel's own inertia about its axle (its cylinder's, no rotor), kg*m^2: what couples spin and chassis (spin_advance) */
    double reaction_nm[2]; /* wheel_j * the spin's change over the last ODE step / h, about the axle, N*m: the chassis takes it next (spin_advance) */
    double pitch_before;   /* the chassis' rate about its axle (its x) before the ODE step in progress, rad/s */
    double pitch_acc;      /* its change over the last ODE step / h, rad/s^2: wheel_j times it turns each spin body next (spin_advance) */
    double wheel_angle[2]; /* each wheel's angle about its axle, rad in (-pi, pi], + forward */
    dJointID lift, lock[2]; /* world_lift: chassis held above the floor, wheels locked */
    dGeomID *wall;          /* the maze's boxes (posts and walls), by wallgrid id */
    double (*wall_bounds)[4]; /* their floor bounds: min x, max x, min y, max y, m */
    int nwalls;
    wallgrid_t *grid;       /* the boxes by cell, for rays and contacts */
    double (*wall_aabb)[6]; /* each box's bounds as ODE has them (dGeomGetAABB), m */
    int *wall_rank;         /* each box's place in the collision tree's walk (maze_order) */
    int *near_ids;          /* room for every box: the candidates of one robot part */
    int ranked;             /* every box has its place: maze contacts by cell (else ODE's tree walk) */
    dGeomID part[WORLD_PARTS]; /* the robot's geoms in its space's order (ODE's), nparts of them */
    int nparts;
    /* With spin bodies the body box and the wheel sides are loose: geoms of no body, put where they stand on the chassis only when a wall or the floor may be near (world_loose_place) */
    world_loose_t loose;   /* the box, the left and the right wheel side; none with hinged wheels */
    int box_low;           /* the box was last put where its bounds may reach the floor's: put it again before the next collision pass */
    int loose_placed;      /* the loose parts stand where the chassis now puts them (world_step clears it as the chassis moves) */
    double floor_top_m;    /* the top of the floor's bounds as ODE has them (dGeomGetAABB), m */
    double parts_box[2][3]; /* the box in the chassis' frame (from its centre of mass) that holds every part: low and high corner, m (parts_box) */
    int parts_boxed;       /* parts_box holds: every part rides on the chassis (not with hinged wheels) */
    dJointID hand_lin, hand_yaw; /* world_hand: a hand's grip on the chassis (made on first use) */
    double carry_pose[3];   /* world_carry: where it was lifted from (x m, y m, heading rad) */
    int carried;
    double box_offset[3];  /* chassis box centre in the chassis body frame */
    double com[3];         /* chassis centre of mass in the robot frame (world_place) */
    double reach_m;        /* a body corner's distance from the centre of mass in the floor's plane, m (sub_steps) */
    int touching, touched_last;
    int clear_now;         /* every part is clear of the walls (sub_steps: by a step's travel and a millimetre; world_step: by WORLD_TOUCH_SLACK_M), in the state before the next ODE step: near_cb skips the maze */
    unsigned collisions;
    unsigned step_kinds, episode_kinds; /* WORLD_CONTACT_* bits: this step's, this episode's */
    unsigned kind_count[WORLD_CONTACT_KINDS]; /* finished episodes by kind */
    double h_s;            /* the ODE step in progress (a sub-step near walls), s */
    double wall_depth_m;   /* deepest wall contact of the last world_step, m */
    double brake_nm;       /* world_brake's load for the next world_step, N*m */
};

#endif

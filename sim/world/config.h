/* config.h - every number of the simulated world and the simulation, and
 * the robot's (which come from the robot file: robot.h).
 *
 * Defaults reproduce the paper's world; each key's unit, range and source
 * is in the table in config.c, which is also what --print-config prints. A
 * config file is INI (parsed by Debian's libinih):
 *
 *   [sim]
 *   step_s = 0.0005
 *
 * Unknown keys, missing values, values out of physical range, a key given
 * twice in a section and indented (continuation) lines are errors
 * "FILE:LINE: section.key: reason" (inifile.h). The firmware's control
 * tick is not here: it is hal.h's HAL_TICK_HZ, a compile-time constant.
 */
#ifndef CONFIG_H
#define CONFIG_H

#include <stddef.h>
#include <stdio.h>

#include "battery.h"

/* One wheel's drive: motor (datasheet figures at rated_v, output shaft),
 * gearbox, H-bridge and encoder. */
typedef struct {
    int motor_model;        /* MOTOR_MODEL_PAPER or MOTOR_MODEL_DATASHEET */
    double rated_v, no_load_rpm, no_load_a, stall_torque_nm, stall_a;
    double friction_load_a; /* friction's rise under load, A of motor current (motor.h); 0 = constant friction */
    double l_h;
    double gear_ratio;
    double rotor_inertia_kgm2; /* at the motor shaft; 0 = ignored */
    double driver_r_ohm;    /* H-bridge on-resistance in series with the motor, ohm */
    double encoder_ppr;     /* encoder counts per motor-shaft revolution */
    int encoder_channels;   /* 1 (pulses) or 2 (quadrature) */
} drive_spec_t;

/* Figures measured on the real robot that the file describes (a robot
 * file's optional [measured.NAME]); mmsim --validate reproduces each one
 * given (-1 = not given). */
typedef struct {
    double fwd_km_mm_s_v;   /* forward speed per volt: slope of steady speed against voltage, mm/s/V */
    double fwd_tm_s;        /* forward time constant of a voltage step (a first-order fit), s */
    double rot_km_deg_s_v;  /* spin rate per volt (the motors at +V and -V), deg/s/V */
    double rot_tm_s;        /* rotation time constant, s */
    double counts_500mm_left, counts_500mm_right; /* encoder counts over 500 mm of straight travel */
} robot_measured_t;

enum { ROBOT_START_CENTRE = 0, ROBOT_START_BACK_TO_WALL = 1 };
#define ROBOT_START_GAP_M 0.0005 /* back_to_wall: the body's rear this far from the wall's face, m */

#define ROBOT_MAX_PARTS 16   /* sensors a robot file may list */
#define ROBOT_NAME_MAX 16    /* bytes of a component's name, with the NUL */
#define ROBOT_SPEC_MAX 64    /* doubles of a sensor kind's specification */

struct sensor_kind_s;
/* A sensor from the robot file: its kind (sensors/sensor.h), name, pose on
 * the chassis and its kind's specification (plain doubles). */
typedef struct {
    const struct sensor_kind_s *kind;
    char name[ROBOT_NAME_MAX];
    double x_m, y_m, z_m;   /* chassis frame: origin at the body's centre on the floor, x right, y forward, z up */
    double yaw_deg;         /* counter-clockwise from straight ahead */
    double pitch_deg;       /* up from level */
    int line;               /* its section's line in the robot file */
    double spec[ROBOT_SPEC_MAX];
} robot_part_t;

/* The arena (config [world]). */
typedef struct {
    double cell_m;          /* cell pitch, post centre to post centre */
    double wall_thick_m;    /* wall thickness = post width */
    double wall_height_m;
    double post_m;          /* post side */
    int centre_post;        /* 1 = the post in the middle of the goal is there */
    double body_wall_mu;    /* robot body/wheel on a wall or post */
    double wall_reflectivity; /* of walls and posts to the IR sensors' light, 0..1 */
    double wall_gloss;      /* the walls' specular (gloss) reflectance straight on, 0..1 */
    double wall_gloss_exp;  /* the gloss lobe's Phong exponent: cos^n of the angle off the mirror direction, 1 */
    /* contact springs and dampers, per kind (world.c turns them into ODE's
     * ERP and CFM for the step in use) */
    double tyre_kp_n_m, tyre_kd_n_s_m;     /* tyre on the floor */
    double wall_kp_n_m, wall_kd_n_s_m;     /* robot body or wheel on a wall or post (and the body on the floor) */
    double caster_kp_n_m, caster_kd_n_s_m; /* caster or skid on the floor */
} simcfg_world_t;

/* The robot (the robot file, robot.h): its [chassis.NAME], [motor.*] and
 * [encoder.*] (drive[]), [battery.NAME], [measured.NAME] and sensors.
 * config_load never sets these. */
typedef struct {
    /* [chassis.NAME] */
    double body_w_m, body_l_m, body_h_m, body_mass_kg;
    double body_clearance_m; /* floor to the underside of the body */
    double wheel_w_m, wheel_mass_kg;
    double wheel_x_m;       /* wheel centre plane from the body's centre line */
    double axle_y_m;        /* axle position along the body, from its centre */
    double caster_r_m, caster_mass_kg, caster_y_m;
    int casters;            /* 1, or 2: a second skid at caster2_y_m, as the first */
    double caster2_y_m;
    double skid_mu;         /* Coulomb friction, caster (skid) on floor; 0 = frictionless */
    double tyre_mu;         /* Coulomb friction, tyre on floor */
    double tyre_mu_dynamic; /* sliding friction; <= tyre_mu */
    double tyre_slip_m_s;   /* contact slip speed above which tyre_mu_dynamic applies */
    int start;              /* ROBOT_START_*: where the robot stands in the start cell */
    double body_com_y_m;    /* the body's centre of mass ahead of its centre (the robot file's) */
    double body_yaw_inertia_kgm2; /* the body's about its vertical axis; 0 = a uniform box's */
    double body_drag_n_s_m; /* N per m/s against the axle midpoint's horizontal velocity; 0 = none */
    double wheel_left_d_m, wheel_right_d_m; /* the robot file's (the model derives each wheel's radius) */
    char chassis_name[ROBOT_NAME_MAX];
    /* [motor.left] [encoder.left], [motor.right] [encoder.right] */
    drive_spec_t drive[2];  /* WORLD_LEFT, WORLD_RIGHT */
    /* [battery.NAME] */
    battery_spec_t battery;
    char battery_name[ROBOT_NAME_MAX];
    /* [measured.NAME] */
    robot_measured_t measured;
    char measured_name[ROBOT_NAME_MAX]; /* "" = no [measured.NAME] */
    /* the sensors: [tof.NAME], [ir.NAME], [gyro.NAME], ... */
    int nparts;             /* sensors, in the robot file's order */
    robot_part_t part[ROBOT_MAX_PARTS];
    char path[256];         /* the robot file as given (the paper robot's is built in) */
} simcfg_robot_t;

/* The serial link to an MCU (config [link]). */
typedef struct {
    double compat_range_m;  /* compat protocol's distance scale: 65535 = this distance (--protocol compat) */
} simcfg_link_t;

/* The robot's asymmetries (config [asymmetry]): right minus left, 0 = symmetric. */
typedef struct {
    double wheel_d_diff_m, motor_k_diff_pct, tyre_mu_diff, com_x_m, com_y_m;
} simcfg_asym_t;

/* Per-seed spread of the asymmetries (config [variation]). */
typedef struct {
    double wheel_d_sigma_m, motor_k_sigma_pct, tyre_mu_sigma, com_sigma_m;
} simcfg_var_t;

/* The physics engine and the contest's limit (config [sim]). */
typedef struct {
    double step_s;          /* physics step */
    int solver;             /* SIM_SOLVER_QUICKSTEP or SIM_SOLVER_EXACT */
    int solver_iterations;  /* quickstep's iterations per step */
    int wheels;             /* SIM_WHEELS_HINGE or SIM_WHEELS_SPIN: how world.c builds a wheel */
    double time_limit_s;    /* contest limit */
} simcfg_sim_t;

/* Everything a run is built from: the config file's sections and the
 * robot file's robot. */
typedef struct {
    simcfg_world_t world;
    simcfg_robot_t robot;
    simcfg_link_t link;
    simcfg_asym_t asym;
    simcfg_var_t var;
    simcfg_sim_t sim;
} simcfg_t;

enum { MOTOR_MODEL_PAPER = 0, MOTOR_MODEL_DATASHEET = 1 };
enum { SIM_SOLVER_QUICKSTEP = 0, SIM_SOLVER_EXACT = 1 };
enum { SIM_WHEELS_HINGE = 0, SIM_WHEELS_SPIN = 1 };
/* The key table (what --print-config lists), for tests: how many keys,
 * and the i-th key's section, name and range: 0, or -1 past the end. */
size_t config_key_count(void);
int config_key_info(size_t i, const char **section, const char **key, double *min, double *max);
/* A word key's word for value v (config_key_info's min..max are its
 * indexes); NULL for a number key or past the end. */
const char *config_key_word(size_t i, double v);
/* The i-th key's value in c (0 past the end). */
double config_key_value(const simcfg_t *c, size_t i);

/* The defaults: the paper's world and robot (robots/paper.ini, built in). */
void config_defaults(simcfg_t *c);

#define CONFIG_MAX_BYTES (1u << 20) /* bytes of a config file; --print-config's is ~3 KB */

/* Apply an INI file over c. Returns 0, or -1 with one line in err:
 * "FILE:LINE: section.key: reason", "FILE:LINE: line too long (...)" (a
 * line over 197 bytes, what libinih reads whole), "FILE:LINE: NUL byte",
 * or "FILE: cannot open: ...", "FILE: not a regular file (...)", "FILE:
 * too large (...)" (regular files of at most CONFIG_MAX_BYTES only); c is
 * unchanged then. */
int config_load(simcfg_t *c, const char *path, char *err, size_t errlen);

/* Same from a NUL-terminated string (name is used in messages). */
int config_load_string(simcfg_t *c, const char *text, const char *name, char *err, size_t errlen);

/* Write every key with its value, unit and source, as a valid INI file. */
void config_print(const simcfg_t *c, FILE *out);

/* SHA-256 of config_print's and robot_print's text, as 64 hex digits + NUL. */
void config_hash(const simcfg_t *c, char out[65]);

#endif

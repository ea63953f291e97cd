/* sim.h - one run's state, stepped through its const model (model.h): the
 * ODE world, both motors and encoders, every sensor's state (the ToF
 * sensors at their update periods), the contest timers.
 * Time is simulation time only; every noise source has its own stream
 * seeded from the run's seed, so the same inputs give the same run. */
#ifndef SIM_H
#define SIM_H

#include <stddef.h>
#include <stdint.h>

#include "config.h"
#include "encoder.h"
#include "maze/truemaze.h"
#include "model.h"
#include "motor.h"
#include "race.h"
#include "world/sensors/tof.h"
#include "battery.h"
#include "robot.h"
#include "world.h"

#define SIM_EMITTER_GROUPS 4

/* A run's state: all that changes as it steps. The robot and world it
 * simulates are the const model it points to. */
typedef struct sim_state_s {
    const sim_model_t *model; /* the model it was made from (sim_init's m), never changed or freed here */
    const truemaze_t *maze;
    uint64_t seed;
    world_t *world;
    motor_t motor[2];
    encoder_t encoder[2];
    battery_t battery;
    void *part_state[ROBOT_MAX_PARTS]; /* each sensor's run-time state (its kind's) */
    int emitter[SIM_EMITTER_GROUPS];   /* emitter groups on (1) or off */
    /* The robot's ToF sensors (its [tof.*], in the file's order), as the HAL
     * and the link name them: left, front, right. A copy of their state
     * after each step; WORLD_TOF_COUNT slots, ntof used. */
    int ntof;
    int tof_part[WORLD_TOF_COUNT];     /* index in model->part */
    tof_reading_t tof_last[WORLD_TOF_COUNT];
    double tof_true_m[WORLD_TOF_COUNT]; /* ray distance behind the last reading, -1 none */
    uint32_t tof_count[WORLD_TOF_COUNT]; /* readings taken */
    double tof_range_m;                /* the first ToF's range (the link's distance scale); 1.2 without */
    int tof_enabled;
    race_t race;
    uint64_t step;           /* physics steps done */
    int cmd[2];              /* motor commands, -1023..1023 */
    int diverged;            /* the physics diverged (world_sane): sim_step no longer steps */
    /* A push by hand (sim_push): from step push_from for push_steps steps */
    uint64_t push_from, push_steps;
    double push_m, push_rad;  /* the axle's middle forward, m; the turn counter-clockwise, rad */
    double supply_drop_v;     /* V: a series diode between the battery and all it feeds (sim_set_supply_drop) */
} sim_state_t;

/* A run's state for model m (sim_model_build; m and the maze must outlive
 * the state), the robot placed in the start cell facing the start heading,
 * the sensors' noise streams seeded from seed. Returns 0, or -1 if ODE
 * could not be set up. */
int sim_init(sim_state_t *s, const sim_model_t *m, const truemaze_t *maze, uint64_t seed);
/* Release what the state holds (the world, the sensors' states); the model stays the caller's. */
void sim_free(sim_state_t *s);
/* One physics step of s through its model m (the one s was made from):
 * motor currents from the commands, ODE step, encoders, due ToF readings
 * (staggered by a third of a period each), timers. Once the state is no
 * longer sane (world_sane), it sets diverged and does nothing more: the
 * caller ends the run. */
void sim_step(const sim_model_t *m, sim_state_t *s);
double sim_time_s(const sim_state_t *s);

/* The robot's other sensors (robot file components). IR sensors
 * count in the robot file's order; emitter groups 0..SIM_EMITTER_GROUPS-1
 * start off. sim_ir_read samples sensor i's ADC now, with the emitters as
 * they are (0..1023; 0 past the count). The gyro's z rate (rad/s, CCW
 * positive, as its sample rate holds it; 0 without a gyro) and the
 * battery's terminal voltage (V; 0 without one) are the latest step's. */
int sim_ir_count(const sim_state_t *s);
void sim_emitter_set(sim_state_t *s, unsigned group, int on);
int sim_emitter(const sim_state_t *s, unsigned group);
unsigned sim_ir_read(sim_state_t *s, unsigned i);
/* The robot part an `occlude=NAME` holds an object before: the IR or ToF
 * sensor of that name in the robot file, else for "left"/"right" the
 * forward-facing IR sensor (within 30 degrees of straight ahead) left or
 * right of the centre line; -1 if none. */
int sim_occlude_find(const sim_state_t *s, const char *name);
/* The names an occlude may take ("lfs, lds, ..." or "none"), into out. */
void sim_occlude_names(const sim_state_t *s, char *out, size_t len);
/* An object held d_m in front of sensor part (sim_occlude_find) from now
 * for dur_s: its readings see the object instead of the maze (a hand
 * starting mazerunner-core). */
void sim_occlude(sim_state_t *s, int part, double d_m, double dur_s);
/* A person's hands on the robot (--input push, lift, place).
 * sim_push: from the next step the robot is rolled by hand along the floor,
 * its axle's middle dx_m forward and its heading turned dyaw_rad
 * counter-clockwise over dur_s (whole steps, at least one), at the speed
 * (dx_m / dur_s)(1 - cos(2 pi t / dur_s)): from rest to rest, peaking at
 * twice the mean; the step's speed taken at its middle so the steps add up
 * to dx_m at any step size. The wheels roll on the floor and the encoders
 * count as they turn; the motors stay as the firmware drives them (a
 * firmware that drives none is a robot pushed with its motors unpowered, the
 * H-bridge's short brake and the gearbox turning with the wheels; the hand's
 * force, world.h, beats a driven one). -1 (ignored) while carried.
 * sim_lift: carried 50 mm up and held still there (a push stops); the
 * wheels turn free; the sensors see what they see from there (the IR and ToF
 * rays pass over the 50 mm walls: nothing near). sim_place: put back down
 * where it was lifted, level and resting, the wheels as they are. */
int sim_push(sim_state_t *s, double dx_m, double dyaw_rad, double dur_s);
void sim_lift(sim_state_t *s);
void sim_place(sim_state_t *s);
int sim_has_gyro(const sim_state_t *s);
double sim_gyro_rad_s(const sim_state_t *s);
double sim_battery_v(const sim_state_t *s);
/* A series diode's forward drop (V, >= 0) between the battery and all it
 * feeds: the H-bridges' supply and a board's battery divider (UKMARSBOT's
 * D1). A constant drop while current flows: the motors see the battery's
 * terminal voltage less drop_v; 0 (the default) is a robot without one.
 * The diode blocks reverse current, which the battery model never has
 * (the bridges only draw). Set before the first step. */
void sim_set_supply_drop(sim_state_t *s, double drop_v);
/* The supply after that diode, V (>= 0): what the bridges and a divider see. */
double sim_supply_v(const sim_state_t *s);
/* Where ToF sensor i (0..ntof-1) sits and looks (world, m; heading rad). */
void sim_tof_origin(const sim_state_t *s, int i, double pos_m[3], double *dir_rad);
/* Every sensor's latest values for telemetry (no noise drawn, no state
 * changed: a const read): part i's into v, how many (its kind's `units`). */
int sim_part_values(const sim_state_t *s, int i, double v[4]);

#endif

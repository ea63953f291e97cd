/* replay.h - an LCM log of a run (mmsim --lcm-log) loaded for replay: the
 * true maze, config and robot (MM_MAZE), poses, sensors, contest timers, lap
 * events and the mouse's belief, put back into a sim_t at any time so the
 * viewer draws the logged run exactly as it drew the live one (mmview).
 *
 * The sim_t is a stand-in: its ODE world holds the logged maze, and
 * replay_apply places the robot (world_place), sets the ToF readings and
 * the IR emitter groups (MM_PARTS: the beams' colours) and rebuilds the
 * contest timers; it is never stepped. Times are simulation time; a
 * channel's state at time t is its last message with utime <= t. */
#ifndef REPLAY_H
#define REPLAY_H

#include <stddef.h>
#include <stdint.h>

#include "mmlcm_pose_t.h"
#include "mmlcm_race_event_t.h"
#include "mmlcm_race_t.h"
#include "mmlcm_sensors_t.h"
#include "scene.h"
#include "world/sim.h"

typedef struct {
    int64_t utime;
    int16_t cell;
    uint8_t heading;
} replay_belief_t;

/* An MM_PARTS message as the viewer needs it: the emitter groups' states
 * (bit g = group g lit), which colour the IR beams. */
typedef struct {
    int64_t utime;
    uint8_t emitters;
} replay_parts_t;

typedef struct {
    char path[1024];          /* the maze file named in the log */
    maze_t maze;              /* the true maze */
    simcfg_t cfg;             /* the run's config */
    uint64_t seed;
    int centre_post;
    mmlcm_pose_t *pose;       /* in time order */
    size_t npose;
    mmlcm_sensors_t *sensors;
    size_t nsensors;
    mmlcm_race_t *race;
    size_t nrace;
    mmlcm_race_event_t *event;
    size_t nevent;
    replay_parts_t *parts;    /* MM_PARTS (logs before it: none, emitters dark) */
    size_t nparts;
    replay_belief_t *belief; /* the mouse's belief messages */
    uint8_t *belief_walls;    /* their maps: ncells wall bytes each */
    size_t nbelief;
    int64_t end_us;           /* last message time */
    int have_maze;
    maze_t bmap;              /* the belief map replay_belief returns */
} replay_t;

/* Read the log at path. Returns 0, or -1 with one line in err ("PATH: ...":
 * unreadable, not an LCM log, truncated or corrupt event, an mmlcm message
 * that does not decode, no MM_MAZE or no MM_POSE, a bad maze or config).
 * Channels other than mmlcm's are ignored. replay_free in both cases. */
int replay_load(replay_t *r, const char *path, char *err, size_t errlen);
void replay_free(replay_t *r);

/* Length of the log, s (its last message's time). */
double replay_end_s(const replay_t *r);
/* The stand-in simulation for r (the logged maze, config and seed; the
 * centre post as logged). Returns 0, or -1 if ODE fails. sim_free it. */
int replay_sim_init(replay_t *r, sim_t *s);
/* Put the state at t_s (clamped to 0..end) into s: robot pose and wheels,
 * ToF readings, emitter groups, contest timers, sim time (s->step). */
void replay_apply(replay_t *r, sim_t *s, double t_s);
/* The mouse's belief at t_s for the scene overlay (b->map NULL if none yet). */
void replay_belief(replay_t *r, double t_s, scene_belief_t *b);

/* The time of the next (dir > 0) or previous (dir < 0) logged pose after
 * or before t_s; t_s itself at either end. */
double replay_next_s(const replay_t *r, double t_s, int dir);

/* Index of the last of n times (in order) that is <= t_us, or -1. */
long replay_index(const int64_t *times, size_t stride_bytes, size_t n, int64_t t_us);

#endif

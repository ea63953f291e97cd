/* replay.h - an LCM log of a run (mmsim --lcm-log) loaded for replay: the
 * true maze, config and robot (MM_MAZE), poses, sensors, contest timers, lap
 * events and the mouse's belief, turned at any time into the snapshot the
 * viewer draws (snap.h), so it draws the logged run as it drew the live
 * one (mmview).
 *
 * No simulation runs: the run's model is built from the logged config,
 * robot and seed (sim_model_build), and replay_snap puts the logged pose
 * and wheel angles into a snapshot of the robot standing level on the
 * floor (snap_place: the IR beams cast against the maze's geometry), with
 * the logged ToF distances, the IR emitter groups (MM_PARTS: the beams'
 * colours) and the contest timers rebuilt from the lap events. Times are
 * simulation time; a channel's state at time t is its last message with
 * utime <= t. */
#ifndef REPLAY_H
#define REPLAY_H

#include <stddef.h>
#include <stdint.h>

#include "mmlcm_pose_t.h"
#include "mmlcm_race_event_t.h"
#include "mmlcm_race_t.h"
#include "mmlcm_sensors_t.h"
#include "scene.h"
#include "snap.h"
#include "world/model.h"

typedef struct {
    int64_t utime;
    int16_t cell;
    uint8_t heading;
    int8_t state;             /* the firmware's state (mouse.h MOUSE_*) */
} replay_belief_t;

/* An MM_PARTS message as the viewer needs it: the emitter groups' states
 * (bit g = group g lit), which colour the IR beams. */
typedef struct {
    int64_t utime;
    uint8_t emitters;
} replay_parts_t;

typedef struct {
    char path[1024];          /* the maze file named in the log */
    truemaze_t maze;          /* the true maze */
    simcfg_t cfg;             /* the run's config */
    uint64_t seed;
    sim_model_t model;        /* the run's model: cfg with the seed's variation (points to cfg: r stays put) */
    int centre_post;          /* the middle post as logged (the viewer may toggle it) */
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

/* Read the log at path and build the run's model (r->model, which points
 * into r: r must not move while it is used). Returns 0, or -1 with one
 * line in err ("PATH: ...": unreadable, not an LCM log, truncated or
 * corrupt event, an mmlcm message that does not decode, no MM_MAZE or no
 * MM_POSE, a bad maze or config). Channels other than mmlcm's are
 * ignored. replay_free in both cases. */
int replay_load(replay_t *r, const char *path, char *err, size_t errlen);
void replay_free(replay_t *r);

/* Length of the log, s (its last message's time). */
double replay_end_s(const replay_t *r);
/* The snapshot at t_s (clamped to 0..end): the robot's pose and wheels
 * (before the first pose: at the start cell's centre facing the start
 * heading), its sensors' frames and rays, the ToF distances,
 * emitter groups, centre post, contest timers and the simulation time
 * (whole physics steps, as the live run counts it). */
void replay_snap(const replay_t *r, double t_s, snap_t *out);
/* The mouse's belief at t_s for the scene overlay (b->map NULL if none yet). */
void replay_belief(replay_t *r, double t_s, scene_belief_t *b);

/* The time of the next (dir > 0) or previous (dir < 0) logged pose after
 * or before t_s; t_s itself at either end. */
double replay_next_s(const replay_t *r, double t_s, int dir);

/* Index of the last of n times (in order) that is <= t_us, or -1. */
long replay_index(const int64_t *times, size_t stride_bytes, size_t n, int64_t t_us);

#endif

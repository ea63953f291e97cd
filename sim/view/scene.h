/* scene.h - the 3D scene of a simulation in legacy OpenGL: floor, start
 * and goal cells, posts, walls, the robot's body and wheels, the ToF rays
 * with their hit points, each IR sensor's beam (a cone to the first wall,
 * coloured by its emitter group's state), and (toggle) the mouse's discovered walls and its
 * planned path. Needs a current GL context; draws into the viewport given.
 *
 * Cameras (as in the paper): 1 a static bird's view of the whole maze,
 * 2 following the robot from behind, 3 a close-up top view over the robot.
 * Each is an orbit around its target; the user's drag and scroll adjust
 * it through scene_orbit_t.
 *
 * What is drawn comes from the run's const model (its config's maze
 * geometry and robot dimensions), a snapshot of the moment (snap.h: live
 * or replayed) and the true maze; the scene reads no simulation state. */
#ifndef SCENE_H
#define SCENE_H

#include <stddef.h>

#include "maze.h"
#include "maze/truemaze.h"
#include "snap.h"
#include "world/model.h"

enum { SCENE_BIRD = 1, SCENE_FOLLOW = 2, SCENE_TOP = 3, SCENE_CAMERAS = 3 };

/* Colours (0xRRGGBB), exported for tests that look for them. */
#define SCENE_FLOOR 0x1E1E24u
#define SCENE_WALL_TOP 0xD02828u /* wall and post tops (red, as on a real maze) */
#define SCENE_WALL_SIDE 0xE6E6E6u
#define SCENE_ROBOT 0x2A5CE0u    /* robot body */
#define SCENE_START 0x2E8B3Eu
#define SCENE_GOAL 0xD8B020u
#define SCENE_IR_LIT 0xFF50C0u   /* an IR sensor's beam, its emitter group lit (translucent) */
#define SCENE_IR_DARK 0x6070A0u  /* the same, the group dark */

typedef struct {
    double dyaw_rad, dpitch_rad; /* added to the camera's own angles */
    double zoom;                 /* distance factor, 1 = the camera's own */
} scene_orbit_t;

typedef struct {
    const maze_t *map;  /* the mouse's map, or NULL (no overlay) */
    uint16_t cell;      /* the mouse's cell and heading (MAZE_NORTH..) */
    uint8_t heading;
    int state;          /* the firmware's state (belief.h), -1 none */
} scene_belief_t;

/* Eye, target and up vector of camera cam (SCENE_*) for snapshot s's
 * pose in maze m. */
void scene_camera(const sim_model_t *model, const truemaze_t *m, const snap_t *s, int cam, const scene_orbit_t *orbit,
                  double eye[3], double target[3], double up[3]);
/* Draw the scene of snapshot s in maze m for camera cam into the viewport
 * w x h pixels whose lower left corner is (x, y) (GL's window pixels; the
 * whole window is cleared). The field of view is FOV_DEG across the
 * viewport's narrower side, so a tall viewport shows as much across as a
 * square one. overlay: draw b's walls and planned path (b may be NULL). */
void scene_draw(const sim_model_t *model, const truemaze_t *m, const snap_t *s, int cam, const scene_orbit_t *orbit,
                const scene_belief_t *b, int overlay, int x, int y, int w, int h);

/* After scene_draw, in the same frame (the same camera: s, cam, orbit):
 * tint the floor of every cell with its mms colour letter (colours[cell],
 * 0 = none; in scene_cell_rgb's palette) and paint its text (texts + cell
 * * stride, NUL-terminated; texts may be NULL) on the floor, under the
 * robot (depth-tested): centred in the cell, as large as the cell allows
 * (up to 4 characters at full size, longer texts smaller), upright on the
 * screen (its "up" is the camera's forward direction over the floor). */
void scene_draw_cells(const sim_model_t *model, const truemaze_t *m, const snap_t *s, int cam, const scene_orbit_t *orbit,
                      const char *colours, const char *texts, size_t stride);

/* The floor tint of mms colour letter c (mms.h's letters; 0: none). The
 * palette keeps mms's hues but darker and less saturated (every channel at
 * most 0xB4), and moves cyan towards green (0x2A8C78): the mouse's
 * discovered walls are bright cyan (0x30E0FF) and wrong ones magenta
 * (0xFF30FF) bars over the walls, and every tint differs from both by at
 * least 0x84 in some channel. The text is white on tints of luma (Rec. 601) under 128, else black. */
uint32_t scene_cell_rgb(char c);
#define SCENE_OVERLAY_WALL 0x30E0FFu /* a discovered wall as the truth has it */
#define SCENE_OVERLAY_WRONG 0xFF30FFu /* a discovered wall the truth lacks */

#endif

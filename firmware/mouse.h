/* mouse.h - the contest application on top of explore, motion and the HAL.
 * The backend calls fw_setup, fw_tick (control rate) and fw_loop (hal.h). */
#ifndef MOUSE_H
#define MOUSE_H

#include <stdint.h>

#include "maze.h"

#define MOUSE_SPEED_RUNS 3        /* speed runs after the search, unless fw_set_speed_runs */
#define MOUSE_RUN_DEADLINE_S 540u /* no new run after 9 of the 10 minutes */

enum {
    MOUSE_SEARCH = 0, /* exploring until the path is proven, then home */
    MOUSE_TO_RUN,     /* at the start, deciding on a speed run */
    MOUSE_RUN,        /* speed run to the goal */
    MOUSE_RETURN,     /* driving back to the start */
    MOUSE_DONE,
    MOUSE_NO_GOAL,    /* the goal cannot be reached: stopped */
    MOUSE_CRASHED     /* stuck: motors off */
};

typedef struct {
    uint8_t mode;     /* MOUSE_* */
    uint8_t runs;     /* speed runs completed */
    maze_cell_t cell; /* the cell the mouse is in or heading into */
    uint8_t heading;  /* the way it faces, MAZE_NORTH.. */
} mouse_status_t;

/* Before fw_setup: the maze's size, start and goal set (walls are
 * ignored), for the next fw_setup only. Without it the mouse takes the
 * maze the backend announces (hal_maze), else a classic 16x16 with the
 * centre goal. */
void fw_set_maze(const struct maze_s *m);
/* How many speed runs to make after the search (1..255; default
 * MOUSE_SPEED_RUNS); kept across fw_setup. */
void fw_set_speed_runs(uint8_t runs);
const mouse_status_t *mouse_status(void);
/* The mouse's map (for reports and tests). */
const maze_t *mouse_map(void);
uint16_t mouse_proven_at_step(void);


/* ---- External command mode (mmsim --mms) ----
 * After fw_setup, mouse_cmd_mode() hands the moves to the caller: the mouse
 * first senses the start cell (busy), then waits for mouse_cmd_forward /
 * mouse_cmd_turn at a cell centre or, after an odd number of half steps,
 * on the boundary between two cells; runs each on the motion layer
 * (fw_tick and fw_loop as usual) and maps the walls it senses on the way
 * (mouse_map()). mouse_cmd_status() says when a command is over. */
enum { MOUSE_COMMAND = MOUSE_CRASHED + 1 }; /* st.mode in command mode */
enum {
    MOUSE_CMD_DONE = 0, /* the last command is complete */
    MOUSE_CMD_BUSY,     /* a command is under way */
    MOUSE_CMD_BLOCKED,  /* a forward move stopped early: a wall sensed ahead */
    MOUSE_CMD_CRASHED   /* stuck (motion stall): motors off for good */
};
void mouse_cmd_mode(void);
uint8_t mouse_cmd_status(void);
/* Drive `halves` half cells ahead (1..510); -1 (nothing moves) if the map
 * shows a wall at a cell centre passed before the end, a post ahead (facing
 * along a boundary), halves is out of range or a command is under way. A
 * move ending on a boundary stops there; the cell beyond it is sensed on
 * the way in, as in a full step. */
int mouse_cmd_forward(uint16_t halves);
/* Half cells driven by the last forward move (less than asked if blocked:
 * it then stops at the centre of the last free cell). */
uint16_t mouse_cmd_moved(void);
/* Where the mouse stands: 0 at the centre of mouse_status()->cell, else
 * 1 + the side (MAZE_NORTH..) of that cell whose boundary it stands on. */
uint8_t mouse_cmd_edge(void);
/* In-place quarter turn: +1 right, -1 left; -1 if refused. */
int mouse_cmd_turn(int8_t q);
/* In-place eighth turn (mms 1.2's turnRight45/turnLeft45): +1 right, -1
 * left; -1 if refused. At a centre or on a boundary. Facing a diagonal,
 * mouse_cmd_forward drives half-diagonal steps (half a cell's diagonal
 * each) from the middle of one cell boundary to the middle of the next;
 * it refuses (-1, nothing moves) at a cell centre (the diagonal aims at a
 * post) and where the map shows a wall at the middle of a boundary it
 * would cross (unknown counts as open). Diagonals are driven on odometry
 * alone and sense nothing: the cells they cross keep the walls the map
 * had; a straight from the boundary a diagonal reached senses the cell it
 * enters as it starts. */
int mouse_cmd_turn45(int8_t e);
/* The heading in eighths of a turn clockwise from north (0 north, 1
 * north-east, ... 7 north-west); mouse_status()->heading is its quarter
 * part (a diagonal: the cardinal heading 45 degrees anticlockwise of it). */
uint8_t mouse_cmd_heading8(void);
/* The robot was put back at the start (mms ackReset): pose and odometry
 * restart, the map is kept, the start cell is sensed again (busy). */
void mouse_cmd_reset(void);

#endif

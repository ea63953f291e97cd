/* slalom.h - the speed run's moves: straights, diagonals and slaloms, as
 * geometry in the maze's half-cell grid (what the planner needs) and as
 * named trajectories (what the motion layer drives).
 *
 * Grid: half units of RC_CELL_MM / 2 (90 mm in a classic maze). Cell (x, y)
 * has its centre at (2x, 2y); the middles of its sides are (2x, 2y +- 1)
 * (north, south) and (2x +- 1, 2y) (east, west); posts sit at (odd, odd).
 * A run's nodes are side middles (exactly one coordinate odd) and, at the
 * start and the goal, cell centres (both even).
 *
 * Headings in 45-degree steps, clockwise: 0 N, 1 NE, 2 E, 3 SE, 4 S, 5 SW,
 * 6 W, 7 NW (mouse_cmd_heading8's numbering). An orthogonal heading on a
 * side middle crosses that side: N/S on a north or south side (y odd),
 * E/W on an east or west side (x odd). A diagonal heading may stand on
 * either kind of side middle.
 *
 * Each move is given for a right turn, entering at (0, 0) heading N (moves
 * that start orthogonal) or NE (moves that start diagonal); x grows to the
 * right of the entry heading. A left turn mirrors x; other headings rotate
 * the whole move by the entry heading. A move is legal where every side
 * middle it lists is an open wall in the mouse's map (it crosses those
 * sides, or sweeps over them with its body; the others it passes it keeps
 * clear of, posts included). */
#ifndef SLALOM_H
#define SLALOM_H

#include <stdint.h>

typedef enum {
    SLALOM_ORTHO = 0, /* orthogonal straight of n half units (n >= 1) */
    SLALOM_DIAG,      /* diagonal straight of n half steps (127 mm each in a classic maze) */
    SLALOM_S90,       /* 90 inside one cell: the search's smooth turn, corner at the cell centre */
    SLALOM_F90,       /* large 90 through three cells, 180 mm radius about the post's neighbour */
    SLALOM_F180,      /* 180 through two side-by-side cells, 90 mm radius */
    SLALOM_F45,       /* orthogonal -> diagonal, 45 */
    SLALOM_F135,      /* orthogonal -> diagonal, 135 */
    SLALOM_D45,       /* diagonal -> orthogonal, 45 */
    SLALOM_D135,      /* diagonal -> orthogonal, 135 */
    SLALOM_V90,       /* diagonal -> diagonal, 90 */
    SLALOM_KINDS
} slalom_kind_t;

#define SLALOM_MAX_CROSS 3 /* side middles a turn crosses, its exit included */

/* A turn's geometry, for the right-hand version (see above). */
typedef struct {
    int8_t exit_x, exit_y;     /* exit node, half units from the entry node */
    uint8_t turn;              /* heading change, 45-degree steps clockwise */
    uint8_t from_diag;         /* 1: entered on a diagonal heading */
    int8_t corner_x, corner_y; /* where the entry and exit lines meet, half units (F180: its arc's centre) */
    uint8_t crossed;           /* how many of cross[] are used */
    int8_t cross[SLALOM_MAX_CROSS][2]; /* side middles crossed, half units */
} slalom_geom_t;

/* The turns' table, indexed by slalom_kind_t (ORTHO and DIAG have a zero
 * entry: their geometry follows from n). */
extern const slalom_geom_t slalom_geom[SLALOM_KINDS];

/* One step along each heading, half units (x east, y north). */
extern const int8_t slalom_step_x[8], slalom_step_y[8];

/* Where a point of a turn's table (x, y: right turn, entered N or NE)
 * lies from the entry node for the turn to side dir (+1 right, -1 left)
 * entered on heading h8: mirrored for a left turn (the table's NE entry
 * becomes NW), then turned clockwise by quarters onto h8. */
void slalom_place(int8_t x, int8_t y, uint8_t from_diag, int8_t dir, uint8_t h8, int *dx, int *dy);

/* One move of a run: a kind, its side (+1 right / clockwise, -1 left) for
 * turns, and n half units (ORTHO) or half steps (DIAG); n is 1 for turns. */
typedef struct {
    uint8_t kind;
    int8_t dir;
    uint8_t n;
} slalom_move_t;

/* ---- The turns as driven: each a slalom at constant forward speed (the
 * rotation profile motion_slalom runs), sized so that the distance from
 * its start to its corner is robot_config.h's RC_SLALOM_*_MM for that
 * kind (F180: so that it ends RC_CELL_MM to the side). The straights
 * before and after it fill the rest of the room on each side of the
 * corner. ---- */
typedef struct {
    float w_deg_s;   /* peak rotation rate; 0: the turn does not fit at this speed */
    float before_mm; /* straight from the entry node to the turn's start */
    float arc_mm;    /* path length of the turn itself */
    float after_mm;  /* straight from its end to the exit node */
} slalom_drive_t;

/* Each turn kind's speed on a speed run, mm/s (robot_config.h
 * RC_SLALOM_*_MM_S): the safe figures, or the fast ones (fast 1). */
void slalom_run_speeds(uint8_t fast, float v_mm_s[SLALOM_KINDS]);

/* Size each turn kind k for its forward speed v_mm_s[k] (0: not driven),
 * the feed-forward capped at ff_max_cmd (motion_t's while it is driven):
 * drive[] for the executor, turn_s[] the time from entry node to exit node
 * for the planner (-1: the turn does not fit, plan.h: not used). Host
 * builds only (PLAN_ENABLED). */
void slalom_fit_kinds(const float v_mm_s[SLALOM_KINDS], float ff_max_cmd, slalom_drive_t drive[SLALOM_KINDS],
                      float turn_s[SLALOM_KINDS]);

#endif

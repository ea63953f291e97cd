/* slalomrun.c - speed runs on the planner's moves (slalomrun.h):
 * orthogonal straights (centred on the side walls), diagonal straights
 * (odometry's heading held, or the diagonal reference: diagref.h) and
 * slaloms, each turn kind at its own speed (slalom.h). */
#include "slalomrun.h"

#include "plan.h"

#if PLAN_ENABLED /* the planner's RAM: host builds (plan.h) */
#include <math.h>
#include <stdio.h>

#include "diagref.h"
#include "hal.h"
#include "robot_config.h"
#include "slalom.h"

/* ---- Speed runs on plan_run's moves: orthogonal straights (centred on
 * the side walls as above), diagonal straights (odometry's heading held:
 * no side walls there) and slaloms, each turn kind at its own speed
 * (slalom.h). Each turn's straight before it (slalom_drive_t before_mm) is
 * driven as part of the straight move ahead of it, its straight after as
 * part of the one behind it; between two turns those two alone make a
 * straight from one turn's speed to the next's (plan.h's cost). The run tracks the node each move ends on in half units
 * (slalom.h's grid) and its heading in eighths, to tell where the walls
 * ahead and the cell centres are. ---- */
typedef struct {
    slalom_move_t moves[PLAN_MAX_MOVES];
    slalom_drive_t drive[SLALOM_KINDS];
    int16_t count;      /* moves of this run; 0: the orthogonal run (runs.h) */
    int16_t idx;        /* the next move to start */
    int16_t x2, y2;     /* the node the moves so far end on, half units */
    uint8_t h8;         /* the heading there, eighths clockwise from north */
    float carry_mm;     /* the last turn's straight after it, not driven yet */
    uint8_t turn_next;  /* the straight under way leads into the turn moves[idx] */
    uint8_t ortho;      /* the straight under way is orthogonal: centring */
    float v_turn[SLALOM_KINDS]; /* each turn kind's speed this run, mm/s */
    float v_diag;       /* this run's diagonal straights' top speed, mm/s */
    float v_max, accel; /* this run's cruise speed (mm/s) and acceleration (mm/s^2) */
    float err_mm;       /* the largest tracking error of this run */
    uint8_t dirty;      /* the last run's tracking error reached RC_RUN_CLEAN_MM */
    float align_mm;     /* a wall ahead: the straight ends this far before its cell's centre */
    diagref_t ref;      /* the diagonal reference (RC_DIAG_TOF) */
} slalomrun_t;

static slalomrun_t sr;

int slalomrun_active(void) { return sr.count > 0; }

/* the cell whose centre is the node (x2, y2) */
static maze_cell_t node_cell(drive_t *dr, int16_t x2, int16_t y2)
{
    return maze_cell(&dr->ex.map, (uint8_t)(x2 / 2), (uint8_t)(y2 / 2)); /* a cell centre: both even */
}

/* The node and heading after the move mv from the node (*x2, *y2)
 * heading *h8 (half units; eighths clockwise from north). */
static void move_pose(const slalom_move_t *mv, int16_t *x2, int16_t *y2, uint8_t *h8)
{
    if (mv->kind == SLALOM_ORTHO || mv->kind == SLALOM_DIAG) {
        *x2 = (int16_t)(*x2 + mv->n * slalom_step_x[*h8]);
        *y2 = (int16_t)(*y2 + mv->n * slalom_step_y[*h8]);
        return;
    }
    const slalom_geom_t *g = &slalom_geom[mv->kind];
    int dx, dy;
    slalom_place(g->exit_x, g->exit_y, g->from_diag, mv->dir, *h8, &dx, &dy);
    *x2 = (int16_t)(*x2 + dx);
    *y2 = (int16_t)(*y2 + dy);
    *h8 = (uint8_t)((*h8 + mv->dir * g->turn) & 7u);
}

/* Whether the diagonals of a plan start where the robot knows where it
 * is. The half steps driven on diagonals from an F45 or F135 to the turn
 * back to an orthogonal heading are at most RC_DIAG_MAX_HALVES where that
 * entry follows an orthogonal straight of at least RC_DIAG_ENTRY_HALVES
 * (centred on its side walls), else at most RC_DIAG_AFTER_TURN_HALVES
 * (the heading the turns before it left is held blind; -1: no diagonal
 * entered from a turn); the D45 or D135 back leads into such a straight
 * (the robot centred again before its next turn or stop). Without
 * RC_DIAG_ALL_TURNS, no V90, F135 or D135 (turns between diagonals, or
 * into one from a turn) and no lane change (an F45 straight into a D45:
 * with 3.2 mm to the posts it touched on alljapan-012-1991-exp-fin, seed
 * 1, paper robot). The planner alternates straights and turns, so one
 * diagonal's half steps are one DIAG move. */
static int diag_ok(int n)
{
    int limit = 0, driven = 0;
    for (int i = 0; i < n; i++) {
        const slalom_move_t *mv = &sr.moves[i];
        uint8_t k = mv->kind;
        if (!RC_DIAG_ALL_TURNS && (k == SLALOM_V90 || k == SLALOM_F135 || k == SLALOM_D135)) return 0;
        if (k == SLALOM_F45 || k == SLALOM_F135) {
            int centred = i > 0 && sr.moves[i - 1].kind == SLALOM_ORTHO && sr.moves[i - 1].n >= RC_DIAG_ENTRY_HALVES;
            if (!centred && RC_DIAG_AFTER_TURN_HALVES < 0) return 0;
            limit = centred ? RC_DIAG_MAX_HALVES : RC_DIAG_AFTER_TURN_HALVES;
            driven = 0;
        } else if (k == SLALOM_DIAG) {
            driven += mv->n;
            if (driven > limit) return 0;
        } else if (k == SLALOM_D45 || k == SLALOM_D135) {
            if (!RC_DIAG_ALL_TURNS && (i == 0 || sr.moves[i - 1].kind != SLALOM_DIAG)) return 0;
            if (i + 1 >= n || sr.moves[i + 1].kind != SLALOM_ORTHO || sr.moves[i + 1].n < RC_DIAG_ENTRY_HALVES) return 0;
        }
    }
    return 1;
}

/* The orthogonal straight of n half units from the node (x2, y2) heading
 * h8 (even): the half units at its end with no known wall on either side,
 * since the last one with a wall (centring holds nothing there: the robot
 * drives on the heading odometry kept from the turns before it), and in
 * *walled the half units with one. Each half unit lies in the cell of the
 * one of its two nodes that is a cell centre. */
static int blind_halves(drive_t *dr, int16_t x2, int16_t y2, uint8_t h8, int n, int *walled)
{
    uint8_t d = (uint8_t)(h8 >> 1);
    int run = 0;
    *walled = 0;
    for (int k = 0; k < n; k++) {
        int16_t nx = (int16_t)(x2 + slalom_step_x[h8]), ny = (int16_t)(y2 + slalom_step_y[h8]);
        maze_cell_t c = ((x2 | y2) & 1) ? node_cell(dr, nx, ny) : node_cell(dr, x2, y2);
        int w = maze_wall(&dr->ex.map, c, (uint8_t)((d + 1u) & 3u)) == MAZE_WALL_CLOSED ||
                maze_wall(&dr->ex.map, c, (uint8_t)((d + 3u) & 3u)) == MAZE_WALL_CLOSED;
        *walled += w;
        run = w ? 0 : run + 1;
        x2 = nx;
        y2 = ny;
    }
    return run;
}

/* Whether the S90 entered at the node (x2, y2) heading h8 turns in a cell
 * with a wall ahead (straight(): the straight into it aligns on it). */
static int s90_walled(drive_t *dr, int16_t x2, int16_t y2, uint8_t h8)
{
    if (!((x2 | y2) & 1)) return 0;
    maze_cell_t c = node_cell(dr, (int16_t)(x2 + slalom_step_x[h8]), (int16_t)(y2 + slalom_step_y[h8]));
    return !maze_passable(&dr->ex.map, c, (uint8_t)(h8 >> 1), 0);
}

/* Whether a plan takes the robot out of each orthogonal straight that ends
 * with more than RC_BLIND_MAX_HALVES half units without side walls into at
 * most RC_BLIND_MAX_TURNS turns entered across that straight's line
 * before the offset it drifted across that line is measured again: by a
 * wall ahead of such a turn (an S90's straight aligns on it) or by
 * centring on a straight along that line (RC_DIAG_ENTRY_HALVES half units
 * with side walls). Off that straight's line the offset is an error along
 * the robot's way, which sets where each turn starts. */
static int blind_ok(drive_t *dr, int n)
{
    int16_t x2 = (int16_t)(2 * maze_x(&dr->ex.map, dr->ex.map.start)), y2 = (int16_t)(2 * maze_y(&dr->ex.map, dr->ex.map.start));
    uint8_t h8 = (uint8_t)(2u * dr->ex.map.start_heading);
    int axis = -1, turns = 0; /* the drifted straight's axis (h8 >> 1 & 1), -1: none */
    for (int i = 0; i < n; i++) {
        const slalom_move_t *mv = &sr.moves[i];
        uint8_t ax = (uint8_t)((h8 >> 1) & 1u), ortho = !(h8 & 1u);
        if (mv->kind == SLALOM_ORTHO || mv->kind == SLALOM_DIAG) {
            int walled = 0, blind = mv->kind == SLALOM_ORTHO ? blind_halves(dr, x2, y2, h8, mv->n, &walled) : 0;
            if (axis == ax && ortho && walled >= RC_DIAG_ENTRY_HALVES) axis = -1;
            if (blind > RC_BLIND_MAX_HALVES && i + 1 < n) axis = ax, turns = 0;
        } else if (axis >= 0 && ortho && ax != axis) {
            if (mv->kind == SLALOM_S90 && s90_walled(dr, x2, y2, h8)) axis = -1;
            else if (++turns > RC_BLIND_MAX_TURNS) return 0;
        }
        move_pose(mv, &x2, &y2, &h8);
    }
    return 1;
}

/* This run's turns (each kind at its own speed, RC_SLALOM_*_MM_S) and the
 * planner's costs for them: each turn's legs are driven with the straights
 * beside it (straight()), its arc at its speed (turn()). */
static void fit_turns(drive_t *dr, uint8_t fast, float ff_max, plan_costs_t *c)
{
    float whole_s[SLALOM_KINDS];
    slalom_run_speeds(fast, sr.v_turn);
    slalom_fit_kinds(sr.v_turn, ff_max, sr.drive, whole_s);
    for (uint8_t k = 0; k < SLALOM_KINDS; k++) {
        c->v_turn_mm_s[k] = sr.v_turn[k];
        c->before_mm[k] = sr.drive[k].before_mm;
        c->after_mm[k] = sr.drive[k].after_mm;
        c->turn_s[k] = whole_s[k] > 0 ? sr.drive[k].arc_mm / sr.v_turn[k] : -1.0f;
    }
}

/* At the start of a speed run: the moves (sr.count 0 if plan_run finds
 * none: the orthogonal run then), at the safe speeds (cruise, acceleration,
 * turns, diagonals) on the first run and after one whose tracking error
 * reached RC_RUN_CLEAN_MM, else the fast: the runs climb from the safe to
 * the fast figures and fall back after a run that was not clean. */
void slalomrun_begin(drive_t *dr)
{
    sr.count = 0;
    if (!RC_DIAG_RUNS) return;
    uint8_t fast = dr->st.runs > 0 && !sr.dirty;
    plan_costs_t c;
    c.cell_mm = RC_CELL_MM;
    c.v_diag_mm_s = sr.v_diag = fast ? RC_DIAG_FAST_MM_S : RC_DIAG_SAFE_MM_S;
    c.v_max_mm_s = sr.v_max = fast ? RC_RUN_FAST_MM_S : RC_RUN_MM_S;
    c.accel_mm_s2 = sr.accel = fast ? RC_RUN_FAST_ACCEL_MM_S2 : RC_RUN_ACCEL_MM_S2;
    float ff_max = fast ? RC_RUN_FAST_CMD_FF_MAX : RC_CMD_FF_MAX;
    fit_turns(dr, fast, ff_max, &c);
    float t_s;
    int n = plan_run(&dr->ex.map, &c, sr.moves, PLAN_MAX_MOVES, &t_s);
    if (n > 0 && !diag_ok(n)) { /* the same without diagonals */
        c.turn_s[SLALOM_F45] = c.turn_s[SLALOM_F135] = c.turn_s[SLALOM_D45] = c.turn_s[SLALOM_D135] = c.turn_s[SLALOM_V90] = -1;
        n = plan_run(&dr->ex.map, &c, sr.moves, PLAN_MAX_MOVES, &t_s);
    }
    if (RC_BLIND_MAX_HALVES >= 0 && n > 0 && !blind_ok(dr, n)) {
        drive_log(HAL_STR("run %u: orthogonal (a blind straight, a turn)"), dr->st.runs + 1u, 0);
        return;
    }
    if (n <= 0) return;
    dr->mo.ff_max_cmd = ff_max; /* until run_end */
    unsigned diag = 0;
    for (int i = 0; i < n; i++) diag += sr.moves[i].kind == SLALOM_DIAG || sr.moves[i].kind >= SLALOM_F45;
    char line[HAL_LOG_MAX + 1];
    hal_snprintf(line, sizeof line, HAL_STR("run %u: %u moves, %u diagonal, %u mm/s turns"), dr->st.runs + 1u, (unsigned)n, diag, (unsigned)sr.v_turn[SLALOM_S90]);
    hal_log(line);
    sr.count = (int16_t)n;
    sr.idx = 0;
    sr.x2 = (int16_t)(2 * maze_x(&dr->ex.map, dr->ex.map.start));
    sr.y2 = (int16_t)(2 * maze_y(&dr->ex.map, dr->ex.map.start));
    sr.h8 = (uint8_t)(2u * dr->ex.map.start_heading);
    sr.carry_mm = 0;
    sr.turn_next = 0;
    sr.err_mm = 0;
}


/* A straight of n half units or half steps plus run_carry_mm, leading
 * into the turn `next` (NULL: the run's end, at rest) at that turn's
 * speed. Its top speed is the straights' (plan.h), or the speed it starts
 * or ends with where that is higher. */
static void straight(drive_t *dr, uint8_t n, const slalom_move_t *next)
{
    uint8_t ortho = !(sr.h8 & 1u);
    float unit = (sr.h8 & 1u) ? RC_CELL_MM * 0.70710678f : RC_CELL_MM / 2;
    float before = next ? sr.drive[next->kind].before_mm : 0;
    float mm = n * unit + sr.carry_mm + before;
    float v = !ortho ? sr.v_diag : sr.v_max, v_end = next ? sr.v_turn[next->kind] : 0;
    if (!ortho && RC_DIAG_TOF) diagref_anchor(&sr.ref, &dr->mo, sr.x2, sr.y2, sr.h8, sr.carry_mm);
    move_pose(&(slalom_move_t){.kind = ortho ? SLALOM_ORTHO : SLALOM_DIAG, .n = n}, &sr.x2, &sr.y2, &sr.h8);
    drive_forward(dr, mm, fmaxf(fmaxf(v, v_end), fabsf(dr->mo.fwd.speed)), v_end, sr.accel);
    sr.carry_mm = 0;
    sr.ortho = ortho;
    sr.turn_next = next != NULL;
    /* the centre of the next cell ahead (centring's blind band) */
    uint8_t centre = !(sr.x2 & 1) && !(sr.y2 & 1);
    float shift = (centre ? RC_CELL_MM : RC_CELL_MM / 2) - before;
    dr->move_shift_mm = shift < 0 ? shift + RC_CELL_MM : shift;
    /* a wall ahead to align on: at the goal's centre, or at the centre an S90 turns in */
    sr.align_mm = next ? RC_CELL_MM / 2 - before : 0;
    if (ortho && !next && centre) dr->wall_ahead = !maze_passable(&dr->ex.map, node_cell(dr, sr.x2, sr.y2), (uint8_t)(sr.h8 >> 1), 0);
    if (ortho && next && next->kind == SLALOM_S90 && !centre)
        dr->wall_ahead = !maze_passable(&dr->ex.map, node_cell(dr, sr.x2 + slalom_step_x[sr.h8], sr.y2 + slalom_step_y[sr.h8]), (uint8_t)(sr.h8 >> 1), 0);
}

/* The turn sr.moves[sr.idx]: its slalom, at the turn speed throughout. */
static void turn(drive_t *dr)
{
    const slalom_move_t *mv = &sr.moves[sr.idx++];
    const slalom_geom_t *g = &slalom_geom[mv->kind];
    const slalom_drive_t *d = &sr.drive[mv->kind];
    move_pose(mv, &sr.x2, &sr.y2, &sr.h8);
    motion_forward_accel(&dr->mo, d->arc_mm, sr.v_turn[mv->kind], sr.v_turn[mv->kind], sr.accel);
    motion_slalom(&dr->mo, -45.0f * g->turn * mv->dir, d->w_deg_s, RC_SLALOM_ACCEL_DEG_S2); /* right (+1) is clockwise */
    drive_no_centring(dr);
    sr.carry_mm = d->after_mm;
    sr.turn_next = 0;
    dr->waiting = WAIT_SMOOTH;
}

/* The run reached the goal: as runs.c run_plan's end of a run. */
static void run_end(drive_t *dr)
{
    dr->waiting = WAIT_NONE;
    dr->st.cell = node_cell(dr, sr.x2, sr.y2);
    dr->st.heading = (uint8_t)(sr.h8 >> 1);
    dr->st.runs++;
    sr.dirty = sr.err_mm >= RC_RUN_CLEAN_MM;
    dr->mo.ff_max_cmd = RC_CMD_FF_MAX;
    drive_log(HAL_STR("run %u reached the goal at %u s"), dr->st.runs, (unsigned)((hal_micros() - dr->start_us) / 1000000u));
    drive_log(HAL_STR("run %u: largest tracking error %u mm"), dr->st.runs, (unsigned)sr.err_mm);
    sr.count = 0;
    dr->st.mode = MOUSE_RETURN;
}

/* Start the next move: a straight (with the turn after it, if any, in
 * view), the straight between two turns, or a turn. */
static void next_move(drive_t *dr)
{
    if (sr.idx >= sr.count) {
        run_end(dr);
        return;
    }
    const slalom_move_t *mv = &sr.moves[sr.idx];
    if (mv->kind == SLALOM_ORTHO || mv->kind == SLALOM_DIAG) {
        sr.idx++;
        straight(dr, mv->n, sr.idx < sr.count ? &sr.moves[sr.idx] : NULL);
        return;
    }
    if (!sr.turn_next && sr.carry_mm + sr.drive[mv->kind].before_mm > 0.5f) {
        straight(dr, 0, mv); /* the straights after the last turn and before this one */
        return;
    }
    turn(dr);
}

/* One loop of a planned speed run (runs_step while sr.count > 0). */
void slalomrun_step(drive_t *dr)
{
    float e = fmaxf(fabsf(dr->mo.fwd_err_mm), fabsf(dr->mo.rot_err_mm));
    if (e > sr.err_mm) sr.err_mm = e;
    if (dr->waiting == WAIT_NONE) { /* at the start, facing the way the plan starts */
        int8_t q = drive_quarter(dr->st.heading, dr->ex.map.start_heading);
        dr->st.heading = dr->ex.map.start_heading;
        if (q) drive_turn(dr, q);
        else next_move(dr);
        return;
    }
    if (dr->waiting == WAIT_TURN) {
        if (drive_turn_done(dr)) next_move(dr);
        return;
    }
    if (dr->waiting == WAIT_SMOOTH) {
        if (!dr->mo.rot.active) next_move(dr);
        return;
    }
    if (sr.ortho) drive_centring(dr);
    else if (RC_DIAG_TOF) diagref_centring(&sr.ref, &dr->mo, &dr->ex.map);
    else drive_no_centring(dr);
    if (dr->wall_ahead && sr.ortho) drive_align_front(dr, sr.align_mm);
    if (sr.turn_next) {
        if (!dr->mo.fwd.active) turn(dr);
        return;
    }
    if (motion_busy(&dr->mo)) return;
    drive_no_centring(dr);
    if (dr->wall_ahead && !drive_front_fix(dr)) return;
    next_move(dr);
}
#else /* no planner: every speed run is runs.h's */
void slalomrun_begin(drive_t *dr) { (void)dr; }
int slalomrun_active(void) { return 0; }
void slalomrun_step(drive_t *dr) { (void)dr; }
#endif

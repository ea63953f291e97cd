/* board_encoder.h - the wheel encoder part: two channels in quadrature
 * per wheel, every edge of either channel one count (the robot file's
 * encoder_ppr counts per motor turn, times the gear). The board feeds the
 * interrupt pin with A xor B (UKMARSBOT's 74HC86 "pulse doubler") and B
 * to its own pin, so each edge is an interrupt. */
#ifndef BOARD_ENCODER_H
#define BOARD_ENCODER_H

#include <stdint.h>

#include "board.h"

struct avr_t;
struct avr_irq_t;

#define BOARD_EDGES_MAX 512 /* encoder edges in one step, both wheels (~1.5 at full speed) */
#define BOARD_ENCODER_REST_POS 0.5 /* edges (counts): where the position starts, between edge 0 and edge 1 */

typedef struct {
    uint64_t cycle; /* when, AVR cycles */
    int wheel;
    long q;         /* the edge index after it */
} board_edge_t;

typedef struct {
    const sim_state_t *sim;                     /* its wheels' angles */
    struct avr_irq_t *int_pin[2], *b_pin[2]; /* per wheel: A xor B, B */
    int a_leads[2];                       /* 1: A leads B when the wheel turns forward */
    double per_rad[2], last_rad[2], pos[2]; /* edges per wheel radian; the angle and position last seen */
    long q[2];                            /* the edge index shown on the pins */
    board_edge_t edges[BOARD_EDGES_MAX];  /* this step's, sorted by cycle */
    int nedges, next;
    board_stats_t *st;                    /* encoder_edges */
} board_encoder_t;

/* Wire the part to avr's pins as spec says, the wheels at edge 0. */
void board_encoder_init(board_encoder_t *e, struct avr_t *avr, const board_spec_t *spec, const sim_state_t *sim, board_stats_t *st);
/* This step's edges, from the wheel angles after sim_step: the angle taken
 * as moving linearly over the step's cycles from start_cycle, so each edge
 * gets its own cycle inside the step. */
void board_encoder_plan(board_encoder_t *e, uint64_t start_cycle, uint64_t cycles_per_step);
/* 1 and the next planned edge's cycle in *cycle, or 0 if none is left. */
int board_encoder_next(const board_encoder_t *e, uint64_t *cycle);
/* Put the next planned edge's levels on the pins. */
void board_encoder_apply_next(board_encoder_t *e);
/* Raise both wheels' current levels again (after a reset cleared the PIN registers). */
void board_encoder_restore(board_encoder_t *e);

#endif

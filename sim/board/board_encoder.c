/* board_encoder.c - the wheel encoders: two channels in quadrature, every
 * edge of either channel one count (the robot file's encoder_ppr counts per
 * motor turn, times the gear). The board feeds the interrupt pin with A xor
 * B (UKMARSBOT's 74HC86 "pulse doubler") and B to its own pin, so each edge
 * is an interrupt. The wheel's angle after the physics step is taken as
 * moving linearly across the step; each edge it passes is put on the pins
 * at its own cycle inside the step (board.c runs the AVR up to it), so none
 * is lost or bunched at any speed. */
#include "board_int.h"

#include <math.h>

#include <simavr/sim_avr.h>
#include <simavr/sim_irq.h>

/* channel levels of edge index q: A leads B forward: 00 10 11 01 */
static void levels(const board_t *b, int w, long q, int *a, int *bch)
{
    static const int la[4] = { 0, 1, 1, 0 }, lb[4] = { 0, 0, 1, 1 };
    int s = (int)(((q % 4) + 4) % 4);
    *a = b->spec.enc_a_leads[w] ? la[s] : lb[s];
    *bch = b->spec.enc_a_leads[w] ? lb[s] : la[s];
}

static void put(board_t *b, int w, long q)
{
    int a, bch;
    levels(b, w, q, &a, &bch);
    avr_raise_irq(board_pin_irq(b, b->spec.enc_int[w]), (uint32_t)(a ^ bch));
    avr_raise_irq(board_pin_irq(b, b->spec.enc_b[w]), (uint32_t)bch);
}

void board_encoder_init(board_t *b)
{
    for (int w = 0; w < 2; w++) {
        const drive_spec_t *d = &b->sim->model->cfg->drive[w];
        b->enc_per_rad[w] = d->encoder_ppr * d->gear_ratio / (2.0 * M_PI);
        b->enc_last_rad[w] = world_wheel_angle(b->sim->world, w);
        b->enc_pos[w] = 0.0;
        b->enc_q[w] = 0;
        put(b, w, 0);
    }
}

void board_encoder_restore(board_t *b)
{
    for (int w = 0; w < 2; w++) put(b, w, b->enc_q[w]);
}

static void add_edge(board_t *b, uint64_t cycle, int w, long q)
{
    if (b->nedges >= BOARD_EDGES_MAX) return; /* ~100x full speed: the physics has gone wrong */
    int i = b->nedges++;
    while (i > 0 && b->edges[i - 1].cycle > cycle) {
        b->edges[i] = b->edges[i - 1];
        i--;
    }
    b->edges[i] = (board_edge_t){ cycle, w, q };
}

void board_encoder_plan(board_t *b, uint64_t start_cycle)
{
    b->nedges = 0;
    for (int w = 0; w < 2; w++) {
        double ang = world_wheel_angle(b->sim->world, w), d = ang - b->enc_last_rad[w];
        while (d > M_PI) d -= 2.0 * M_PI; /* the hinge angle wraps at +-pi */
        while (d < -M_PI) d += 2.0 * M_PI;
        b->enc_last_rad[w] = ang;
        double p0 = b->enc_pos[w], p1 = p0 + d * b->enc_per_rad[w];
        b->enc_pos[w] = p1;
        long q = b->enc_q[w], q1 = (long)floor(p1);
        for (; q < q1; q++) /* forward: edge q+1 where the position reaches it */
            add_edge(b, start_cycle + (uint64_t)((double)(q + 1 - p0) / (p1 - p0) * (double)b->cycles_per_step), w, q + 1);
        for (; q > q1; q--) /* backward: edge q-1 where the position falls below q */
            add_edge(b, start_cycle + (uint64_t)((p0 - (double)q) / (p0 - p1) * (double)b->cycles_per_step), w, q - 1);
    }
}

void board_encoder_apply(board_t *b, const board_edge_t *e)
{
    b->enc_q[e->wheel] = e->q;
    b->st.encoder_edges[e->wheel]++;
    put(b, e->wheel, e->q);
}

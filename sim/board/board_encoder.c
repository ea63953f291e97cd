/* board_encoder.c - the wheel encoder part (board_encoder.h): each edge
 * the wheel passes in a step is put on the pins through their ioport IRQs
 * at its own cycle (board.c runs the AVR up to it), so none is lost or
 * bunched at any speed. */
#include "board_encoder.h"

#include <math.h>

#include <simavr/sim_avr.h>
#include <simavr/sim_irq.h>

#include "avrhost.h"

/* channel levels of edge index q: A leads B forward: 00 10 11 01 */
static void levels(const board_encoder_t *e, int w, long q, int *a, int *bch)
{
    static const int la[4] = { 0, 1, 1, 0 }, lb[4] = { 0, 0, 1, 1 };
    int s = (int)(((q % 4) + 4) % 4);
    *a = e->a_leads[w] ? la[s] : lb[s];
    *bch = e->a_leads[w] ? lb[s] : la[s];
}

static void put(board_encoder_t *e, int w, long q)
{
    int a, bch;
    levels(e, w, q, &a, &bch);
    avr_raise_irq(e->int_pin[w], (uint32_t)(a ^ bch));
    avr_raise_irq(e->b_pin[w], (uint32_t)bch);
}

void board_encoder_init(board_encoder_t *e, avr_t *avr, const board_spec_t *spec, const sim_state_t *sim, board_stats_t *st)
{
    e->sim = sim;
    e->st = st;
    e->nedges = e->next = 0;
    for (int w = 0; w < 2; w++) {
        const drive_spec_t *d = &sim->model->drive[w];
        e->int_pin[w] = avrhost_pin_irq(avr, spec->enc_int[w].port, spec->enc_int[w].bit);
        e->b_pin[w] = avrhost_pin_irq(avr, spec->enc_b[w].port, spec->enc_b[w].bit);
        e->a_leads[w] = spec->enc_a_leads[w];
        e->per_rad[w] = d->encoder_ppr * d->gear_ratio / (2.0 * M_PI);
        e->last_rad[w] = world_wheel_angle(sim->world, w);
        /* at rest mid-way between two edges, as a real disc almost always is:
         * at exactly an edge (0.0) the hinge angle's rounding noise at rest
         * (~1e-14 counts) crossed it back and forth, 2-3 edges at t = 0 */
        e->pos[w] = BOARD_ENCODER_REST_POS;
        e->q[w] = 0;
        put(e, w, 0);
    }
}

void board_encoder_restore(board_encoder_t *e)
{
    for (int w = 0; w < 2; w++) put(e, w, e->q[w]);
}

static void add_edge(board_encoder_t *e, uint64_t cycle, int w, long q)
{
    if (e->nedges >= BOARD_EDGES_MAX) return; /* ~100x full speed: the physics has gone wrong */
    int i = e->nedges++;
    while (i > 0 && e->edges[i - 1].cycle > cycle) {
        e->edges[i] = e->edges[i - 1];
        i--;
    }
    e->edges[i] = (board_edge_t){ cycle, w, q };
}

void board_encoder_plan(board_encoder_t *e, uint64_t start_cycle, uint64_t cycles_per_step)
{
    e->nedges = e->next = 0;
    for (int w = 0; w < 2; w++) {
        double ang = world_wheel_angle(e->sim->world, w), d = ang - e->last_rad[w];
        while (d > M_PI) d -= 2.0 * M_PI; /* the hinge angle wraps at +-pi */
        while (d < -M_PI) d += 2.0 * M_PI;
        e->last_rad[w] = ang;
        double p0 = e->pos[w], p1 = p0 + d * e->per_rad[w];
        e->pos[w] = p1;
        long q = e->q[w], q1 = (long)floor(p1);
        for (; q < q1; q++) /* forward: edge q+1 where the position reaches it */
            add_edge(e, start_cycle + (uint64_t)((double)(q + 1 - p0) / (p1 - p0) * (double)cycles_per_step), w, q + 1);
        for (; q > q1; q--) /* backward: edge q-1 where the position falls below q */
            add_edge(e, start_cycle + (uint64_t)((p0 - (double)q) / (p0 - p1) * (double)cycles_per_step), w, q - 1);
    }
}

int board_encoder_next(const board_encoder_t *e, uint64_t *cycle)
{
    if (e->next >= e->nedges) return 0;
    *cycle = e->edges[e->next].cycle;
    return 1;
}

void board_encoder_apply_next(board_encoder_t *e)
{
    const board_edge_t *ed = &e->edges[e->next++];
    e->q[ed->wheel] = ed->q;
    e->st->encoder_edges[ed->wheel]++;
    put(e, ed->wheel, ed->q);
}

/* run_watch.c - --watch NAME[,NAME...] for the drivers that run an image
 * on an emulated processor (run_board.c, run_link.c's --avr: the AVR's
 * SRAM, sim/board/watch.h; run_armboard.c: the ARM core's, sim/arm/armwatch.h):
 * the firmware's variables looked up at the start and, after the
 * processor's cycles of each step, read by the driver's sampler and handed
 * to the telemetry (MM_WATCH) and the report. Reading SRAM changes nothing:
 * the run is the same with or without. */
#include "run_driver.h"

#include <stdio.h>

int run_watch_started(run_watch_t *w, int lookup_rc, const char *err, run_watch_sample_t sample, void *ctx)
{
    if (lookup_rc != 0) {
        fprintf(stderr, "mmsim: %s\n", err);
        w->list.n = 0;
        return RUN_BAD_INPUT;
    }
    w->sample = sample, w->ctx = ctx;
    return 0;
}

static void avr_sample(const watch_list_t *w, void *avr, double *values) { watch_sample(w, avr, values); }

int run_watch_open(run_t *r, run_watch_t *w, const struct avr_t *avr)
{
    char err[600];
    w->list.n = 0;
    if (!r->o->watch) return 0;
    int rc = watch_open(&w->list, r->o->avr_elf, r->o->watch, avr, stderr, err, sizeof err);
    return run_watch_started(w, rc, err, avr_sample, (void *)avr); /* only read: watch_sample takes it const */
}

void run_watch_step(run_t *r, run_watch_t *w)
{
    if (!w->list.n) return;
    w->sample(&w->list, w->ctx, w->values);
    if (r->tel_on) telem_watch(&r->tel, &r->sim, w->list.n, w->list.names, w->list.types, w->values);
    if (r->rep) report_watch(r->rep, w->list.n, w->list.names, w->values);
}

/* run_watch.c - --watch NAME[,NAME...] for the drivers that run an AVR
 * image (run_board.c, and run_link.c's --avr): the firmware's variables
 * looked up at the start (sim/board/watch.h) and, after the AVR's cycles of
 * each step, read and handed to the telemetry (MM_WATCH) and the report.
 * Reading SRAM changes nothing: the run is the same with or without. */
#include "run_driver.h"

#include <stdio.h>

int run_watch_open(run_t *r, run_watch_t *w, const struct avr_t *avr)
{
    char err[600];
    w->list.n = 0;
    if (!r->o->watch) return 0;
    if (watch_open(&w->list, r->o->avr_elf, r->o->watch, avr, stderr, err, sizeof err) != 0) {
        fprintf(stderr, "mmsim: %s\n", err);
        return RUN_BAD_INPUT;
    }
    return 0;
}

void run_watch_step(run_t *r, run_watch_t *w, const struct avr_t *avr)
{
    if (!w->list.n) return;
    watch_sample(&w->list, avr, w->values);
    if (r->tel_on) telem_watch(&r->tel, &r->sim, w->list.n, w->list.names, w->list.types, w->values);
    if (r->rep) report_watch(r->rep, w->list.n, w->list.names, w->values);
}

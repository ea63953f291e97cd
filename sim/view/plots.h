/* plots.h - the run report's page of plots against time (FILE-plots.png
 * beside --report FILE.png): speed, yaw rate, each motor's volts and
 * current, wheel speeds, the battery, each sensor kind's reading (one
 * curve per sensor) and each watched firmware variable, one panel each on
 * a shared time axis; laps shaded, wall contacts marked.
 *
 * Memory does not grow with the run: samples go into at most
 * PLOTS_BUCKETS buckets holding each series' minimum, maximum and last
 * value; when they are full, neighbours merge in pairs (each bucket then
 * covers twice the samples), so extremes are never lost and a panel draws
 * each bucket as its min..max span joined to the next bucket's last value.
 *
 * Page: PLOTS_W_PX wide, PLOTS_TOP_PX + panels * PLOTS_PANEL_PX +
 * PLOTS_BOTTOM_PX tall. */
#ifndef PLOTS_H
#define PLOTS_H

#include <jansson.h>

#include "image.h"
#include "world/sim.h"

#define PLOTS_BUCKETS 2048   /* buckets kept at most, whatever the run's length */
#define PLOTS_W_PX 1200      /* page width, px */
#define PLOTS_TOP_PX 60      /* title band: the run's title, the legend of laps and contacts, px */
#define PLOTS_PANEL_PX 156   /* one panel: its title line, plot box and gap, px */
#define PLOTS_BOTTOM_PX 44   /* the time axis' labels, px */
#define PLOTS_WATCH_MAX 16   /* watched variables plotted at most */

typedef struct plots plots_t;

/* Start recording the run of s (initialised, not yet stepped): its first
 * sample is taken now, at time 0. NULL out of memory. */
plots_t *plots_new(const sim_state_t *s);
void plots_free(plots_t *p);
/* After every physics step: notes the wall contacts begun (world_collisions). */
void plots_contacts(plots_t *p, const sim_state_t *s);
/* One sample of every series now; watch: n values of the watched variables
 * (n = 0: none yet). */
void plots_sample(plots_t *p, const sim_state_t *s, int n, const double *watch);

/* Draw the page into im (initialised here; image_free it) for the run as it
 * ended (laps from s->race); names: the n watched variables' names.
 * *desc gets each panel's title, series, pixel box and axis (the report's
 * JSON "plots"). Returns 0, or -1 out of memory. */
int plots_draw(const plots_t *p, const sim_state_t *s, int n, const char *const *names, const char *title, image_t *im,
               json_t **desc);

#endif

/* lcmlog.h - reading LCM event logs (mmsim --lcm-log, lcm-logger): LCM's
 * event-log reader with the checks every reader of ours needs (a regular
 * file, an LCM log at all, no truncated or corrupt event), shared by mmlog
 * and the replay (replay.h). */
#ifndef LCMLOG_H
#define LCMLOG_H

#include <lcm/eventlog.h>
#include <stddef.h>

/* Called with each whole event, in file order; return 0 to go on, non-zero
 * to stop reading (lcmlog_each then returns that value). */
typedef int (*lcmlog_fn)(void *ctx, const lcm_eventlog_event_t *ev);

/* Read the log at path. Returns 0 once every event has been passed to fn;
 * fn's non-zero value if it stopped; -1 with one line in err ("PATH: ...")
 * if the file is not a regular readable file, holds no LCM event although
 * not empty, or ends in a truncated or corrupt event (fn has then seen the
 * events before it). *events (if not NULL) = whole events read. */
int lcmlog_each(const char *path, lcmlog_fn fn, void *ctx, long *events, char *err, size_t errlen);

#endif

/* lcmlog.h - reading LCM event logs (mmsim --lcm-log, lcm-logger) with
 * the checks every reader of ours needs, shared by mmlog and the replay
 * (replay.h): a regular file (infile.h), an LCM log at all, and each
 * event's lengths checked against LCM's limits and the bytes left in the
 * file before anything is read or allocated. */
#ifndef LCMLOG_H
#define LCMLOG_H

#include <lcm/eventlog.h>
#include <stddef.h>

#include "mmlcm_belief_t.h"
#include "mmlcm_maze_t.h"
#include "mmlcm_parts_t.h"
#include "mmlcm_watch_t.h"

/* A 10-minute contest logged at --lcm-rate 1000 is ~200 MB. */
#define LCMLOG_MAX_BYTES (1ull << 32) /* bytes */

/* Called with each whole event, in file order; return 0 to go on, non-zero
 * to stop reading (lcmlog_each then returns that value). The event and
 * its buffers are valid during the call only. */
typedef int (*lcmlog_fn)(void *ctx, const lcm_eventlog_event_t *ev);

/* Read the log at path. Returns 0 once every event has been passed to fn;
 * fn's non-zero value if it stopped; -1 with one line in err if path is
 * not a regular file of at most LCMLOG_MAX_BYTES ("PATH: ..."), holds no
 * LCM log although not empty ("PATH: not an LCM log (...)"), or an event
 * is truncated or corrupt ("PATH: event N at byte B: truncated: ..." or
 * "...: corrupt: ..."; fn has then seen the N - 1 events before it).
 * *events (if not NULL) = whole events read. */
int lcmlog_each(const char *path, lcmlog_fn fn, void *ctx, long *events, char *err, size_t errlen);

/* An MM_BELIEF, MM_MAZE, MM_PARTS or MM_WATCH message from a log, decoded whole or not at all:
 * 0 (free it with mmlcm_*_decode_cleanup), or -1 with nothing allocated if
 * the data is not exactly one such message (a count below 0, a string
 * without its NUL, bytes missing or left over). The types with fixed
 * sizes are safe to decode directly (compare the length used with len). */
int lcmlog_decode_belief(const void *data, int len, mmlcm_belief_t *m);
int lcmlog_decode_maze(const void *data, int len, mmlcm_maze_t *m);
int lcmlog_decode_parts(const void *data, int len, mmlcm_parts_t *m);
int lcmlog_decode_watch(const void *data, int len, mmlcm_watch_t *m);

#endif

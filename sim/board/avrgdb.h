/* avrgdb.h - simavr's gdb stub (sim_gdb.h) for one core, reachable from
 * this machine only: avr-gdb attaches with `target remote :PORT`. simavr
 * binds its stub to every interface; its listening socket is replaced,
 * under the same descriptor, by one bound to 127.0.0.1 before anything is
 * accepted. What simavr prints about the connection (its printf) is
 * dropped, never in stdout's JSON.
 *
 * simavr checks breakpoints and its socket between avr_run calls only, so
 * while gdb is attached (or the core is halted for it) the caller runs one
 * instruction per call with simavr's gdb run callback; with no gdb
 * attached (before gdb comes back after a disconnect) simavr's plain
 * callback runs the core in batches as without the stub: a connection
 * waiting on the socket is noticed at the caller's next run. Both give
 * the same instructions at the same cycles.
 *
 * Wall time enters only while the core is halted (avrgdb_wait blocks on
 * the socket); the caller advances nothing then, so the simulation's time
 * never depends on it. */
#ifndef AVRGDB_H
#define AVRGDB_H

#include <stddef.h>

struct avr_t;

#define AVRGDB_WAIT_US 20000     /* halted: the longest wait for gdb's next packet per call, us of wall time */
#define AVRGDB_FD_SCAN_MAX 4096  /* descriptors searched for simavr's sockets */

typedef struct {
    unsigned port;     /* the TCP port on 127.0.0.1 */
    int listen_fd;     /* the listening socket (simavr's descriptor, our loopback socket) */
    int client_fd;     /* simavr's connection to gdb; -1 none known */
    int accepting;     /* a connection was waiting: simavr accepts it at its next packet check */
} avrgdb_t;

/* Start the stub on 127.0.0.1:port (1-65535) and halt the core: it runs
 * when gdb says continue or step. SIGPIPE is ignored from now on (a send
 * to a gdb that is gone is an error return, never the end of the
 * process). 0, or -1 with "cannot listen on 127.0.0.1:PORT: REASON" in
 * err (the port in use, a port below 1024 without the right, ...). */
int avrgdb_start(avrgdb_t *g, struct avr_t *avr, unsigned port, char *err, size_t errn);
/* Before a run: 1 if gdb is attached, about to be, or the core is halted
 * or stepping for it (simavr's gdb run callback set: one instruction per
 * avr_run call), else 0 (simavr's plain callback: batches allowed). */
int avrgdb_attached(avrgdb_t *g, struct avr_t *avr);
/* One avr_run with simavr's prints dropped (halted for gdb inside a
 * batch: simavr's gdb callback from now on). Returns the core's state. */
int avrgdb_run(avrgdb_t *g, struct avr_t *avr);
/* The stub stopped: its sockets closed, simavr's plain run callback back. */
void avrgdb_stop(struct avr_t *avr);
/* The core halted for gdb: serve its packets, waiting up to AVRGDB_WAIT_US
 * for one (no busy loop). */
void avrgdb_wait(avrgdb_t *g, struct avr_t *avr);

#endif

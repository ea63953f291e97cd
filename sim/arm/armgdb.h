/* armgdb.h - a GDB remote serial protocol stub for the Cortex-M core
 * (armcore.c), reachable from this machine only: gdb-multiarch attaches
 * with `target remote :PORT`. It serves what gdb needs for an M-profile
 * image: qSupported, the target description (qXfer:features:read, the
 * org.gnu.gdb.arm.m-profile feature: r0-r12, sp, lr, pc, xpsr), ?, g/G,
 * p/P, m/M, c/C, s/S, vCont (c, s: gdb single-steps with the core's own
 * step, not by breakpoints), Z0/z0 and Z1/z1 (both are the core's
 * breakpoints: flash is never patched), k, D and the interrupt byte (0x03).
 *
 * Memory: gdb reads flash and SRAM; it writes SRAM only. Peripheral, PPB
 * and bit-band addresses are refused (an error reply): a read through the
 * models could change them (a status flag cleared by reading it), so the
 * debugger never touches them and a run is the same with it as without.
 *
 * Frozen lockstep: armgdb_run_until_ps is armcore_run_until_ps for the
 * caller's physics loop; while the core is halted for gdb (at its first
 * instruction until gdb says continue or step, at a breakpoint, after a
 * step, after an interrupt, at a crash) it serves gdb's socket and advances
 * nothing, so the simulation's time never depends on wall time and the
 * run's output equals the run's without --gdb. A crash halts for gdb too
 * (signal 11: its registers and memory can be read); the run then ends
 * as without gdb. */
#ifndef ARMGDB_H
#define ARMGDB_H

#include <stddef.h>
#include <stdint.h>

#include "armcore.h"

#define ARMGDB_PACKET_MAX 4096 /* bytes of a packet's data either way (qSupported's PacketSize) */

typedef struct armgdb armgdb_t;

/* Listen on 127.0.0.1:port (1-65535), the core halted at its first
 * instruction. SIGPIPE is not raised by the stub's sends (a gdb gone is an
 * error return). NULL with "cannot listen on 127.0.0.1:PORT: REASON" in
 * err (the port in use, a port below 1024 without the right, ...). */
armgdb_t *armgdb_new(armcore_t *core, unsigned port, char *err, size_t errn);
/* Run the core to simulated time t_ps (armcore_run_until_ps), halting and
 * serving gdb as above. 0, or 1 if the firmware crashed. */
int armgdb_run_until_ps(armgdb_t *g, uint64_t t_ps);
/* The run's end: a gdb waiting for the core to stop is told the program
 * exited (W00; X0b, signal 11, after a crash), then the sockets closed.
 * NULL is fine. */
void armgdb_free(armgdb_t *g);

#endif

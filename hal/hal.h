/* hal.h - the hardware seam. The firmware talks to the world only through
 * these functions; a backend implements all of them:
 *   hal/sim      links the firmware into the simulator (host, in-process)
 *   hal/arduino  an Arduino library speaking the wire protocol (HIL)
 *
 * This is the part the maze algorithms need today: time and a log line.
 * Motors, encoders, distance sensors and the control tick come with the
 * firmware issue and are added here, not elsewhere.
 *
 * Backend guarantees:
 * - hal_micros: microseconds since start, monotonic, wrapping at 2^32
 *   (71.6 minutes). In hal/sim it is simulation time, never wall clock.
 * - hal_log: one text line without the trailing newline, at most
 *   HAL_LOG_MAX bytes; the backend may print, forward or drop it, and must
 *   not block for longer than it takes to queue it.
 */
#ifndef HAL_H
#define HAL_H

#include <stdint.h>

#define HAL_LOG_MAX 80 /* bytes per log line, without the NUL */

uint32_t hal_micros(void);
void hal_log(const char *line);

#endif

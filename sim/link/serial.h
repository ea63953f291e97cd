/* serial.h - the host end of a UART: a serial device set to raw 8N1 at any
 * baud rate (standard or custom, up to 12,000,000, via termios2/BOTHER), or
 * a pseudo-terminal for tests and other tools. File descriptors are
 * non-blocking. */
#ifndef SERIAL_H
#define SERIAL_H

#include <stddef.h>
#include <stdint.h>

#define SERIAL_BAUD_MAX 12000000u /* highest baud accepted, bits/s */

/* Open a serial device raw 8N1 at baud. Returns the fd, or -1 with a
 * one-line message in err. */
int serial_open(const char *path, uint32_t baud, char *err, size_t errn);
/* Create a pseudo-terminal (its slave side set raw); returns the master fd
 * and the slave's path in path, or -1 with err. */
int serial_open_pty(char *path, size_t pathn, char *err, size_t errn);
/* Is a program on the other side of the pty master (slave open)? 1/0. */
int serial_pty_peer(int master_fd);
/* Has the device gone (hang-up or error: unplugged)? 1/0. A raw terminal
 * with VMIN=0 reads 0 bytes when idle, so read()'s 0 cannot tell. */
int serial_hung_up(int fd);
/* Raw 8N1 at baud on an open terminal fd; 0 or -1 (errno set). */
int serial_set_raw(int fd, uint32_t baud);

#endif

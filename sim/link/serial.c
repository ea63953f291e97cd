/* serial.c - raw 8N1 terminals with any baud (see serial.h). Uses Linux
 * termios2 (asm/termbits.h) directly: it cannot be mixed with <termios.h>
 * in one file, and it is what sets a custom rate (BOTHER). */
#define _GNU_SOURCE
#include "serial.h"

#include <asm/termbits.h>
#include <errno.h>
#include <fcntl.h>
#include <poll.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/ioctl.h>
#include <unistd.h>

int serial_set_raw(int fd, uint32_t baud)
{
    struct termios2 t;
    if (ioctl(fd, TCGETS2, &t) != 0) return -1;
    /* what cfmakeraw does, plus 8N1, receiver on, no modem control lines */
    t.c_iflag &= ~(tcflag_t)(IGNBRK | BRKINT | PARMRK | ISTRIP | INLCR | IGNCR | ICRNL | IXON | IXOFF | IXANY);
    t.c_oflag &= ~(tcflag_t)OPOST;
    t.c_lflag &= ~(tcflag_t)(ECHO | ECHONL | ICANON | ISIG | IEXTEN);
    t.c_cflag &= ~(tcflag_t)(CSIZE | PARENB | CSTOPB | CRTSCTS | CBAUD | (CBAUD << IBSHIFT));
    t.c_cflag |= CS8 | CREAD | CLOCAL | BOTHER | (BOTHER << IBSHIFT);
    t.c_ispeed = t.c_ospeed = baud;
    t.c_cc[VMIN] = 0;
    t.c_cc[VTIME] = 0;
    return ioctl(fd, TCSETS2, &t);
}

int serial_open(const char *path, uint32_t baud, char *err, size_t errn)
{
    int fd = open(path, O_RDWR | O_NOCTTY | O_NONBLOCK | O_CLOEXEC);
    if (fd < 0) {
        snprintf(err, errn, "%s: cannot open: %s", path, strerror(errno));
        return -1;
    }
    if (!isatty(fd)) {
        snprintf(err, errn, "%s: not a serial device (terminal)", path);
        close(fd);
        return -1;
    }
    if (serial_set_raw(fd, baud) != 0) {
        snprintf(err, errn, "%s: cannot set raw 8N1 at %u baud: %s", path, (unsigned)baud, strerror(errno));
        close(fd);
        return -1;
    }
    struct termios2 t; /* the driver may round the rate: report what it took */
    if (ioctl(fd, TCGETS2, &t) == 0 && t.c_ospeed != 0 && t.c_ospeed != baud) {
        snprintf(err, errn, "%s: device cannot do %u baud (gave %u)", path, (unsigned)baud, (unsigned)t.c_ospeed);
        close(fd);
        return -1;
    }
    ioctl(fd, TCFLSH, TCIOFLUSH);
    return fd;
}

int serial_open_pty(char *path, size_t pathn, char *err, size_t errn)
{
    int m = posix_openpt(O_RDWR | O_NOCTTY);
    if (m < 0 || grantpt(m) != 0 || unlockpt(m) != 0 || ptsname_r(m, path, pathn) != 0) {
        snprintf(err, errn, "cannot create a pseudo-terminal: %s", strerror(errno));
        if (m >= 0) close(m);
        return -1;
    }
    int s = open(path, O_RDWR | O_NOCTTY | O_CLOEXEC);
    if (s < 0 || serial_set_raw(s, 115200) != 0) { /* the slave's settings stay while the pty exists */
        snprintf(err, errn, "%s: cannot set the pseudo-terminal raw: %s", path, strerror(errno));
        if (s >= 0) close(s);
        close(m);
        return -1;
    }
    close(s); /* until a peer opens it, the master sees a hang-up */
    int fl = fcntl(m, F_GETFL);
    fcntl(m, F_SETFL, fl | O_NONBLOCK);
    fcntl(m, F_SETFD, FD_CLOEXEC);
    return m;
}

int serial_hung_up(int fd)
{
    struct pollfd p = { fd, POLLIN, 0 };
    if (poll(&p, 1, 0) < 0) return 0;
    return (p.revents & (POLLHUP | POLLERR | POLLNVAL)) != 0;
}

int serial_pty_peer(int master_fd)
{
    struct pollfd p = { master_fd, POLLIN, 0 };
    if (poll(&p, 1, 0) < 0) return 0;
    return !(p.revents & POLLHUP);
}

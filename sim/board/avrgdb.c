/* avrgdb.c - simavr's gdb stub on the loopback interface (see avrgdb.h). */
#include "avrgdb.h"

#include <arpa/inet.h>
#include <errno.h>
#include <fcntl.h>
#include <netinet/in.h>
#include <poll.h>
#include <signal.h>
#include <stdio.h>
#include <string.h>
#include <sys/socket.h>
#include <unistd.h>

#include <simavr/sim_avr.h>
#include <simavr/sim_gdb.h>

/* fd is an IPv4 TCP socket bound to port: 1 listening (on every interface
 * if any is set), 2 connected, 0 neither */
static int socket_kind(int fd, unsigned port, int any)
{
    int on = 0;
    socklen_t n = sizeof on;
    struct sockaddr_in a;
    socklen_t an = sizeof a;
    if (getsockopt(fd, SOL_SOCKET, SO_ACCEPTCONN, &on, &n) != 0) return 0;
    if (getsockname(fd, (struct sockaddr *)&a, &an) != 0 || an < sizeof a || a.sin_family != AF_INET) return 0;
    if (ntohs(a.sin_port) != port) return 0;
    if (on) return !any || a.sin_addr.s_addr == htonl(INADDR_ANY) ? 1 : 0;
    an = sizeof a;
    return getpeername(fd, (struct sockaddr *)&a, &an) == 0 ? 2 : 0;
}

/* the first descriptor of that kind; -1 none */
static int find_socket(unsigned port, int kind, int any)
{
    for (int fd = 0; fd < AVRGDB_FD_SCAN_MAX; fd++)
        if (socket_kind(fd, port, any) == kind) return fd;
    return -1;
}

/* The listener at fd replaced under the same number (simavr keeps using
 * it) by a fresh socket listening on 127.0.0.1:port: dup2 closes simavr's
 * one, which has accepted nothing yet. 0, or -1 with errno set. */
static int to_loopback(int fd, unsigned port)
{
    int s = socket(AF_INET, SOCK_STREAM, 0), one = 1;
    if (s < 0) return -1;
    int rc = dup2(s, fd);
    close(s);
    if (rc < 0) return -1;
    struct sockaddr_in a = { .sin_family = AF_INET, .sin_port = htons((uint16_t)port) };
    a.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    (void)fcntl(fd, F_SETFD, FD_CLOEXEC); /* no child process inherits the stub */
    (void)setsockopt(fd, SOL_SOCKET, SO_REUSEADDR, &one, sizeof one);
    if (bind(fd, (struct sockaddr *)&a, sizeof a) != 0 || listen(fd, 1) != 0) return -1;
    return 0;
}

/* simavr's printf output (lines about the connection; gdb says the same
 * to its user): dropped, never in stdout's JSON */
static FILE *dropped(void)
{
    static FILE *null;
    if (!null) null = fopen("/dev/null", "w");
    return null ? null : stderr;
}

int avrgdb_start(avrgdb_t *g, struct avr_t *avr, unsigned port, char *err, size_t errn)
{
    FILE *out = stdout;
    stdout = dropped();
    avr->gdb_port = (int)port;
    errno = 0;
    int rc = avr_gdb_init(avr);
    int e = errno;
    stdout = out;
    if (rc != 0)
        return snprintf(err, errn, "cannot listen on 127.0.0.1:%u: %s", port, e ? strerror(e) : "simavr's gdb stub did not start"), -1;
    int fd = find_socket(port, 1, 1);
    if (fd < 0 || to_loopback(fd, port) != 0) {
        e = fd < 0 ? 0 : errno;
        avr_deinit_gdb(avr);
        return snprintf(err, errn, "cannot listen on 127.0.0.1:%u: %s", port,
                        e ? strerror(e) : "simavr's listening socket not found"), -1;
    }
    signal(SIGPIPE, SIG_IGN);
    *g = (avrgdb_t){ .port = port, .listen_fd = fd, .client_fd = -1 };
    avr->state = cpu_Stopped;
    return 0;
}

int avrgdb_attached(avrgdb_t *g, struct avr_t *avr)
{
    int halted = avr->state != cpu_Running && avr->state != cpu_Sleeping; /* stopped, stepping: gdb's */
    if (g->client_fd >= 0 && socket_kind(g->client_fd, g->port, 0) != 2) g->client_fd = -1; /* gdb left: simavr closed it */
    if (g->client_fd < 0 && (g->accepting || halted)) {
        g->client_fd = find_socket(g->port, 2, 0);
        g->accepting = 0;
    }
    if (g->client_fd < 0) { /* a connection waiting: simavr accepts it at its next packet check */
        struct pollfd p = { .fd = g->listen_fd, .events = POLLIN };
        g->accepting = poll(&p, 1, 0) == 1 && (p.revents & POLLIN);
    }
    int on = g->client_fd >= 0 || g->accepting || halted;
    avr->run = on ? avr_callback_run_gdb : avr_callback_run_raw;
    if (on) avr->run_cycle_limit = 1;
    return on;
}

int avrgdb_run(avrgdb_t *g, struct avr_t *avr)
{
    /* halted for gdb inside a batch (a BREAK instruction): simavr's plain callback would not serve it */
    if (avr->run == avr_callback_run_raw && avr->state != cpu_Running && avr->state != cpu_Sleeping) avrgdb_attached(g, avr);
    FILE *out = stdout;
    stdout = dropped();
    int state = avr_run(avr);
    stdout = out;
    return state;
}

void avrgdb_wait(avrgdb_t *g, struct avr_t *avr)
{
    FILE *out = stdout;
    stdout = dropped();
    avr_gdb_processor(avr, AVRGDB_WAIT_US);
    stdout = out;
    if (g->client_fd < 0) g->accepting = 1; /* it may have accepted one: look for it at the next run */
}

void avrgdb_stop(struct avr_t *avr) { avr_deinit_gdb(avr); }

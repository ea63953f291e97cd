/* armgdb.c - the GDB remote serial protocol stub for the Cortex-M core (see
 * armgdb.h). Packets follow the GDB manual's "Remote Protocol" appendix:
 * $DATA#CS framed, acknowledged with + (resent on -), hex replies. */
#include "armgdb.h"

#include <arpa/inet.h>
#include <errno.h>
#include <netinet/in.h>
#include <netinet/tcp.h>
#include <poll.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/socket.h>
#include <unistd.h>

#include <unicorn/unicorn.h>

#define NREGS 17        /* r0-r12, sp, lr, pc, xpsr: the m-profile feature's order */
#define XPSR_REG 16
#define XPSR_T (1u << 24)
#define MEM_CHUNK 2000u /* bytes of one m reply (its hex fits ARMGDB_PACKET_MAX) */
#define SIG_TRAP 5
#define SIG_INT 2
#define SIG_SEGV 11

struct armgdb {
    armcore_t *core;
    int listen_fd, fd;       /* fd: gdb's connection, -1 none */
    bool halted, crash_told;
    uint32_t brk[ARMCORE_BREAKS_MAX];
    int nbrk;
    char in[2 * ARMGDB_PACKET_MAX + 64];
    size_t nin;
    char out[2 * ARMGDB_PACKET_MAX + 8]; /* the last reply, framed (resent on -) */
    size_t nout;
};

/* The target description: gdb's M-profile feature (gdb/features/arm/arm-m-profile.xml's registers). */
static const char TDESC[] =
    "<?xml version=\"1.0\"?><!DOCTYPE target SYSTEM \"gdb-target.dtd\"><target><architecture>arm</architecture>"
    "<feature name=\"org.gnu.gdb.arm.m-profile\">"
    "<reg name=\"r0\" bitsize=\"32\"/><reg name=\"r1\" bitsize=\"32\"/><reg name=\"r2\" bitsize=\"32\"/>"
    "<reg name=\"r3\" bitsize=\"32\"/><reg name=\"r4\" bitsize=\"32\"/><reg name=\"r5\" bitsize=\"32\"/>"
    "<reg name=\"r6\" bitsize=\"32\"/><reg name=\"r7\" bitsize=\"32\"/><reg name=\"r8\" bitsize=\"32\"/>"
    "<reg name=\"r9\" bitsize=\"32\"/><reg name=\"r10\" bitsize=\"32\"/><reg name=\"r11\" bitsize=\"32\"/>"
    "<reg name=\"r12\" bitsize=\"32\"/><reg name=\"sp\" bitsize=\"32\" type=\"data_ptr\"/>"
    "<reg name=\"lr\" bitsize=\"32\"/><reg name=\"pc\" bitsize=\"32\" type=\"code_ptr\"/>"
    "<reg name=\"xpsr\" bitsize=\"32\"/></feature></target>";

static const int UC_REGS[NREGS - 1] = {
    UC_ARM_REG_R0, UC_ARM_REG_R1, UC_ARM_REG_R2, UC_ARM_REG_R3, UC_ARM_REG_R4, UC_ARM_REG_R5, UC_ARM_REG_R6, UC_ARM_REG_R7,
    UC_ARM_REG_R8, UC_ARM_REG_R9, UC_ARM_REG_R10, UC_ARM_REG_R11, UC_ARM_REG_R12, UC_ARM_REG_SP, UC_ARM_REG_LR, UC_ARM_REG_PC,
};

/* ---- the connection ---- */
static void drop_client(armgdb_t *g)
{
    if (g->fd >= 0) close(g->fd);
    g->fd = -1, g->nin = 0, g->nout = 0, g->nbrk = 0;
    armcore_set_breaks(g->core, NULL, 0);
    g->halted = false; /* gdb gone: the firmware runs on, breakpoints cleared */
}

static void send_all(armgdb_t *g, const char *p, size_t n)
{
    while (n > 0 && g->fd >= 0) {
        ssize_t k = send(g->fd, p, n, MSG_NOSIGNAL);
        if (k < 0 && errno == EINTR) continue;
        if (k <= 0) { drop_client(g); return; }
        p += k, n -= (size_t)k;
    }
}

/* A reply framed $DATA#CS, kept for a resend. */
static void reply(armgdb_t *g, const char *data)
{
    size_t n = strlen(data);
    if (n > sizeof g->out - 4) n = sizeof g->out - 4;
    unsigned cs = 0;
    g->out[0] = '$';
    for (size_t i = 0; i < n; i++) g->out[1 + i] = data[i], cs += (unsigned char)data[i];
    snprintf(g->out + 1 + n, 4, "#%02x", cs & 0xFFu);
    g->nout = n + 4;
    send_all(g, g->out, g->nout);
}

static void stop_reply(armgdb_t *g, int sig)
{
    char m[8];
    snprintf(m, sizeof m, "S%02x", sig);
    reply(g, m);
}

static bool accept_client(armgdb_t *g)
{
    int fd = accept(g->listen_fd, NULL, NULL);
    if (fd < 0) return false;
    int one = 1;
    setsockopt(fd, IPPROTO_TCP, TCP_NODELAY, &one, sizeof one);
    g->fd = fd, g->nin = 0, g->nout = 0;
    return true;
}

/* ---- registers and memory ---- */
static uint32_t get_reg(armgdb_t *g, int n)
{
    if (n < XPSR_REG) return armcore_reg(g->core, UC_REGS[n]);
    uint32_t apsr = armcore_reg(g->core, UC_ARM_REG_APSR), ipsr = armcore_reg(g->core, UC_ARM_REG_IPSR);
    return (apsr & 0xF80F0000u) | (ipsr & 0x1FFu) | XPSR_T;
}

static int set_reg(armgdb_t *g, int n, uint32_t v)
{
    if (n < 0 || n >= NREGS) return -1;
    if (n == XPSR_REG) return armcore_set_reg(g->core, UC_ARM_REG_APSR_NZCV, v); /* the flags; IPSR and EPSR stay the core's */
    return armcore_set_reg(g->core, UC_REGS[n], v);
}

static void hex32(char *p, uint32_t v) /* little-endian, as the target stores it */
{
    for (int i = 0; i < 4; i++) sprintf(p + 2 * i, "%02x", (v >> (8 * i)) & 0xFFu);
}

static int unhex(const char *p, size_t n, uint8_t *out)
{
    for (size_t i = 0; i < n; i++) {
        unsigned b;
        if (sscanf(p + 2 * i, "%2x", &b) != 1) return -1;
        out[i] = (uint8_t)b;
    }
    return 0;
}

static uint32_t le32(const uint8_t *b) { return (uint32_t)b[0] | (uint32_t)b[1] << 8 | (uint32_t)b[2] << 16 | (uint32_t)b[3] << 24; }

static void read_regs(armgdb_t *g)
{
    char m[NREGS * 8 + 1];
    for (int i = 0; i < NREGS; i++) hex32(m + 8 * i, get_reg(g, i));
    reply(g, m);
}

static void write_regs(armgdb_t *g, const char *p)
{
    uint8_t b[NREGS * 4];
    if (strlen(p) < sizeof b * 2 || unhex(p, sizeof b, b) != 0) { reply(g, "E01"); return; }
    for (int i = 0; i < NREGS; i++) set_reg(g, i, le32(b + 4 * i));
    reply(g, "OK");
}

static void read_mem(armgdb_t *g, const char *p)
{
    unsigned long a, n;
    static char m[2 * MEM_CHUNK + 1];
    uint8_t b[MEM_CHUNK];
    if (sscanf(p, "%lx,%lx", &a, &n) != 2 || a > UINT32_MAX) { reply(g, "E01"); return; }
    if (n > MEM_CHUNK) n = MEM_CHUNK;
    if (armcore_read(g->core, (uint32_t)a, b, n) != 0) { reply(g, "E01"); return; } /* flash and SRAM only: see armgdb.h */
    for (unsigned long i = 0; i < n; i++) sprintf(m + 2 * i, "%02x", b[i]);
    m[2 * n] = 0;
    reply(g, m);
}

static void write_mem(armgdb_t *g, const char *p)
{
    unsigned long a, n;
    int at = 0;
    uint8_t b[ARMGDB_PACKET_MAX / 2];
    if (sscanf(p, "%lx,%lx:%n", &a, &n, &at) != 2 || !at || a > UINT32_MAX || n > sizeof b || strlen(p + at) < 2 * n ||
        unhex(p + at, n, b) != 0 || armcore_write(g->core, (uint32_t)a, b, n) != 0) {
        reply(g, "E01");
        return;
    }
    reply(g, "OK");
}

/* ---- breakpoints: the core's, checked at its blocks' starts ---- */
static void breakpoint(armgdb_t *g, const char *p, bool insert)
{
    unsigned type;
    unsigned long a;
    if (sscanf(p, "%u,%lx", &type, &a) != 2 || a > UINT32_MAX) { reply(g, "E01"); return; }
    if (type > 1) { reply(g, ""); return; } /* watchpoints: not supported (an empty reply says so) */
    uint32_t addr = (uint32_t)a & ~1u;
    int i = 0;
    while (i < g->nbrk && g->brk[i] != addr) i++;
    if (insert && i == g->nbrk) {
        if (g->nbrk == ARMCORE_BREAKS_MAX) { reply(g, "E02"); return; }
        g->brk[g->nbrk++] = addr;
    } else if (!insert && i < g->nbrk) {
        g->brk[i] = g->brk[--g->nbrk];
    }
    armcore_set_breaks(g->core, g->brk, g->nbrk);
    reply(g, "OK");
}

static void xfer_features(armgdb_t *g, const char *p)
{
    unsigned long off, len;
    static char m[ARMGDB_PACKET_MAX + 2];
    if (sscanf(p, "target.xml:%lx,%lx", &off, &len) != 2) { reply(g, "E00"); return; }
    size_t total = sizeof TDESC - 1;
    if (off > total) { reply(g, "E01"); return; }
    if (len > ARMGDB_PACKET_MAX) len = ARMGDB_PACKET_MAX;
    size_t n = total - off < len ? total - off : len;
    m[0] = off + n < total ? 'm' : 'l';
    memcpy(m + 1, TDESC + off, n);
    m[1 + n] = 0;
    reply(g, m);
}

static void query(armgdb_t *g, const char *p)
{
    if (!strncmp(p, "qSupported", 10)) {
        char m[64];
        snprintf(m, sizeof m, "PacketSize=%x;qXfer:features:read+", ARMGDB_PACKET_MAX);
        reply(g, m);
    } else if (!strncmp(p, "qXfer:features:read:", 20)) {
        xfer_features(g, p + 20);
    } else if (!strcmp(p, "qAttached")) {
        reply(g, "1");
    } else {
        reply(g, ""); /* not supported: gdb falls back */
    }
}

/* Resume (c, s): an address given moves the PC first. step: halt after one instruction. */
static void resume(armgdb_t *g, const char *p, bool step)
{
    unsigned long a;
    if (sscanf(p, "%lx", &a) == 1) armcore_set_reg(g->core, UC_ARM_REG_PC, (uint32_t)a);
    armcore_halt_at(g->core, step ? armcore_cycles(g->core) + 1 : UINT64_MAX);
    g->halted = false;
}

/* vCont: the first action is the one thread's (c, C, s, S); vCont? lists them, so gdb steps with s (not by breakpoints). */
static void vcont(armgdb_t *g, const char *p)
{
    if (!strcmp(p, "vCont?")) { reply(g, "vCont;c;C;s;S"); return; }
    if (strncmp(p, "vCont;", 6) != 0) { reply(g, ""); return; }
    char a = p[6];
    if (a == 'c' || a == 'C') resume(g, "", false);
    else if (a == 's' || a == 'S') resume(g, "", true);
    else reply(g, "E01");
}

/* One packet's data (NUL-terminated). */
static void dispatch(armgdb_t *g, char *p)
{
    unsigned n;
    switch (p[0]) {
    case '?': stop_reply(g, SIG_TRAP); break;
    case 'g': read_regs(g); break;
    case 'G': write_regs(g, p + 1); break;
    case 'p':
        if (sscanf(p + 1, "%x", &n) != 1 || n >= NREGS) { reply(g, "E01"); break; }
        char m[9];
        hex32(m, get_reg(g, (int)n));
        reply(g, m);
        break;
    case 'P': {
        uint8_t b[4];
        char *eq = strchr(p, '=');
        if (sscanf(p + 1, "%x=", &n) != 1 || !eq || strlen(eq + 1) < 8 || unhex(eq + 1, 4, b) != 0 || set_reg(g, (int)n, le32(b)) != 0) {
            reply(g, "E01");
            break;
        }
        reply(g, "OK");
        break;
    }
    case 'm': read_mem(g, p + 1); break;
    case 'M': write_mem(g, p + 1); break;
    case 'c': resume(g, p + 1, false); break;
    case 's': resume(g, p + 1, true); break;
    case 'C': /* with a signal: there is no process to deliver it to; as c and s */
    case 'S': resume(g, strchr(p, ';') ? strchr(p, ';') + 1 : "", p[0] == 'S'); break;
    case 'Z': breakpoint(g, p + 1, true); break;
    case 'z': breakpoint(g, p + 1, false); break;
    case 'H': reply(g, "OK"); break;
    case 'v': vcont(g, p); break;
    case 'q': query(g, p); break;
    case 'D': reply(g, "OK"); drop_client(g); break;
    case 'k': drop_client(g); break;
    default: reply(g, ""); break;
    }
}

/* The packets in g->in: each acknowledged and dispatched; an interrupt byte halts a running core. */
static void parse(armgdb_t *g)
{
    size_t i = 0;
    while (i < g->nin && g->fd >= 0) {
        char ch = g->in[i];
        if (ch == 0x03) {
            i++;
            if (!g->halted) g->halted = true, stop_reply(g, SIG_INT);
            continue;
        }
        if (ch == '-' && g->nout) { send_all(g, g->out, g->nout); i++; continue; }
        if (ch != '$') { i++; continue; }
        char *start = g->in + i, *end = memchr(start, '#', g->nin - i);
        if (!end || (size_t)(end - g->in) + 3 > g->nin) break; /* incomplete: wait for the rest */
        unsigned cs = 0, want = 0;
        for (char *q = start + 1; q < end; q++) cs += (unsigned char)*q;
        char hx[3] = { end[1], end[2], 0 };
        i = (size_t)(end - g->in) + 3;
        if (sscanf(hx, "%2x", &want) != 1 || want != (cs & 0xFFu)) { send_all(g, "-", 1); continue; }
        send_all(g, "+", 1);
        *end = 0;
        dispatch(g, start + 1);
    }
    if (g->fd < 0) return;
    memmove(g->in, g->in + i, g->nin - i);
    g->nin -= i;
    if (g->nin == sizeof g->in) g->nin = 0; /* a packet longer than any gdb sends: dropped */
}

/* Bytes from gdb into g->in, waiting up to timeout_ms (-1: until some come). false: none came. */
static bool receive(armgdb_t *g, int timeout_ms)
{
    struct pollfd p = { g->fd, POLLIN, 0 };
    int r = poll(&p, 1, timeout_ms);
    if (r <= 0) return false;
    ssize_t k = recv(g->fd, g->in + g->nin, sizeof g->in - g->nin, 0);
    if (k < 0 && errno == EINTR) return false;
    if (k <= 0) { drop_client(g); return false; }
    g->nin += (size_t)k;
    return true;
}

/* Halted: gdb's packets served until it resumes the core or leaves (a gdb to come is waited for). */
static void serve(armgdb_t *g)
{
    while (g->halted) {
        if (g->fd < 0) {
            struct pollfd p = { g->listen_fd, POLLIN, 0 };
            if (poll(&p, 1, -1) > 0) accept_client(g);
            continue;
        }
        if (receive(g, -1)) parse(g);
    }
}

/* Running: a connection waiting is accepted (the core halts for it), an interrupt byte read. No wait. */
static void look(armgdb_t *g)
{
    if (g->fd < 0) {
        struct pollfd p = { g->listen_fd, POLLIN, 0 };
        if (poll(&p, 1, 0) > 0 && accept_client(g)) g->halted = true; /* gdb's ? is answered as a stop */
        return;
    }
    if (receive(g, 0)) parse(g);
}

int armgdb_run_until_ps(armgdb_t *g, uint64_t t_ps)
{
    for (;;) {
        if (g->halted) serve(g);
        look(g);
        if (g->halted) continue;
        int rc = armcore_run_until_ps(g->core, t_ps);
        if (rc == ARMCORE_HALTED) {
            g->halted = true;
            stop_reply(g, SIG_TRAP);
            continue;
        }
        if (rc == 1 && g->fd >= 0 && !g->crash_told) {
            g->crash_told = true, g->halted = true;
            stop_reply(g, SIG_SEGV);
            continue;
        }
        return rc;
    }
}

armgdb_t *armgdb_new(armcore_t *core, unsigned port, char *err, size_t errn)
{
    armgdb_t *g = calloc(1, sizeof *g);
    if (!g) return snprintf(err, errn, "cannot listen on 127.0.0.1:%u: out of memory", port), NULL;
    g->core = core, g->fd = -1, g->halted = true;
    g->listen_fd = socket(AF_INET, SOCK_STREAM | SOCK_CLOEXEC, 0);
    int one = 1;
    struct sockaddr_in a = { 0 };
    a.sin_family = AF_INET, a.sin_port = htons((uint16_t)port), a.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    if (port < 1 || port > 65535) errno = EINVAL;
    if (port < 1 || port > 65535 || g->listen_fd < 0 || setsockopt(g->listen_fd, SOL_SOCKET, SO_REUSEADDR, &one, sizeof one) != 0 ||
        bind(g->listen_fd, (struct sockaddr *)&a, sizeof a) != 0 || listen(g->listen_fd, 1) != 0) {
        snprintf(err, errn, "cannot listen on 127.0.0.1:%u: %s", port, strerror(errno));
        armgdb_free(g);
        return NULL;
    }
    return g;
}

void armgdb_free(armgdb_t *g)
{
    if (!g) return;
    if (g->fd >= 0 && !g->halted) reply(g, armcore_crashed(g->core, NULL, NULL) ? "X0b" : "W00"); /* gdb waits: the run ended */
    if (g->fd >= 0) close(g->fd);
    if (g->listen_fd >= 0) close(g->listen_fd);
    free(g);
}

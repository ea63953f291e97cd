/* datadir.c - the places data files are searched (datadir.h). */
#include "datadir.h"

#include <limits.h>
#include <stdio.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#ifndef MMSIM_DATADIR
#define MMSIM_DATADIR "" /* built outside the Makefile: no source tree known */
#endif

static int is_dir(const char *p)
{
    struct stat st;
    return p[0] && stat(p, &st) == 0 && S_ISDIR(st.st_mode);
}

/* PREFIX/share/mmsim for the running program PREFIX/bin/mmsim (Linux's
 * /proc/self/exe), or "" */
static void installed(char *out, size_t n)
{
    char exe[DATADIR_PATH_MAX];
    out[0] = '\0';
    ssize_t k = readlink("/proc/self/exe", exe, sizeof exe - 1);
    if (k <= 0) return;
    exe[k] = '\0';
    char *slash = strrchr(exe, '/'); /* .../bin/mmsim -> .../bin */
    if (!slash) return;
    *slash = '\0';
    slash = strrchr(exe, '/'); /* .../bin -> ... */
    if (!slash) return;
    *slash = '\0';
    if (snprintf(out, n, "%s/share/mmsim", exe) >= (int)n) out[0] = '\0'; /* too long: not searched */
}

int datadir_find(const char *rel, char *out, size_t outn)
{
    char dirs[DATADIR_MAX][DATADIR_PATH_MAX];
    int n = datadir_list(dirs);
    for (int i = 0; i < n; i++) {
        struct stat st;
        if (snprintf(out, outn, "%s%s%s", dirs[i], dirs[i][0] ? "/" : "", rel) >= (int)outn) return -1;
        if (stat(out, &st) == 0 && S_ISREG(st.st_mode)) return 0;
    }
    return -1;
}

int datadir_list(char dirs[DATADIR_MAX][DATADIR_PATH_MAX])
{
    int n = 0;
    dirs[n++][0] = '\0';
    installed(dirs[n], DATADIR_PATH_MAX);
    if (is_dir(dirs[n])) n++;
    snprintf(dirs[n], DATADIR_PATH_MAX, "%s", MMSIM_DATADIR);
    if (is_dir(dirs[n]) && (n < 2 || strcmp(dirs[n], dirs[n - 1]))) n++;
    return n;
}

/* fuzz_contest.c - libFuzzer target for contest files (make fuzz).
 *
 * The input is a contest file (contest_load: the regular-file reader, the
 * line scan, libinih, the key table, the checks between keys, and the
 * line and column of each error). Either the load fails with one line
 * "PATH:..." and leaves the profile as it was, or the profile is inside its
 * ranges (the goal and start inside the maze, the goal's corners ordered)
 * and --print-contest's text of it loads back to the same text. */
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "contest/contest.h"

static char path[64], path2[64];

static void check(int ok, const char *what)
{
    if (!ok) {
        fprintf(stderr, "fuzz_contest: %s\n", what);
        abort();
    }
}

/* --print-contest's text without its first line (which names the file) */
static char *print(const contest_t *c)
{
    char *text = NULL;
    size_t len = 0;
    FILE *mem = open_memstream(&text, &len);
    check(mem != NULL, "open_memstream");
    contest_print(c, mem);
    fclose(mem);
    char *nl = strchr(text, '\n');
    memmove(text, nl + 1, strlen(nl + 1) + 1);
    return text;
}

static void check_loaded(const contest_t *c)
{
    check(c->max_width >= 1 && c->max_width <= TRUEMAZE_MAX_SIZE && c->max_height >= 1 && c->max_height <= TRUEMAZE_MAX_SIZE, "maze size");
    check(c->goal[0] <= c->goal[2] && c->goal[1] <= c->goal[3] && c->goal[2] < c->max_width && c->goal[3] < c->max_height, "goal");
    check(c->start[0] < c->max_width && c->start[1] < c->max_height, "start");
    check(c->post_m >= c->wall_thick_m, "posts thinner than walls");
    char *text = print(c), err[600];
    static contest_t again;
    FILE *f = fopen(path2, "wb");
    check(f && fputs(text, f) >= 0 && fclose(f) == 0, "cannot write the printed file");
    if (contest_load(&again, path2, err, sizeof err) != 0) {
        fprintf(stderr, "fuzz_contest: the printed contest does not load: %s\n%s", err, text);
        abort();
    }
    char *text2 = print(&again);
    check(!strcmp(text, text2), "the printed contest loads to another one");
    free(text);
    free(text2);
    unlink(path2);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    static contest_t c, before;
    char err[600] = "";
    if (!path[0]) { /* in memory if there is a tmpfs; removed after each run */
        const char *dir = access("/dev/shm", W_OK) ? "/tmp" : "/dev/shm";
        snprintf(path, sizeof path, "%s/fuzz_contest_%d.ini", dir, (int)getpid());
        snprintf(path2, sizeof path2, "%s/fuzz_contest_%d_printed.ini", dir, (int)getpid());
    }
    FILE *f = fopen(path, "wb");
    check(f && fwrite(data, 1, size, f) == size && fclose(f) == 0, "cannot write the input file");
    memset(&c, 0x5a, sizeof c);
    before = c;
    int rc = contest_load(&c, path, err, sizeof err);
    if (rc == 0) {
        check_loaded(&c);
    } else {
        check(rc == -1, "return value");
        check(!memcmp(&c, &before, sizeof c), "a failed load changed the profile");
        check(!strncmp(err, path, strlen(path)) && err[strlen(path)] == ':' && !strchr(err, '\n'), err);
    }
    unlink(path);
    return 0;
}

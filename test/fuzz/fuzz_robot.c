/* fuzz_robot.c - libFuzzer target for the robot file (make fuzz).
 *
 * The input is a robot file (robot_load: the regular-file reader, the line
 * scan, the section scan, libinih, each component's schema and the checks)
 * and, up to its first NUL, a robot string (robot_load_string, as a log's
 * MM_MAZE robot in the replay). Either the load fails with one line
 * "NAME:..." and leaves the config as it was, or the robot has at most
 * its parts (16 sensors, 3 ToF, 8 IR) and --print-robot's text of it loads
 * back to the same text (a log's MM_MAZE robot replays). */
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "world/config.h"
#include "world/robot.h"
#include "world/world.h"

static char path[64];

static void check(int ok, const char *what)
{
    if (!ok) {
        fprintf(stderr, "fuzz_robot: %s\n", what);
        abort();
    }
}

static char *print(const simcfg_t *c)
{
    char *text = NULL;
    size_t len = 0;
    FILE *mem = open_memstream(&text, &len);
    check(mem != NULL, "open_memstream");
    robot_print(c, mem);
    fclose(mem);
    return text;
}

static void check_loaded(const simcfg_t *c, const char *name)
{
    check(c->robot.nparts >= 0 && c->robot.nparts <= ROBOT_MAX_PARTS, "more sensors than ROBOT_MAX_PARTS");
    check(robot_count(c, "tof") <= WORLD_TOF_COUNT, "more ToF sensors than WORLD_TOF_COUNT");
    check(robot_count(c, "ir") <= ROBOT_MAX_IR, "more IR sensors than ROBOT_MAX_IR");
    check(c->robot.tyre_mu_dynamic <= c->robot.tyre_mu, "tyre_mu_dynamic above tyre_mu");
    char *text = print(c), err[600];
    simcfg_t again;
    config_defaults(&again);
    if (robot_load_string(&again, text, name, err, sizeof err) != 0) {
        fprintf(stderr, "fuzz_robot: the printed robot does not load: %s\n%s", err, text);
        abort();
    }
    char *text2 = print(&again);
    check(!strcmp(text, text2), "the printed robot loads to another one");
    free(text);
    free(text2);
}

static void one(int rc, const simcfg_t *c, const simcfg_t *before, const char *err, const char *name)
{
    if (rc == 0) {
        check_loaded(c, name);
        return;
    }
    check(rc == -1, "return value");
    check(!memcmp(c, before, sizeof *c), "a failed load changed the config");
    check(!strncmp(err, name, strlen(name)) && err[strlen(name)] == ':' && !strchr(err, '\n'), err);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    static simcfg_t c, before; /* ~10 KB each */
    char err[600] = "";
    if (!path[0]) /* in memory if there is a tmpfs; removed after each run */
        snprintf(path, sizeof path, "%s/fuzz_robot_%d.ini", access("/dev/shm", W_OK) ? "/tmp" : "/dev/shm", (int)getpid());
    FILE *f = fopen(path, "wb");
    check(f && fwrite(data, 1, size, f) == size && fclose(f) == 0, "cannot write the input file");
    config_defaults(&c);
    before = c;
    one(robot_load(&c, path, err, sizeof err), &c, &before, err, path);
    char *text = malloc(size + 1);
    check(text != NULL, "malloc");
    memcpy(text, data, size);
    text[size] = '\0';
    config_defaults(&c);
    one(robot_load_string(&c, text, "fuzz.ini", err, sizeof err), &c, &before, err, "fuzz.ini");
    free(text);
    unlink(path);
    return 0;
}

/* fuzz_config.c - libFuzzer target for the INI config (make fuzz).
 *
 * The input is a config file (config_load: the regular-file reader, the
 * line scan, libinih, the key table and the cross-checks) and, up to its
 * first NUL, a config string (config_load_string, as a log's MM_MAZE
 * config in the replay). Either the load fails with one line "fuzz.ini:..."
 * and leaves the config as it was, or every key is in its range and
 * --print-config's text of it loads back to the same text (a log's
 * MM_MAZE config replays). */
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "world/config.h"

static char path[64];

static void check(int ok, const char *what)
{
    if (!ok) {
        fprintf(stderr, "fuzz_config: %s\n", what);
        abort();
    }
}

static char *print(const simcfg_t *c)
{
    char *text = NULL;
    size_t len = 0;
    FILE *mem = open_memstream(&text, &len);
    check(mem != NULL, "open_memstream");
    config_print(c, mem);
    fclose(mem);
    return text;
}

static void check_loaded(const simcfg_t *c)
{
    for (size_t i = 0; i < config_key_count(); i++) {
        const char *section, *key;
        double lo, hi, v = config_key_value(c, i);
        config_key_info(i, &section, &key, &lo, &hi);
        if (!(v >= lo && v <= hi)) {
            fprintf(stderr, "fuzz_config: %s.%s = %g is outside [%g, %g]\n", section, key, v, lo, hi);
            abort();
        }
    }
    char *text = print(c), err[600];
    simcfg_t again;
    config_defaults(&again);
    if (config_load_string(&again, text, "printed", err, sizeof err) != 0) {
        fprintf(stderr, "fuzz_config: the printed config does not load: %s\n%s", err, text);
        abort();
    }
    char *text2 = print(&again);
    check(!strcmp(text, text2), "the printed config loads to another one");
    free(text);
    free(text2);
}

static void one(int rc, const simcfg_t *c, const simcfg_t *before, const char *err, const char *name)
{
    if (rc == 0) {
        check_loaded(c);
        return;
    }
    check(rc == -1, "return value");
    check(!memcmp(c, before, sizeof *c), "a failed load changed the config");
    check(!strncmp(err, name, strlen(name)) && err[strlen(name)] == ':' && !strchr(err, '\n'), err);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    simcfg_t c, before;
    char err[600] = "";
    if (!path[0]) /* in memory if there is a tmpfs (the disk's writes: 300 runs/s); removed after each run */
        snprintf(path, sizeof path, "%s/fuzz_config_%d.ini", access("/dev/shm", W_OK) ? "/tmp" : "/dev/shm", (int)getpid());
    FILE *f = fopen(path, "wb");
    check(f && fwrite(data, 1, size, f) == size && fclose(f) == 0, "cannot write the input file");
    config_defaults(&c);
    before = c;
    one(config_load(&c, path, err, sizeof err), &c, &before, err, path);
    char *text = malloc(size + 1);
    check(text != NULL, "malloc");
    memcpy(text, data, size);
    text[size] = '\0';
    config_defaults(&c);
    one(config_load_string(&c, text, "fuzz.ini", err, sizeof err), &c, &before, err, "fuzz.ini");
    free(text);
    unlink(path);
    return 0;
}

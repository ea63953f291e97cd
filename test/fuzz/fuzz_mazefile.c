/* fuzz_mazefile.c - libFuzzer target for the maze parser (make fuzz).
 *
 * Any input must give a maze or one "NAME:LINE:COL: message" line, never a
 * crash or a read past the buffer (the input is not NUL-terminated, and
 * ASan sees any overread). A maze that parses must survive write -> read
 * intact in both formats, and writing it again must give the same text. */
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "maze/mazefile.h"

static truemaze_t first, second;
static char text[1 << 16], again[1 << 16];

/* "fuzz:LINE:COL: " with LINE, COL >= 1, then a message, all on one line. */
static int well_formed_error(const char *err)
{
    unsigned long line = 0, col = 0;
    int used = 0;
    if (sscanf(err, "fuzz:%lu:%lu: %n", &line, &col, &used) != 2 || used == 0) return 0;
    return line >= 1 && col >= 1 && err[used] != '\0' && !strchr(err, '\n') && !strchr(err, '\r');
}

static void check(int ok, const char *what)
{
    if (!ok) {
        fprintf(stderr, "fuzz_mazefile: %s\n", what);
        abort();
    }
}

/* One letter per cell: a start inside a goal area other than the default
 * centre cannot be written (see mazefile_format), so that goal is not
 * compared. */
static int goal_writable(const truemaze_t *m)
{
    truemaze_t centre;
    truemaze_init(&centre, m->width, m->height);
    return !truemaze_is_goal(m, m->start) || memcmp(centre.goal, m->goal, sizeof m->goal) == 0;
}

static int same_walls(const truemaze_t *x, const truemaze_t *y)
{
    return x->width == y->width && x->height == y->height && memcmp(x->cell, y->cell, truemaze_cells(x)) == 0;
}

static void check_text_round_trip(void)
{
    char err[MAZEFILE_ERR_LEN];
    size_t n = mazefile_format(&first, text, sizeof text);
    check(n < sizeof text && strlen(text) == n, "text writer length");
    check(mazefile_parse(&second, text, n, "rt", NULL, err, sizeof err) == 0, "written text does not parse");
    check(same_walls(&first, &second), "walls differ after the text round trip");
    check(first.start == second.start && first.start_heading == second.start_heading, "start differs");
    if (!goal_writable(&first)) return; /* the goal read back is another one: the text changes too */
    check(memcmp(first.goal, second.goal, sizeof first.goal) == 0, "goal differs");
    check(mazefile_format(&second, again, sizeof again) == n && strcmp(text, again) == 0, "text not stable");
}

static void check_mms_round_trip(void)
{
    char err[MAZEFILE_ERR_LEN];
    mazefile_info_t info;
    size_t n = mazefile_format_mms(&first, text, sizeof text);
    check(n < sizeof text && strlen(text) == n, "mms writer length");
    check(mazefile_parse(&second, text, n, "rt", &info, err, sizeof err) == 0 && info.mms_format, "written mms does not parse");
    check(same_walls(&first, &second), "walls differ after the mms round trip");
    check(mazefile_format_mms(&second, again, sizeof again) == n && strcmp(text, again) == 0, "mms not stable");
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    char err[MAZEFILE_ERR_LEN];
    err[0] = '\0';
    if (mazefile_parse(&first, (const char *)data, size, "fuzz", NULL, err, sizeof err) != 0) {
        check(well_formed_error(err), err);
        return 0;
    }
    check(first.width >= 1 && first.width <= TRUEMAZE_MAX_SIZE && first.height >= 1 && first.height <= TRUEMAZE_MAX_SIZE, "size");
    check(first.start < truemaze_cells(&first) && first.start_heading < 4, "start");
    check_text_round_trip();
    check_mms_round_trip();
    return 0;
}

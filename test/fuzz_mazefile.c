/* fuzz_mazefile.c - libFuzzer target for the maze parser (make fuzz).
 * Any input must give a maze or one error line, never a crash or a read
 * past the buffer; a maze that parses must survive write -> read intact. */
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "mazefile.h"

static maze_t a, b;
static char text[1 << 16];

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    char err[MAZEFILE_ERR_LEN];
    if (mazefile_parse(&a, (const char *)data, size, "fuzz", NULL, err, sizeof err) != 0) {
        if (!memchr(err, ':', strlen(err)) || strchr(err, '\n')) abort(); /* one "name:line:col:" line */
        return 0;
    }
    maze_t centre;
    maze_init(&centre, a.width, a.height);
    if (maze_is_goal(&a, a.start) && memcmp(centre.goal, a.goal, sizeof a.goal) != 0)
        return 0; /* not writable: see mazefile_format */
    size_t n = mazefile_format(&a, text, sizeof text);
    if (n >= sizeof text) abort();
    if (mazefile_parse(&b, text, n, "rt", NULL, err, sizeof err) != 0) abort();
    if (a.width != b.width || a.height != b.height || memcmp(a.cell, b.cell, sizeof a.cell) ||
        memcmp(a.goal, b.goal, sizeof a.goal) || a.start != b.start || a.start_heading != b.start_heading)
        abort();
    return 0;
}

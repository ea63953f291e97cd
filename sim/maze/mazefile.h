/* mazefile.h - maze files on the host: the micromouseonline text format
 * (posts 'o' or '+', walls '---' and '|', optional 'S'/'G' letters in cell
 * centres) and mms's numeric format (one line per cell: "X Y N E S W").
 *
 * Errors are one line "NAME:LINE:COL: what is wrong" written into err.
 * The parser never reads past the buffer and never allocates.
 */
#ifndef MAZEFILE_H
#define MAZEFILE_H

#include <stddef.h>
#include "truemaze.h"

#define MAZEFILE_ERR_LEN 320
#define MAZEFILE_MAX_BYTES (1u << 20) /* larger files are rejected */

/* Extra facts from the file that the map itself does not hold. */
typedef struct {
    int has_start;  /* an 'S' letter was present */
    int has_goal;   /* at least one 'G' letter was present */
    int mms_format; /* the file was in mms numeric format */
} mazefile_info_t;

/* Parse text (len bytes, not necessarily NUL-terminated) into the true
 * maze m. Format auto-detected: text if the first non-blank character
 * is 'o' or '+', numeric if it is a digit. name is used in error messages.
 * Returns 0, or -1 with err filled. info may be NULL. */
int mazefile_parse(truemaze_t *m, const char *text, size_t len, const char *name,
                   mazefile_info_t *info, char *err, size_t errlen);

/* Read and parse a file ("-" = stdin). Returns 0, or -1 with err filled
 * (including "NAME: cannot open: reason"). */
int mazefile_load(truemaze_t *m, const char *path, mazefile_info_t *info,
                  char *err, size_t errlen);

/* Write m in the text format with 'o' posts, 'S' in the start cell and 'G'
 * in every goal cell, LF line ends, no trailing spaces. Like snprintf:
 * returns the length the whole text needs; writes at most cap bytes
 * including a terminating NUL.
 * A start cell inside a goal area other than the default centre cannot be
 * written (one letter per cell); that goal is written without the start. */
size_t mazefile_format(const truemaze_t *m, char *buf, size_t cap);

/* Write m in mms numeric format (same snprintf convention). */
size_t mazefile_format_mms(const truemaze_t *m, char *buf, size_t cap);

#endif

/* datadir.h - where the data files (boards/, robots/, contests/) are found, from any
 * working directory: the working directory first (a user's own files and
 * paths as given), then an installed tree beside the program
 * (PREFIX/share/mmsim for PREFIX/bin/mmsim, `make install`), then the
 * source tree the program was built from (MMSIM_DATADIR, set by the
 * Makefile to the repository's absolute path). */
#ifndef DATADIR_H
#define DATADIR_H

#include <stddef.h>

#define DATADIR_MAX 3          /* places searched */
#define DATADIR_PATH_MAX 4096  /* bytes of one place's path */

/* The places to search, in order, into dirs; returns how many. The first
 * is "" (the working directory: a file there is named "boards/X", as
 * given); the others are absolute folders, each existing. */
int datadir_list(char dirs[DATADIR_MAX][DATADIR_PATH_MAX]);
/* The first place holding the file rel (e.g. "robots/ukmarsbot.ini"):
 * its path into out ("robots/ukmarsbot.ini" in the working directory,
 * else DIR/robots/ukmarsbot.ini). 0, or -1 if none holds it (or the path
 * is longer than outn). */
int datadir_find(const char *rel, char *out, size_t outn);

#endif

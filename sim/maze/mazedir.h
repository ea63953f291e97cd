/* mazedir.h - the maze files of a folder, for batch commands. */
#ifndef MAZEDIR_H
#define MAZEDIR_H

#include <stddef.h>

/* Every *.txt file directly in dir, as "dir/name", sorted by name.
 * Returns the count (0 = none), or -1 if dir cannot be read (errno set).
 * Free the list with mazedir_free. */
long mazedir_list(const char *dir, char ***names);
void mazedir_free(char **names, long n);
/* mazedir_list for a command: on no files, an unreadable folder or a
 * listed name that is not a regular file (a FIFO, a directory, a dangling
 * link), prints one line "DIR: ..." or "DIR/NAME.txt: ..." on stderr and
 * returns -1. */
long mazedir_list_or_report(const char *dir, char ***names);

#endif

/* mazedir.c - list a folder's maze files in a stable (sorted) order, so a
 * batch's output is the same on every machine. */
#include "mazedir.h"

#include <dirent.h>
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "io/infile.h"

static int compare_names(const void *a, const void *b) { return strcmp(*(char *const *)a, *(char *const *)b); }

long mazedir_list(const char *dir, char ***names)
{
    DIR *d = opendir(dir);
    *names = NULL;
    if (!d) return -1;
    char **list = NULL;
    size_t n = 0, cap = 0;
    struct dirent *e;
    while ((e = readdir(d)) != NULL) {
        size_t len = strlen(e->d_name);
        if (len < 5 || strcmp(e->d_name + len - 4, ".txt") != 0) continue;
        if (n == cap) {
            cap = cap ? cap * 2 : 64;
            char **grown = realloc(list, cap * sizeof *list);
            if (!grown) break;
            list = grown;
        }
        size_t size = strlen(dir) + len + 2;
        list[n] = malloc(size);
        if (!list[n]) break;
        snprintf(list[n++], size, "%s/%s", dir, e->d_name);
    }
    closedir(d);
    if (n) qsort(list, n, sizeof *list, compare_names);
    *names = list;
    return (long)n;
}

void mazedir_free(char **names, long n)
{
    for (long i = 0; i < n; i++) free(names[i]);
    free(names);
}

long mazedir_list_or_report(const char *dir, char ***names)
{
    char err[600] = "";
    long n = mazedir_list(dir, names);
    if (n < 0) fprintf(stderr, "%s: cannot open: %s\n", dir, strerror(errno));
    else if (n == 0) fprintf(stderr, "%s: no .txt maze files\n", dir);
    /* every entry a regular file, before any job starts: a FIFO would hang
     * its job, a directory fail late */
    for (long i = 0; i < n && !err[0]; i++)
        if (infile_check((*names)[i], INFILE_NO_LIMIT, err, sizeof err) != 0) fprintf(stderr, "%s\n", err);
    if (n <= 0 || err[0]) {
        mazedir_free(*names, n > 0 ? n : 0);
        *names = NULL;
        return -1;
    }
    return n;
}

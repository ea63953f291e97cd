/* inisec.h - the section bookkeeping of a board file, the same for both
 * readers (the AVR boards' sim/board/board_file.c, the STM32 boards'
 * sim/arm/stm32board_file.c): which of the fixed sections a file gives and
 * the line of each, a key looked up in a section's table with the errors
 * of a key outside any section or unknown, and the load's error at a line
 * of the file being read (inifile_verror's one line). */
#ifndef INISEC_H
#define INISEC_H

#include <stddef.h>

#include "world/keytab.h"

#define INISEC_FIXED_MAX 16

typedef struct {
    const char *path;                /* the file being read: the one errors name */
    char *err;                       /* the load's error line */
    size_t errn;
    const char *const *fixed;        /* the fixed sections' names */
    size_t nfixed;                   /* at most INISEC_FIXED_MAX */
    int line[INISEC_FIXED_MAX];      /* each fixed section's first line, 0: not given */
} inisec_t;

void inisec_init(inisec_t *s, const char *path, char *err, size_t errn, const char *const *fixed, size_t nfixed);
/* A section met at line: the index of the fixed section it is (its first line kept), -1 if none. */
int inisec_section(inisec_t *s, const char *section, int line);
/* A fixed section's first line, 0: not given (or not a fixed section). */
int inisec_line(const inisec_t *s, const char *section);
/* The key named key of tab (tab_section NULL: any section) for a key in section; NULL with why:
 * "KEY: a key outside any [section]" or "SECTION.KEY: unknown key". */
const keytab_t *inisec_key(const char *section, const char *key, const keytab_t *tab, size_t n, const char *tab_section,
                           char *why, size_t len);
/* The load's error at line (0: none) of s->path; returns -1. */
int inisec_fail(inisec_t *s, int line, const char *fmt, ...) __attribute__((format(printf, 3, 4)));

#endif

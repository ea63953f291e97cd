/* inifile.h - the one reading path of the INI files (the config, robot
 * files and board files): a regular file of bounded size, a line scan,
 * then Debian's libinih with the caller's handlers.
 *
 * The line scan reads each line as libinih does and refuses what libinih
 * would read wrongly or silently, each as "NAME:LINE: reason":
 *   - a NUL byte (libinih stops there);
 *   - a line over INIFILE_MAX_LINE bytes (libinih reads the rest of it as
 *     a line of its own);
 *   - an indented line after a key (libinih hands it over as that key's
 *     value again: a continuation line, `body_mass_g = 127` then `  1999`
 *     would set 1999);
 *   - a key given twice in one section (libinih hands over both);
 *   - "[" without "]" and a line that is neither a key, a [section], a
 *     comment nor blank.
 * It hands each [section] line to the caller with its line number, all of
 * them before libinih hands over the first key. The first error in the
 * file's line order is the one reported. */
#ifndef INIFILE_H
#define INIFILE_H

#include <stdarg.h>
#include <stddef.h>

/* bytes of a line without its CR LF: libinih's line buffer (INI_MAX_LINE,
 * 200) holds them and a NUL (inifile.c checks the two agree) */
#define INIFILE_MAX_LINE 197
/* bytes of an error line: room for "unknown key" and every key name a
 * section has (a chassis has about 40) */
#define INIFILE_ERR_MAX 2048

typedef struct {
    /* Each "[section]" line (the text between the brackets) in the file's
     * order, before any key: 0, or -1 with the reason in why. NULL: any
     * section is accepted here. */
    int (*section)(void *user, const char *section, int line, char *why, size_t len);
    /* Each key with its value, in the file's order: 0, or -1 with
     * "section.key: reason" in why. */
    int (*key)(void *user, const char *section, const char *key, const char *val, char *why, size_t len);
    void *user;
    const char *syntax; /* what a line should be, for its syntax error: "want key = value or [section]" */
} inifile_t;

/* Parse text (len bytes and a NUL after them; name is used in messages,
 * its NUL bytes are an error). 0, or -1 with one line
 * in err: "NAME:LINE: reason" (the first error in line order) or "NAME:
 * out of memory". */
int inifile_parse(const inifile_t *r, const char *text, size_t len, const char *name, char *err, size_t errlen);

/* One error line of a file into err: "NAME:LINE: reason" (LINE <= 0:
 * "NAME: reason"), the reason printf-style (a va_list). Returns -1. */
int inifile_verror(char *err, size_t errlen, const char *name, int line, const char *fmt, va_list ap)
    __attribute__((format(printf, 5, 0)));

/* Read the file at path (a regular file of at most max_bytes: io/infile.h)
 * and parse it as inifile_parse does, named by its path. */
int inifile_load(const inifile_t *r, const char *path, size_t max_bytes, char *err, size_t errlen);

#endif

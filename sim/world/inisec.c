/* inisec.c - a board file's section bookkeeping (inisec.h). */
#include "world/inisec.h"

#include <stdarg.h>
#include <stdio.h>
#include <string.h>

#include "world/inifile.h"

void inisec_init(inisec_t *s, const char *path, char *err, size_t errn, const char *const *fixed, size_t nfixed)
{
    s->path = path;
    s->err = err;
    s->errn = errn;
    s->fixed = fixed;
    s->nfixed = nfixed < INISEC_FIXED_MAX ? nfixed : INISEC_FIXED_MAX;
}

static int fixed_index(const inisec_t *s, const char *section)
{
    for (size_t i = 0; i < s->nfixed; i++)
        if (!strcmp(section, s->fixed[i])) return (int)i;
    return -1;
}

int inisec_section(inisec_t *s, const char *section, int line)
{
    int i = fixed_index(s, section);
    if (i >= 0 && !s->line[i]) s->line[i] = line;
    return i;
}

int inisec_line(const inisec_t *s, const char *section)
{
    int i = fixed_index(s, section);
    return i >= 0 ? s->line[i] : 0;
}

const keytab_t *inisec_key(const char *section, const char *key, const keytab_t *tab, size_t n, const char *tab_section,
                           char *why, size_t len)
{
    if (!*section) {
        snprintf(why, len, "%s: a key outside any [section]", key);
        return NULL;
    }
    const keytab_t *k = keytab_find(tab, n, tab_section, key);
    if (!k) snprintf(why, len, "%s.%s: unknown key", section, key);
    return k;
}

int inisec_fail(inisec_t *s, int line, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    inifile_verror(s->err, s->errn, s->path, line, fmt, ap);
    va_end(ap);
    return -1;
}

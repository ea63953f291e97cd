/* inifile.c - the INI reading path (see inifile.h): the line scan, then
 * libinih. The scan classifies each line by libinih's own rules
 * (ini.c's ini_parse_stream with Debian's build options: ';' and '#'
 * comments, inline ';' comments after a blank, '=' or ':' between key and
 * value, a UTF-8 BOM skipped on the first line, multi-line values on). */
#include "inifile.h"

#include <ctype.h>
#include <stdarg.h>
#include <glib.h>
#include <ini.h>
#include <stdlib.h>
#include <string.h>

#include "io/infile.h"

#if INIFILE_MAX_LINE != INI_MAX_LINE - 3
#error "INIFILE_MAX_LINE is not libinih's line buffer less CR, LF and NUL"
#endif

typedef struct {
    const inifile_t *r;
    const char *name;
    int err_line;       /* the scan's first error's line, 0: none */
    char err[INIFILE_ERR_MAX]; /* its message, "NAME:LINE: reason" */
    char section[INIFILE_MAX_LINE + 1];
    char prev_key[INIFILE_MAX_LINE + 1]; /* the last key since the last [section], "" if none */
    GHashTable *keys;   /* "section\nkey" -> the line that gave it */
} scan_t;

int inifile_verror(char *err, size_t errlen, const char *name, int line, const char *fmt, va_list ap)
{
    char why[INIFILE_ERR_MAX];
    vsnprintf(why, sizeof why, fmt, ap);
    if (line > 0) snprintf(err, errlen, "%s:%d: %s", name, line, why);
    else snprintf(err, errlen, "%s: %s", name, why);
    return -1;
}

/* The scan's error at line (printf-style reason); returns -1. */
static int scan_fail(scan_t *s, int line, const char *fmt, ...) __attribute__((format(printf, 3, 4)));
static int scan_fail(scan_t *s, int line, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    s->err_line = line;
    inifile_verror(s->err, sizeof s->err, s->name, line, fmt, ap);
    va_end(ap);
    return -1;
}

static char *rstrip(char *s)
{
    size_t n = strlen(s);
    while (n > 0 && isspace((unsigned char)s[n - 1])) s[--n] = '\0';
    return s;
}

static char *lskip(char *s)
{
    while (*s && isspace((unsigned char)*s)) s++;
    return s;
}

/* The first of chars in s, or an inline comment's ';' after a blank, or
 * the end (libinih's ini_find_chars_or_comment). */
static char *stop_at(char *s, const char *chars)
{
    int was_space = 0;
    while (*s && (!chars || !strchr(chars, *s)) && !(was_space && *s == ';')) {
        was_space = isspace((unsigned char)*s);
        s++;
    }
    return s;
}

/* "section.key", or "key" before any section. */
static const char *dot(const scan_t *s) { return *s->section ? "." : ""; }

/* A "[...]" line at start: the caller's section check. */
static int scan_section(scan_t *s, char *start, int line)
{
    char *end = stop_at(start + 1, "]");
    if (*end != ']') return scan_fail(s, line, "'[' without ']'");
    *end = '\0';
    snprintf(s->section, sizeof s->section, "%s", start + 1);
    s->prev_key[0] = '\0';
    char why[300];
    if (s->r->section && s->r->section(s->r->user, s->section, line, why, sizeof why) != 0) return scan_fail(s, line, "%s", why);
    return 0;
}

/* A "key = value" line at start: no key twice in one section. */
static int scan_key(scan_t *s, char *start, int line)
{
    char *end = stop_at(start, "=:");
    if (*end != '=' && *end != ':') return scan_fail(s, line, "syntax error (%s)", s->r->syntax);
    *end = '\0';
    rstrip(start);
    snprintf(s->prev_key, sizeof s->prev_key, "%s", start);
    char *id = g_strdup_printf("%s\n%s", s->section, start);
    gpointer first = g_hash_table_lookup(s->keys, id);
    if (first) {
        g_free(id);
        return scan_fail(s, line, "%s%s%s: given twice (first on line %d)", s->section, dot(s), start, GPOINTER_TO_INT(first));
    }
    g_hash_table_insert(s->keys, id, GINT_TO_POINTER(line));
    return 0;
}

/* One line (NUL-terminated, without its LF), number `line`. */
static int scan_line(scan_t *s, char *text, int line)
{
    char *start = text;
    if (line == 1 && (unsigned char)start[0] == 0xEF && (unsigned char)start[1] == 0xBB && (unsigned char)start[2] == 0xBF)
        start += 3;
    start = lskip(rstrip(start));
    if (!*start || *start == ';' || *start == '#') return 0;
    if (*s->prev_key && start > text)
        return scan_fail(s, line, "%s%s%s: an indented line continues its value (INI continuation lines are refused: start the line in its first column)",
                         s->section, dot(s), s->prev_key);
    if (*start == '[') return scan_section(s, start, line);
    return scan_key(s, start, line);
}

/* Every line up to the first error: NUL bytes, length, then scan_line. */
static void scan_text(scan_t *s, const char *text, size_t len)
{
    char buf[INIFILE_MAX_LINE + 2];
    int line = 1;
    for (size_t start = 0; start < len; line++) {
        const char *nl = memchr(text + start, '\n', len - start);
        size_t end = nl ? (size_t)(nl - text) : len, n = end - start;
        if (memchr(text + start, '\0', n)) {
            scan_fail(s, line, "NUL byte");
            return;
        }
        if (n > 0 && text[end - 1] == '\r') n--;
        if (n > INIFILE_MAX_LINE) {
            scan_fail(s, line, "line too long (%zu bytes; at most %d)", n, INIFILE_MAX_LINE);
            return;
        }
        memcpy(buf, text + start, n);
        buf[n] = '\0';
        if (scan_line(s, buf, line) != 0) return;
        start = end + 1;
    }
}

typedef struct {
    const inifile_t *r;
    int failed;       /* a key handler failed: why holds its reason */
    char why[INIFILE_ERR_MAX];
} keys_t;

static int on_key(void *user, const char *section, const char *key, const char *val)
{
    keys_t *k = user;
    if (k->failed) return 1; /* the first error only: libinih reports its line */
    if (k->r->key(k->r->user, section, key, val, k->why, sizeof k->why) == 0) return 1;
    k->failed = 1;
    return 0;
}

int inifile_parse(const inifile_t *r, const char *text, size_t len, const char *name, char *err, size_t errlen)
{
    scan_t *s = calloc(1, sizeof *s);
    keys_t k = { r, 0, "" };
    if (!s) {
        snprintf(err, errlen, "%s: out of memory", name);
        return -1;
    }
    s->r = r;
    s->name = name;
    s->keys = g_hash_table_new_full(g_str_hash, g_str_equal, g_free, NULL);
    scan_text(s, text, len);
    /* libinih even after a scan error: a key's error on an earlier line
     * comes first (its sections up to the scan's error are known) */
    int rc = ini_parse_string(text, on_key, &k), out = -1;
    if (rc < 0) snprintf(err, errlen, "%s: out of memory", name);
    else if (s->err_line > 0 && (rc == 0 || s->err_line <= rc)) snprintf(err, errlen, "%s", s->err);
    else if (rc > 0) snprintf(err, errlen, "%s:%d: %s", name, rc, k.failed ? k.why : "syntax error");
    else out = 0;
    g_hash_table_destroy(s->keys);
    free(s);
    return out;
}

int inifile_load(const inifile_t *r, const char *path, size_t max_bytes, char *err, size_t errlen)
{
    size_t len;
    /* a regular file of a bounded size: a FIFO or /dev/zero hung, a
     * directory read as an empty file */
    char *text = infile_read(path, max_bytes, &len, err, errlen);
    if (!text) return -1;
    int rc = inifile_parse(r, text, len, path, err, errlen);
    free(text);
    return rc;
}

/* keytab.c - table-driven INI keys (see keytab.h). */
#include "keytab.h"

#include <errno.h>
#include <stdlib.h>
#include <string.h>

static double per(const keytab_t *k) { return k->per > 0 ? k->per : 1.0; }
static void *at(const keytab_t *k, void *t) { return (char *)t + k->offset; }
static double *field(const keytab_t *k, void *t) { return at(k, t); }
/* A list key's count of numbers given (keytab.h). */
static int *count(const keytab_t *k, void *t) { return (int *)(void *)((char *)t + k->size); }
static int count_of(const keytab_t *k, const void *t) { return *(const int *)(const void *)((const char *)t + k->size); }

/* A number or word (already divided by per) into k's field, by its type. */
static void store(const keytab_t *k, void *t, double v)
{
    if (k->type == KEYTAB_INT) *(int *)at(k, t) = (int)v;
    else if (k->type == KEYTAB_U32) *(uint32_t *)at(k, t) = (uint32_t)v;
    else *field(k, t) = v;
}

static double load(const keytab_t *k, const void *t)
{
    const void *f = (const char *)t + k->offset;
    if (k->type == KEYTAB_INT) return *(const int *)f;
    if (k->type == KEYTAB_U32) return *(const uint32_t *)f;
    if (k->type == KEYTAB_DOUBLE) return *(const double *)f;
    return 0.0;
}

static int whole(const keytab_t *k) { return k->whole || k->type == KEYTAB_INT || k->type == KEYTAB_U32; }

void keytab_defaults(const keytab_t *tab, size_t n, void *target)
{
    for (size_t i = 0; i < n; i++) {
        const keytab_t *k = &tab[i];
        double d = isnan(k->def) ? 0.0 : k->def;
        if (k->type == KEYTAB_TEXT || k->type == KEYTAB_PARSED) {
            memset(at(k, target), 0, k->size);
        } else if (k->type == KEYTAB_DOUBLES) {
            for (int j = 0; j < k->list; j++) field(k, target)[j] = d / per(k);
        } else if (k->list) {
            *count(k, target) = isnan(k->def) ? 0 : 1;
            for (int j = 0; j < k->list; j++) field(k, target)[j] = j ? 0.0 : d / per(k);
        } else {
            store(k, target, d / per(k));
        }
    }
}

const keytab_t *keytab_find(const keytab_t *tab, size_t n, const char *section, const char *key)
{
    for (size_t i = 0; i < n; i++)
        if ((!section || !tab[i].section || !strcmp(tab[i].section, section)) && !strcmp(tab[i].key, key)) return &tab[i];
    return NULL;
}

const keytab_t *keytab_missing(const keytab_t *tab, size_t n, uint64_t seen)
{
    for (size_t i = 0; i < n && i < 64; i++)
        if (isnan(tab[i].def) && !(seen & (1ull << i))) return &tab[i];
    return NULL;
}

static int word(const keytab_t *k, void *t, const char *where, const char *val, char *reason, size_t len)
{
    for (int i = 0; i <= (int)k->max; i++)
        if (!strcmp(val, k->choices[i])) {
            store(k, t, i);
            return 0;
        }
    int n = snprintf(reason, len, "%s.%s: '%s' is not one of", where, k->key, val);
    for (int i = 0; i <= (int)k->max && n > 0 && (size_t)n < len; i++)
        n += snprintf(reason + n, len - (size_t)n, " %s", k->choices[i]);
    return -1;
}

static int text(const keytab_t *k, void *t, const char *where, const char *val, char *reason, size_t len)
{
    if (strlen(val) >= k->size) {
        snprintf(reason, len, "%s.%s: '%.40s...' is longer than %zu characters", where, k->key, val, k->size - 1);
        return -1;
    }
    memcpy(at(k, t), val, strlen(val) + 1);
    return 0;
}

/* One number at *p (leading blanks skipped), range-checked; *p moves past it. */
static int number_at(const keytab_t *k, const char **p, const char *where, double *out, char *reason, size_t len)
{
    char *end;
    errno = 0;
    double v = strtod(*p, &end);
    if (errno || end == *p || !isfinite(v) || (*end && *end != ' ' && *end != '\t')) {
        snprintf(reason, len, "%s.%s: '%s' is not a number", where, k->key, *p);
        return -1;
    }
    if (whole(k) && v != floor(v)) {
        snprintf(reason, len, "%s.%s: %g is not a whole number", where, k->key, v);
        return -1;
    }
    if (v < k->min || v > k->max) {
        snprintf(reason, len, "%s.%s: %g %s is out of range [%g, %g]", where, k->key, v, k->unit, k->min, k->max);
        return -1;
    }
    while (*end == ' ' || *end == '\t') end++;
    *p = end;
    *out = v / per(k);
    return 0;
}

/* The numbers of val into v[] (at most cap): how many, or -1. */
static int numbers(const keytab_t *k, const char *where, const char *val, double *v, int cap, char *reason, size_t len)
{
    const char *p = val;
    int n = 0;
    while (*p) {
        if (n == cap && !k->list) {
            snprintf(reason, len, "%s.%s: '%s' is not a number", where, k->key, val);
            return -1;
        }
        if (n == cap) {
            snprintf(reason, len, "%s.%s: more than %d numbers", where, k->key, cap);
            return -1;
        }
        if (number_at(k, &p, where, &v[n], reason, len) != 0) return -1;
        n++;
    }
    return n;
}

int keytab_set(const keytab_t *k, void *t, const char *where, const char *val, char *reason, size_t len)
{
    if (!val || !*val) {
        snprintf(reason, len, "%s.%s: missing value", where, k->key);
        return -1;
    }
    if (k->type == KEYTAB_TEXT) return text(k, t, where, val, reason, len);
    if (k->type == KEYTAB_PARSED) {
        char why[160];
        if (k->parse(val, at(k, t), why, sizeof why) == 0) return 0;
        snprintf(reason, len, "%s.%s: %s", where, k->key, why);
        return -1;
    }
    if (k->choices) return word(k, t, where, val, reason, len);
    double v[64];
    int cap = k->list > 0 ? (k->list < 64 ? k->list : 64) : 1;
    int n = numbers(k, where, val, v, cap, reason, len);
    if (n < 0) return -1;
    if (k->type == KEYTAB_DOUBLES) {
        if (n != cap) {
            snprintf(reason, len, "%s.%s: %d numbers, want %d", where, k->key, n, cap);
            return -1;
        }
        memcpy(field(k, t), v, sizeof v[0] * (size_t)n);
        return 0;
    }
    if (!k->list) {
        store(k, t, v[0]);
        return 0;
    }
    *count(k, t) = n;
    for (int i = 0; i < cap; i++) field(k, t)[i] = i < n ? v[i] : 0.0;
    return 0;
}

double keytab_get(const keytab_t *k, const void *t) { return load(k, t) * per(k); }

/* v (stored) in as few digits as read back the same double, at least 9:
 * the defaults print as before, and a value given with more digits prints
 * with them (with 9 only, 0.079999999999 printed as 0.08, which the
 * corridor check rejected when the printed config, as a log's MM_MAZE,
 * was loaded again; and two such configs had the same hash). */
static void number(double stored, double p, FILE *out)
{
    char buf[40];
    for (int digits = 9; digits <= 17; digits++) {
        snprintf(buf, sizeof buf, "%.*g", digits, stored * p);
        if (strtod(buf, NULL) / p == stored) break;
    }
    fputs(buf, out);
}

void keytab_print(const keytab_t *k, const void *t, FILE *out)
{
    const double *f = (const double *)(const void *)((const char *)t + k->offset);
    fprintf(out, "%s = ", k->key);
    if (k->type == KEYTAB_TEXT) {
        fputs((const char *)t + k->offset, out);
    } else if (k->choices) {
        fputs(k->choices[(int)load(k, t)], out);
    } else if (k->list) {
        int n = k->type == KEYTAB_DOUBLES ? k->list : count_of(k, t);
        for (int i = 0; i < n; i++) {
            if (i) fputc(' ', out);
            number(f[i], per(k), out);
        }
    } else {
        number(load(k, t), per(k), out);
    }
    fprintf(out, " ; %s; %s\n", k->unit, k->source);
}

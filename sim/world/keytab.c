/* keytab.c - table-driven INI keys (see keytab.h). */
#include "keytab.h"

#include <errno.h>
#include <stdlib.h>
#include <string.h>

static double per(const keytab_t *k) { return k->per > 0 ? k->per : 1.0; }
static double *field(const keytab_t *k, void *t) { return (double *)((char *)t + k->offset); }
static double cfield(const keytab_t *k, const void *t) { return *(const double *)((const char *)t + k->offset); }

void keytab_defaults(const keytab_t *tab, size_t n, void *target)
{
    for (size_t i = 0; i < n; i++) {
        double d = isnan(tab[i].def) ? 0.0 : tab[i].def;
        if (tab[i].list) {
            field(&tab[i], target)[-1] = isnan(tab[i].def) ? 0 : 1;
            for (int j = 0; j < tab[i].list; j++) field(&tab[i], target)[j] = j ? 0.0 : d / per(&tab[i]);
        } else {
            *field(&tab[i], target) = d / per(&tab[i]);
        }
    }
}

const keytab_t *keytab_find(const keytab_t *tab, size_t n, const char *section, const char *key)
{
    for (size_t i = 0; i < n; i++)
        if ((!section || !tab[i].section || !strcmp(tab[i].section, section)) && !strcmp(tab[i].key, key)) return &tab[i];
    return NULL;
}

static int word(const keytab_t *k, void *t, const char *where, const char *val, char *reason, size_t len)
{
    for (int i = 0; i <= (int)k->max; i++)
        if (!strcmp(val, k->choices[i])) {
            *field(k, t) = i;
            return 0;
        }
    int n = snprintf(reason, len, "%s.%s: '%s' is not one of", where, k->key, val);
    for (int i = 0; i <= (int)k->max && n > 0 && (size_t)n < len; i++)
        n += snprintf(reason + n, len - (size_t)n, " %s", k->choices[i]);
    return -1;
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
    if (k->whole && v != floor(v)) {
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

int keytab_set(const keytab_t *k, void *t, const char *where, const char *val, char *reason, size_t len)
{
    if (!val || !*val) {
        snprintf(reason, len, "%s.%s: missing value", where, k->key);
        return -1;
    }
    if (k->choices) return word(k, t, where, val, reason, len);
    const char *p = val;
    double v[64];
    int n = 0, cap = k->list > 0 ? k->list : 1;
    while (*p) {
        if (n == cap && !k->list) {
            snprintf(reason, len, "%s.%s: '%s' is not a number", where, k->key, val);
            return -1;
        }
        if (n == cap || n == 64) {
            snprintf(reason, len, "%s.%s: more than %d numbers", where, k->key, cap);
            return -1;
        }
        if (number_at(k, &p, where, &v[n], reason, len) != 0) return -1;
        n++;
    }
    if (!k->list) {
        *field(k, t) = v[0];
        return 0;
    }
    field(k, t)[-1] = n;
    for (int i = 0; i < cap; i++) field(k, t)[i] = i < n ? v[i] : 0.0;
    return 0;
}

double keytab_get(const keytab_t *k, const void *t) { return cfield(k, t) * per(k); }

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
    fprintf(out, "%s = ", k->key);
    if (k->choices) {
        fputs(k->choices[(int)cfield(k, t)], out);
    } else if (k->list) {
        int n = (int)field(k, (void *)t)[-1];
        for (int i = 0; i < n; i++) {
            if (i) fputc(' ', out);
            number(field(k, (void *)t)[i], per(k), out);
        }
    } else {
        number(cfield(k, t), per(k), out);
    }
    fprintf(out, " ; %s; %s\n", k->unit, k->source);
}

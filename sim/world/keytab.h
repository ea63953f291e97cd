/* keytab.h - tables of INI keys that set double fields of a struct by
 * offset: the config's keys and each robot component's schema. A key has
 * a unit, a physical range and the source of its default; a file's value
 * divided by `per` is what the struct holds (a robot file's mm into the
 * simulator's m: 96 / 1000 is the double nearest 0.096, as the literal). A key whose default is KEYTAB_REQUIRED has none: a
 * section that lacks it is an error. */
#ifndef KEYTAB_H
#define KEYTAB_H

#include <math.h>
#include <stddef.h>
#include <stdio.h>

#define KEYTAB_REQUIRED NAN

typedef struct {
    const char *section;        /* the config's section; NULL in a component's schema */
    const char *key;
    size_t offset;              /* of a double in the target struct */
    double def, min, max;       /* in the file's unit */
    const char *unit, *source;
    const char *const *choices; /* a word key: its words, the value is the index */
    int whole;                  /* 1: a whole number (a count, or 0/1) */
    double per;                 /* file units per stored unit (mm per m: 1000): stored = value / per; 0 means 1 */
    int list;                   /* >0: up to this many numbers, space-separated, into consecutive doubles; the count goes to the double before them */
} keytab_t;

/* The stored default of every key of tab into target (required keys: 0). */
void keytab_defaults(const keytab_t *tab, size_t n, void *target);
/* The key named `key` in tab (section NULL: any), NULL if none. */
const keytab_t *keytab_find(const keytab_t *tab, size_t n, const char *section, const char *key);
/* Parse val into k's field of target. 0, or -1 with "where.key: reason"
 * in reason (where = the section as the file names it). */
int keytab_set(const keytab_t *k, void *target, const char *where, const char *val, char *reason, size_t len);
/* The value in the file's unit. */
double keytab_get(const keytab_t *k, const void *target);
/* "key = value ; unit; source" as a line (value in as few digits as read
 * back the same, at least 9). */
void keytab_print(const keytab_t *k, const void *target, FILE *out);

#endif

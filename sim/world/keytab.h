/* keytab.h - tables of INI keys that set fields of a struct by offset: the
 * config's keys, each robot component's schema and the board file's. A key
 * has a unit, a physical range and the source of its default; a file's
 * number divided by `per` is what the struct holds (a robot file's mm into
 * the simulator's m: 96 / 1000 is the double nearest 0.096, as the
 * literal). A key whose default is KEYTAB_REQUIRED has none: a section that
 * lacks it is an error (keytab_missing).
 *
 * A field is a double unless the key's type says otherwise: an int or a
 * uint32_t (whole numbers, or a word's index), a char array (text), an
 * array of exactly `list` doubles, or what the key's own parse function
 * makes of the text (a board's pin "D11"). A double key with `list` > 0
 * takes up to `list` numbers and stores how many in an int of the same
 * struct (at offset `size`). */
#ifndef KEYTAB_H
#define KEYTAB_H

#include <math.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>

#define KEYTAB_REQUIRED NAN

typedef enum {
    KEYTAB_DOUBLE = 0, /* a double; with list > 0 up to `list` numbers, their count in the int at offset `size` */
    KEYTAB_INT,        /* an int: a whole number, or a word's index */
    KEYTAB_U32,        /* a uint32_t: a whole number */
    KEYTAB_TEXT,       /* a char array of `size` bytes: 1 to size - 1 characters */
    KEYTAB_DOUBLES,    /* exactly `list` numbers into consecutive doubles */
    KEYTAB_PARSED,     /* `size` bytes that `parse` makes of the text */
} keytab_type_t;

/* A parsed key's text into field: 0, or -1 with "expected ..., got '...'"
 * in why. */
typedef int (*keytab_parse_fn)(const char *val, void *field, char *why, size_t len);

typedef struct {
    const char *section;        /* the config's or a board file's section; NULL in a component's schema */
    const char *key;
    size_t offset;              /* of the field in the target struct */
    double def, min, max;       /* in the file's unit */
    const char *unit, *source;
    const char *const *choices; /* a word key: its words, the value is the index */
    int whole;                  /* 1: a whole number (a count, or 0/1) */
    double per;                 /* file units per stored unit (mm per m: 1000): stored = value / per; 0 means 1 */
    int list;                   /* KEYTAB_DOUBLE: >0: up to this many numbers, space-separated, into consecutive doubles; the count goes to the int at `size`. KEYTAB_DOUBLES: exactly this many */
    keytab_type_t type;
    size_t size;                /* KEYTAB_TEXT, KEYTAB_PARSED: bytes of the field; a KEYTAB_DOUBLE list: the offset of its count (an int) in the target struct */
    keytab_parse_fn parse;      /* KEYTAB_PARSED */
} keytab_t;

/* The stored default of every key of tab into target (required keys: 0,
 * text ""). */
void keytab_defaults(const keytab_t *tab, size_t n, void *target);
/* The key named `key` in tab (section NULL: any), NULL if none. */
const keytab_t *keytab_find(const keytab_t *tab, size_t n, const char *section, const char *key);
/* Parse val into k's field of target. 0, or -1 with "where.key: reason"
 * in reason (where = the section as the file names it). */
int keytab_set(const keytab_t *k, void *target, const char *where, const char *val, char *reason, size_t len);
/* The first required key of tab (at most 64 keys) whose bit in seen (bit
 * i: tab[i] was given) is clear, NULL if none. */
const keytab_t *keytab_missing(const keytab_t *tab, size_t n, uint64_t seen);
/* The value in the file's unit (a number or word key; 0 for the others). */
double keytab_get(const keytab_t *k, const void *target);
/* "key = value ; unit; source" as a line (value in as few digits as read
 * back the same, at least 9): a number, word or text key. */
void keytab_print(const keytab_t *k, const void *target, FILE *out);

#endif

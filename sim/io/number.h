/* number.h - the one form of a number every flag and option text takes: a
 * plain decimal (digits, an optional leading '-' and one '.'), so 0x1,
 * 1e0, +1, 0x1p1, " 1", inf and nan are refused everywhere alike
 * (docs/REFERENCE.md, "Exit codes and numbers"). */
#ifndef NUMBER_H
#define NUMBER_H

#include <stddef.h>

/* Are the n bytes at s a plain decimal number? 1 or 0. */
int io_plain_decimal(const char *s, size_t n);
/* The plain decimal of n bytes at s into *v: 0, or -1 (not one, or out of
 * a double's range). */
int io_decimal(const char *s, size_t n, double *v);

#endif

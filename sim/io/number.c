/* number.c - plain decimal numbers (see number.h). */
#include "number.h"

#include <ctype.h>
#include <errno.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

int io_plain_decimal(const char *s, size_t n)
{
    size_t i = n > 0 && s[0] == '-', digits = 0;
    while (i < n && isdigit((unsigned char)s[i])) i++, digits++;
    if (i < n && s[i] == '.')
        for (i++; i < n && isdigit((unsigned char)s[i]); i++) digits++;
    return digits > 0 && i == n;
}

int io_decimal(const char *s, size_t n, double *v)
{
    char buf[64];
    if (n >= sizeof buf || !io_plain_decimal(s, n)) return -1;
    memcpy(buf, s, n);
    buf[n] = '\0';
    errno = 0;
    *v = strtod(buf, NULL);
    return errno || !isfinite(*v) ? -1 : 0;
}

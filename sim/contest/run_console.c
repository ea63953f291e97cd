/* run_console.c - a board's console text in the JSON (run_driver.h). */
#include <stdlib.h>
#include <string.h>

#include "run_driver.h"

json_t *run_console_json(const char *text, size_t n)
{
    json_t *cj = json_stringn(text, n);
    if (cj) return cj;
    char *t = malloc(n + 1); /* not UTF-8: bytes above 0x7F as '?' */
    if (t) memcpy(t, text, n + 1);
    for (size_t i = 0; t && i < n; i++)
        if ((unsigned char)t[i] > 0x7F) t[i] = '?';
    cj = t ? json_stringn(t, n) : json_null();
    free(t);
    return cj ? cj : json_null();
}

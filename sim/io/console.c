/* console.c - a firmware's serial output as a run keeps it (console.h). */
#include "console.h"

#include <stdlib.h>
#include <string.h>

int console_init(console_t *c, char *err, size_t errn)
{
    memset(c, 0, sizeof *c);
    c->text = malloc(CONSOLE_KEEP);
    c->tail = malloc(CONSOLE_TAIL);
    if (!c->text || !c->tail) {
        console_free(c);
        return snprintf(err, errn, "out of memory"), -1;
    }
    c->text[0] = '\0';
    return 0;
}

void console_free(console_t *c)
{
    free(c->text);
    free(c->tail);
    c->text = c->tail = NULL;
}

/* Does the stream end with the text looked for? (its last look_len bytes are in the ring) */
static int ends_with_look(const console_t *c)
{
    if (c->total < c->look_len) return 0;
    uint64_t from = c->total - c->look_len;
    for (size_t i = 0; i < c->look_len; i++)
        if (c->tail[(from + i) % CONSOLE_TAIL] != c->look[i]) return 0;
    return 1;
}

void console_byte(console_t *c, uint8_t byte)
{
    char ch = (char)byte;
    if (c->len + 1 < CONSOLE_KEEP) {
        c->text[c->len++] = ch;
        c->text[c->len] = '\0';
    } else c->dropped++;
    c->tail[c->total % CONSOLE_TAIL] = ch;
    c->total++;
    if (c->look_len && !c->look_at && ends_with_look(c)) c->look_at = c->total;
    if (c->echo) {
        fputc(ch, c->echo);
        if (ch == '\n') fflush(c->echo);
    }
}

void console_look_for(console_t *c, const char *text)
{
    size_t n = strlen(text);
    if (n > CONSOLE_LOOK_MAX) n = CONSOLE_LOOK_MAX;
    memcpy(c->look, text, n);
    c->look[n] = '\0';
    c->look_len = n;
    c->look_at = 0;
}

int console_seen(const console_t *c) { return c->look_at != 0; }

size_t console_read(const console_t *c, uint64_t *pos, char *buf, size_t n, uint64_t *lost)
{
    size_t k = 0;
    while (k < n && *pos < c->len) buf[k++] = c->text[(*pos)++]; /* the kept part first */
    uint64_t oldest = c->total > CONSOLE_TAIL ? c->total - CONSOLE_TAIL : 0;
    if (k < n && *pos < oldest) {
        if (lost) *lost += oldest - *pos;
        *pos = oldest;
    }
    while (k < n && *pos < c->total) buf[k++] = c->tail[(*pos)++ % CONSOLE_TAIL];
    return k;
}

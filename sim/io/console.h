/* console.h - a firmware's serial output as a run keeps it, for either
 * board: the first CONSOLE_KEEP bytes for the JSON (the rest counted),
 * the last CONSOLE_TAIL bytes for a reader that follows it live (--console
 * pty), and one text looked for in every byte (--end-on), so a firmware
 * that logs a megabyte is still heard past the kept part. */
#ifndef IO_CONSOLE_H
#define IO_CONSOLE_H

#include <stddef.h>
#include <stdint.h>
#include <stdio.h>

#define CONSOLE_KEEP (1u << 20)   /* bytes kept for the JSON, with the terminating NUL */
#define CONSOLE_TAIL (1u << 16)   /* bytes a live reader may lag behind (64 KiB: 2 s of bulebule's 29 kB/s log) */
#define CONSOLE_LOOK_MAX 64       /* the longest text looked for (--end-on's limit) */

typedef struct {
    char *text;                   /* NUL-terminated, its first len bytes */
    size_t len;
    uint64_t total, dropped;      /* every byte received; those past the kept part */
    char *tail;                   /* ring: byte i of the stream at tail[i % CONSOLE_TAIL] */
    char look[CONSOLE_LOOK_MAX + 1];
    size_t look_len;              /* 0: nothing looked for */
    uint64_t look_at;             /* the stream's length when the text ended (0: not seen) */
    FILE *echo;                   /* every byte echoed live; NULL: none */
} console_t;

/* 0, or -1 with "out of memory" in err. */
int console_init(console_t *c, char *err, size_t errn);
void console_free(console_t *c);
/* One byte from the firmware. */
void console_byte(console_t *c, uint8_t byte);
/* Look for text (1..CONSOLE_LOOK_MAX bytes; longer is cut) in the bytes from now on. */
void console_look_for(console_t *c, const char *text);
/* 1 once the text looked for has appeared. */
int console_seen(const console_t *c);
/* The bytes from stream position *pos on, at most n, into buf; *pos moves
 * past them. The kept part is always there; a byte past it and older than
 * the tail is skipped (counted in *lost, if given). */
size_t console_read(const console_t *c, uint64_t *pos, char *buf, size_t n, uint64_t *lost);

#endif
